// rockroll orbits --out DIR: orbits.csv and orbits.json written and read back; bad input refused.
#include "tests/CliRunner.h"
#include "tests/CsvReader.h"
#include "tests/TestTmp.h"
#include "tests/TextFile.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

using namespace rockroll::test;

namespace {
const std::string kScenario = std::string("'") + ROCKROLL_SOURCE_DIR + "/scenarios/70ton-loaded.toml'";
}

TEST(OrbitsCommand, WritesCsvAndJsonThatReadBack) {
    const auto dir = makeTestTempDir();
    const CliOutcome r = runRockroll(dir, "orbits " + kScenario +
                                              " --model eom --amplitude-in 0.25 --from-mph 12 --to-mph 11.75 "
                                              "--step-mph 0.25 --start-duration-s 20 --refinements 0 --out out");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto j = nlohmann::json::parse(readTextFile(dir / "out" / "orbits.json"));
    EXPECT_EQ(j.at("model"), "eom");
    EXPECT_TRUE(j.contains("provenance"));
    const auto& points = j.at("points");
    ASSERT_GE(points.size(), 2u);
    const CsvTable csv = parseCsvTable(readTextFile(dir / "out" / "orbits.csv"));
    ASSERT_EQ(csv.rows.size(), points.size());
    for (const char* c : {"speed_mph", "branch", "converged", "period", "roll_amplitude_deg", "wheel_lift_fraction",
                          "max_wheel_load_lb", "max_side_bearing_load_lb", "max_center_plate_load_lb",
                          "max_multiplier", "stable"})
        EXPECT_GE(csv.find(c), 0) << c;
    const auto speed = csv.numbers("speed_mph");
    for (size_t i = 0; i < points.size(); ++i) {
        EXPECT_EQ(speed[i], points[i].at("speed_mph").get<double>());
        const std::string conv = csv.rows[i][size_t(csv.find("converged"))];
        EXPECT_EQ(conv, points[i].at("converged").get<bool>() ? "true" : "false");
        if (points[i].at("converged").get<bool>()) {
            EXPECT_EQ(*parseNumber(csv.rows[i][size_t(csv.find("roll_amplitude_deg"))]),
                      points[i].at("roll_amplitude_deg").get<double>());
            EXPECT_EQ(csv.rows[i][size_t(csv.find("stable"))], points[i].at("stable").get<bool>() ? "yes" : "no");
        } else {
            EXPECT_EQ(csv.rows[i][size_t(csv.find("roll_amplitude_deg"))], "");  // never reported as an orbit
        }
    }
    EXPECT_TRUE(points[0].at("converged").get<bool>());
}

TEST(OrbitsCommand, RefusesATrackThatDoesNotRepeat) {
    const auto dir = makeTestTempDir();
    const CliOutcome r = runRockroll(dir, "orbits " + kScenario +
                                              " --model eom --from-mph 12 --to-mph 11 --set track.rails=4");
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_NE(r.err.find("rails"), std::string::npos) << r.err;
}

// --iterate finds each orbit by iterating the map; orbits.json says so and leaves the
// multipliers it does not compute empty (the reduced model, light rocking at 0.25 in).
TEST(OrbitsCommand, IteratesTheReducedModel) {
    const auto dir = makeTestTempDir();
    const CliOutcome r = runRockroll(dir, "orbits " + kScenario +
                                              " --model reduced --amplitude-in 0.25 --from-mph 12 --to-mph 11.5 "
                                              "--step-mph 0.5 --start-duration-s 20 --settle-periods 5 --iterate --json");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["orbit_method"], "iteration");
    EXPECT_EQ(j["settle_periods"], 5);
    ASSERT_EQ(j["points"].size(), 2u);
    EXPECT_TRUE(j["accuracy"].is_null());  // fixed-step RK4: no accuracy
    for (const auto& p : j["points"]) {
        EXPECT_TRUE(p["converged"].get<bool>()) << p.dump();
        EXPECT_TRUE(p["stable"].get<bool>());
        EXPECT_TRUE(p["largest_real_multiplier"].is_null());
        EXPECT_TRUE(p["multipliers"].empty());
        EXPECT_LT(p["max_multiplier"].get<double>(), 1.0);
    }
}

