// rockroll validate: the committed report names the commit it came from, and
// the quick run regenerates a complete report whose every file reads back: each
// CSV as an RFC 4180 table with its required columns by name, each JSON, and each
// plot's sidecar (python/rockroll_plots (figures.py)) against the CSV columns it says it drew.
#include "app/ValidateSections.h"
#include "tests/CliRunner.h"
#include "tests/CsvReader.h"
#include "tests/PlotSidecar.h"
#include "tests/TestTmp.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <regex>
#include <set>
#include <sstream>
#include <sys/wait.h>
#include <tuple>

namespace {
namespace fs = std::filesystem;
using rockroll::test::CsvTable;
using rockroll::test::parseCsvTable;
using rockroll::test::parseNumber;
using rockroll::test::checkPlotSidecar;

using rockroll::test::readTextFile;
const std::string kSource = std::string(ROCKROLL_SCENARIO_DIR) + "/..";

const std::vector<std::string> kHistoryColumns{"t_s",           "roll_deg",           "cross_level_F_in",
                                               "car_body_vertical_in", "side_bearing_F_L_lb", "side_bearing_F_R_lb",
                                               "wheel_lift_F1_L_in",   "wheel_lift_F1_R_in",  "wheels_F_L_lb",
                                               "wheels_F_R_lb"};
const std::vector<std::string> kSweepNumbers{"speed_mph",         "max_roll_deg",      "steady_roll_amplitude_deg",
                                             "peak_to_peak_roll_deg", "max_wheel_lift_in", "max_wheel_load_lb",
                                             "min_wheel_load_ratio",  "max_side_bearing_load_lb",
                                             "max_center_plate_load_lb"};
const std::vector<std::string> kSteadyNumbers{"branch",
                                              "path",
                                              "speed_mph",
                                              "roll_amplitude_deg",
                                              "roll_first_harmonic_deg",
                                              "wheel_lift_fraction",
                                              "side_bearing_load_mean_lb",
                                              "side_bearing_load_first_harmonic_lb",
                                              "folds_before"};

void expectColumns(const CsvTable& t, const std::vector<std::string>& names, std::vector<std::string>& errors,
                   const std::string& file) {
    for (const auto& n : names)
        if (t.find(n) < 0) errors.push_back(file + ": no column " + n);
}

void expectValues(const CsvTable& t, const std::string& col, const std::set<std::string>& allowed,
                  std::vector<std::string>& errors, const std::string& file) {
    const int k = t.find(col);
    if (k < 0) return;
    for (size_t r = 0; r < t.rows.size(); ++r)
        if (!allowed.count(t.rows[r][k]))
            errors.push_back(file + " row " + std::to_string(r + 1) + ": " + col + " = \"" + t.rows[r][k] + "\"");
}

const std::vector<std::string> kOrbitNumbers{"speed_mph", "period", "roll_amplitude_deg", "wheel_lift_fraction",
                                             "max_multiplier", "largest_real_multiplier", "smallest_real_multiplier"};

/// Reads back one CSV written by validate; returns what is wrong with it.
std::vector<std::string> checkValidateCsv(const fs::path& path, bool quick) {
    std::vector<std::string> errors;
    const std::string name = path.filename().string();
    CsvTable t;
    try {
        t = parseCsvTable(readTextFile(path.string()));
    } catch (const std::exception& e) {
        return {name + ": " + e.what()};
    }
    if (t.rows.empty()) errors.push_back(name + ": no rows");
    std::vector<std::string> numeric;
    if (name.rfind("timehistory_", 0) == 0) {
        expectColumns(t, kHistoryColumns, errors, name);
        numeric = t.columns;  // every channel is a number
    } else if (name.rfind("sweep_", 0) == 0) {
        expectColumns(t, {"direction", "start", "failed", "regime"}, errors, name);
        expectColumns(t, kSweepNumbers, errors, name);
        expectValues(t, "direction", {"up", "down"}, errors, name);
        expectValues(t, "start", {"rest", "continued"}, errors, name);
        expectValues(t, "failed", {"0", "1"}, errors, name);
        // A failed speed has no summary: only its speed must be a number.
        CsvTable ok = t, failed = t;
        ok.rows.clear(), failed.rows.clear();
        const int f = t.find("failed");
        for (const auto& r : t.rows) (f >= 0 && r[f] == "1" ? failed : ok).rows.push_back(r);
        for (const auto& c : kSweepNumbers) try {
                (void)ok.numbers(c);
            } catch (const std::exception& e) {
                errors.push_back(name + ": " + e.what());
            }
        numeric = {"speed_mph"};
        t = failed;
    } else if (name.rfind("steady_", 0) == 0) {
        expectColumns(t, {"stable"}, errors, name);
        expectColumns(t, kSteadyNumbers, errors, name);
        // The quick run traces without stability: every solution must say so, never "yes".
        expectValues(t, "stable", quick ? std::set<std::string>{"not computed"}
                                        : std::set<std::string>{"yes", "no", "not computed"},
                     errors, name);
        numeric = kSteadyNumbers;
    } else if (name.rfind("orbits_", 0) == 0) {
        // One row per orbit point computed: converged rows carry numbers; a failed point only its speed.
        expectColumns(t, {"converged", "stable"}, errors, name);
        expectColumns(t, kOrbitNumbers, errors, name);
        expectValues(t, "converged", {"0", "1"}, errors, name);
        CsvTable ok = t;
        ok.rows.clear();
        const int c = t.find("converged"), st = t.find("stable");
        for (const auto& r : t.rows)
            if (c >= 0 && r[c] == "1") {
                ok.rows.push_back(r);
                if (st >= 0 && r[st] != "yes" && r[st] != "no") errors.push_back(name + ": stable = \"" + r[st] + "\"");
            } else if (st >= 0 && !r[st].empty()) {
                errors.push_back(name + ": a point that did not converge has a stability");
            }
        // The reduced model's orbits are found by iteration (docs/orbits.md): no real multipliers, empty cells.
        const bool iterated = name.size() > 12 && name.substr(name.size() - 12) == "_reduced.csv";
        for (const auto& col : kOrbitNumbers) try {
                const bool real = std::string(col).find("real_multiplier") != std::string::npos;
                if (iterated && real) {
                    const int k = ok.find(col);
                    for (const auto& r : ok.rows)
                        if (k >= 0 && !r[k].empty()) errors.push_back(name + ": " + col + " = \"" + r[k] + "\" (iteration gives none)");
                    continue;
                }
                for (double v : ok.numbers(col))
                    if (!std::isfinite(v)) errors.push_back(name + ": " + col + " holds " + std::to_string(v));
            } catch (const std::exception& e) {
                errors.push_back(name + ": " + e.what());
            }
        numeric = {"speed_mph"};
    } else if (name == "wheel_rail_table3.csv" || name == "wheel_rail_flange_climb.csv") {
        // Section 12: one row per run; a failed run holds only its case.
        const bool table3 = name == "wheel_rail_table3.csv";
        const std::vector<std::string> cases{"amplitude_in", "speed_mph"};
        const std::vector<std::string> measures =
            table3 ? std::vector<std::string>{"max_roll_deg", "steady_max_roll_deg", "max_wheel_lift_in",
                                              "max_wheel_load_lb", "min_wheel_load_ratio", "max_side_bearing_load_lb",
                                              "max_single_wheel_l_over_v", "max_truck_side_l_over_v",
                                              "energy_balance_error"}
                   : std::vector<std::string>{"nadal_limit", "held_l_over_v", "l_over_v_margin", "longest_flange_contact_s", "max_flange_force_lb",
                                              "max_lift_in_flange_contact_in", "max_wheelset_lateral_in",
                                              "max_single_wheel_l_over_v", "min_wheel_load_ratio", "max_roll_deg"};
        expectColumns(t, {"car", "failed", "regime"}, errors, name);
        expectColumns(t, cases, errors, name);
        expectColumns(t, measures, errors, name);
        expectValues(t, "failed", {"0", "1"}, errors, name);
        if (table3) expectValues(t, "lateral", {"restraint", "creep_and_flange"}, errors, name);
        CsvTable ok = t;
        ok.rows.clear();
        const int f = t.find("failed");
        for (const auto& r : t.rows)
            if (f >= 0 && r[f] == "0") ok.rows.push_back(r);
        for (const auto& c : measures) try {
                for (double v : ok.numbers(c))
                    if (!std::isfinite(v)) errors.push_back(name + ": " + c + " holds " + std::to_string(v));
            } catch (const std::exception& e) {
                errors.push_back(name + ": " + e.what());
            }
        if (!table3) {
            // The climb margin is the held L/V over Nadal's limit, and a run the monitor did not
            // stop never held more than the limit (the monitor reads the same rows).
            const int held = t.find("held_l_over_v_in_flange_contact"), margin = t.find("climb_margin"),
                      nadal = t.find("nadal_limit"), stopped = t.find("stopped_at_s");
            if (held < 0 || margin < 0 || nadal < 0 || stopped < 0) {
                errors.push_back(name + ": no climb columns");
            } else {
                for (const auto& r : ok.rows) {
                    if (r[held].empty() != r[margin].empty()) errors.push_back(name + ": held L/V without a margin");
                    if (r[held].empty()) continue;
                    const double m = parseNumber(r[margin]).value_or(NAN), h = parseNumber(r[held]).value_or(NAN),
                                 n = parseNumber(r[nadal]).value_or(NAN);
                    if (std::abs(m - h / n) > 1e-3) errors.push_back(name + ": climb margin " + r[margin] + " is not " + r[held] + " / " + r[nadal]);
                    if (r[stopped].empty() && m > 1 + 1e-3) errors.push_back(name + ": a run that was not stopped held a climb margin of " + r[margin]);
                }
            }
        }
        numeric = cases;
    } else {
        errors.push_back(name + ": a CSV this test does not know; add its columns here");
    }
    for (const auto& c : numeric) try {
            for (double v : t.numbers(c))
                if (!std::isfinite(v)) errors.push_back(name + ": " + c + " holds " + std::to_string(v));
        } catch (const std::exception& e) {
            errors.push_back(name + ": " + e.what());
        }
    return errors;
}

/// What each plot of validate must draw: (CSV name prefix, x column, y column, y scale).
struct Drawn {
    std::string csvPrefix, x, y;
    double yScale;
    bool operator<(const Drawn& o) const { return std::tie(csvPrefix, x, y, yScale) < std::tie(o.csvPrefix, o.x, o.y, o.yScale); }
};

std::set<Drawn> expectedLines(const std::string& png) {
    std::smatch m;
    std::set<Drawn> e;
    auto scale = [](const std::string& col) { return col.size() > 3 && col.substr(col.size() - 3) == "_lb" ? 1e-3 : 1.0; };
    if (png == "timehistory.png") {
        for (size_t k = 1; k < kHistoryColumns.size(); ++k)
            e.insert({"timehistory_", "t_s", kHistoryColumns[k], scale(kHistoryColumns[k])});
    } else if (std::regex_match(png, m, std::regex("sweep_loads_(.+)\\.png"))) {
        for (const char* y : {"max_wheel_lift_in", "max_wheel_load_lb", "max_side_bearing_load_lb"})
            e.insert({"sweep_" + m[1].str() + "_", "speed_mph", y, scale(y)});
    } else if (std::regex_match(png, m, std::regex("sweep_(.+)\\.png"))) {
        e.insert({"sweep_" + m[1].str() + "_", "speed_mph", "steady_roll_amplitude_deg", 1});
    } else if (std::regex_match(png, m, std::regex("steady_(.+)\\.png"))) {
        e.insert({"steady_" + m[1].str() + ".csv", "speed_mph", "roll_amplitude_deg", 1});
        e.insert({"sweep_" + m[1].str() + "_", "speed_mph", "steady_roll_amplitude_deg", 1});
        e.insert({"orbits_" + m[1].str() + "_", "speed_mph", "roll_amplitude_deg", 1});
    }
    return e;
}

/// The sidecar draws exactly the expected (file, x, y, scale) lines.
std::vector<std::string> checkPlotColumns(const fs::path& dir, const std::string& png) {
    const std::set<Drawn> expected = expectedLines(png);
    if (expected.empty()) return {png + ": a plot this test does not know; add what it must draw here"};
    if (!fs::exists(dir / (png + ".json"))) return {png + ": no sidecar " + png + ".json (python/rockroll_plots (figures.py) writes one)"};
    nlohmann::json side;
    try {
        side = nlohmann::json::parse(readTextFile(dir / (png + ".json")));
    } catch (const std::exception& e) {
        return {png + ".json: " + e.what()};
    }
    std::set<Drawn> drawn;
    std::vector<std::string> errors;
    for (const auto& l : side["lines"]) {
        const std::string csv = l.at("csv").get<std::string>();
        bool known = false;
        for (const auto& d : expected)
            if (csv.rfind(d.csvPrefix, 0) == 0 && d.x == l.at("x").get<std::string>() && d.y == l.at("y").get<std::string>()) {
                known = true;
                drawn.insert(d);
                if (l.at("x_scale").get<double>() != 1.0 || l.at("y_scale").get<double>() != d.yScale)
                    errors.push_back(png + ": " + d.y + " drawn with scale " + l.at("y_scale").dump());
            }
        if (!known)
            errors.push_back(png + ": draws " + l.at("y").get<std::string>() + " against " + l.at("x").get<std::string>() +
                             " from " + csv + ", which it should not");
    }
    for (const auto& d : expected)
        if (!drawn.count(d)) errors.push_back(png + ": does not draw " + d.y + " against " + d.x + " from " + d.csvPrefix + "*");
    return errors;
}

std::string join(const std::vector<std::string>& v) {
    std::string s;
    for (const auto& x : v) s += x + "\n";
    return s;
}

struct ReadBack {
    int csvs = 0, jsons = 0, pngs = 0;
};

/// Every file validate wrote to `out` reads back (gtest failures for what does not).
ReadBack checkValidateOutput(const fs::path& out, bool quick) {
    // Every file reads back. JSON: parses; validation.json names only files that exist.
    ReadBack n;
    std::set<std::string> listed;
    for (const auto& e : fs::directory_iterator(out)) {
        const std::string name = e.path().filename().string();
        if (e.path().extension() == ".json") {
            ++n.jsons;
            nlohmann::json j;
            try {
                j = nlohmann::json::parse(readTextFile(e.path().string()));
            } catch (const std::exception& x) {
                ADD_FAILURE() << name << ": " << x.what();
                continue;
            }
            if (name != "validation.json") continue;
            for (const char* key : {"timehistories", "sweeps", "steady", "orbits"}) {
                if (!(j.contains(key) && j[key].is_array() && !j[key].empty())) {
                    ADD_FAILURE() << "validation.json: no " << key;
                    continue;
                }
                for (const auto& item : j[key]) {
                    const std::string file = item.at("file").get<std::string>();
                    listed.insert(file);
                    EXPECT_TRUE(fs::exists(out / file)) << "validation.json lists " << file;
                }
            }
            // Section 12's files.
            if (!(j.contains("wheel_rail") && j["wheel_rail"].contains("files"))) {
                ADD_FAILURE() << "validation.json: no wheel_rail files";
            } else {
                for (const auto& item : j["wheel_rail"]["files"]) {
                    const std::string file = item.at("file").get<std::string>();
                    listed.insert(file);
                    EXPECT_TRUE(fs::exists(out / file)) << "validation.json lists " << file;
                }
            }
        } else if (e.path().extension() == ".csv") {
            ++n.csvs;
            EXPECT_EQ(join(checkValidateCsv(e.path(), quick)), "");
        }
    }
    for (const auto& e : fs::directory_iterator(out))
        if (e.path().extension() == ".csv") {
            EXPECT_TRUE(listed.count(e.path().filename().string())) << e.path().filename() << " is not in validation.json";
        }
    // Plots: each PNG's sidecar draws the expected columns, and its values are the CSV's.
    for (const auto& e : fs::directory_iterator(out)) {
        if (e.path().extension() != ".png") continue;
        ++n.pngs;
        const std::string png = e.path().filename().string();
        EXPECT_EQ(join(checkPlotColumns(out, png)), "");
        EXPECT_EQ(join(checkPlotSidecar(out, png)), "");
    }
    return n;
}

}  // namespace

