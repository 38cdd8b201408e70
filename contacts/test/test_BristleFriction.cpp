// The elasto-plastic friction law: stick without creep, slip at the limit.
#include "contacts/BristleFriction.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace rockroll;

namespace {
const BristleFrictionLaw kLaw{4000.0, 4e6, 1.4e4};  // F_c, k_b, c_b (ζ ≈ 0.5 on 50 kg)

/// A mass m on a friction contact, pushed by a constant force; integrates
/// x, v and the bristle deflection w with small explicit steps.
struct Block {
    double x = 0, v = 0, w = 0;
    void run(double push, double m, double seconds) {
        const double dt = 1e-5;
        for (int i = 0; i < int(seconds / dt); ++i) {
            const BristleFrictionState f = calcBristleFriction(w, v, kLaw);
            v += dt * (push + f.force) / m;
            x += dt * v;
            w += dt * f.deflectionRate;
        }
    }
};
}  // namespace

TEST(BristleFriction, StickIsASpringWithoutSlip) {
    const BristleFrictionState s = calcBristleFriction(1e-4, 0.01, kLaw);  // 10 % of the limit
    EXPECT_DOUBLE_EQ(s.deflectionRate, 0.01);
    EXPECT_NEAR(s.force, -(4e6 * 1e-4 + kLaw.damping * 0.01), 1e-9);
    EXPECT_FALSE(s.slipping);
}

TEST(BristleFriction, SlipHoldsTheCoulombLimit) {
    const double wMax = 4000.0 / 4e6;
    const BristleFrictionState s = calcBristleFriction(wMax, 0.3, kLaw);
    EXPECT_DOUBLE_EQ(s.deflectionRate, 0.0);
    EXPECT_DOUBLE_EQ(s.force, -4000.0);
    EXPECT_TRUE(s.slipping);
    const BristleFrictionState r = calcBristleFriction(-wMax, -0.3, kLaw);
    EXPECT_DOUBLE_EQ(r.force, 4000.0);
}

TEST(BristleFriction, ReversalSticksAgain) {
    const double wMax = 4000.0 / 4e6;
    const BristleFrictionState s = calcBristleFriction(wMax, -0.3, kLaw);
    EXPECT_DOUBLE_EQ(s.deflectionRate, -0.3);
    EXPECT_FALSE(s.slipping);
}

TEST(BristleFriction, SteadyForceBelowLimitDoesNotCreep) {
    Block b;
    b.run(0.6 * 4000, 50, 0.5);  // settle (the step overshoots to 1.2 × push, still sticking)
    const double x1 = b.x;
    b.run(0.6 * 4000, 50, 2.0);  // hold
    EXPECT_NEAR(b.x, x1, 1e-9) << "creep under a steady force below the limit";
    EXPECT_NEAR(b.x, 0.6 * 4000 / 4e6, 1e-7);  // bristle deflection only: it never slipped
}

TEST(BristleFriction, ForceAboveLimitSlipsWithCoulombDrag) {
    Block b;
    b.run(1.2 * 4000, 50, 0.5);
    const double v1 = b.v;
    b.run(1.2 * 4000, 50, 1.0);
    const double accel = (b.v - v1) / 1.0;
    EXPECT_NEAR(accel, 0.2 * 4000 / 50, 0.2);  // (F − F_c)/m = 16 m/s²
}

TEST(BristleFriction, NoNormalLoadCarriesNothing) {
    BristleFrictionLaw law = kLaw;
    law.limit = 0;
    const BristleFrictionState s = calcBristleFriction(1e-4, 0.2, law);
    EXPECT_EQ(s.force, 0.0);
    EXPECT_LT(s.deflectionRate, 0.0);  // relaxes
}
