// Cars as data: scenarios/cars/*.toml are the built-in cars, each value with its
// unit and its source; a scenario can also take a car file of its own.
#include "scenarios/ScenarioLoader.h"
#include "tests/TestCases.h"
#include "tests/TextFile.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>

namespace rockroll {
namespace {

namespace fs = std::filesystem;
using test_cases::replaceOnce;

using rockroll::test::readTextFile;

void expectSameCar(const CarParameters& a, const CarParameters& b, const std::string& what) {
    EXPECT_EQ(a.name, b.name) << what;
    for (const auto& info : getCarParameterTable())
        EXPECT_EQ(a.*(info.member), b.*(info.member)) << what << ": " << info.key;
}

TEST(CarFiles, EveryFileInScenariosCarsIsABuiltInCarWithTheSameValues) {
    std::set<std::string> files;
    for (const auto& e : fs::directory_iterator(fs::path(ROCKROLL_SOURCE_DIR) / "scenarios" / "cars")) {
        if (e.path().extension() != ".toml") continue;
        const std::string name = e.path().stem().string();
        files.insert(name);
        expectSameCar(loadCarFile(e.path().string()), makeCarParameters(name), name);
    }
    const auto names = getCarNames();
    EXPECT_EQ(files, std::set<std::string>(names.begin(), names.end()));
    EXPECT_GE(files.size(), 3u);
}

TEST(CarFiles, PublishedValuesAreReadExactly) {
    namespace u = units;
    const CarParameters loaded = makeCarParameters("70ton-loaded"), empty = makeCarParameters("70ton-empty"),
                        heavy = makeCarParameters("100ton-loaded");
    EXPECT_EQ(loaded.bodyAndBolstersWeight, 172650 * u::lbf);
    EXPECT_EQ(loaded.rollInertia, 1288800 * u::lbInS2);
    EXPECT_EQ(loaded.sideBearingAboveSprings, 12.1875 * u::inch);
    EXPECT_EQ(loaded.truckSpacing, 39.0 * u::foot);
    EXPECT_EQ(empty.cgAboveCenterPlate, 35.0 * u::inch);
    // The empty car's pitch inertia is the loaded car's scaled by weight (docs/model.md §5).
    EXPECT_EQ(empty.pitchInertia, 16650000 * (66000.0 / 172650.0) * u::lbInS2);
    EXPECT_EQ(heavy.gibRate, 55000 * u::lbfPerInch);
    EXPECT_EQ(heavy.wheelRadius, 18.0 * u::inch);
    EXPECT_EQ(heavy.centerPlateRimPoints, 16);
}

void expectCarError(const std::string& text, const std::string& needle) {
    try {
        parseCarFile(text, "mycar.toml");
        ADD_FAILURE() << "accepted; expected an error containing: " << needle;
    } catch (const ScenarioError& e) {
        EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("mycar.toml"), std::string::npos) << e.what();
    }
}

TEST(CarFiles, BadCarFilesAreRefusedNamingTheKey) {
    const std::string good = readTextFile(fs::path(ROCKROLL_SOURCE_DIR) / "scenarios/cars/70ton-loaded.toml");
    EXPECT_NO_THROW(parseCarFile(good, "mycar.toml"));
    expectCarError(replaceOnce(good, "gib_rate = ", "gib_rat = "), "'parameters.gib_rate'");
    expectCarError(replaceOnce(good, "\"20840 lb/in\"", "\"20840 lb\""), "'parameters.spring_vertical_rate.value'");
    expectCarError(replaceOnce(good, "\"14 in\"", "\"-14 in\""), "'parameters.center_plate_diameter.value'");
    expectCarError(replaceOnce(good, "source = \"report Table 2\" }", "source = \"\" }"), ".source'");
    expectCarError(replaceOnce(good, "name = \"70ton-loaded\"", ""), "'name'");
    expectCarError(good + "\nextra = 1\n", "'parameters.extra'");
    expectCarError("name = \"x\"\n[parameters\n", "mycar.toml:2");
}

TEST(CarFiles, AScenarioTakesACarFileRelativeToItself) {
    const fs::path dir = fs::path(ROCKROLL_TEST_TMP) / "car_files";
    fs::create_directories(dir / "cars");
    std::string car = readTextFile(fs::path(ROCKROLL_SOURCE_DIR) / "scenarios/cars/70ton-loaded.toml");
    car = replaceOnce(car, "name = \"70ton-loaded\"", "name = \"my-hopper\"");
    car = replaceOnce(car, "side_bearing_clearance = { value = \"0.25 in\"", "side_bearing_clearance = { value = \"0.125 in\"");
    std::ofstream(dir / "cars" / "my-hopper.toml") << car;
    std::string scenario = readTextFile(fs::path(ROCKROLL_SOURCE_DIR) / "scenarios/70ton-loaded.toml");
    scenario = replaceOnce(scenario, "base = \"70ton-loaded\"", "file = \"cars/my-hopper.toml\"");
    std::ofstream(dir / "mine.toml") << scenario;
    const Scenario sc = loadScenarioFile((dir / "mine.toml").string());
    EXPECT_EQ(sc.car.name, "my-hopper");
    EXPECT_EQ(sc.car.sideBearingClearance, 0.125 * units::inch);
    EXPECT_EQ(sc.car.bodyAndBolstersWeight, 172650 * units::lbf);

    // The resolved scenario carries the whole car inline, so it reloads without the file.
    const Scenario again = parseScenario(formatScenarioToml(sc), "again.toml");
    expectSameCar(again.car, sc.car, "inline round trip");

    const std::string both = replaceOnce(scenario, "file = \"cars/my-hopper.toml\"",
                                         "file = \"cars/my-hopper.toml\"\nbase = \"70ton-loaded\"");
    EXPECT_THROW(parseScenario(both, (dir / "both.toml").string()), ScenarioError);
    const std::string missing = replaceOnce(scenario, "cars/my-hopper.toml", "cars/none.toml");
    try {
        parseScenario(missing, (dir / "missing.toml").string());
        ADD_FAILURE() << "a missing car file was accepted";
    } catch (const ScenarioError& e) {
        EXPECT_NE(std::string(e.what()).find("car.file"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("cannot open car file"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace rockroll