TEST(Validate, CommittedReportNamesAnExistingCommit) {
    const std::string report = readTextFile(kSource + "/results/REPORT.md");
    ASSERT_FALSE(report.empty()) << "results/REPORT.md is missing";
    std::smatch m;
    ASSERT_TRUE(std::regex_search(report, m, std::regex("Generated from commit ([0-9a-f]{40})")))
        << "REPORT.md does not name its commit";
    EXPECT_EQ(report.find("uncommitted changes"), std::string::npos) << "generated from a dirty tree";
    const std::string cmd = "git -C '" + kSource + "' cat-file -e " + m[1].str() + "^{commit} 2>/dev/null";
    if (std::system(("git -C '" + kSource + "' rev-parse 2>/dev/null").c_str()) == 0) {
        EXPECT_EQ(std::system(cmd.c_str()), 0) << "commit " << m[1] << " is not in this repository";
    }
}

TEST(Validate, QuickRunWritesAReportWithEverySection) {
    const std::filesystem::path out = rockroll::test::makeTestTempDir() / "out";
    const std::string cmd = std::string(ROCKROLL_BIN) + " validate --quick --out '" + out.string() + "' > /dev/null 2>&1";
    ASSERT_EQ(std::system(cmd.c_str()), 0);
    const std::string report = readTextFile(out / "REPORT.md");
    for (const char* section : {"Time histories", "Roll against speed", "Table 3", "Table 4", "Describing-function",
                                "Modes", "Convergence", "degrees of freedom", "criteria", "Attribution",
                                "Where the upper branch ends", "The wheel–rail contact", "closest to flange climb"})
        EXPECT_NE(report.find(section), std::string::npos) << section;
    // The quick attribution and convergence sections produce their tables.
    for (const char* table : {"| half car: `unsprung_gravity = false` |", "| reduced: `truck_weight = true` |",
                              "| half car: `unsprung_mass_scale = 0.01` |", "**Pass or fail per case**",
                              "| halfcar severe (16.5 mph) | severe |"})
        EXPECT_NE(report.find(table), std::string::npos) << table;
    EXPECT_NE(report.find("Generated from commit"), std::string::npos);
    for (const char* file : {"timehistory.png", "sweep_70ton-loaded_0.75in.png", "steady_70ton-loaded_0.75in.png",
                             "sweep_70ton-loaded_0.75in_reduced.csv", "validation.json"})
        EXPECT_TRUE(std::filesystem::exists(out / file)) << file;
    // Nothing half-written is left behind.
    for (const auto& e : std::filesystem::directory_iterator(out))
        EXPECT_EQ(e.path().string().find(".tmp"), std::string::npos) << e.path();

    // The phase times read back: every phase once, in order, none negative, and together
    // no more than the whole run; the header lists the same phases.
    const nlohmann::json meta = nlohmann::json::parse(readTextFile(out / "validation.json"));
    ASSERT_TRUE(meta.contains("phases") && meta["phases"].is_array());
    std::vector<std::string> names;
    double wallSum = 0;
    for (const auto& p : meta["phases"]) {
        names.push_back(p.at("phase").get<std::string>());
        EXPECT_GE(p.at("wall_min").get<double>(), 0) << names.back();
        EXPECT_GE(p.at("cpu_min").get<double>(), 0) << names.back();
        wallSum += p.at("wall_min").get<double>();
        EXPECT_NE(report.find(fmt::format("{} {:.1f} (", names.back(), p.at("wall_min").get<double>())), std::string::npos)
            << names.back() << " is not in REPORT.md's phase line";
    }
    EXPECT_EQ(join(names), join({"convergence", "time histories", "speed sweeps", "describing function", "Tables 3 and 4",
                                 "modes", "added degrees of freedom", "attribution", "periodic orbits",
                                 "wheel-rail contact", "plots"}));
    EXPECT_LE(wallSum, meta.at("wall_min").get<double>() + 1e-9);
    EXPECT_GT(meta.at("cpu_min").get<double>(), 0);

    const ReadBack n = checkValidateOutput(out, true);
    // Quick run: 4 time histories, 6 sweeps, 1 steady, 1 orbit branch, 2 of the wheel–rail contact;
    // a time-history plot, 2 per sweep case, 1 steady.
    EXPECT_EQ(n.csvs, 14);
    EXPECT_EQ(n.pngs, 14);
    EXPECT_EQ(n.jsons, n.pngs + 1);
}

