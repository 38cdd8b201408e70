// Off-centre lading (car parameters cg_longitudinal_offset and cg_lateral_offset; the full
// car): the closed form of mbmodel/OffCentreStatics.h reduces to the lever rule in the rigid
// limit, and the full car's solved static state is that closed form; an offset breaks the
// mirror on purpose; a car at rest with an offset stays at rest.
#include "mbmodel/OffCentreStatics.h"
#include "mbmodel/RockingModel.h"
#include "mbmodel/CarSide.h"
#include "scenarios/ModelRegistry.h"
#include "scenarios/ScenarioLoader.h"
#include "scenarios/ScenarioRun.h"
#include "tests/TestCases.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fmt/format.h>

using namespace rockroll;

namespace {
constexpr double in = units::inch;

std::unique_ptr<RockingModel> makeFullCar(const CarParameters& car) {
    TrackSpec track;
    track.amplitude = 0.75 * in;
    return ModelRegistry::get().getModel("fullcar").makeMultibody(
        car, TrackInput(track),
        ModelOptions{16.5 * units::mph, TrackEntry::Lead, TrackMotion{}, AttributionSwitches{}, WheelRailSettings{},
                     CarBodySettings{}});
}

CarParameters makeOffCentreCar(const char* name, double exIn, double eyIn) {
    CarParameters car = makeCarParameters(name);
    car.cgLongitudinalOffset = exIn * in;
    car.cgLateralOffset = eyIn * in;
    return car;
}
}  // namespace

// The rigid limit is the lever rule. Trucks 10⁶ times stiffer (springs and contacts): each
// truck's wheels share its moment Q·e_y over the gauge. With a pivot plate as well (k_θ → 0,
// e_y = 0, as a pivot cannot hold a lateral offset): the trucks share the body's weight as
// W·(½ ± e_x/s).
TEST(OffCentreLading, TheClosedFormIsTheLeverRuleInTheRigidLimit) {
    for (const bool pivot : {false, true}) {
        SCOPED_TRACE(pivot ? "pivot plate, e_x = 24 in" : "the car's plate, e_y = 2 in");
        CarParameters car = makeOffCentreCar("70ton-loaded", pivot ? 24 : 0, pivot ? 0 : 2);
        if (pivot) car.centerPlateDiameter = 1e-3 * in;
        car.springVerticalRate *= 1e6;
        car.contactStiffnessScale = 1e6;
        const OffCentreStatics cf = calcOffCentreStatics(car);
        const double W = car.getCarBodyWeight(), s = car.truckSpacing;
        const double ex = car.cgLongitudinalOffset, ey = car.cgLateralOffset;
        const double Wu = car.wheelsetWeight + car.sideFrameWeight;
        for (int t = 0; t < 2; ++t) {
            const double Q = W * (0.5 + (t == 0 ? ex : -ex) / s);
            EXPECT_NEAR(cf.trucks[t].centerPlate, Q, 1e-5 * std::abs(Q - W / 2)) << t;
            // Each wheelset's wheels: (Q + W_B)/4 + W_u/2 each, and ±Q·e_y/g between a wheelset's two.
            const double base = (Q + car.bolsterWeight) / 4 + Wu / 2, d = Q * ey / car.gauge / 2;
            EXPECT_NEAR(cf.trucks[t].wheel[kLeft], base + d, 1e-5 * (std::abs(base - W / 4) + d)) << t;
            EXPECT_NEAR(cf.trucks[t].wheel[kRight], base - d, 1e-5 * (std::abs(base - W / 4) + d)) << t;
        }
        EXPECT_TRUE(cf.getIsValid());
    }
}

// The full car's static state, solved by Newton's method from the trucks' statics, against
// the closed form: every center plate and wheel within 0.1 % of the load the offset moves
// onto or off it (the closed form is linear in the angles, of order 1e-3 rad), and the
// body's and bolsters' roll and the pitch within 0.1 %. The cases: longitudinal and lateral offsets alone and together on the
// car files' plate (its rim carries pitch moment: 18 % less load transfer than the lever
// rule at 2 in), and 24 in on a 0.5 in plate (close to a pivot).
TEST(OffCentreLading, TheSolvedStaticStateIsTheClosedForm) {
    struct Case {
        const char* car;
        double ex, ey, plateDiameter;  // [in]; 0: the car file's plate
    };
    for (const Case& c : {Case{"70ton-loaded", 2, 0, 0}, Case{"70ton-loaded", 0, 2, 0}, Case{"70ton-loaded", -2, 1, 0},
                          Case{"70ton-loaded", 24, 0, 0.5}, Case{"100ton-loaded", 0, 1.5, 0},
                          Case{"70ton-empty", 2, -2, 0}}) {
        SCOPED_TRACE(fmt::format("{} e_x {} in, e_y {} in, plate {} in", c.car, c.ex, c.ey, c.plateDiameter));
        CarParameters car = makeOffCentreCar(c.car, c.ex, c.ey);
        if (c.plateDiameter > 0) car.centerPlateDiameter = c.plateDiameter * in;
        const OffCentreStatics cf = calcOffCentreStatics(car);
        ASSERT_TRUE(cf.getIsValid());
        const auto model = makeFullCar(car);
        const SimTK::State s = model->makeStaticState();
        model->getSystem().realize(s, SimTK::Stage::Acceleration);
        EXPECT_LT(s.getUDot().normInf(), 1e-8);
        const CarSample sample = model->calcSample(s);
        const double static0 = car.getCarBodyWeight() / 2;
        for (int t = 0; t < 2; ++t) {
            const Truck& truck = model->getTruck(t);
            const double Q = cf.trucks[t].centerPlate;
            EXPECT_NEAR(sample.trucks[t].centerPlate, Q, 1e-3 * std::abs(Q - static0) + 1e-9 * Q) << t;
            const double centred = (Q + car.bolsterWeight) / 4 + (car.wheelsetWeight + car.sideFrameWeight) / 2;
            for (int w = 0; w < truck.getNumWheelsets(); ++w)
                for (int side : {kLeft, kRight}) {
                    const double closed = cf.trucks[t].wheel[side];
                    // What the offset moves: the truck's share, then the side's.
                    const double moved = std::abs(closed - static0 / 2) + std::abs(closed - centred);
                    EXPECT_NEAR(model->getStaticWheelLoad(t, w, side), closed, 1e-3 * moved) << t << w << side;
                }
            EXPECT_NEAR(sample.trucks[t].bolsterRoll, cf.trucks[t].bolsterRoll,
                        1e-3 * std::abs(cf.trucks[t].bolsterRoll) + 1e-12);
        }
        EXPECT_NEAR(sample.angles[0], (cf.trucks[0].carBodyRoll + cf.trucks[1].carBodyRoll) / 2,
                    1e-3 * std::abs(cf.trucks[0].carBodyRoll) + 1e-12);
        EXPECT_NEAR(sample.angles[1], cf.pitch, 1e-3 * std::abs(cf.pitch) + 1e-12);
    }
}

