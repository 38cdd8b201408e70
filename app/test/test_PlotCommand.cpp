// rockroll plot DIR: for each kind of output (run of the reduced and the full car,
// sweep, steady, modes, study) a real output made by the CLI (the study: a fixture
// made to the study command's spec, tests/data/study-output) is plotted, and every
// plot's sidecar is read back: each drawn line comes from the columns it should,
// with the CSV's values (tests/PlotSidecar.h); PNG and SVG exist and are not empty.
// Bad input (not an output, a malformed file, no matplotlib, an existing plots/)
// exits 2 and leaves no plots directory behind.
#include "tests/CliRunner.h"
#include "tests/CsvReader.h"
#include "tests/PlotSidecar.h"
#include "tests/TestTmp.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>
#include <set>
#include <sys/wait.h>

namespace fs = std::filesystem;
using rockroll::test::checkPlotSidecar;
using rockroll::test::parseCsvTable;
using rockroll::test::CliOutcome;
using rockroll::test::readTextFile;
using rockroll::test::runRockroll;

namespace {

const std::string kScenario = std::string(ROCKROLL_SCENARIO_DIR) + "/70ton-loaded.toml";

std::string join(const std::vector<std::string>& v) {
    std::string s;
    for (const auto& x : v) s += x + "\n";
    return s;
}

/// A line of a sidecar: (csv, x, y, y scale).
using Drawn = std::tuple<std::string, std::string, std::string, double>;

/// Plots `out` and checks every figure: PNG and SVG exist and are not empty, the
/// sidecar reads back against the CSV (in `out`). Returns the figures' sidecars by PNG name.
std::map<std::string, nlohmann::json> plotAndReadBack(const fs::path& out) {
    const CliOutcome o = runRockroll(out.parent_path(), "plot '" + out.string() + "'");
    EXPECT_EQ(o.exitCode, 0) << o.err;
    std::map<std::string, nlohmann::json> sidecars;
    EXPECT_FALSE(fs::exists(out / "plots.partial"));
    if (!fs::is_directory(out / "plots")) {
        ADD_FAILURE() << "no " << (out / "plots");
        return sidecars;
    }
    for (const auto& e : fs::directory_iterator(out / "plots")) {
        if (e.path().extension() != ".png") continue;
        const std::string png = e.path().filename().string();
        EXPECT_GT(fs::file_size(e.path()), 0u) << png;
        const fs::path svg = fs::path(e.path()).replace_extension(".svg");
        EXPECT_TRUE(fs::exists(svg) && fs::file_size(svg) > 0) << svg;
        EXPECT_EQ(join(checkPlotSidecar(out / "plots", png, out)), "") << png;
        sidecars[png] = nlohmann::json::parse(readTextFile(out / "plots" / (png + ".json")));
        EXPECT_EQ(sidecars[png].at("svg"), svg.filename().string());
    }
    EXPECT_FALSE(sidecars.empty()) << "no plots in " << (out / "plots");
    return sidecars;
}

std::set<Drawn> drawnLines(const nlohmann::json& sidecar) {
    std::set<Drawn> d;
    for (const auto& l : sidecar.at("lines"))
        d.insert({l.at("csv"), l.at("x"), l.at("y"), l.at("y_scale").get<double>()});
    return d;
}

/// The time-history lines a run's plot must draw: roll and each truck's cross-level,
/// every wheel's load (each truck side's pair where the model has no single wheels),
/// side bearings, center plates, wheel lifts; loads in 1000 lb.
std::set<Drawn> expectedHistoryLines(const std::vector<std::string>& header) {
    std::set<Drawn> e;
    bool singleWheels = false;
    for (const auto& c : header) singleWheels = singleWheels || std::regex_match(c, std::regex("wheel_[FR][0-9]+_[LR]_lb"));
    const std::regex loads(singleWheels ? "wheel_[FR][0-9]+_[LR]_lb|side_bearing_[FR]_[LR]_lb|center_plate_[FR]_lb"
                                        : "wheels_[FR]_[LR]_lb|side_bearing_[FR]_[LR]_lb|center_plate_[FR]_lb");
    const std::regex others("roll_deg|cross_level_[FR]_in|wheel_lift_[FR][0-9]+_[LR]_in");
    for (const auto& c : header) {
        if (std::regex_match(c, loads)) e.insert({"history.csv", "t_s", c, 1e-3});
        if (std::regex_match(c, others)) e.insert({"history.csv", "t_s", c, 1.0});
    }
    return e;
}

void checkRunPlot(const std::string& model, size_t wheelLifts) {
    const fs::path dir = rockroll::test::makeTestTempDir();
    const CliOutcome run = runRockroll(dir, "run '" + kScenario + "' --model " + model + " --duration-s 1 --out run");
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const auto sidecars = plotAndReadBack(dir / "run");
    ASSERT_EQ(sidecars.count("timehistory.png"), 1u);
    const auto header = parseCsvTable(readTextFile(dir / "run" / "history.csv")).columns;
    const std::set<Drawn> expected = expectedHistoryLines(header), drawn = drawnLines(sidecars.at("timehistory.png"));
    EXPECT_EQ(drawn, expected);
    size_t lifts = 0;
    for (const auto& d : drawn) lifts += std::get<2>(d).rfind("wheel_lift_", 0) == 0;
    EXPECT_EQ(lifts, wheelLifts) << "every wheel's lift";
}

}  // namespace

