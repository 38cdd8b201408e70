// Freight channels (per-wheel unloading and L/V, car-body accelerations, per-truck
// loads), the channel table they are declared in, the summary fields and the
// criteria ([criteria] limits, pass/fail).
#include "app/CommandResults.h"
#include "bespoke/EomHalfCarModel.h"
#include "mbmodel/HalfCarModel.h"
#include "scenarios/ModelRegistry.h"
#include "scenarios/ScenarioRun.h"
#include "tests/CsvReader.h"
#include "tests/TestCases.h"
#include "tests/TestTmp.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>

using namespace rockroll;
using test_cases::makeCase;

namespace {
const char* kModels[] = {"halfcar", "fullcar", "eom", "reduced"};

std::vector<std::string> columnsWithRole(const ChannelLayout& l, const std::vector<int>& indices) {
    std::vector<std::string> out;
    for (int i : indices) out.push_back(l.names[i]);
    return out;
}

double maxAbs(const std::vector<double>& x) {
    double m = 0;
    for (double v : x) m = std::max(m, std::abs(v));
    return m;
}
}  // namespace

// ---- the channel table -----------------------------------------------------------

TEST(FreightCriteria, ChannelTableDerivesColumnsAndRolesFromOneDeclaration) {
    struct Sample {
        double a = 0, b = 0;
    };
    ChannelTable<Sample> t;
    t.add("load_F_L", "lb", ChannelRole::SingleWheelLoad | ChannelRole::TruckSideWheelLoad,
          [](const Sample& s) { return s.a; });
    t.add("mode", "", [](const Sample& s) { return s.b; });
    EXPECT_EQ(t.getLayout().names, (std::vector<std::string>{"load_F_L_lb", "mode"}));
    EXPECT_EQ(t.getLayout().singleWheelLoad, std::vector<int>{0});
    EXPECT_EQ(t.getLayout().truckSideWheelLoad, std::vector<int>{0});
    std::vector<double> out;
    t.evaluate({2.5, 7}, out);
    EXPECT_EQ(out, (std::vector<double>{2.5, 7}));
    // A CSV header must not split: no comma, quote or blank in a name; no name twice.
    EXPECT_THROW(t.add("wheel,1", "lb", [](const Sample&) { return 0.0; }), std::invalid_argument);
    EXPECT_THROW(t.add("wheel 1", "lb", [](const Sample&) { return 0.0; }), std::invalid_argument);
    EXPECT_THROW(t.add("load_F_L", "lb", [](const Sample&) { return 0.0; }), std::invalid_argument);
}

TEST(FreightChannels, EveryModelDeclaresUniqueNamesWithUnitsAndTheFreightRoles) {
    for (const char* model : kModels) {
        const Scenario sc = makeCase(model, 0.75, 16.5, 1);
        const auto m = ModelRegistry::get().getModel(model).make(sc, makeTrackMotion(sc));
        const ChannelLayout& l = m->getChannels();
        ASSERT_EQ(l.names.size(), l.channels.size());
        for (size_t i = 0; i < l.names.size(); ++i) {
            EXPECT_EQ(l.names[i].find(','), std::string::npos) << model << " " << l.names[i];
            EXPECT_EQ(l.find(l.names[i]), int(i)) << model << " " << l.names[i] << " twice";
        }
        const size_t wheels = std::string(model) == "fullcar" ? 8 : 2;
        EXPECT_EQ(l.wheelUnloading.size(), wheels) << model;
        // L/V only where the model has lateral wheel forces: not the reduced model's massless truck.
        EXPECT_EQ(l.lOverV.size(), std::string(model) == "reduced" ? 0 : wheels) << model;
        EXPECT_EQ(l.carBodyVerticalAccel.size(), std::string(model) == "fullcar" ? 3u : 1u) << model;
        EXPECT_EQ(l.carBodyLateralAccel.size(), l.carBodyVerticalAccel.size()) << model;
        for (int i : l.wheelUnloading) EXPECT_EQ(l.channels[i].unit, "ratio");
        for (int i : l.carBodyVerticalAccel) EXPECT_EQ(l.channels[i].unit, "g");
        EXPECT_EQ(l.centerPlate.size(), std::string(model) == "fullcar" ? 2u : 1u) << model;
        for (int i : l.centerPlate) EXPECT_FALSE(l.channels[i].truck.empty()) << model;
    }
}

// ---- physical checks ---------------------------------------------------------------

