// Whole-model invariants and the rocking behaviour the issue asks for.
#include "mbmodel/RockingModel.h"
#include "scenarios/ScenarioRun.h"
#include "tests/TestCases.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace rockroll;

using test_cases::makeCase;

namespace {
std::vector<double> column(const ScenarioRun& r, const std::string& name) { return test_cases::getColumn(r.result, name); }
}  // namespace

TEST(ModelInvariants, ZeroAmplitudeGivesStaticLoads) {
    for (const char* model : {"halfcar", "fullcar"}) {
        const ScenarioRun r = runScenario(makeCase(model, 0.0, 16.5, 3.0));
        const RunSummary& s = r.summary;
        EXPECT_NEAR(s.maxRollDeg, 0.0, 1e-9) << model;
        EXPECT_NEAR(s.rawMaxWheelLoadLb, s.staticWheelLoadLb, 1e-6 * s.staticWheelLoadLb) << model;
        EXPECT_NEAR(s.maxWheelLoadLb, s.staticWheelLoadLb, 1e-6 * s.staticWheelLoadLb) << model;
        EXPECT_NEAR(s.rawMaxCenterPlateLoadLb, s.staticCenterPlateLoadLb, 1e-6 * s.staticCenterPlateLoadLb);
        EXPECT_EQ(s.rawMaxSideBearingLoadLb, 0.0);
        EXPECT_NEAR(s.minWheelLoadRatio, 1.0, 1e-6);
        EXPECT_EQ(s.maxWheelLiftIn, 0.0);
        EXPECT_EQ(s.regime, "light");
    }
}

TEST(ModelInvariants, MirroredInputGivesMirroredResponse) {
    for (const char* model : {"halfcar", "fullcar"}) {
        Scenario a = makeCase(model, 0.75, 16.5, model == std::string("halfcar") ? 10.0 : 5.0);
        Scenario b = a;
        b.track.mirror = true;
        const ScenarioRun ra = runScenario(a), rb = runScenario(b);
        const auto rollA = column(ra, "roll_deg"), rollB = column(rb, "roll_deg");
        const auto latA = column(ra, "car_body_lateral_in"), latB = column(rb, "car_body_lateral_in");
        const auto sbAL = column(ra, "side_bearing_F_L_lb"), sbBR = column(rb, "side_bearing_F_R_lb");
        const auto sbAR = column(ra, "side_bearing_F_R_lb");
        double peak = 0, worst = 0, peakSb = 0, worstSb = 0;
        for (size_t i = 0; i < rollA.size(); ++i) {
            peak = std::max(peak, std::abs(rollA[i]));
            worst = std::max(worst, std::abs(rollA[i] + rollB[i]));
            peakSb = std::max({peakSb, sbAL[i], sbAR[i]});
            worstSb = std::max(worstSb, std::abs(sbAL[i] - sbBR[i]));
        }
        EXPECT_GT(peak, 0.3) << model;
        EXPECT_LT(worst, 0.01 * peak) << model << ": roll is not mirrored";
        // Side-bearing impacts are short and stiff; integration error shifts them slightly.
        EXPECT_LT(worstSb, 0.05 * std::max(peakSb, 1.0)) << model << ": side-bearing forces are not mirrored";
        double peakLat = 0;
        for (double y : latA) peakLat = std::max(peakLat, std::abs(y));
        for (size_t i = 0; i < latA.size(); ++i) ASSERT_NEAR(latA[i], -latB[i], 0.01 * peakLat + 1e-6) << model;
    }
}

TEST(ModelInvariants, FullCarWithTruckSpacingEqualRailLengthMatchesHalfCar) {
    // 70-ton car: truck spacing 39 ft = rail length, both trucks entering together.
    struct Case { double amplitude, speed; const char* regime; };
    for (const Case c : {Case{0.6, 16.0, "light"}, Case{0.75, 22.0, "moderate"}}) {
        Scenario half = makeCase("halfcar", c.amplitude, c.speed, 15.0);
        half.entry = TrackEntry::Synchronized;
        Scenario full = half;
        full.model = "fullcar";
        const ScenarioRun h = runScenario(half), f = runScenario(full);
        EXPECT_EQ(h.summary.regime, c.regime);
        EXPECT_EQ(f.summary.regime, c.regime);
        EXPECT_NEAR(f.summary.maxRollDeg, h.summary.maxRollDeg, 0.05 * h.summary.maxRollDeg) << c.regime;
        EXPECT_NEAR(f.summary.steadyRollAmplitudeDeg, h.summary.steadyRollAmplitudeDeg,
                    0.05 * h.summary.steadyRollAmplitudeDeg)
            << c.regime;
    }
}

