// The attribution switches (docs/model.md, "Parameters"; results/REPORT.md section 10): the reduced model's [reduced] truck_weight
// and the Simbody models' [attribution] unsprung_gravity / unsprung_mass_scale. Each
// must change exactly what it says in the static state, and nothing else.
#include "bespoke/ReducedHalfCarModel.h"
#include "scenarios/ModelRegistry.h"
#include "tests/TestCases.h"
#include "mbmodel/RockingModel.h"
#include "scenarios/ScenarioRun.h"
#include "scenarios/SpeedSweep.h"
#include "tests/TestCases.h"

#include <gtest/gtest.h>

using namespace rockroll;

namespace {
/// The minimal scenario with the half car (the switches' own model).
const std::string kBase = test_cases::replaceOnce(test_cases::kMinimalScenarioToml, "model = \"fullcar\"",
                                                  "model = \"halfcar\"");

std::string errorOf(const std::string& extra) {
    try {
        parseScenario(kBase + extra, "case.toml");
    } catch (const ScenarioError& e) {
        return e.what();
    }
    return "";
}

/// Static state of a Simbody model: accelerations and the channels.
struct Static {
    double maxUDot = 0;
    std::vector<double> channels;
    std::unique_ptr<RockingModel> model;
    double get(const std::string& name) const { return channels[model->getChannels().find(name)]; }
};

Static makeStatic(const std::string& modelName, AttributionSwitches a) {
    Static out;
    ModelOptions options{16.5 * units::mph, TrackEntry::Lead, TrackMotion{}, AttributionSwitches{}, WheelRailSettings{}, CarBodySettings{}};
    options.attribution = a;
    TrackSpec track;
    track.amplitude = 0.75 * units::inch;
    out.model = ModelRegistry::get().getModel(modelName).makeMultibody(makeCarParameters("70ton-loaded"), TrackInput(track), options);
    const SimTK::State s = out.model->makeStaticState();
    out.model->getSystem().realize(s, SimTK::Stage::Acceleration);
    for (int i = 0; i < s.getNU(); ++i) out.maxUDot = std::max(out.maxUDot, std::abs(s.getUDot()[i]));
    out.model->calcChannels(s, out.channels);
    return out;
}
}  // namespace

TEST(Attribution, ScenarioKeysAreReadAndRangeChecked) {
    const Scenario sc = parseScenario(kBase +
                                          "[reduced]\ntruck_weight = true\n[attribution]\nunsprung_gravity = false\n"
                                          "unsprung_mass_scale = 0.01\n",
                                      "x.toml");
    EXPECT_TRUE(sc.reduced.truckWeight);
    EXPECT_FALSE(sc.attribution.unsprungGravity);
    EXPECT_EQ(sc.attribution.unsprungMassScale, 0.01);
    const Scenario def = parseScenario(kBase, "x.toml");
    EXPECT_FALSE(def.reduced.truckWeight);
    EXPECT_TRUE(def.attribution.isDefault());

    std::string e = errorOf("[attribution]\nunsprung_mass_scale = 0\n");
    EXPECT_NE(e.find("case.toml"), std::string::npos) << e;
    EXPECT_NE(e.find("attribution.unsprung_mass_scale"), std::string::npos) << e;
    EXPECT_NE(e.find("[0.001, 1]"), std::string::npos) << e;
    EXPECT_NE(errorOf("[attribution]\nunsprung_mass_scale = 2\n"), "");
    EXPECT_NE(errorOf("[attribution]\nunsprung_mass_scale = \"0.1 lb\"\n"), "");
    e = errorOf("[attribution]\nunsprung_gravity = \"no\"\n");
    EXPECT_NE(e.find("attribution.unsprung_gravity"), std::string::npos) << e;
    EXPECT_NE(e.find("true or false"), std::string::npos) << e;
    e = errorOf("[reduced]\ntruck_weight = 1\n");
    EXPECT_NE(e.find("reduced.truck_weight"), std::string::npos) << e;
    EXPECT_NE(errorOf("[reduced]\ntruck_wieght = true\n").find("no such key"), std::string::npos);
    EXPECT_NE(errorOf("[attribution]\ngravity = false\n").find("no such key"), std::string::npos);
}

