// Measured track from CSV ([track] file; docs/cli.md, "Measured track"): the shipped table of the
// report's staggered rectified sine runs as the built-in sine does, and the loader
// names the file, line and column of a bad table.
#include "scenarios/ScenarioRun.h"
#include "tests/TestCases.h"
#include "tests/TestTmp.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdlib>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

using namespace rockroll;

namespace {
const std::string kScenarios = ROCKROLL_SCENARIO_DIR;

std::string loadError(const std::string& path) {
    try {
        loadScenarioFile(path);
    } catch (const ScenarioError& e) {
        return e.what();
    }
    return "";
}
}  // namespace

// scenarios/tracks/staggered-0.75in.csv is one rail of the built-in rectified sine
// (0.75 in, 39 ft), 100 rows a rail at 6 decimals of an inch, repeated. Its rails
// differ from the built-in's by the linear interpolation between rows,
// A (pi h / L)^2 / 8 = 0.75 in x (pi / 100)^2 / 8 = 9e-5 in at most, and the
// rounding (5e-7 in); the run agrees with the built-in's to a small fraction of
// its responses (measured, halfcar 6 s: max roll 2.69737 vs 2.69689 deg, side bearing
// 83862 vs 83853 lb, wheel load 98011 vs 98010 lb, lift 0.04586 vs 0.04562 in).
TEST(MeasuredTrack, ShippedStaggeredCsvRunsAsTheBuiltInSine) {
    Scenario builtIn = loadScenarioFile(kScenarios + "/70ton-loaded.toml");
    Scenario measured = loadScenarioFile(kScenarios + "/measured-staggered.toml");
    ASSERT_EQ(measured.track.measured.size(), 101u);
    EXPECT_TRUE(measured.track.repeat);
    // The rails themselves, everywhere along several rails.
    const TrackInput a(builtIn.track), b(measured.track);
    double worst = 0;
    for (double s = 0; s < 5 * builtIn.track.railLength; s += 0.01)
        for (int i = 0; i < 2; ++i) worst = std::max(worst, std::abs(a.calcRails(s).z[i] - b.calcRails(s).z[i]));
    EXPECT_LT(worst, 1e-4 * units::inch) << "largest rail-height difference " << worst / units::inch << " in";
    EXPECT_GT(worst, 0.0);  // it is a table, not the formula

    for (Scenario* sc : {&builtIn, &measured}) {
        sc->model = "halfcar";
        sc->run.duration = 6;
    }
    const RunSummary x = runScenario(builtIn).summary, y = runScenario(measured).summary;
    auto near = [](double u, double v, double rel) { return std::abs(u - v) <= rel * std::max(std::abs(u), std::abs(v)); };
    EXPECT_TRUE(near(x.maxRollDeg, y.maxRollDeg, 2e-3)) << x.maxRollDeg << " vs " << y.maxRollDeg;
    EXPECT_TRUE(near(x.peakToPeakRollDeg, y.peakToPeakRollDeg, 2e-3)) << x.peakToPeakRollDeg << " vs " << y.peakToPeakRollDeg;
    EXPECT_TRUE(near(x.maxWheelLoadLb, y.maxWheelLoadLb, 2e-3)) << x.maxWheelLoadLb << " vs " << y.maxWheelLoadLb;
    EXPECT_TRUE(near(x.maxSideBearingLoadLb, y.maxSideBearingLoadLb, 2e-3))
        << x.maxSideBearingLoadLb << " vs " << y.maxSideBearingLoadLb;
    // Lift is the difference of two large displacements (0.046 in here; measured 0.00024 in apart):
    // compared absolutely, at a small fraction of the report's "approaching 2 in".
    EXPECT_NEAR(x.maxWheelLiftIn, y.maxWheelLiftIn, 1e-3);
    EXPECT_EQ(x.regime, y.regime);
    std::printf("built-in vs CSV (halfcar, 6 s): max roll %.6f vs %.6f deg, wheel load %.1f vs %.1f lb, side bearing "
                "%.1f vs %.1f lb, lift %.5f vs %.5f in\n",
                x.maxRollDeg, y.maxRollDeg, x.maxWheelLoadLb, y.maxWheelLoadLb, x.maxSideBearingLoadLb,
                y.maxSideBearingLoadLb, x.maxWheelLiftIn, y.maxWheelLiftIn);
}