TEST(PlotCommand, RunOfTheReducedModel) { checkRunPlot("reduced", 2); }

// The full car: two trucks, four wheelsets, every wheel's load and lift.
TEST(PlotCommand, RunOfTheFullCarDrawsEveryWheel) { checkRunPlot("fullcar", 8); }

TEST(PlotCommand, SweepUpAndDownWithItsJumpSpeeds) {
    const fs::path dir = rockroll::test::makeTestTempDir();
    const CliOutcome sweep = runRockroll(dir, "sweep '" + kScenario + "' --model reduced --from-mph 14 --to-mph 17 --step-mph 1 "
                                      "--duration-s 2 --direction both --out sweep");
    ASSERT_EQ(sweep.exitCode, 0) << sweep.err;
    const auto sidecars = plotAndReadBack(dir / "sweep");
    ASSERT_EQ(sidecars.count("sweep_roll.png"), 1u);
    ASSERT_EQ(sidecars.count("sweep_loads.png"), 1u);
    EXPECT_EQ(drawnLines(sidecars.at("sweep_roll.png")),
              (std::set<Drawn>{{"sweep.csv", "speed_mph", "steady_roll_amplitude_deg", 1.0},
                               {"sweep.csv", "speed_mph", "max_roll_deg", 1.0}}));
    EXPECT_EQ(drawnLines(sidecars.at("sweep_loads.png")),
              (std::set<Drawn>{{"sweep.csv", "speed_mph", "max_wheel_lift_in", 1.0},
                               {"sweep.csv", "speed_mph", "max_wheel_load_lb", 1e-3},
                               {"sweep.csv", "speed_mph", "max_side_bearing_load_lb", 1e-3}}));
    // Up and down, each drawn from its own rows.
    std::set<std::string> directions;
    for (const auto& l : sidecars.at("sweep_roll.png").at("lines")) {
        directions.insert(l.at("where").at("direction").get<std::string>());
        EXPECT_EQ(l.at("points"), 4) << l.dump();
    }
    EXPECT_EQ(directions, (std::set<std::string>{"up", "down"}));

    // The jumps of sweep.json: one per direction; each found one is marked at its speed on both roll panels.
    const auto doc = nlohmann::json::parse(readTextFile(dir / "sweep" / "sweep.json"));
    const auto& jumps = doc.at("jumps");
    ASSERT_EQ(jumps.size(), 2u);
    // The rule, recomputed from sweep.csv: the largest rise going up, the largest fall coming down.
    const auto table = parseCsvTable(readTextFile(dir / "sweep" / "sweep.csv"));
    for (const auto& j : jumps) {
        std::vector<double> speed, amp;
        for (const auto& r : table.rows)
            if (r[table.find("direction")] == j.at("direction").get<std::string>()) {
                speed.push_back(std::stod(r[table.find("speed_mph")]));
                amp.push_back(std::stod(r[table.find("steady_roll_amplitude_deg")]));
            }
        const double sign = j.at("direction") == "up" ? 1 : -1;
        double best = 0, at = NAN;
        for (size_t i = 1; i < amp.size(); ++i)
            if (sign * (amp[i] - amp[i - 1]) > best) best = sign * (amp[i] - amp[i - 1]), at = speed[i];
        if (std::isnan(at)) {
            EXPECT_TRUE(j.at("jump_speed_mph").is_null()) << j.dump();
        } else {
            EXPECT_EQ(j.at("jump_speed_mph").get<double>(), at) << j.dump();
        }
        EXPECT_EQ(j.at("steady_roll_change_deg").get<double>(), best) << j.dump();
    }
    std::multiset<double> marked, expected;
    for (const auto& m : sidecars.at("sweep_roll.png").value("markers", nlohmann::json::array())) {
        const auto& j = jumps.at(m.at("index").get<size_t>());
        EXPECT_EQ(m.at("json"), "sweep.json");
        EXPECT_EQ(m.at("x").get<double>(), j.at("jump_speed_mph").get<double>());
        marked.insert(m.at("x").get<double>());
    }
    for (const auto& j : jumps)
        if (!j.at("jump_speed_mph").is_null()) expected.insert({j.at("jump_speed_mph").get<double>(), j.at("jump_speed_mph").get<double>()});
    EXPECT_EQ(marked, expected) << "each jump on both roll panels";
}