TEST(FreightChannels, AtRestAccelerationsUnloadingAndLOverVAreZero) {
    for (const char* model : kModels) {
        const Scenario sc = makeCase(model, 0.0, 16.5, 0.2);
        const ScenarioRun r = runScenario(sc);
        const auto m = ModelRegistry::get().getModel(model).make(sc, makeTrackMotion(sc));
        const ChannelLayout& l = m->getChannels();
        for (const auto& name : columnsWithRole(l, l.wheelUnloading))
            EXPECT_LT(maxAbs(test_cases::getColumn(r.result, name)), 1e-6) << model << " " << name;
        for (const auto& name : columnsWithRole(l, l.lOverV))
            EXPECT_LT(maxAbs(test_cases::getColumn(r.result, name)), 1e-6) << model << " " << name;
        for (const auto* role : {&l.carBodyVerticalAccel, &l.carBodyLateralAccel})
            for (const auto& name : columnsWithRole(l, *role))
                EXPECT_LT(maxAbs(test_cases::getColumn(r.result, name)), 1e-6) << model << " " << name;
        const RunSummary& s = r.summary;
        EXPECT_LT(std::abs(s.maxWheelUnloading), 1e-6) << model;
        EXPECT_LT(s.maxCarBodyVerticalAccelG, 1e-6) << model;
        EXPECT_LT(s.maxCarBodyLateralAccelG, 1e-6) << model;
        if (std::string(model) == "reduced") EXPECT_TRUE(std::isnan(s.maxLOverV));
        else EXPECT_LT(s.maxLOverV, 1e-6) << model;
        EXPECT_TRUE(s.passesCriteria()) << model << " " << s.describeCriteria();
        // Per-truck loads at rest: the static center-plate load, side bearings open.
        for (const TruckLoads& t : s.trucks) {
            EXPECT_NEAR(t.maxCenterPlateLoadLb, s.staticCenterPlateLoadLb, 1e-6 * s.staticCenterPlateLoadLb) << model;
            EXPECT_NEAR(t.minCenterPlateLoadLb, s.staticCenterPlateLoadLb, 1e-6 * s.staticCenterPlateLoadLb) << model;
            EXPECT_EQ(t.maxSideBearingLoadLb[0], 0.0) << model;
            EXPECT_EQ(t.maxSideBearingLoadLb[1], 0.0) << model;
        }
    }
}

TEST(FreightChannels, UnloadingIsOneMinusLoadOverStaticLoad) {
    for (const char* model : {"halfcar", "eom", "reduced"}) {
        const ScenarioRun r = runScenario(makeCase(model, 0.75, 16.5, 3));
        for (const char* side : {"L", "R"}) {
            const auto load = test_cases::getColumn(r.result, std::string("wheels_F_") + side + "_lb");
            const auto unloading = test_cases::getColumn(r.result, std::string("wheel_unloading_F1_") + side + "_ratio");
            const double staticLoad = load.front();  // the run starts at rest
            double peak = 0;
            for (size_t i = 0; i < load.size(); ++i) {
                ASSERT_NEAR(unloading[i], 1 - load[i] / staticLoad, 1e-9) << model << " " << side << " " << i;
                peak = std::max(peak, unloading[i]);
            }
            EXPECT_GT(peak, 0.1) << model << ": the case should unload a wheel";
        }
    }
}