// A section that fails is reported with its error (stderr, REPORT.md, validation.json),
// the sections after it still run, and validate exits 4 (docs/cli.md, "Exit codes"). The
// failure is injected through ROCKROLL_VALIDATE_FAIL_SECTION (app/Validate.cpp).
TEST(Validate, AFailedSectionIsReportedAndTheOthersStillRun) {
    const fs::path dir = rockroll::test::makeTestTempDir(), out = dir / "out";
    const std::string cmd = "ROCKROLL_VALIDATE_FAIL_SECTION='time histories' " + std::string(ROCKROLL_BIN) +
                            " validate --quick --out '" + out.string() + "' > /dev/null 2> '" +
                            (dir / "stderr.txt").string() + "'";
    EXPECT_EQ(rockroll::test::getExitCode(std::system(cmd.c_str())), 4);
    const std::string err = readTextFile(dir / "stderr.txt");
    EXPECT_NE(err.find("section \"time histories\" FAILED: injected failure"), std::string::npos) << err;
    EXPECT_NE(err.find("1 section(s) failed: time histories: injected failure"), std::string::npos) << err;
    const std::string report = readTextFile(out / "REPORT.md");
    EXPECT_NE(report.find("## time histories\n\n**This section failed:** injected failure"), std::string::npos);
    // The others ran and wrote their tables.
    for (const char* section : {"Roll against speed", "Table 3", "Table 4", "Describing-function", "Modes",
                                "Convergence", "degrees of freedom", "criteria", "Attribution"})
        EXPECT_NE(report.find(section), std::string::npos) << section;
    EXPECT_TRUE(fs::exists(out / "sweep_70ton-loaded_0.75in_reduced.csv"));
    const nlohmann::json meta = nlohmann::json::parse(readTextFile(out / "validation.json"));
    ASSERT_TRUE(meta.contains("failed_sections")) << meta.dump();
    ASSERT_EQ(meta["failed_sections"].size(), 1u);
    EXPECT_NE(meta["failed_sections"][0].get<std::string>().find("time histories: injected failure"), std::string::npos);
}

