#include "scenarios/ScenarioLoader.h"
#include "tests/TestCases.h"
#include "tests/TestTmp.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <regex>

using namespace rockroll;

namespace {
const std::string kGood = test_cases::kMinimalScenarioToml;

std::string errorOf(const std::string& text) {
    try {
        parseScenario(text, "case.toml");
    } catch (const ScenarioError& e) {
        return e.what();
    }
    return "";
}
}  // namespace

TEST(ScenarioLoader, ShippedScenariosLoadWithTheirUnits) {
    for (const char* name : {"70ton-loaded", "70ton-empty", "100ton-loaded"}) {
        const Scenario sc = loadScenarioFile(std::string(ROCKROLL_SCENARIO_DIR) + "/" + name + ".toml");
        EXPECT_EQ(sc.car.name, name);
        EXPECT_NEAR(sc.track.amplitude, 0.75 * 0.0254, 1e-12);
        EXPECT_NEAR(sc.track.railLength, 39 * 0.3048, 1e-12);
    }
    const Scenario def = getDefaultScenario();
    EXPECT_EQ(def.model, "fullcar");
    EXPECT_NEAR(def.speed, 16.5 * 0.44704, 1e-12);
    EXPECT_EQ(def.run.duration, 20.0);
}

TEST(ScenarioLoader, OverridesAnyCarParameterWithUnits) {
    const Scenario sc = parseScenario(test_cases::replaceOnce(kGood, "base = \"70ton-loaded\"",
                                              "base = \"70ton-loaded\"\nside_bearing_clearance = \"0.1875 in\""),
                                      "x.toml");
    EXPECT_NEAR(sc.car.sideBearingClearance, 0.1875 * 0.0254, 1e-12);
}

TEST(ScenarioLoader, ErrorsNameFileKeyValueAndExpectation) {
    // A car inline (by its name, without base or file) must give every parameter.
    std::string e = errorOf(test_cases::replaceOnce(kGood, "base = \"70ton-loaded\"", "name = \"mine\""));
    EXPECT_NE(e.find("case.toml"), std::string::npos) << e;
    EXPECT_NE(e.find("car.body_and_bolsters_weight"), std::string::npos) << e;
    EXPECT_NE(e.find("missing"), std::string::npos) << e;

    e = errorOf(test_cases::replaceOnce(kGood, "\"16.5 mph\"", "\"16.5 in\""));
    EXPECT_NE(e.find("run.speed"), std::string::npos) << e;
    EXPECT_NE(e.find("16.5 in"), std::string::npos) << e;
    EXPECT_NE(e.find("mph"), std::string::npos) << e;

    e = errorOf(test_cases::replaceOnce(kGood, "\"0.75 in\"", "0.75"));
    EXPECT_NE(e.find("track.amplitude"), std::string::npos) << e;

    e = errorOf(test_cases::replaceOnce(kGood, "duration = \"20 s\"", "duration = \"20 s\"\nspeeed = \"3 mph\""));
    EXPECT_NE(e.find("run.speeed"), std::string::npos) << e;

    e = errorOf(test_cases::replaceOnce(kGood, "\"fullcar\"", "\"quartercar\""));
    EXPECT_NE(e.find("halfcar"), std::string::npos) << e;

    e = errorOf(test_cases::replaceOnce(kGood, "base = \"70ton-loaded\"", "base = \"70ton-loaded\"\nroll_inertia = \"12 in\""));
    EXPECT_NE(e.find("car.roll_inertia"), std::string::npos) << e;

    e = errorOf("[car\nbase=1");
    EXPECT_NE(e.find("case.toml"), std::string::npos) << e;
}

TEST(ScenarioLoader, CommandLineRejectsABadScenarioWithNonZeroExit) {
    const std::string path = (rockroll::test::makeTestTempDir() / "bad_scenario.toml").string();
    std::ofstream(path) << test_cases::replaceOnce(kGood, "\"0.75 in\"", "\"0.75 parsecs\"");
    const std::string cmd = std::string(ROCKROLL_BIN) + " run " + path + " --json > /dev/null 2> " + path + ".err";
    const int status = std::system(cmd.c_str());
    EXPECT_NE(status, 0);
    std::ifstream err(path + ".err");
    const std::string msg((std::istreambuf_iterator<char>(err)), std::istreambuf_iterator<char>());
    EXPECT_NE(msg.find("bad_scenario.toml"), std::string::npos) << msg;
    EXPECT_NE(msg.find("track.amplitude"), std::string::npos) << msg;
    EXPECT_NE(msg.find("parsecs"), std::string::npos) << msg;
}