TEST(PlotCommand, Steady) {
    const fs::path dir = rockroll::test::makeTestTempDir();
    const CliOutcome steady = runRockroll(dir, "steady '" + kScenario + "' --from-mph 14 --to-mph 15 --stability none --out steady");
    ASSERT_EQ(steady.exitCode, 0) << steady.err;
    const auto sidecars = plotAndReadBack(dir / "steady");
    ASSERT_EQ(sidecars.count("steady.png"), 1u);
    EXPECT_EQ(drawnLines(sidecars.at("steady.png")),
              (std::set<Drawn>{{"steady.csv", "speed_mph", "roll_amplitude_deg", 1.0},
                               {"steady.csv", "speed_mph", "wheel_lift_fraction", 1.0}}));
}

TEST(PlotCommand, Orbits) {
    const fs::path dir = rockroll::test::makeTestTempDir();
    const CliOutcome orbits = runRockroll(dir, "orbits '" + kScenario + "' --model eom --amplitude-in 0.25 --from-mph 12 "
                                               "--to-mph 11.75 --step-mph 0.25 --start-duration-s 10 --out orbits");
    ASSERT_EQ(orbits.exitCode, 0) << orbits.err;
    const auto sidecars = plotAndReadBack(dir / "orbits");
    ASSERT_EQ(sidecars.count("orbits.png"), 1u);
    EXPECT_EQ(drawnLines(sidecars.at("orbits.png")),
              (std::set<Drawn>{{"orbits.csv", "speed_mph", "roll_amplitude_deg", 1.0},
                               {"orbits.csv", "speed_mph", "max_multiplier", 1.0}}));
}

TEST(PlotCommand, Modes) {
    const fs::path dir = rockroll::test::makeTestTempDir();
    const CliOutcome modes = runRockroll(dir, "modes '" + kScenario + "' --model halfcar --out modes");
    ASSERT_EQ(modes.exitCode, 0) << modes.err;
    const auto sidecars = plotAndReadBack(dir / "modes");
    ASSERT_EQ(sidecars.count("modes.png"), 1u);
    EXPECT_EQ(drawnLines(sidecars.at("modes.png")),
              (std::set<Drawn>{{"modes.csv", "frequency_hz", "damping_ratio", 1.0},
                               {"modes.csv", "table1_formula_hz", "frequency_hz", 1.0}}));
}