TEST(ModelInvariants, OneInchCrossLevelNear16MphReachesSideBearingsAndLiftsAWheel) {
    // Rocking is a resonance; its speed in our model may differ a little from the report's.
    int severe = 0;
    for (double speed : {15.0, 16.5, 18.0}) {
        const ScenarioRun r = runScenario(makeCase("fullcar", 1.0, speed, 15.0));
        if (r.summary.rawMaxSideBearingLoadLb > 0 && r.summary.maxWheelLiftIn > 0) ++severe;
        EXPECT_GT(r.summary.maxRollDeg, 1.0) << speed << " mph";
    }
    EXPECT_GE(severe, 1);
}

TEST(ModelInvariants, WithoutTrackInputEnergyOnlyDecays) {
    // Level track (no energy supplied): kick the car body into roll and sway and
    // check that kinetic + potential energy (gravity, springs, contacts, bristles)
    // never rises above its initial value, and that rocking dies out.
    for (const char* name : {"halfcar", "fullcar"}) {
        Scenario sc = makeCase(name, 0.0, 16.5, 1.0);
        const auto model = makeScenarioModel(sc);
        SimTK::State s = model->makeStaticState();
        const SimTK::MobilizedBody& body = model->getCarBody();
        if (std::string(name) == "halfcar") {
            body.setOneU(s, 0, 0.15);  // roll rate [rad/s]
            body.setOneU(s, 1, 0.10);  // lateral [m/s]
        } else {
            body.setUToFitAngularVelocity(s, SimTK::Vec3(0.15, 0, 0));
            body.setUToFitLinearVelocity(s, SimTK::Vec3(0, 0.10, 0));
        }
        const double e0 = model->calcMechanicalEnergy(s);
        SimTK::CPodesIntegrator integ(model->getSystem());
        integ.setAccuracy(1e-5);
        integ.initialize(s);
        double eMax = e0, eEnd = e0;
        for (int k = 1; k <= 300; ++k) {
            const double t = 0.01 * k;
            while (integ.getTime() < t) integ.stepTo(t);
            eEnd = model->calcMechanicalEnergy(integ.getState());
            eMax = std::max(eMax, eEnd);
        }
        const double kick = e0 - model->calcMechanicalEnergy(model->makeStaticState());
        ASSERT_GT(kick, 100.0) << name;
        EXPECT_LT(eMax - e0, 1e-3 * kick) << name << ": energy rose without input";
        EXPECT_LT(e0 - eEnd, kick * 1.001) << name;   // cannot lose more than it had above rest
        EXPECT_GT(e0 - eEnd, 0.2 * kick) << name;     // friction and contact damping dissipate
    }
}

TEST(ModelInvariants, ResponseConvergesAsContactStiffnessGrows) {
    auto maxRoll = [](double amplitude, double speed, double scale) {
        Scenario sc = makeCase("halfcar", amplitude, speed, 12.0);
        sc.car.contactStiffnessScale = scale;
        return runScenario(sc).summary.maxRollDeg;
    };
    // Moderate rocking: successive doublings change max roll less and less.
    const double r05 = maxRoll(0.75, 22, 0.5), r1 = maxRoll(0.75, 22, 1), r2 = maxRoll(0.75, 22, 2),
                 r4 = maxRoll(0.75, 22, 4);
    EXPECT_LT(std::abs(r4 - r2), std::abs(r1 - r05));
    EXPECT_NEAR(r4, r1, 0.03 * r4);
    // Severe rocking (center plate lifts, wheels lift): max roll within 5 %.
    const double s1 = maxRoll(0.75, 16.5, 1), s4 = maxRoll(0.75, 16.5, 4);
    EXPECT_NEAR(s4, s1, 0.05 * s4);
}
