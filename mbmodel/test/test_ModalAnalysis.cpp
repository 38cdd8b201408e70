// Modes of the linearized Simbody models against the report's Table 1.
#include "mbmodel/ModalAnalysis.h"
#include "scenarios/ModelRegistry.h"
#include "scenarios/ScenarioRun.h"
#include "tests/TestTmp.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

using namespace rockroll;

namespace {
std::vector<Mode> calcCarModes(const std::string& carName, const std::string& model) {
    TrackSpec level;
    level.railLength = 39 * units::foot;
    const auto m = ModelRegistry::get().getModel(model).makeMultibody(
        makeModalCar(makeCarParameters(carName)), TrackInput(level),
        ModelOptions{15 * units::mph, TrackEntry::Lead, TrackMotion{}, AttributionSwitches{}, WheelRailSettings{}, CarBodySettings{}});
    return calcModes(*m);
}
const Mode& find(const std::vector<Mode>& modes, const std::string& name) {
    for (const auto& m : modes)
        if (m.name == name) return m;
    throw std::runtime_error("no mode " + name);
}
double estimate(const CarParameters& car, const std::string& body, const std::string& motion) {
    for (const auto& e : calcTable1Estimates(car))
        if (e.body == body && e.motion == motion) return e.frequencyHz;
    throw std::runtime_error("no estimate");
}
}  // namespace

TEST(ModalAnalysis, Table1FormulasReproduceTheReportsValues) {
    for (const char* name : {"70ton-loaded", "100ton-loaded", "70ton-empty"})
        for (const auto& e : calcTable1Estimates(makeCarParameters(name)))
            if (e.reportHz > 0) {
                EXPECT_NEAR(e.frequencyHz, e.reportHz, 0.015 * e.reportHz) << name << " " << e.body << " " << e.motion;
            }
}

TEST(ModalAnalysis, CarBodyModesAgainstTheUncoupledEstimates) {
    for (const char* carName : {"70ton-loaded", "100ton-loaded", "70ton-empty"}) {
        const CarParameters car = makeCarParameters(carName);
        const auto modes = calcCarModes(carName, "halfcar");
        // Heave does not couple with sway and roll: the estimate holds.
        EXPECT_NEAR(find(modes, "car body heave").frequencyHz, estimate(car, "car body", "heave"), 0.01 * 2.2) << carName;
        // Sway and roll couple through the CG height: the two coupled modes lie
        // outside the pair of uncoupled ones (the lower below, the upper above).
        const double lower = find(modes, "car body lower sway-roll").frequencyHz;
        const double upper = find(modes, "car body upper sway-roll").frequencyHz;
        const double roll = estimate(car, "car body", "roll"), sway = estimate(car, "car body", "sway");
        EXPECT_LT(lower, std::min(roll, sway)) << carName;
        EXPECT_GT(upper, std::max(roll, sway)) << carName;
        // Without friction, nothing damps the car body on its springs.
        EXPECT_LT(find(modes, "car body heave").dampingRatio, 0.01);
        for (const auto& m : modes) EXPECT_GT(m.frequencyHz, 0.1);
    }
}

TEST(ModalAnalysis, FullCarAddsPitchAndYawAndAgreesWithTheHalfCar) {
    const auto half = calcCarModes("70ton-loaded", "halfcar");
    const auto full = calcCarModes("70ton-loaded", "fullcar");
    for (const char* name : {"car body heave", "car body lower sway-roll", "car body upper sway-roll"})
        EXPECT_NEAR(find(full, name).frequencyHz, find(half, name).frequencyHz, 0.05 * find(half, name).frequencyHz) << name;
    EXPECT_GT(find(full, "car body pitch").frequencyHz, 0.5);
    EXPECT_GT(find(full, "car body yaw").frequencyHz, 0.5);
    EXPECT_NO_THROW(find(full, "wheelset sway (4)"));
}

TEST(ModalAnalysis, ModesCommandPrintsJsonWithNamedModes) {
    const std::filesystem::path json = rockroll::test::makeTestTempDir() / "modes.json";
    const std::string cmd = std::string(ROCKROLL_BIN) + " modes " + ROCKROLL_SCENARIO_DIR +
                            "/70ton-loaded.toml --model halfcar --json > '" + json.string() + "'";
    ASSERT_EQ(std::system(cmd.c_str()), 0);
    std::ifstream in(json);
    const auto j = nlohmann::json::parse(in);
    ASSERT_TRUE(j.contains("modes"));
    bool heave = false, roll = false, sway = false;
    for (const auto& m : j["modes"]) {
        const std::string name = m["name"];
        heave |= name.find("heave") != std::string::npos;
        roll |= name.find("roll") != std::string::npos;
        sway |= name.find("sway") != std::string::npos;
        EXPECT_GT(m["frequency_hz"].get<double>(), 0);
        EXPECT_TRUE(m.contains("damping_ratio"));
    }
    EXPECT_TRUE(heave && roll && sway);
}