TEST(Attribution, SwitchOnAModelItDoesNotApplyToIsAScenarioError) {
    Scenario sc = parseScenario(kBase + "[reduced]\ntruck_weight = true\n", "x.toml");
    sc.run.duration = 0.1;
    EXPECT_THROW(runScenario(sc), ScenarioError);  // halfcar
    sc.model = "reduced";
    EXPECT_NO_THROW(runScenario(sc));
    Scenario a = parseScenario(kBase + "[attribution]\nunsprung_gravity = false\n", "x.toml");
    a.run.duration = 0.1;
    for (const char* m : {"eom", "reduced"}) {
        a.model = m;
        EXPECT_THROW(runScenario(a), ScenarioError) << m;
    }
    // A threaded sweep reports it before its threads start (not std::terminate).
    SweepSpec spec;
    spec.scenario = a;
    spec.fromMph = 15, spec.toMph = 16, spec.stepMph = 1;
    EXPECT_THROW(runSweeps({spec, spec}, 2), ScenarioError);
}

TEST(Attribution, ReducedTruckWeightGivesTheSimbodyHalfCarsStaticWheelLoad) {
    Scenario sc = test_cases::makeCase("reduced", 0.0, 16.5, 0.5);
    const RunSummary massless = runScenario(sc).summary;
    sc.reduced.truckWeight = true;
    const ScenarioRun weighted = runScenario(sc);
    sc.reduced.truckWeight = false;
    sc.model = "halfcar";
    sc.run.duration = 0.05;
    const RunSummary halfcar = runScenario(sc).summary;
    const CarParameters car = makeCarParameters("70ton-loaded");
    const double lb = units::lbf;
    // The report's formulation: the car body's share only.
    EXPECT_NEAR(massless.staticWheelLoadLb, car.getCarBodyWeight() / 4 / lb, 1e-6 * massless.staticWheelLoadLb);
    EXPECT_NEAR(weighted.summary.staticWheelLoadLb, halfcar.staticWheelLoadLb, 0.005 * halfcar.staticWheelLoadLb);
    EXPECT_NEAR(weighted.summary.staticWheelLoadLb,
                massless.staticWheelLoadLb + (car.bolsterWeight / 2 + car.wheelsetWeight + car.sideFrameWeight) / lb,
                1e-6 * halfcar.staticWheelLoadLb);
    EXPECT_NEAR(weighted.summary.staticCenterPlateLoadLb, halfcar.staticCenterPlateLoadLb,
                1e-6 * halfcar.staticCenterPlateLoadLb);
    // It is an equilibrium: at zero amplitude nothing moves.
    for (double roll : test_cases::getColumn(weighted.result, "roll_deg")) EXPECT_NEAR(roll, 0.0, 1e-12);
    for (double z : test_cases::getColumn(weighted.result, "car_body_vertical_in")) EXPECT_NEAR(z, 0.0, 1e-9);
    for (double w : test_cases::getColumn(weighted.result, "wheels_F_L_lb"))
        EXPECT_NEAR(w, weighted.summary.staticWheelLoadLb, 1e-6 * w);
}

TEST(Attribution, SimbodyTruckGravityOffLowersTheStaticWheelLoadByTheTruckWeight) {
    const CarParameters car = makeCarParameters("70ton-loaded");
    const double truckWeightPerSide = (car.wheelsetWeight + car.sideFrameWeight) / units::lbf;  // 2 wheelsets, ½ each
    for (const char* m : {"halfcar", "fullcar"}) {
        const Static on = makeStatic(m, {});
        const Static off = makeStatic(m, {false, 1.0});
        EXPECT_LT(off.maxUDot, 1e-6) << m;
        for (const char* T : {"F", "R"}) {
            if (on.model->getChannels().find(std::string("wheels_") + T + "_L_lb") < 0) continue;
            for (const char* S : {"L", "R"}) {
                const std::string w = std::string("wheels_") + T + "_" + S + "_lb";
                EXPECT_NEAR(on.get(w) - off.get(w), truckWeightPerSide, 1e-6 * on.get(w)) << m << " " << w;
                const std::string sp = std::string("spring_") + T + "_" + S + "_lb";
                EXPECT_NEAR(on.get(sp), off.get(sp), 1e-6 * on.get(sp)) << m << " " << sp;
            }
            const std::string cp = std::string("center_plate_") + T + "_lb";
            EXPECT_NEAR(on.get(cp), off.get(cp), 1e-6 * on.get(cp)) << m;
        }
    }
}

