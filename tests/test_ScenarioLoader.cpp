#include "scenarios/ScenarioLoader.h"
#include "tests/TestCases.h"
#include "tests/TestTmp.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
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
    std::string e = errorOf(test_cases::replaceOnce(kGood, "speed = \"16.5 mph\"\n", ""));
    EXPECT_NE(e.find("case.toml"), std::string::npos) << e;
    EXPECT_NE(e.find("run.speed"), std::string::npos) << e;
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