TEST(FreightChannels, LOverVIsTheLateralOverTheVerticalContactForceOfEachWheel) {
    // Simbody half car, a state off equilibrium (wheelset shifted, bodies rolled), against the contact's own forces.
    const Scenario sc = makeCase("halfcar", 0.75, 16.5, 1);
    const HalfCarModel model(sc.car, TrackInput(sc.track), ModelOptions{sc.speed, sc.entry, makeTrackMotion(sc), {}, sc.wheelRail, {}});
    SimTK::State s = model.makeStaticState();
    model.getTruck(0).getWheelset(0).setOneQ(s, 1, 0.002);
    model.getTruck(0).getWheelset(0).setOneU(s, 1, 0.05);
    model.getCarBody().setOneQ(s, 0, 0.01);
    std::vector<double> v;
    model.calcChannels(s, v);
    const WheelRailForces f = model.getTruck(0).getWheelRail(0).calcForces(s);
    const ChannelLayout& l = model.getChannels();
    for (int side : {0, 1}) {
        const std::string S = side == 0 ? "L" : "R";
        ASSERT_GT(f.normal[side], 0);
        EXPECT_NE(f.lateral[side], 0);
        EXPECT_DOUBLE_EQ(v[l.find("l_over_v_F1_" + S + "_ratio")], f.lateral[side] / f.normal[side]) << S;
    }
    // The equation-of-motion half car, the same definition on its own forces.
    const EomHalfCarModel eom(sc.car, makeEquivalentWheelsetInput(TrackInput(sc.track), makeTrackMotion(sc), sc.car.wheelbase));
    EomHalfCarModel::State y = eom.makeStaticState();
    y[3 * EomHalfCarModel::Wheelset + 1] = 0.002;
    y[EomHalfCarModel::kNumDofs + 3 * EomHalfCarModel::Wheelset + 1] = 0.05;
    const EomHalfCarModel::Forces ef = eom.calcForces(0, y);
    eom.calcChannels(0, y, v);
    for (int side : {0, 1}) {
        const std::string S = side == 0 ? "L" : "R";
        ASSERT_GT(ef.wheel[side], 0);
        EXPECT_DOUBLE_EQ(v[eom.getChannels().find("l_over_v_F1_" + S + "_ratio")], ef.wheelLateral[side] / ef.wheel[side]);
    }
    // A lifted wheel carries no lateral force: its L/V is 0, not a division by zero.
    EXPECT_EQ(calcLOverV(0, 0), 0.0);
    EXPECT_TRUE(std::isinf(calcLOverV(1, 0)));
}

TEST(FreightChannels, MirroredInputMirrorsTheFreightChannels) {
    for (const char* model : {"eom", "halfcar"}) {
        Scenario a = makeCase(model, 0.75, 16.5, 4.0);
        Scenario b = a;
        b.track.mirror = true;
        const ScenarioRun ra = runScenario(a), rb = runScenario(b);
        auto col = [](const ScenarioRun& r, const std::string& n) { return test_cases::getColumn(r.result, n); };
        const auto uL = col(ra, "wheel_unloading_F1_L_ratio"), uR = col(rb, "wheel_unloading_F1_R_ratio");
        const auto lvL = col(ra, "l_over_v_F1_L_ratio"), lvR = col(rb, "l_over_v_F1_R_ratio");
        const auto ayA = col(ra, "car_body_lateral_accel_g"), ayB = col(rb, "car_body_lateral_accel_g");
        const auto azA = col(ra, "car_body_vertical_accel_g"), azB = col(rb, "car_body_vertical_accel_g");
        const double peakU = maxAbs(uL), peakLv = maxAbs(lvL);
        EXPECT_GT(peakU, 0.1) << model;
        EXPECT_GT(peakLv, 0.1) << model;
        double worstU = 0, worstLv = 0;
        for (size_t i = 0; i < uL.size(); ++i) {
            worstU = std::max(worstU, std::abs(uL[i] - uR[i]));
            worstLv = std::max(worstLv, std::abs(lvL[i] + lvR[i]));
        }
        // Impacts are short and stiff; integration error shifts them slightly (as ModelInvariants).
        EXPECT_LT(worstU, 0.05 * peakU) << model;
        EXPECT_LT(worstLv, 0.05 * peakLv) << model;
        // Accelerations peak at those impacts, so a shift of an impact by one output sample
        // changes a sample by much of its peak: the filtered maxima are compared instead.
        const RunSummary &sa = ra.summary, &sb = rb.summary;
        EXPECT_GT(sa.maxCarBodyLateralAccelG, 0.05) << model;
        EXPECT_NEAR(sa.maxCarBodyVerticalAccelG, sb.maxCarBodyVerticalAccelG, 0.03 * sa.maxCarBodyVerticalAccelG) << model;
        EXPECT_NEAR(sa.maxCarBodyLateralAccelG, sb.maxCarBodyLateralAccelG, 0.03 * sa.maxCarBodyLateralAccelG) << model;
        EXPECT_NEAR(sa.maxLOverV, sb.maxLOverV, 0.03 * sa.maxLOverV) << model;
        // The lateral acceleration changes sign with the mirror, the vertical does not: the
        // signed extremes swap.
        EXPECT_NEAR(*std::max_element(ayA.begin(), ayA.end()), -*std::min_element(ayB.begin(), ayB.end()),
                    0.05 * maxAbs(ayA)) << model;
        EXPECT_NEAR(*std::min_element(azA.begin(), azA.end()), *std::min_element(azB.begin(), azB.end()),
                    0.05 * maxAbs(azA)) << model;
        std::cout << model << ": worst unloading " << worstU << " of " << peakU << ", L/V " << worstLv << " of "
                  << peakLv << "; max az " << sa.maxCarBodyVerticalAccelG << " / " << sb.maxCarBodyVerticalAccelG
                  << ", max ay " << sa.maxCarBodyLateralAccelG << " / " << sb.maxCarBodyLateralAccelG << "\n";
    }
}