TEST(MeasuredTrack, ShippedIrregularProfileLoadsAndEndsLevel) {
    const Scenario sc = loadScenarioFile(kScenarios + "/measured-irregular.toml");
    ASSERT_EQ(sc.track.measured.size(), 121u);
    EXPECT_NEAR(sc.track.taper, 30 * units::foot, 1e-12);
    const TrackInput track(sc.track);
    const double last = sc.track.measured.back().distance;
    EXPECT_NE(track.calcRails(last).z[0], 0.0);  // it does not end level ...
    EXPECT_EQ(track.calcRails(last + sc.track.taper + 0.01).z[0], 0.0);  // ... until the taper has run out
    EXPECT_EQ(track.calcRails(-0.5).z[0], 0.0);
}

TEST(MeasuredTrack, LoaderNamesFileLineAndColumn) {
    const auto dir = test::makeTestTempDir();
    std::filesystem::create_directories(dir / "tracks");
    std::ofstream(dir / "tracks" / "bad.csv") << "# survey\ndistance [ft], left [in], right [in]\n0, 0, 0\n5, 0.1, 0\n4, 0, 0\n";
    const std::string scenario = test_cases::replaceOnce(test_cases::kMinimalScenarioToml, "amplitude = \"0.75 in\"\n",
                                                         "file = \"tracks/bad.csv\"\n");
    std::ofstream(dir / "case.toml") << scenario;
    const std::string e = loadError((dir / "case.toml").string());
    EXPECT_NE(e.find("key 'track.file' = \"tracks/bad.csv\""), std::string::npos) << e;
    EXPECT_NE(e.find("bad.csv:5: column 1 (distance [ft]) = \"4\": distances must increase strictly"), std::string::npos)
        << e;
    // Missing file; file with the sine's amplitude; repeat of a table that does not close.
    std::ofstream(dir / "missing.toml")
        << test_cases::replaceOnce(test_cases::kMinimalScenarioToml, "amplitude = \"0.75 in\"\n", "file = \"nope.csv\"\n");
    EXPECT_NE(loadError((dir / "missing.toml").string()).find("cannot open track file"), std::string::npos);
    std::ofstream(dir / "both.toml") << test_cases::replaceOnce(test_cases::kMinimalScenarioToml, "[track]\n",
                                                                "[track]\nfile = \"tracks/bad.csv\"\n");
    EXPECT_NE(loadError((dir / "both.toml").string()).find("key 'track.amplitude'"), std::string::npos);
    std::ofstream(dir / "tracks" / "open.csv") << "distance [m], left [mm], right [mm]\n0, 0, 0\n10, 5, 0\n";
    std::ofstream(dir / "open.toml") << test_cases::replaceOnce(test_cases::kMinimalScenarioToml,
                                                                "amplitude = \"0.75 in\"\n",
                                                                "file = \"tracks/open.csv\"\nrepeat = true\n");
    EXPECT_NE(loadError((dir / "open.toml").string()).find("key 'track.repeat' = true: expected a measured table whose last row equals its first"),
              std::string::npos)
        << loadError((dir / "open.toml").string());
}

// The resolved scenario (provenance) carries the table inline: rebuilding it gives the same rails.
TEST(MeasuredTrack, ProvenanceTomlRebuildsTheTrack) {
    const Scenario sc = loadScenarioFile(kScenarios + "/measured-irregular.toml");
    const Scenario again = parseScenario(formatScenarioToml(sc), "provenance");
    ASSERT_EQ(again.track.measured.size(), sc.track.measured.size());
    EXPECT_EQ(again.track.taper, sc.track.taper);
    EXPECT_EQ(again.track.repeat, sc.track.repeat);
    const TrackInput a(sc.track), b(again.track);
    for (double s = -1; s < 140; s += 0.37)
        for (int i = 0; i < 2; ++i) EXPECT_EQ(a.calcRails(s).z[i], b.calcRails(s).z[i]) << s;
}