// Moving the load from one side to the other mirrors every static wheel load, left for right.
TEST(OffCentreLading, ALateralOffsetBreaksTheMirrorOnPurpose) {
    const auto left = makeFullCar(makeOffCentreCar("70ton-loaded", 6, 2));
    const auto right = makeFullCar(makeOffCentreCar("70ton-loaded", 6, -2));
    for (int t = 0; t < 2; ++t)
        for (int w = 0; w < 2; ++w) {
            const double l = left->getStaticWheelLoad(t, w, kLeft), r = left->getStaticWheelLoad(t, w, kRight);
            EXPECT_GT(l - r, 0.1 * r);
            EXPECT_NEAR(right->getStaticWheelLoad(t, w, kRight), l, 1e-9 * l);
            EXPECT_NEAR(right->getStaticWheelLoad(t, w, kLeft), r, 1e-9 * r);
        }
}

// On level rails the off-centre car stays where it was placed: no roll, pitch or wheel load
// moves in 2 s, and every wheel's unloading is measured from its own static load.
TEST(OffCentreLading, AnOffCentreCarAtRestStaysAtRest) {
    Scenario sc = test_cases::makeCase("fullcar", 0.0, 16.5, 2.0);
    sc.car.cgLongitudinalOffset = 12 * in;
    sc.car.cgLateralOffset = 2 * in;
    const RunResult r = runScenario(sc).result;
    for (const char* name : {"roll_deg", "pitch_deg", "wheel_F1_L_lb", "wheel_R2_R_lb", "center_plate_F_lb"}) {
        const std::vector<double> x = test_cases::getColumn(r, name);
        const auto [lo, hi] = std::minmax_element(x.begin(), x.end());
        EXPECT_LT(*hi - *lo, 1e-6 * std::max(std::abs(*hi), 1e-3)) << name;
    }
    EXPECT_GT(std::abs(test_cases::getColumn(r, "roll_deg").front()), 0.1);
    for (const char* name : {"wheel_unloading_F1_L_ratio", "wheel_unloading_R2_R_ratio"})
        EXPECT_LT(std::abs(test_cases::getColumn(r, name).back()), 1e-6) << name;
}

// Moving on: the off-centre car balances its energy, and the load moved to the other side on
// the mirrored track mirrors the response (roll negated, each wheel's load its mirror wheel's).
TEST(OffCentreLading, TheOffCentreCarBalancesItsEnergyAndMirrors) {
    Scenario a = test_cases::makeCase("fullcar", 0.5, 16.5, 6.0);
    a.car.cgLongitudinalOffset = 12 * in;
    a.car.cgLateralOffset = 2 * in;
    a.run.integrator.accuracy = 1e-6;
    Scenario b = a;
    b.car.cgLateralOffset = -2 * in;
    b.track.mirror = true;
    const ScenarioRun ra = runScenario(a), rb = runScenario(b);
    EXPECT_LE(ra.summary.energyBalanceError, 0.01);
    EXPECT_LE(rb.summary.energyBalanceError, 0.01);
    auto worstMismatch = [&](const std::string& x, const std::string& y, double sign) {
        const auto xa = test_cases::getColumn(ra.result, x), yb = test_cases::getColumn(rb.result, y);
        double peak = 0, worst = 0;
        for (size_t i = 0; i < xa.size(); ++i) {
            peak = std::max(peak, std::abs(xa[i]));
            worst = std::max(worst, std::abs(xa[i] - sign * yb[i]));
        }
        return worst / peak;
    };
    EXPECT_GT(ra.summary.maxRollDeg, 0.5);
    EXPECT_LT(worstMismatch("roll_deg", "roll_deg", -1), 1e-3);
    EXPECT_LT(worstMismatch("wheel_F1_L_lb", "wheel_F1_R_lb", 1), 1e-3);
    EXPECT_LT(worstMismatch("wheel_R2_R_lb", "wheel_R2_L_lb", 1), 1e-3);
    std::printf("off-centre car, e = (12, ±2) in, 0.5 in, 16.5 mph: max roll %.3f deg, energy error %.2e, mirror %.1e\n",
                ra.summary.maxRollDeg, ra.summary.energyBalanceError, worstMismatch("roll_deg", "roll_deg", -1));
}