// ---- summary and files ---------------------------------------------------------------

TEST(FreightChannels, SummaryAndHistoryCarryTheFreightFieldsAndReadBack) {
    // `rockroll run` writes history.csv and summary.json; both are read back here and
    // compared with the same run made in this process.
    const auto dir = test::makeTestTempDir();
    const std::string cmd = std::string(ROCKROLL_BIN) + " run '" + ROCKROLL_SOURCE_DIR +
                            "/scenarios/70ton-loaded.toml' --model fullcar --duration-s 2 --out '" + dir.string() +
                            "/run' --json > '" + dir.string() + "/stdout.json'";
    ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
    Scenario sc = loadScenarioFile(std::string(ROCKROLL_SOURCE_DIR) + "/scenarios/70ton-loaded.toml");
    sc.model = "fullcar";
    sc.run.duration = 2;
    const ScenarioRun run = runScenario(sc);

    std::ifstream csv(dir / "run" / "history.csv");
    std::stringstream text;
    text << csv.rdbuf();
    const test::CsvRecords records = test::parseCsv(text.str());
    ASSERT_EQ(records.front(), run.result.history.names);
    for (const char* name : {"l_over_v_F1_L_ratio", "wheel_unloading_R2_R_ratio", "car_body_vertical_accel_g",
                             "car_body_lateral_accel_R_g", "center_plate_R_lb", "side_bearing_F_L_lb"})
        EXPECT_NE(std::find(records.front().begin(), records.front().end(), name), records.front().end()) << name;
    const int lv = run.result.history.column("l_over_v_F1_L_ratio");
    ASSERT_EQ(records.size(), run.result.history.samples.size() + 1);
    for (size_t i = 1; i < records.size(); i += 97) {  // 7 significant digits in the file
        const double v = run.result.history.samples[i - 1][lv];
        EXPECT_NEAR(std::stod(records[i][lv]), v, 1e-6 * std::abs(v) + 1e-12) << i;
    }

    std::ifstream js(dir / "run" / "summary.json");
    const nlohmann::json j = nlohmann::json::parse(js);
    const RunSummary& s = run.summary;
    EXPECT_DOUBLE_EQ(j.at("max_l_over_v").get<double>(), s.maxLOverV);
    EXPECT_DOUBLE_EQ(j.at("max_truck_side_l_over_v").get<double>(), s.maxTruckSideLOverV);
    EXPECT_DOUBLE_EQ(j.at("max_car_body_vertical_accel_g").get<double>(), s.maxCarBodyVerticalAccelG);
    EXPECT_DOUBLE_EQ(j.at("max_car_body_lateral_accel_g").get<double>(), s.maxCarBodyLateralAccelG);
    EXPECT_DOUBLE_EQ(j.at("max_wheel_unloading").get<double>(), s.maxWheelUnloading);
    EXPECT_GT(s.maxLOverV, 0);
    EXPECT_GT(s.maxCarBodyLateralAccelG, 0);
    ASSERT_EQ(j.at("trucks").size(), 2u);
    EXPECT_EQ(j.at("trucks")[1].at("truck"), "R");
    EXPECT_DOUBLE_EQ(j.at("trucks")[0].at("max_center_plate_load_lb").get<double>(), s.trucks[0].maxCenterPlateLoadLb);
    const auto& criteria = j.at("criteria");
    ASSERT_EQ(criteria.size(), s.criteria.size());
    for (size_t i = 0; i < criteria.size(); ++i) {
        EXPECT_EQ(criteria[i].at("name"), s.criteria[i].name);
        EXPECT_EQ(criteria[i].at("unit"), s.criteria[i].unit);
        EXPECT_DOUBLE_EQ(criteria[i].at("limit").get<double>(), s.criteria[i].limit);
        if (!s.criteria[i].evaluated()) {
            // The restraint's single-wheel L/V, both wheels of a wheelset one ratio: not evaluated.
            EXPECT_EQ(s.criteria[i].name, "l_over_v");
            EXPECT_TRUE(criteria[i].at("value").is_null());
            continue;
        }
        EXPECT_DOUBLE_EQ(criteria[i].at("value").get<double>(), s.criteria[i].value);
        EXPECT_EQ(criteria[i].at("pass").get<bool>(), s.criteria[i].passes());
    }
    EXPECT_EQ(j.at("criteria_pass").get<bool>(), s.passesCriteria());
    // The raw maximum is the largest |value| of those very columns.
    double rawAz = 0;
    for (const char* n : {"car_body_vertical_accel_g", "car_body_vertical_accel_F_g", "car_body_vertical_accel_R_g"})
        rawAz = std::max(rawAz, maxAbs(test_cases::getColumn(run.result, n)));
    EXPECT_DOUBLE_EQ(s.rawMaxCarBodyVerticalAccelG, rawAz);
}