// A spreadsheet saves CSV with a UTF-8 byte-order mark and CRLF line ends: the shipped
// staggered table saved so, with its comments or with the header first (as a spreadsheet
// writes it), reads as the same rows and runs as the shipped file does.
TEST(MeasuredTrack, SpreadsheetCsvWithByteOrderMarkAndCrlfRuns) {
    namespace fs = std::filesystem;
    const fs::path dir = test::makeTestTempDir();
    std::ifstream in(kScenarios + "/tracks/staggered-0.75in.csv", std::ios::binary);
    std::string withComments, headerFirst;
    for (std::string line; std::getline(in, line);) {
        withComments += line + "\r\n";
        if (!line.starts_with("#")) headerFirst += line + "\r\n";
    }
    const Scenario shipped = loadScenarioFile(kScenarios + "/measured-staggered.toml");
    std::ifstream scenarioIn(kScenarios + "/measured-staggered.toml");
    const std::string scenario((std::istreambuf_iterator<char>(scenarioIn)), std::istreambuf_iterator<char>());
    for (const auto& [name, text] : {std::pair{"comments", withComments}, std::pair{"header-first", headerFirst}}) {
        SCOPED_TRACE(name);
        fs::create_directories(dir / name / "tracks");
        std::ofstream(dir / name / "tracks" / "staggered-0.75in.csv", std::ios::binary) << "\xEF\xBB\xBF" << text;
        std::ofstream(dir / name / "s.toml") << scenario;
        Scenario sc = loadScenarioFile((dir / name / "s.toml").string());
        ASSERT_EQ(sc.track.measured.size(), shipped.track.measured.size());
        for (size_t i = 0; i < sc.track.measured.size(); ++i) {
            EXPECT_EQ(sc.track.measured[i].distance, shipped.track.measured[i].distance) << i;
            EXPECT_EQ(sc.track.measured[i].crossLevel, shipped.track.measured[i].crossLevel) << i;
            EXPECT_EQ(sc.track.measured[i].profile, shipped.track.measured[i].profile) << i;
        }
        sc.model = "reduced";
        sc.run.duration = 0.5;
        Scenario reference = shipped;
        reference.model = "reduced";
        reference.run.duration = 0.5;
        EXPECT_EQ(runScenario(sc).result.history.samples, runScenario(reference).result.history.samples);
    }
}

// scenarios/tracks/federal-harmonics-1.25in.csv holds the federal "harmonics" limit as its
// generator (scripts/make-federal-harmonics-track.py) states it: seven low joints, alternating
// rails half a 39 ft rail apart, the cross-level changing by 1.25 in from each to the next
// (six consecutive pairs), level track before and after.
TEST(MeasuredTrack, FederalHarmonicsTableObeysItsRule) {
    const Scenario sc = loadScenarioFile(kScenarios + "/federal-harmonics.toml");
    EXPECT_FALSE(sc.track.repeat);
    const TrackInput track(sc.track);
    // The low joints: each rail's local minima below level, from the table's rows.
    struct Joint {
        double s;
        int rail;
    };
    std::vector<Joint> joints;
    const auto& rows = sc.track.measured;
    for (int rail : {0, 1})
        for (size_t i = 1; i + 1 < rows.size(); ++i) {
            const double z = track.calcRails(rows[i].distance).z[size_t(rail)];
            if (z < -1e-9 && z < track.calcRails(rows[i - 1].distance).z[size_t(rail)] &&
                z < track.calcRails(rows[i + 1].distance).z[size_t(rail)])
                joints.push_back({rows[i].distance, rail});
        }
    std::sort(joints.begin(), joints.end(), [](const Joint& a, const Joint& b) { return a.s < b.s; });
    ASSERT_EQ(joints.size(), 7u);
    for (size_t k = 1; k < joints.size(); ++k) {
        EXPECT_NE(joints[k].rail, joints[k - 1].rail) << "joints stagger from rail to rail";
        EXPECT_NEAR(joints[k].s - joints[k - 1].s, 19.5 * units::foot, 1e-9);
        const double difference = track.calcCrossLevel(joints[k].s) - track.calcCrossLevel(joints[k - 1].s);
        EXPECT_NEAR(std::abs(difference), 1.25 * units::inch, 1e-6 * units::inch) << "pair " << k;
    }
    // No larger cross-level difference between any two points of the table within a pair's spacing.
    double largest = 0;
    for (size_t i = 0; i < rows.size(); ++i)
        for (size_t j = i + 1; j < rows.size() && rows[j].distance - rows[i].distance <= 19.5 * units::foot + 1e-9; ++j)
            largest = std::max(largest, std::abs(track.calcCrossLevel(rows[j].distance) - track.calcCrossLevel(rows[i].distance)));
    EXPECT_NEAR(largest, 1.25 * units::inch, 1e-6 * units::inch);
    // Level at the start (the car starts at rest on level rails) and after the last dip.
    EXPECT_NEAR(track.calcLeadInDistance(), 39 * units::foot, 1e-9);
    EXPECT_EQ(track.calcRails(rows.back().distance).z[0], 0.0);
    EXPECT_EQ(track.calcRails(rows.back().distance).z[1], 0.0);
}

