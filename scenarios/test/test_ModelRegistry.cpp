// The model registry: every time-domain model is reachable by its name alone, runs
// from its own static state, continues from its own RestartState and refuses
// another model's.
#include "mbmodel/RockingModel.h"
#include "scenarios/ModelRegistry.h"
#include "tests/TestCases.h"

#include <gtest/gtest.h>
#include <fstream>
#include <iterator>
#include <set>

namespace rockroll {
namespace {

using test_cases::makeCase;

TEST(ModelRegistry, NamesAreUniqueAndEveryModelCanBeBuilt) {
    const ModelRegistry& registry = ModelRegistry::get();
    const std::vector<std::string> names = registry.getNames();
    EXPECT_EQ(std::set<std::string>(names.begin(), names.end()).size(), names.size());
    EXPECT_EQ(names, (std::vector<std::string>{"halfcar", "fullcar", "eom", "reduced"}));
    EXPECT_EQ(registry.getMultibodyNames(), (std::vector<std::string>{"halfcar", "fullcar"}));
    for (const ModelDescriptor& d : registry.getModels()) {
        EXPECT_FALSE(d.description.empty()) << d.name;
        ASSERT_TRUE(d.make) << d.name;
        EXPECT_EQ(registry.find(d.name), &d);
    }
    EXPECT_EQ(registry.find("tram"), nullptr);
    try {
        registry.getModel("tram");
        FAIL() << "no error for an unknown model";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("\"tram\""), std::string::npos) << e.what();
        for (const auto& n : names) EXPECT_NE(std::string(e.what()).find(n), std::string::npos) << e.what();
    }
}

/// A run from rest starts at the model's static state; its RestartState names the
/// model and carries its final state; a run continued from it starts there.
TEST(ModelRegistry, EveryModelRunsFromItsStaticStateAndContinuesFromItsRestartState) {
    for (const ModelDescriptor& d : ModelRegistry::get().getModels()) {
        const Scenario sc = makeCase(d.name, 0.75, 16.5, 0.4);
        const auto model = d.make(sc, makeTrackMotion(sc));
        const std::vector<double> y0 = model->calcStaticState();
        ASSERT_FALSE(y0.empty()) << d.name;
        const ScenarioRun first = runScenario(sc);
        EXPECT_EQ(first.restart.model, d.name);
        EXPECT_EQ(first.restart.y.size(), y0.size()) << d.name;
        EXPECT_EQ(first.restart.speed, sc.speed) << d.name;
        EXPECT_NEAR(first.restart.distance, sc.speed * first.result.simTime, 1e-9) << d.name;
        EXPECT_NE(first.restart.y, y0) << d.name << ": the car did not move";
        // The same run, started explicitly from the static state, is the same run.
        const RunResult again = model->simulate(sc, y0);
        EXPECT_EQ(toVector(again.history.samples.back()), toVector(first.result.history.samples.back())) << d.name;

        RunStart start;
        start.from = first.restart;
        start.staticReference = first.staticReference;
        const ScenarioRun next = runScenario(sc, start);
        EXPECT_EQ(next.summary.model, d.name);
        EXPECT_NEAR(next.restart.distance, 2 * first.restart.distance, 1e-9) << d.name;
    }
}

TEST(ModelRegistry, AStateContinuesOnlyInTheModelThatProducedIt) {
    const Scenario half = makeCase("halfcar", 0.75, 16.5, 0.2);
    RunStart start;
    start.from = runScenario(half).restart;
    for (const char* other : {"fullcar", "eom", "reduced"}) {
        try {
            runScenario(makeCase(other, 0.75, 16.5, 0.2), start);
            ADD_FAILURE() << "a halfcar state was accepted by " << other;
        } catch (const ScenarioError& e) {
            EXPECT_NE(std::string(e.what()).find("cannot continue a \"halfcar\" state"), std::string::npos) << e.what();
        }
    }
}

TEST(ModelRegistry, SwitchesApplyByCapabilityNotByName) {
    Scenario sc = makeCase("eom", 0.75, 16.5, 0.2);
    sc.attribution.unsprungGravity = false;
    try {
        checkSwitchesApply(sc);
        FAIL() << "attribution switch accepted for eom";
    } catch (const ScenarioError& e) {
        EXPECT_NE(std::string(e.what()).find("expected model halfcar or fullcar"), std::string::npos) << e.what();
    }
    sc = makeCase("halfcar", 0.75, 16.5, 0.2);
    sc.reduced.truckWeight = true;
    try {
        checkSwitchesApply(sc);
        FAIL() << "reduced.truck_weight accepted for halfcar";
    } catch (const ScenarioError& e) {
        EXPECT_NE(std::string(e.what()).find("expected model reduced"), std::string::npos) << e.what();
    }
    sc.model = "nonesuch";
    sc.reduced.truckWeight = false;
    EXPECT_THROW(checkSwitchesApply(sc), ScenarioError);
    EXPECT_THROW(makeScenarioModel(makeCase("eom", 0.75, 16.5, 0.2)), ScenarioError);
}

// Each model lists the keys it uses; a key the scenario sets outside that list is ignored
// and reported (docs/cli.md, "Which model uses which key").
TEST(ModelRegistry, IgnoredSettingsAreTheSetKeysTheModelDoesNotUse) {
    Scenario sc = loadScenarioFile(std::string(ROCKROLL_SCENARIO_DIR) + "/70ton-loaded.toml");
    for (const char* model : {"halfcar", "fullcar"}) {
        sc.model = model;
        EXPECT_EQ(getIgnoredSettings(sc), std::vector<std::string>{}) << model;
    }
    sc.model = "reduced";
    EXPECT_EQ(getIgnoredSettings(sc), (std::vector<std::string>{"integrator.accuracy", "integrator.method"}));
    EXPECT_EQ(getRecordedOutputRate(sc), 200);
    sc.model = "eom";
    EXPECT_EQ(getIgnoredSettings(sc), std::vector<std::string>{"integrator.method"});
    EXPECT_EQ(getRecordedOutputRate(sc), 500);
    sc = loadScenarioFile(std::string(ROCKROLL_SCENARIO_DIR) + "/70ton-loaded.toml",
                          {{"integrator.max_step", "0.001 s"}, {"track.entry", "synchronized"}, {"eom.small_angles", "true"}});
    sc.model = "eom";
    EXPECT_EQ(getIgnoredSettings(sc), (std::vector<std::string>{"integrator.max_step", "integrator.method", "track.entry"}));
    sc.model = "fullcar";
    EXPECT_EQ(getIgnoredSettings(sc), std::vector<std::string>{"eom.small_angles"});
}

// The reduced model records every step of its fixed 0.005 s (report §2.2): an output rate
// set to anything else is refused, not silently replaced.
TEST(ModelRegistry, TheReducedModelRefusesAnOutputRateItDoesNotRecordAt) {
    Scenario sc = loadScenarioFile(std::string(ROCKROLL_SCENARIO_DIR) + "/70ton-loaded.toml",
                                   {{"run.output_rate", "500 Hz"}});
    sc.model = "halfcar";
    EXPECT_NO_THROW(checkSwitchesApply(sc));
    sc.model = "reduced";
    try {
        checkSwitchesApply(sc);
        FAIL() << "500 Hz accepted for the reduced model";
    } catch (const ScenarioError& e) {
        EXPECT_NE(std::string(e.what()).find("key 'run.output_rate' = 500 Hz: expected 200 Hz for model \"reduced\""),
                  std::string::npos)
            << e.what();
    }
    sc.run.outputRate = 200;
    EXPECT_NO_THROW(checkSwitchesApply(sc));
}

// docs/cli.md's table of keys says, for every key, which models use it, as the registry does.
TEST(ModelRegistry, TheDocsSayWhichModelUsesWhichKey) {
    std::ifstream in(std::string(ROCKROLL_SOURCE_DIR) + "/docs/cli.md");
    const std::string all((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const size_t section = all.find("#### Which model uses which key");
    ASSERT_NE(section, std::string::npos);
    const std::string doc = all.substr(section);
    const ModelRegistry& registry = ModelRegistry::get();
    for (const std::string& key : getScenarioKeys()) {
        // A car parameter has a row of its own when some model does not use it.
        size_t at = doc.find("| `" + key + "` | ");
        if (at == std::string::npos && findCarParameter(key.substr(4))) at = doc.find("| `car.<parameter>` | ");
        ASSERT_NE(at, std::string::npos) << key << ": no row in docs/cli.md, \"Keys and defaults\"";
        const std::string line = doc.substr(at, doc.find('\n', at) - at);
        const std::string usedBy = line.substr(line.rfind(" | ") + 3);
        std::set<std::string> documented, actual;
        for (const ModelDescriptor& m : registry.getModels()) {
            if (m.usesSetting(key)) actual.insert(m.name);
            if (usedBy.starts_with("every model") || usedBy.find("`" + m.name + "`") != std::string::npos)
                documented.insert(m.name);
        }
        EXPECT_EQ(documented, actual) << key << ": " << line;
        EXPECT_FALSE(actual.empty()) << key << " is used by no model";
    }
}

// What a model's descriptor leaves out of its settings it does not use: a car parameter
// missing from a model's list, changed by 30 % (the rim from 8 to 12 points), leaves a 3 s
// run of that model bit for bit the same (docs/cli.md, "Which model uses which key").
TEST(ModelRegistry, ACarParameterAModelDoesNotUseLeavesItsRunUnchanged) {
    for (const ModelDescriptor& m : ModelRegistry::get().getModels()) {
        const Scenario base = makeCase(m.name, 0.75, 16.5, 3.0);
        const SampleTable reference = runScenario(base).result.history.samples;
        int checked = 0;
        for (const CarParameterInfo& info : getCarParameterTable()) {
            if (m.usesSetting(std::string("car.") + info.key)) continue;
            SCOPED_TRACE(m.name + " " + info.key);
            Scenario sc = base;
            double& v = sc.car.*(info.member);
            // An offset's default is 0: moved by 2 in.
            v = info.integer ? v + 4 : info.isSigned ? v + 2 * units::inch : v * 1.3;
            EXPECT_EQ(runScenario(sc).result.history.samples, reference);
            ++checked;
        }
        EXPECT_EQ(checked, m.name == "fullcar" ? 0 : m.name == "reduced" ? 19 : 10) << m.name;
    }
}

}  // namespace
}  // namespace rockroll