// The committed results/ read back as the quick run's do (results/ is regenerated
// by `rockroll validate`; a file written by an older writer fails here).
TEST(Validate, CommittedResultsReadBack) {
    const fs::path results = fs::path(kSource) / "results";
    const std::string report = readTextFile(results / "REPORT.md");
    ASSERT_FALSE(report.empty()) << "results/REPORT.md is missing";
    const bool quick = report.find("`rockroll validate --quick`") != std::string::npos;
    const ReadBack n = checkValidateOutput(results, quick);
    EXPECT_GT(n.csvs, 0);
    EXPECT_GT(n.pngs, 0);
    EXPECT_EQ(n.jsons, n.pngs + 1) << "every PNG has its sidecar, plus validation.json";
}

// The read-back checks can fail: a shifted header, a wrong column in a plot, or a
// quick-run steady CSV that calls a solution stable.
TEST(Validate, ReadBackChecksCatchWrongFiles) {
    const fs::path dir = rockroll::test::makeTestTempDir();
    auto write = [&](const std::string& name, const std::string& text) { std::ofstream(dir / name) << text; };
    // The header that shifted every column on main.
    write("steady_70ton-loaded_0.75in.csv",
          "branch,stable (1 yes, 0 no, -1 not computed),speed_mph,roll_amplitude_deg,wheel_lift_fraction,"
          "max_wheel_load_lb,max_side_bearing_load_lb,folds_before\n0,-1,12.0000,0.6100,0.0000,40000,1000,0\n");
    EXPECT_NE(join(checkValidateCsv(dir / "steady_70ton-loaded_0.75in.csv", true)), "");
    const std::string good =
        "branch,path,stable,speed_mph,roll_amplitude_deg,roll_first_harmonic_deg,wheel_lift_fraction,"
        "side_bearing_load_mean_lb,side_bearing_load_first_harmonic_lb,twin_stayed,twin_max_truck_side_wheel_load_lb,"
        "twin_max_side_bearing_load_lb,checked,stability_evidence,folds_before\n"
        "0,0,yes,12.0000,0.6100,0.6000,0.0000,0,0,yes,40000,1000,1,floquet+persistence,0\n"
        "0,0,yes,12.5000,0.6500,0.6400,0.0000,0,0,yes,41000,1100,0,interpolated,0\n";
    write("steady_70ton-loaded_0.75in.csv", good);
    EXPECT_NE(join(checkValidateCsv(dir / "steady_70ton-loaded_0.75in.csv", true)), "") << "quick run said stable";
    EXPECT_EQ(join(checkValidateCsv(dir / "steady_70ton-loaded_0.75in.csv", false)), "");
    // Section 12: a run the monitor let finish cannot have held more than Nadal's limit in flange contact.
    const std::string climbHeader =
        "car,amplitude_in,speed_mph,failed,regime,stopped_at_s,stop_reason,nadal_limit,held_l_over_v,l_over_v_margin,"
        "held_l_over_v_wheel,held_l_over_v_in_flange_contact,climb_margin,held_in_flange_contact_wheel,"
        "longest_flange_contact_s,max_flange_force_lb,max_lift_in_flange_contact_in,max_wheelset_lateral_in,"
        "max_single_wheel_l_over_v,min_wheel_load_ratio,max_roll_deg\n";
    auto climbRow = [](const std::string& stopped, const std::string& held, const std::string& margin) {
        return "70ton-loaded,0.75,16,0,severe," + stopped + ",,1.1277,0.9,0.7981,l_over_v_T1_L," + held + "," + margin +
               ",flange_T11_L,0.2,30000,0.1,0.4,0.95,0.05,3.2\n";
    };
    write("wheel_rail_flange_climb.csv", climbHeader + climbRow("", "0.9", "0.7981"));
    EXPECT_EQ(join(checkValidateCsv(dir / "wheel_rail_flange_climb.csv", false)), "");
    write("wheel_rail_flange_climb.csv", climbHeader + climbRow("", "1.2", "1.0641"));
    EXPECT_NE(join(checkValidateCsv(dir / "wheel_rail_flange_climb.csv", false)), "") << "climbed but not stopped";
    write("wheel_rail_flange_climb.csv", climbHeader + climbRow("9.5", "1.2", "0.5"));
    EXPECT_NE(join(checkValidateCsv(dir / "wheel_rail_flange_climb.csv", false)), "") << "margin is not held / Nadal";
    write("other.csv", "a,b\n1,2\n");
    EXPECT_NE(join(checkValidateCsv(dir / "other.csv", true)), "") << "unknown CSV";

    auto sidecar = [&](const std::string& y, double ys, double drawnY) {
        nlohmann::json where = nlohmann::json::object(), sample = nlohmann::json::object(), l = nlohmann::json::object();
        where["branch"] = "0";
        sample["index"] = 1, sample["x"] = 12.5, sample["y"] = drawnY;
        l["csv"] = "steady_70ton-loaded_0.75in.csv", l["where"] = where, l["x"] = "speed_mph", l["y"] = y;
        l["x_scale"] = 1.0, l["y_scale"] = ys, l["points"] = 2, l["samples"] = nlohmann::json::array({sample});
        nlohmann::json doc = nlohmann::json::object();
        doc["lines"] = nlohmann::json::array({l});
        write("steady_70ton-loaded_0.75in.png.json", doc.dump());
    };
    sidecar("roll_amplitude_deg", 1.0, 0.65);
    EXPECT_EQ(join(checkPlotSidecar(dir, "steady_70ton-loaded_0.75in.png")), "");
    sidecar("roll_amplitude_deg", 1.0, 1100);  // drew another column's values under this name
    EXPECT_NE(join(checkPlotSidecar(dir, "steady_70ton-loaded_0.75in.png")), "");
    sidecar("twin_max_side_bearing_load_lb", 1.0, 1100);  // honest sidecar, wrong column for this plot
    EXPECT_EQ(join(checkPlotSidecar(dir, "steady_70ton-loaded_0.75in.png")), "");
    const std::string wrong = join(checkPlotColumns(dir, "steady_70ton-loaded_0.75in.png"));
    EXPECT_NE(wrong.find("draws twin_max_side_bearing_load_lb against speed_mph from steady_70ton-loaded_0.75in.csv, which it "
                         "should not"), std::string::npos) << wrong;
}