// On the harmonics track's level lead-in (39 ft) the rails do no work: the worst energy-balance
// error is taken from 0.5 s after the perturbation starts: from 0.5 s it would be the ratio of
// two near-zero energies (docs/validation.md, "Statistics").
TEST(MeasuredTrack, TheWorstEnergyErrorIsTakenAfterTheLevelLeadIn) {
    Scenario sc = loadScenarioFile(kScenarios + "/federal-harmonics.toml");
    sc.model = "halfcar";
    sc.run.duration = 8;
    const RunSummary s = runScenario(sc).summary;
    EXPECT_NEAR(s.criteriaFromS, 39 * units::foot / sc.speed, 0.01);
    EXPECT_LT(s.worstEnergyBalanceError, 0.05) << s.worstEnergyBalanceError;
    EXPECT_LE(s.energyBalanceError, s.worstEnergyBalanceError);
}

// The uneven-joints table (scenarios/tracks/uneven-joints.csv) follows the rule its generator
// (scripts/make-uneven-joints-track.py) states: twelve joints on each rail, one rail apart, the
// right rail's 0.35 of a rail after the left's; each joint's depth within ±25 % of its rail's
// (0.75 in left, 0.5 in right); around each joint the rail is the rectified sine of that depth;
// level before the first dip and after the last.
TEST(MeasuredTrack, UnevenJointsTableObeysItsRule) {
    const Scenario sc = loadScenarioFile(kScenarios + "/uneven-joints.toml");
    const TrackInput track(sc.track);
    const auto& rows = sc.track.measured;
    const double L = 39 * units::foot, in = units::inch;
    std::array<std::vector<std::pair<double, double>>, 2> joints;  // per rail: (s, depth)
    for (int rail : {0, 1})
        for (size_t i = 1; i + 1 < rows.size(); ++i) {
            const double z = track.calcRails(rows[i].distance).z[size_t(rail)];
            if (z < -1e-9 && z < track.calcRails(rows[i - 1].distance).z[size_t(rail)] &&
                z < track.calcRails(rows[i + 1].distance).z[size_t(rail)])
                joints[size_t(rail)].push_back({rows[i].distance, -z});
        }
    ASSERT_EQ(joints[0].size(), 12u);
    ASSERT_EQ(joints[1].size(), 12u);
    const std::array<double, 2> depth{0.75 * in, 0.5 * in};
    bool depthsDiffer = false;
    for (int rail : {0, 1})
        for (size_t k = 0; k < 12; ++k) {
            const auto [sj, dj] = joints[size_t(rail)][k];
            EXPECT_NEAR(sj, joints[0][k].first + (rail == 1 ? 0.35 * L : 0.0), 1e-6) << rail << " " << k;
            if (k > 0) {
                EXPECT_NEAR(sj - joints[size_t(rail)][k - 1].first, L, 1e-6);
            }
            EXPECT_GE(dj, 0.75 * depth[size_t(rail)] - 1e-6 * in);
            EXPECT_LE(dj, 1.25 * depth[size_t(rail)] + 1e-6 * in);
            if (k > 0 && std::abs(dj - joints[size_t(rail)][k - 1].second) > 0.01 * in) depthsDiffer = true;
            // The rectified sine of this joint's depth over the rows within half a rail of it.
            for (const auto& row : rows) {
                if (std::abs(row.distance - sj) > L / 2 - 1e-6) continue;
                ASSERT_NEAR(track.calcRails(row.distance).z[size_t(rail)],
                            -dj * (1 - std::abs(std::sin(M_PI * (row.distance - sj) / L))), 2e-6 * in)
                    << rail << " " << k << " at " << row.distance;
            }
        }
    EXPECT_TRUE(depthsDiffer) << "the scatter gives each joint its own depth";
    EXPECT_NEAR(track.calcLeadInDistance(), L, 1e-6);
    EXPECT_EQ(track.calcRails(rows.back().distance).z[0], 0.0);
    EXPECT_EQ(track.calcRails(rows.back().distance).z[1], 0.0);
}

// The shipped table is what its script writes with its default options (the seed included).
TEST(MeasuredTrack, UnevenJointsTableIsItsScriptsOutput) {
    const std::filesystem::path out = rockroll::test::makeTestTempDir() / "uneven-joints.csv";
    const std::string cmd = "/usr/bin/python3 '" + std::string(ROCKROLL_SOURCE_DIR) +
                            "/scripts/make-uneven-joints-track.py' --out '" + out.string() + "' > /dev/null";
    ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
    auto read = [](const std::filesystem::path& p) {
        std::ifstream f(p, std::ios::binary);
        std::stringstream ss;
        ss << f.rdbuf();
        return ss.str();
    };
    const std::string written = read(out), shipped = read(kScenarios + "/tracks/uneven-joints.csv");
    EXPECT_FALSE(shipped.empty());
    EXPECT_EQ(written, shipped);
}