TEST(FreightChannels, ReducedModelReportsNoLOverVInsteadOfAFakeOne) {
    const ScenarioRun run = runScenario(makeCase("reduced", 0.75, 16.5, 1.0));
    const nlohmann::ordered_json j = app::toJson(run.summary);
    EXPECT_TRUE(j.at("max_l_over_v").is_null());
    bool found = false;
    for (const auto& c : j.at("criteria"))
        if (c.at("name") == "l_over_v") {
            found = true;
            EXPECT_TRUE(c.at("value").is_null());
            EXPECT_TRUE(c.at("pass").is_null());
        }
    EXPECT_TRUE(found);
    for (const auto& n : run.result.history.names) EXPECT_EQ(n.find("l_over_v"), std::string::npos) << n;
}

// With equal lateral shares a lifted wheel would carry lateral force (L/V ±infinity):
// that eom model records no L/V, and a run that lifts a wheel finishes. Before, the
// runaway check ("channel l_over_v_F1_R_ratio is -inf") stopped it, and with it every
// describing-function twin orbit on a wheel-lift stretch (validate section 5's stability).
TEST(FreightChannels, EomWithEqualLateralSharesReportsNoLOverVAndRunsThroughWheelLift) {
    Scenario sc = makeCase("eom", 0.75, 16.5, 20.0);  // the default case: severe, a wheel lifts
    sc.eom.equalLateralShares = true;
    const ScenarioRun run = runScenario(sc);  // a NumericalFailure fails the test
    EXPECT_GT(run.summary.maxWheelLiftIn, 0.05) << "the case must lift a wheel";
    EXPECT_TRUE(std::isnan(run.summary.maxLOverV));
    for (const auto& n : run.result.history.names) EXPECT_EQ(n.find("l_over_v"), std::string::npos) << n;
    // The describing function's twin is such a model.
    const EomHalfCarModel twin(sc.car, makeEquivalentWheelsetInput(TrackInput(sc.track), makeTrackMotion(sc), sc.car.wheelbase),
                               EomSimplifications::describingFunctionTwin());
    EXPECT_TRUE(twin.getChannels().lOverV.empty());
}

// ---- criteria -------------------------------------------------------------------------

TEST(FreightCriteria, ValueAtOrBelowTheLimitPassesAboveFailsUnevaluatedIsIgnored) {
    RunSummary s;
    s.peakToPeakRollDeg = 6.0;
    s.maxWheelUnloading = 0.95;
    s.maxLOverV = std::numeric_limits<double>::quiet_NaN();
    s.maxTruckSideLOverV = 0.3;
    s.maxCarBodyVerticalAccelG = 0.2;
    s.maxCarBodyLateralAccelG = 0.8;
    CriteriaLimits limits;
    limits.lOverV = 1.13;  // resolved (resolveCriteriaLimits): Nadal's limit
    s.criteria = evaluateCriteria(s, limits);
    ASSERT_EQ(s.criteria.size(), 6u);
    EXPECT_TRUE(s.criteria[0].passes());   // 6 deg at a 6 deg limit
    EXPECT_FALSE(s.criteria[1].passes());  // 0.95 > 0.9
    EXPECT_FALSE(s.criteria[2].evaluated());
    EXPECT_FALSE(s.criteria[2].passes());
    EXPECT_TRUE(s.criteria[3].passes());   // truck side 0.3 ≤ 0.5
    EXPECT_TRUE(s.criteria[4].passes());
    EXPECT_FALSE(s.criteria[5].passes());  // 0.8 g > 0.75 g
    EXPECT_FALSE(s.passesCriteria());
    EXPECT_EQ(s.describeCriteria(), "FAIL wheel_unloading,car_body_lateral_accel (not evaluated: l_over_v)");
    limits.wheelUnloading = 1;
    limits.carBodyLateralAccelG = 0.8;
    s.criteria = evaluateCriteria(s, limits);
    EXPECT_TRUE(s.passesCriteria());
    EXPECT_EQ(s.describeCriteria(), "pass (not evaluated: l_over_v)");
    s.maxLOverV = 0.5;
    s.criteria = evaluateCriteria(s, limits);
    EXPECT_EQ(s.describeCriteria(), "pass");
    s.maxTruckSideLOverV = 0.6;
    s.criteria = evaluateCriteria(s, limits);
    EXPECT_EQ(s.describeCriteria(), "FAIL truck_side_l_over_v");
}