// Section 9 judges each sweep by its own scenario's [criteria] (with validate's two
// options on top), not by the first sweep's: a car with a tighter vertical-acceleration
// limit fails where the same point passes under the default limits, and is marked.
TEST(Validate, CriteriaSectionJudgesEachSweepByItsOwnLimits) {
    using namespace rockroll;
    using namespace rockroll::app;
    Settings s;
    s.rollLimitDeg = 6;
    s.wheelLoadLimit = 0.1;
    SweepPoint p;
    p.speedMph = 15;
    p.direction = "up";
    p.summary.peakToPeakRollDeg = 2;
    p.summary.maxWheelUnloading = 0.5;
    p.summary.maxCarBodyVerticalAccelG = 0.5;
    p.summary.maxCarBodyLateralAccelG = 0.1;
    p.summary.maxTruckSideLOverV = 0.3;
    // As summarizeRun judges them; the section re-judges these values by each sweep's limits.
    p.summary.criteria = evaluateCriteria(p.summary, CriteriaLimits{});
    SweepResult ownDefaults;
    ownDefaults.c = {"car-a", 0.75, 10, 20, ""};
    ownDefaults.model = "halfcar";
    ownDefaults.up = {p};
    SweepResult tight = ownDefaults;
    tight.c.car = "car-b";
    tight.criteria.carBodyVerticalAccelG = 0.4;
    ownDefaults.criteria.lOverV = tight.criteria.lOverV = 1.13;  // resolved, as section 2's sweeps are
    const std::string md = makeCriteriaSection(s, {ownDefaults, tight});
    EXPECT_NE(md.find("| car-a | 0.75 | halfcar | up | none | none | n/e | none | none | none |"), std::string::npos) << md;
    EXPECT_NE(md.find("| car-b* | 0.75 | halfcar | up | none | none | n/e | none | 15 | none |"), std::string::npos) << md;
    EXPECT_NE(md.find("car-b: car_body_vertical_accel ≤ 0.4 g;"), std::string::npos) << md;
    EXPECT_EQ(md.find("car-a:"), std::string::npos) << md;
}

