// The wheel–rail laws on their own (contacts/WheelRailLaws.h): creep slope and
// saturation, the flange's geometry and force split, and Nadal's limit.
#include "contacts/WheelRailLaws.h"

#include <cmath>
#include <gtest/gtest.h>
#include <numbers>

using namespace rockroll;

namespace {
WheelRailSettings makeSettings() {
    WheelRailSettings w;
    w.lateral = LateralWheelRail::CreepAndFlange;
    w.friction = 0.4;
    w.creepCoefficient = 8e6;
    w.flangeAngle = 70 * std::numbers::pi / 180;
    w.flangewayClearance = 0.01;
    w.flangeHeight = 0.025;
    return w;
}
}  // namespace

TEST(WheelRailLaws, SaturationFractionHasSlopeOneAtZeroAndReachesOneWithZeroSlopeAtThree) {
    const double h = 1e-6;
    EXPECT_NEAR(calcSaturatedCreepFraction(h) / h, 1.0, 1e-6);
    EXPECT_DOUBLE_EQ(calcSaturatedCreepFraction(3.0), 1.0);
    EXPECT_DOUBLE_EQ(calcSaturatedCreepFraction(10.0), 1.0);
    EXPECT_NEAR((calcSaturatedCreepFraction(3.0) - calcSaturatedCreepFraction(3.0 - h)) / h, 0.0, 1e-5);
    // Monotonic between.
    double last = 0;
    for (double b = 0.1; b < 3; b += 0.1) {
        EXPECT_GT(calcSaturatedCreepFraction(b), last) << b;
        last = calcSaturatedCreepFraction(b);
    }
}

TEST(WheelRailLaws, CreepForceIsKalkerLinearForSmallCreepageAndSaturatesAtMuN) {
    const WheelRailSettings w = makeSettings();
    const double N = 1.5e5, V = 7.0;
    // Small creepage: F = −n·f₂₂·v/V (to g(β)/β = 1 − β/3 + …, β ≈ 4e-5 here), one wheel
    // and two lumped wheels.
    const double v = 1e-6;
    for (double n : {1.0, 2.0})
        EXPECT_NEAR(calcLateralCreepForce(v, V, N, n, w), -n * w.creepCoefficient * v / V,
                    2e-5 * n * w.creepCoefficient * v / V);
    // Large creepage: exactly μN, opposing the slip either way.
    EXPECT_DOUBLE_EQ(calcLateralCreepForce(0.5, V, N, 1, w), -w.friction * N);
    EXPECT_DOUBLE_EQ(calcLateralCreepForce(-0.5, V, N, 1, w), w.friction * N);
    // β = 1.5: F = μN·g(1.5).
    const double v15 = 1.5 * w.friction * N * V / w.creepCoefficient;
    EXPECT_NEAR(calcLateralCreepForce(v15, V, N, 1, w), -w.friction * N * (1.5 - 0.75 + 0.125), 1e-9 * N);
    // No load, no force; below kMinCreepSpeed the creepage uses it.
    EXPECT_EQ(calcLateralCreepForce(0.1, V, 0, 1, w), 0.0);
    EXPECT_DOUBLE_EQ(calcLateralCreepForce(v, 0.0, N, 1, w), calcLateralCreepForce(v, kMinCreepSpeed, N, 1, w));
}

TEST(WheelRailLaws, FlangeTouchesAtTheClearanceAndSplitsItsForceAtTheFlangeAngle) {
    WheelRailSettings w = makeSettings();
    w.friction = 0;  // normal force alone
    const UnilateralContactLaw normal{1e9, 0};
    const double V = 7.0;
    EXPECT_EQ(calcFlangeForces(0.009, 0, 0, 0, V, 1, normal, w).normal, 0.0);
    const double x = 1e-4;
    const FlangeForces f = calcFlangeForces(w.flangewayClearance + x, 0, 0, 0, V, 1, normal, w);
    const double sg = std::sin(w.flangeAngle), cg = std::cos(w.flangeAngle);
    EXPECT_NEAR(f.penetration, x * sg, 1e-15);
    EXPECT_NEAR(f.normal, 1e9 * x * sg, 1e-6);
    EXPECT_NEAR(f.towardRail, -f.normal * sg, 1e-6);
    EXPECT_NEAR(f.vertical, f.normal * cg, 1e-6);
    EXPECT_NEAR(-f.towardRail / f.vertical, std::tan(w.flangeAngle), 1e-12);
    EXPECT_NEAR(calcFlangeEnergy(w.flangewayClearance + x, 0, normal, w), 0.5 * 1e9 * x * x * sg * sg, 1e-9);
    EXPECT_EQ(f.energy, calcFlangeEnergy(w.flangewayClearance + x, 0, normal, w));
    // Lifting the wheel moves the face away: the penetration falls by h·cos γ.
    const double h = 1e-5;
    EXPECT_NEAR(calcFlangeForces(w.flangewayClearance + x, 0, h, 0, V, 1, normal, w).penetration, x * sg - h * cg,
                1e-15);
    // Above the flange height there is no flange.
    EXPECT_EQ(calcFlangeForces(w.flangewayClearance + 0.05, 0, w.flangeHeight, 0, V, 1, normal, w).normal, 0.0);
}

TEST(WheelRailLaws, NadalLimitIsItsClosedFormAndTheFlangeSlidingDownAtSaturationReachesIt) {
    const double g75 = 75 * std::numbers::pi / 180;
    EXPECT_NEAR(calcNadalLimit(g75, 0.5), (std::tan(g75) - 0.5) / (1 + 0.5 * std::tan(g75)), 1e-15);
    EXPECT_NEAR(calcNadalLimit(g75, 0.5), 1.1277, 1e-4);  // AAR-1B at μ = 0.5
    EXPECT_NEAR(calcNadalLimit(g75, 0.0), std::tan(g75), 1e-12);
    // A flange sliding down its rail's face with saturated friction: the rail's lateral
    // over vertical force on the wheel is Nadal's limit.
    const WheelRailSettings w = makeSettings();
    const UnilateralContactLaw normal{1e9, 0};
    const FlangeForces f = calcFlangeForces(w.flangewayClearance + 1e-4, 0, 0, -1.0, 7.0, 1, normal, w);
    EXPECT_DOUBLE_EQ(f.friction, w.friction * f.normal);
    EXPECT_NEAR(-f.towardRail / f.vertical, calcNadalLimit(w.flangeAngle, w.friction), 1e-12);
}

TEST(WheelRailLaws, FlangeDissipationIsItsHuntCrossleyPartPlusFrictionAndNeverNegative) {
    const WheelRailSettings w = makeSettings();
    const UnilateralContactLaw normal{1e9, 5};
    for (double e : {0.0101, 0.0102})
        for (double de : {-0.01, 0.0, 0.02})
            for (double dh : {-0.03, 0.0, 0.01}) {
                const FlangeForces f = calcFlangeForces(e, de, 0.0, dh, 7.0, 2, normal, w);
                const double sg = std::sin(w.flangeAngle), cg = std::cos(w.flangeAngle);
                const double rate = de * sg - dh * cg, slide = de * cg + dh * sg;
                EXPECT_GE(f.dissipatedPower, 0.0);
                // Power balance: the force's work on the wheel is minus what the contact stores and dissipates.
                const double storedRate = normal.stiffness * f.penetration * rate;
                EXPECT_NEAR(f.towardRail * de + f.vertical * dh, -(storedRate + f.dissipatedPower),
                            1e-9 * (1 + std::abs(storedRate)))
                    << e << " " << de << " " << dh << " " << slide;
            }
}