// One declared range per value (docs/cli.md, "Accepted ranges"), NaN and infinity refused everywhere, integers
// that do not wrap, and the file's line in every message.
TEST(ScenarioLoader, RangesRefuseNonFiniteOutOfRangeAndWrappedValues) {
    using test_cases::replaceOnce;
    // kMinimalScenarioToml starts with a newline: [car] is line 2, amplitude line 5, speed line 8, accuracy line 13.
    const std::string rails = errorOf(replaceOnce(kGood, "rail_length = \"39 ft\"", "rail_length = \"39 ft\"\nrails = 4294967297"));
    EXPECT_NE(rails.find("case.toml:7: key 'track.rails' = 4294967297: expected an integer in [0, 100000]"),
              std::string::npos) << rails;
    const std::string nanAccuracy = errorOf(replaceOnce(kGood, "accuracy = 1e-4", "accuracy = nan"));
    EXPECT_NE(nanAccuracy.find("case.toml:13: key 'integrator.accuracy' = nan: expected a number in [1e-10, 0.1]"),
              std::string::npos) << nanAccuracy;
    const std::string fast = errorOf(replaceOnce(kGood, "\"16.5 mph\"", "\"500 mph\""));
    EXPECT_NE(fast.find("case.toml:8: key 'run.speed'"), std::string::npos) << fast;
    EXPECT_NE(fast.find("expected a speed in [0.1 mph, 150 mph]"), std::string::npos) << fast;
    const std::string deep = errorOf(replaceOnce(kGood, "\"0.75 in\"", "\"50 in\""));
    EXPECT_NE(deep.find("case.toml:5: key 'track.amplitude'"), std::string::npos) << deep;
    EXPECT_NE(deep.find("[0 in, 3 in]"), std::string::npos) << deep;
    const std::string nanRatio = errorOf(replaceOnce(kGood, "base = \"70ton-loaded\"", "base = \"70ton-loaded\"\ncenter_plate_rim_points = nan"));
    EXPECT_NE(nanRatio.find("case.toml:4: key 'car.center_plate_rim_points' = nan"), std::string::npos) << nanRatio;
    EXPECT_NE(errorOf(replaceOnce(kGood, "accuracy = 1e-4", "accuracy = 1e-14")).find("integrator.accuracy"), std::string::npos);
    EXPECT_NE(errorOf(replaceOnce(kGood, "\"20 s\"", "\"1e9 s\"")).find("run.duration"), std::string::npos);
    EXPECT_NE(errorOf(replaceOnce(kGood, "\"20 s\"", "\"20 s\"\noutput_rate = \"1e9 Hz\"")).find("run.output_rate"),
              std::string::npos);
    EXPECT_EQ(errorOf(kGood), "");
}