// Tables 3 and 4: each row is one run (the up sweep's point, the down sweep's point, the
// run from rest), never the larger of two runs quantity by quantity; a case a model was
// not swept on says so.
TEST(Validate, BranchTableTakesEveryCellOfARowFromOneRun) {
    using namespace rockroll;
    using namespace rockroll::app;
    using namespace rockroll::app::validate_detail;
    auto point = [](double mph, const char* direction, double roll, double sideBearing) {
        SweepPoint p;
        p.speedMph = mph;
        p.direction = direction;
        p.summary.maxRollDeg = roll;
        p.summary.maxSideBearingLoadLb = sideBearing;
        p.summary.steady.rollDeg = roll / 2;
        p.summary.steady.sideBearingLoadLb = sideBearing / 2;
        p.summary.regime = "severe";
        return p;
    };
    SweepResult r;
    r.c = {"car-a", 1.0, 10, 20, ""};
    r.model = "halfcar";
    r.up = {point(14.5, "up", 2, 90000), point(15, "up", 3, 80000)};
    r.down = {point(15.5, "down", 9, 50000), point(15, "down", 8, 60000)};
    RunSummary rest;
    rest.model = "halfcar", rest.car = "car-a", rest.amplitudeIn = 1.0, rest.speedMph = 15;
    rest.maxRollDeg = 1, rest.maxSideBearingLoadLb = 70000, rest.regime = "light";
    const auto rows = collectBranchRows({r}, "car-a", 1.0, 15, {"halfcar", "eom"}, {rest});
    ASSERT_EQ(rows.size(), 6u);
    EXPECT_EQ(rows[0].start, "from rest");
    EXPECT_EQ(rows[1].start, "up sweep");
    EXPECT_EQ(rows[2].start, "down sweep");
    ASSERT_TRUE(rows[1].summary && rows[2].summary && rows[0].summary);
    EXPECT_EQ(rows[1].summary->maxRollDeg, 3);  // the up sweep's 15 mph point: roll and load from it alone
    EXPECT_EQ(rows[1].summary->maxSideBearingLoadLb, 80000);
    EXPECT_EQ(rows[2].summary->maxRollDeg, 8);
    EXPECT_EQ(rows[2].summary->maxSideBearingLoadLb, 60000);
    EXPECT_FALSE(rows[4].summary);  // eom: not swept here
    EXPECT_EQ(rows[4].missing, "not swept on this case");
    const std::vector<BranchColumn> columns{{"roll, deg", 0, 1, 1}, {"side bearing, lb", 3, 1, 0}};
    const std::string whole = formatBranchTable(rows, columns, {9, 100000}, false);
    EXPECT_NE(whole.find("| report | | | | 9 | 100000 |"), std::string::npos) << whole;
    EXPECT_NE(whole.find("| halfcar | up sweep | 15 | severe | 3.0 (-67 %) | 80000 (-20 %) |"), std::string::npos) << whole;
    EXPECT_NE(whole.find("| halfcar | down sweep | 15 | severe | 8.0 (-11 %) | 60000 (-40 %) |"), std::string::npos) << whole;
    EXPECT_NE(whole.find("| halfcar | from rest | 15 | light | 1.0 (-89 %) | 70000 (-30 %) |"), std::string::npos) << whole;
    EXPECT_NE(whole.find("| eom | up sweep | — | not swept on this case |"), std::string::npos) << whole;
    const std::string steady = formatBranchTable(rows, columns, {9, 100000}, true);
    EXPECT_NE(steady.find("| halfcar | down sweep | 15 | severe | 4.0 (-56 %) | 30000 (-70 %) |"), std::string::npos) << steady;
}