// A study: one figure per varied parameter, each response against it, lines by the
// other parameter's values and by status; a failed point draws nothing.
TEST(PlotCommand, StudyFixture) {
    const fs::path dir = rockroll::test::makeTestTempDir();
    fs::copy(fs::path(ROCKROLL_SOURCE_DIR) / "tests/data/study-output", dir / "study");
    const auto sidecars = plotAndReadBack(dir / "study");
    const auto study = nlohmann::json::parse(readTextFile(dir / "study" / "study.json"));
    ASSERT_EQ(sidecars.size(), study.at("varied").size());
    for (const auto& v : study.at("varied")) {
        const std::string x = v.at("column"), png = "study_" + x + ".png";
        ASSERT_EQ(sidecars.count(png), 1u) << png;
        std::set<std::string> ys, statuses;
        for (const auto& l : sidecars.at(png).at("lines")) {
            EXPECT_EQ(l.at("x"), x);
            ys.insert(l.at("y").get<std::string>());
            statuses.insert(l.at("where").at("status").get<std::string>());
            EXPECT_EQ(l.at("where").size(), study.at("varied").size()) << "the other parameter and the status";
        }
        EXPECT_EQ(ys, (std::set<std::string>{"max_roll_deg", "peak_to_peak_roll_deg", "max_wheel_lift_in",
                                             "max_wheel_unloading", "max_side_bearing_load_lb", "max_l_over_v"}));
        EXPECT_EQ(statuses, (std::set<std::string>{"ok", "derailed"}));
    }
}

TEST(PlotCommand, BadInputExits2AndLeavesNoPlots) {
    const fs::path dir = rockroll::test::makeTestTempDir();
    fs::create_directories(dir / "empty");
    CliOutcome o = runRockroll(dir, "plot empty");
    EXPECT_EQ(o.exitCode, 2);
    EXPECT_NE(o.err.find("is not a rockroll output directory"), std::string::npos) << o.err;
    EXPECT_TRUE(fs::is_empty(dir / "empty"));

    o = runRockroll(dir, "plot no-such-dir");
    EXPECT_EQ(o.exitCode, 2) << o.err;

    // A history without the center-plate channels.
    fs::create_directories(dir / "bad");
    std::ofstream(dir / "bad" / "history.csv") << "t_s,roll_deg\n0,0\n0.1,0.2\n";
    std::ofstream(dir / "bad" / "summary.json") << "{}\n";
    o = runRockroll(dir, "plot bad");
    EXPECT_EQ(o.exitCode, 2);
    EXPECT_NE(o.err.find("history.csv: no center-plate column"), std::string::npos) << o.err;
    EXPECT_FALSE(fs::exists(dir / "bad" / "plots"));
    EXPECT_FALSE(fs::exists(dir / "bad" / "plots.partial"));

    // The study fixture: plots once, then plots/ exists and needs --force.
    fs::copy(fs::path(ROCKROLL_SOURCE_DIR) / "tests/data/study-output", dir / "study");
    ASSERT_EQ(runRockroll(dir, "plot study").exitCode, 0);
    o = runRockroll(dir, "plot study");
    EXPECT_EQ(o.exitCode, 2);
    EXPECT_NE(o.err.find("--force"), std::string::npos) << o.err;
    EXPECT_EQ(runRockroll(dir, "plot study --force").exitCode, 0);

    // No Python at ROCKROLL_PYTHON; a Python without matplotlib (a stand-in package that fails to import).
    o = runRockroll(dir, "plot study --force", "ROCKROLL_PYTHON=/no/such/python");
    EXPECT_EQ(o.exitCode, 2);
    EXPECT_NE(o.err.find("ROCKROLL_PYTHON /no/such/python"), std::string::npos) << o.err;
    fs::create_directories(dir / "nompl" / "matplotlib");
    std::ofstream(dir / "nompl" / "matplotlib" / "__init__.py") << "raise ImportError('no matplotlib here')\n";
    {
        std::ofstream py(dir / "python-without-matplotlib");
        py << "#!/bin/sh\nexport PYTHONPATH='" << (dir / "nompl").string() << "':\"$PYTHONPATH\"\nexec /usr/bin/python3 \"$@\"\n";
    }
    fs::permissions(dir / "python-without-matplotlib", fs::perms::owner_all);
    o = runRockroll(dir, "plot study --force", "ROCKROLL_PYTHON='" + (dir / "python-without-matplotlib").string() + "'");
    EXPECT_EQ(o.exitCode, 2);
    EXPECT_NE(o.err.find("matplotlib is missing"), std::string::npos) << o.err;
    EXPECT_TRUE(fs::exists(dir / "study" / "plots" / "study_run.speed_mph.png")) << "the old plots are kept";
}