// --start-sweep-from-mph: the first shooting starts from the end of a speed sweep that
// comes down to --from-mph, the way onto an upper branch a run from rest does not reach
// (docs/orbits.md). The JSON names the start; the first orbit is the one the sweep's end
// sits on (light rocking at 0.25 in: 0.194 deg at the sweep's end, 0.194 deg orbit).
TEST(OrbitsCommand, StartsFromTheEndOfADownSweep) {
    const auto dir = makeTestTempDir();
    const CliOutcome r = runRockroll(dir, "orbits " + kScenario +
                                              " --model eom --amplitude-in 0.25 --start-sweep-from-mph 12.5 --from-mph 12 "
                                              "--to-mph 11.75 --step-mph 0.25 --start-duration-s 10 --refinements 0 --json");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    const auto& start = j.at("start");
    EXPECT_EQ(start.at("sweep_from_mph").get<double>(), 12.5);
    EXPECT_NE(start.at("kind").get<std::string>().find("down sweep from 12.5 mph"), std::string::npos) << start;
    const auto& first = j.at("points").at(0);
    ASSERT_TRUE(first.at("converged").get<bool>()) << first;
    EXPECT_NEAR(first.at("roll_amplitude_deg").get<double>(), start.at("steady_roll_amplitude_deg").get<double>(),
                0.05 * start.at("steady_roll_amplitude_deg").get<double>());
}

TEST(OrbitsCommand, RefusesAStartSweepFromItsOwnSpeed) {
    const auto dir = makeTestTempDir();
    const CliOutcome r = runRockroll(dir, "orbits " + kScenario +
                                              " --model eom --from-mph 12 --to-mph 11 --start-sweep-from-mph 12");
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_NE(r.err.find("--start-sweep-from-mph"), std::string::npos) << r.err;
}

// A ramp that nothing would use is refused, never silently dropped: the start from rest
// has no speed change; a --fresh sweep starts every speed from rest.
TEST(OrbitsCommand, RefusesAStartRampWithoutAStartSweep) {
    const auto dir = makeTestTempDir();
    const CliOutcome r = runRockroll(dir, "orbits " + kScenario + " --model eom --from-mph 12 --to-mph 11 --start-speed-ramp-s 0");
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_NE(r.err.find("--start-sweep-from-mph"), std::string::npos) << r.err;
    const CliOutcome sweep = runRockroll(dir, "sweep " + kScenario + " --from-mph 12 --to-mph 13 --step-mph 1 --fresh --speed-ramp-s 0");
    EXPECT_EQ(sweep.exitCode, 2) << sweep.err;
    EXPECT_NE(sweep.err.find("--fresh"), std::string::npos) << sweep.err;
}

// A setting the computation would not use is refused (exit 2), not dropped: Newton's options
// with --iterate, an integrator accuracy for the fixed-step reduced model.
TEST(OrbitsCommand, RefusesSettingsItWouldNotUse) {
    const auto dir = makeTestTempDir();
    const std::string base = "orbits " + kScenario + " --model reduced --from-mph 12 --to-mph 11.5 ";
    const CliOutcome a = runRockroll(dir, base + "--iterate --newton-steps 5");
    EXPECT_EQ(a.exitCode, 2) << a.err;
    EXPECT_NE(a.err.find("--newton-steps"), std::string::npos) << a.err;
    const CliOutcome b = runRockroll(dir, base + "--iterate --accuracy 1e-9");
    EXPECT_EQ(b.exitCode, 2) << b.err;
    EXPECT_NE(b.err.find("does not use it"), std::string::npos) << b.err;
}