TEST(FreightCriteria, TheSingleWheelLimitLeftZeroIsNadalsOfTheWheelRailSettings) {
    Scenario sc = parseScenario(test_cases::kMinimalScenarioToml, "t.toml");
    EXPECT_EQ(sc.criteria.lOverV, 0.0);
    EXPECT_DOUBLE_EQ(resolveCriteriaLimits(sc).lOverV, calcNadalLimit(75 * units::degree, 0.5));
    sc.wheelRail.friction = 0.3;
    EXPECT_DOUBLE_EQ(resolveCriteriaLimits(sc).lOverV, calcNadalLimit(75 * units::degree, 0.3));
    sc.criteria.lOverV = 0.9;
    EXPECT_EQ(resolveCriteriaLimits(sc).lOverV, 0.9);
}

TEST(FreightCriteria, ScenarioTableSetsValidatesAndWritesTheLimits) {
    const std::string base = test_cases::kMinimalScenarioToml;
    const Scenario d = parseScenario(base, "t.toml");
    EXPECT_EQ(d.criteria.rollPeakToPeakDeg, 6);
    EXPECT_EQ(d.criteria.wheelUnloading, 0.9);
    const Scenario sc = parseScenario(base + "\n[criteria]\nroll_peak_to_peak = \"4 deg\"\nwheel_unloading = 0.6\n"
                                             "l_over_v = 0.8\ncar_body_vertical_accel_g = 0.5\n"
                                             "car_body_lateral_accel_g = 0.3\n",
                                      "t.toml");
    EXPECT_EQ(sc.criteria.rollPeakToPeakDeg, 4);
    EXPECT_EQ(sc.criteria.wheelUnloading, 0.6);
    EXPECT_EQ(sc.criteria.lOverV, 0.8);
    EXPECT_EQ(sc.criteria.carBodyVerticalAccelG, 0.5);
    EXPECT_EQ(sc.criteria.carBodyLateralAccelG, 0.3);
    // Written and read back unchanged.
    const Scenario again = parseScenario(formatScenarioToml(sc), "again.toml");
    EXPECT_EQ(again.criteria.rollPeakToPeakDeg, 4);
    EXPECT_EQ(again.criteria.carBodyLateralAccelG, 0.3);
    auto fails = [&](const std::string& table, const std::string& expected) {
        try {
            parseScenario(base + "\n[criteria]\n" + table + "\n", "t.toml");
            ADD_FAILURE() << table << " was accepted";
        } catch (const ScenarioError& e) {
            EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
            EXPECT_NE(std::string(e.what()).find("t.toml"), std::string::npos) << e.what();
        }
    };
    fails("wheel_unloading = 1.5", "criteria.wheel_unloading");
    fails("l_over_v = -1", "criteria.l_over_v");
    fails("roll_peak_to_peak = \"6 in\"", "criteria.roll_peak_to_peak");
    fails("car_body_lateral_accel_g = 0", "criteria.car_body_lateral_accel_g");
    fails("max_roll = 3", "max_roll");
}

TEST(FreightCriteria, LimitsReachTheRunSummary) {
    Scenario sc = makeCase("reduced", 0.75, 16.5, 2.0);
    sc.criteria.rollPeakToPeakDeg = 0.01;
    const ScenarioRun r = runScenario(sc);
    ASSERT_GT(r.summary.peakToPeakRollDeg, 0.01);
    EXPECT_EQ(r.summary.criteria[0].name, "roll_peak_to_peak");
    EXPECT_EQ(r.summary.criteria[0].limit, 0.01);
    EXPECT_FALSE(r.summary.criteria[0].passes());
    EXPECT_FALSE(r.summary.passesCriteria());
}