TEST(Attribution, SimbodyTruckMassScaleKeepsTheStaticLoads) {
    for (const char* m : {"halfcar", "fullcar"}) {
        const Static on = makeStatic(m, {});
        const Static small = makeStatic(m, {true, 0.01});
        EXPECT_LT(small.maxUDot, 1e-4) << m;  // accelerations of a 100× lighter body: round-off ×100
        ASSERT_EQ(on.channels.size(), small.channels.size());
        for (size_t i = 0; i < on.channels.size(); ++i) {
            // Stored energy is not a load: the scaled masses' gravity energy is
            // smaller, and the constant force that puts their weight back has none.
            if (int(i) == on.model->getChannels().energyStored) continue;
            EXPECT_NEAR(on.channels[i], small.channels[i], 1e-6 * (1 + std::abs(on.channels[i])))
                << m << " " << on.model->getChannels().names[i];
        }
    }
    // And a short run at rest stays there.
    Scenario sc = test_cases::makeCase("halfcar", 0.0, 16.5, 0.2);
    sc.attribution.unsprungMassScale = 0.01;
    const RunSummary r = runScenario(sc).summary;
    EXPECT_NEAR(r.maxWheelLoadLb, r.staticWheelLoadLb, 1e-4 * r.staticWheelLoadLb);
    EXPECT_LT(r.maxRollDeg, 1e-9);
}

// With truck_weight, every mode's solution carries the weights in the vertical
// balances (summed directly), and the moment balances are those of the massless truck.
TEST(Attribution, ReducedTruckWeightEntersEveryModesVerticalBalance) {
    const CarParameters car = makeCarParameters("70ton-loaded");
    const ReducedHalfCarModel m(car, [](double) { return RailState{}; }, ReducedOptions{true});
    const TruckGeometry& g = m.getTruckGeometry();
    EXPECT_DOUBLE_EQ(g.bolsterWeight, car.bolsterWeight);
    EXPECT_DOUBLE_EQ(g.wheelsetWeight, 2 * (car.wheelsetWeight + car.sideFrameWeight));
    auto y = m.makeStaticState();
    y[0] = 0.03, y[1] = 0.004, y[2] -= 0.01;
    auto mem = m.makeStaticMemory();
    TruckInputs in = m.makeTruckInputs(0.1, y, mem);
    in.railZ = {0.004, -0.003};
    const double side[2] = {+1, -1};
    int solved = 0;
    for (const TruckMode& mode : enumerateTruckModes()) {
        const TruckSolution s = solveTruckMode(g, in, mode);
        if (s.violation >= 1e300) continue;
        ++solved;
        double Fz = -g.bolsterWeight, Wz = s.wheel[0] + s.wheel[1] - g.wheelsetWeight;
        double M = g.cpAboveSprings * s.pinForce, WM = g.halfGauge * (s.wheel[0] - s.wheel[1]) + g.springTopAboveRail * s.pinForce;
        for (int i : {0, 1}) {
            const double load = s.spring[i] + s.friction[i];
            Fz += -s.rim[i] - s.sideBearing[i] + load;
            Wz -= load;
            M += side[i] * (-g.a_c * s.rim[i] - g.a_s * s.sideBearing[i] + g.l_s * load);
            WM -= side[i] * g.l_s * load;
        }
        ASSERT_NEAR(Fz, 0.0, 0.1) << mode.describe();
        ASSERT_NEAR(Wz, 0.0, 0.1) << mode.describe();
        ASSERT_NEAR(M, 0.0, 0.1) << mode.describe();
        ASSERT_NEAR(WM, 0.0, 0.1) << mode.describe();
    }
    EXPECT_GT(solved, 10000);
}