TEST(ScenarioLoader, CheckScenarioRefusesValuesChangedAfterLoading) {
    const Scenario good = parseScenario(kGood, "case.toml");
    EXPECT_NO_THROW(checkScenario(good));
    auto errorAfter = [&](const std::function<void(Scenario&)>& change) {
        Scenario sc = good;
        change(sc);
        try {
            checkScenario(sc);
        } catch (const ScenarioError& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    EXPECT_NE(errorAfter([](Scenario& sc) { sc.speed = 500 * units::mph; }).find("case.toml: key 'run.speed' = 500 mph"),
              std::string::npos);
    EXPECT_NE(errorAfter([](Scenario& sc) { sc.car.springVerticalRate = std::nan(""); }).find("car.spring_vertical_rate"),
              std::string::npos);
    EXPECT_NE(errorAfter([](Scenario& sc) { sc.run.duration = 0.001; }).find("[0.05 s, 3600 s]"), std::string::npos);
    // The car's geometry: trucks within its length, the CG between the trucks and inside the rails.
    EXPECT_NE(errorAfter([](Scenario& sc) { sc.car.truckSpacing = 60 * units::foot; })
                  .find("case.toml: key 'car.truck_spacing' = 60 ft: expected the outer wheelsets within the car body's length"),
              std::string::npos);
    EXPECT_NE(errorAfter([](Scenario& sc) { sc.car.cgLongitudinalOffset = -20 * units::foot; })
                  .find("key 'car.cg_longitudinal_offset' = -240 in: expected the car body's CG between the truck centres"),
              std::string::npos);
    EXPECT_NE(errorAfter([](Scenario& sc) { sc.car.cgLateralOffset = 30 * units::inch; })
                  .find("key 'car.cg_lateral_offset' = 30 in: expected the car body's CG inside the rails, |offset| < gauge / 2 = 28.25 in"),
              std::string::npos);
    EXPECT_EQ(errorAfter([](Scenario& sc) { sc.car.cgLateralOffset = -2 * units::inch; }), "");
    EXPECT_NE(errorAfter([](Scenario& sc) {
                  sc.run.duration = 0.2, sc.run.outputRate = 10, sc.filterCutoffHz = 2;
              }).find("expected at least 4 output intervals, a duration ≥ 0.4 s"),
              std::string::npos);
    EXPECT_NE(errorAfter([](Scenario& sc) { sc.filterCutoffHz = 300; }).find("Nyquist"), std::string::npos);
    // The [criteria] limits share the one range table with the reader.
    EXPECT_NE(errorAfter([](Scenario& sc) { sc.criteria.wheelUnloading = 1.5; })
                  .find("key 'criteria.wheel_unloading' = 1.5: expected a number in (0, 1]"),
              std::string::npos);
}

// Every boolean key is a TOML boolean: toml++ alone would read 0 and 1 as false and true.
TEST(ScenarioLoader, BooleansAreTomlBooleansOnly) {
    for (const char* text : {"[track]\nmirror = 1\n", "[track]\nrepeat = 0\n", "[eom]\nsmall_angles = 1\n",
                             "[limits]\nenabled = 0\n", "[reduced]\ntruck_weight = 1\n",
                             "[attribution]\nunsprung_gravity = 0\n"})
        EXPECT_NE(errorOf(text).find("expected true or false"), std::string::npos) << text << ": " << errorOf(text);
    EXPECT_EQ(errorOf("[eom]\nsmall_angles = true\n"), "");
    const std::string e = errorOf("[criteria]\nl_over_v = 20\n");
    EXPECT_NE(e.find("criteria.l_over_v"), std::string::npos) << e;
    EXPECT_NE(e.find("(0, 10]"), std::string::npos) << e;
}

TEST(ScenarioLoader, MemoryEstimateRefusesARunAboveTheLimit) {
    Scenario sc = parseScenario(kGood, "case.toml");
    // 20 s at 500 Hz, 40 channels: 10001 rows of 41 doubles plus row overhead, about 3.6 MiB.
    EXPECT_NEAR(estimateHistoryBytes(20, 500, 40), 10001.0 * (41 * 8 + 40), 1e-6);
    ASSERT_EQ(setenv("ROCKROLL_MAX_MEMORY_MB", "1", 1), 0);
    try {
        checkMemoryEstimate(sc, 40);
        ADD_FAILURE() << "a 3.6 MiB history passed a 1 MiB limit";
    } catch (const ScenarioError& e) {
        EXPECT_NE(std::string(e.what()).find("10001 samples x 41 channels, about 4 MiB"), std::string::npos) << e.what();
    }
    ASSERT_EQ(setenv("ROCKROLL_MAX_MEMORY_MB", "10", 1), 0);
    EXPECT_NO_THROW(checkMemoryEstimate(sc, 40));
    ASSERT_EQ(setenv("ROCKROLL_MAX_MEMORY_MB", "lots", 1), 0);
    EXPECT_THROW(getMemoryLimitBytes(), std::invalid_argument);
    unsetenv("ROCKROLL_MAX_MEMORY_MB");
    EXPECT_EQ(getMemoryLimitBytes(), 2048.0 * 1024 * 1024);
}

TEST(ScenarioLoader, EveryDeclaredRangeIsInTheDocs) {
    std::ifstream in(std::string(ROCKROLL_SOURCE_DIR) + "/docs/cli.md");
    const std::string readme((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    for (const ValueRange& r : getValueRanges()) {
        if (r.key.rfind("car.", 0) == 0) continue;  // the car's parameters: finite and ≥ 0 (docs/cli.md says so)
        EXPECT_NE(readme.find("| `" + r.key + "` | " + r.describe() + " |"), std::string::npos) << r.key;
    }
}

// Input size limits (docs/cli.md, "Input size limits"): a track file over kMaxTrackFileBytes
// (a sparse 100 MB file here) and a scenario file over kMaxScenarioFileBytes are refused
// before they are read; a device or a folder named as a track file is refused, not read
// for ever (/dev/zero) or half-read.
TEST(ScenarioLoader, FilesOverTheSizeLimitsOrNotRegularAreRefused) {
    namespace fs = std::filesystem;
    const fs::path dir = test::makeTestTempDir();
    auto loadError = [](const fs::path& p) -> std::string {
        try {
            loadScenarioFile(p.string());
        } catch (const ScenarioError& e) {
            return e.what();
        }
        return "";
    };
    auto withTrackFile = [&](const std::string& name, const std::string& file) {
        const fs::path p = dir / name;
        std::ofstream(p) << test_cases::replaceOnce(kGood, "amplitude = \"0.75 in\"\n", "file = \"" + file + "\"\n");
        return p;
    };
    std::ofstream(dir / "huge.csv") << "distance [m], left [m], right [m]\n";
    fs::resize_file(dir / "huge.csv", 100'000'000);
    const std::string huge = loadError(withTrackFile("huge.toml", "huge.csv"));
    EXPECT_NE(huge.find("key 'track.file' = \"huge.csv\""), std::string::npos) << huge;
    EXPECT_NE(huge.find("the track file is 100000000 bytes; expected at most 16777216 bytes (16 MiB"), std::string::npos)
        << huge;
    for (const std::string& notFile : {std::string("/dev/zero"), dir.string()}) {
        const std::string e = loadError(withTrackFile("device.toml", notFile));
        EXPECT_NE(e.find(notFile + ": cannot open track file: not a regular file"), std::string::npos) << e;
    }
    std::ofstream(dir / "big.toml") << kGood;
    fs::resize_file(dir / "big.toml", kMaxScenarioFileBytes + 1);
    const std::string big = loadError(dir / "big.toml");
    EXPECT_NE(big.find("the scenario file is 16777217 bytes; expected at most 16777216 bytes (16 MiB"), std::string::npos)
        << big;
}

// Every key may be left out and takes its default, the value of scenarios/70ton-loaded.toml
// (docs/cli.md, "Keys and defaults"): an empty file is the default case, key for key.
TEST(ScenarioLoader, AnEmptyScenarioIsTheDefaultCase) {
    Scenario def = getDefaultScenario();
    def.description.clear();
    const Scenario empty = parseScenario("", "empty.toml");
    EXPECT_EQ(formatScenarioToml(empty), formatScenarioToml(def));
    EXPECT_TRUE(empty.settingsSet.empty());
    // A car, an amplitude and a speed: the rest as the default case.
    const Scenario five = parseScenario("[car]\nbase = \"70ton-loaded\"\n[track]\namplitude = \"0.75 in\"\n[run]\n"
                                        "speed = \"15 mph\"\n",
                                        "five.toml");
    Scenario expected = def;
    expected.speed = 15 * units::mph;
    EXPECT_EQ(formatScenarioToml(five), formatScenarioToml(expected));
    EXPECT_EQ(five.settingsSet, (std::vector<std::string>{"car.base", "run.speed", "track.amplitude"}));
}

// What the user set is what the file holds and what the overrides add, never a default.
TEST(ScenarioLoader, SettingsSetAreTheFileKeysAndTheOverrides) {
    const Scenario sc = parseScenario(kGood, "case.toml", {{"integrator.max_step", "0.001 s"}, {"eom.small_angles", "true"}});
    EXPECT_EQ(sc.settingsSet,
              (std::vector<std::string>{"car.base", "eom.small_angles", "integrator.accuracy", "integrator.max_step",
                                        "integrator.method", "run.duration", "run.model", "run.speed",
                                        "track.amplitude", "track.rail_length"}));
}

// A count is a whole number: center_plate_rim_points = 2.5 is refused by the loader with the
// file, line, key and value, in a scenario and in a car file, before any model is built.
TEST(ScenarioLoader, CountsMustBeIntegers) {
    const std::string e = errorOf(test_cases::replaceOnce(kGood, "base = \"70ton-loaded\"",
                                                          "base = \"70ton-loaded\"\ncenter_plate_rim_points = 2.5"));
    EXPECT_NE(e.find("case.toml:4: key 'car.center_plate_rim_points' = 2.5: expected an integer"), std::string::npos)
        << e;
    EXPECT_EQ(e.find("CenterPlateContact"), std::string::npos) << e;
    EXPECT_EQ(parseScenario(test_cases::replaceOnce(kGood, "base = \"70ton-loaded\"",
                                                    "base = \"70ton-loaded\"\ncenter_plate_rim_points = 8"),
                            "case.toml")
                  .car.centerPlateRimPoints,
              8);
    const ValueRange& range = getValueRange("car.center_plate_rim_points");
    EXPECT_TRUE(range.integer);
    EXPECT_FALSE(range.contains(2.5));
    EXPECT_TRUE(range.contains(4));
}
