// PeriodicShooting on maps whose fixed points are known: the Newton step's
// backtracking and the stall rule (mbmodel/PeriodicShooting.h).
#include "mbmodel/PeriodicShooting.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace rockroll;

namespace {
Eigen::VectorXd one(double v) { return Eigen::VectorXd::Constant(1, v); }
}  // namespace

// F(x) = P(x) − x = atan(x): full Newton steps from x = 3 overshoot and diverge
// (|x| grows every step); halving the step while the mismatch does not fall converges.
TEST(PeriodicShooting, BacktrackingConvergesWhereFullNewtonStepsDiverge) {
    const PeriodicShooting::Map map = [](const Eigen::VectorXd& x) { return Eigen::VectorXd(x.array() + x.array().atan()); };
    ShootingSettings s;
    s.maxIterations = 30;
    s.tolerance = 1;
    s.maxStep = 1e9;  // no cap: the backtracking alone keeps the steps in check
    const ShootingResult r = PeriodicShooting(map, one(1e-6), s).solve(one(3.0));
    ASSERT_TRUE(r.converged) << r.failure;
    EXPECT_LT(std::abs(r.x[0]), 1e-6);
    EXPECT_NEAR(r.multipliers[0].real(), 2.0, 1e-4);  // P'(0) = 1 + 1

    s.lineSearchHalvings = 0;  // full steps only: the mismatch grows past 10× and the search ends
    const ShootingResult full = PeriodicShooting(map, one(1e-6), s).solve(one(3.0));
    EXPECT_FALSE(full.converged);
}

// A map with no fixed point (P(x) = x + 1): no step lowers the mismatch, and the search
// stops after two such steps instead of spending every Newton step.
TEST(PeriodicShooting, StopsWhenTwoStepsRunningLowerNothing) {
    const PeriodicShooting::Map map = [](const Eigen::VectorXd& x) { return Eigen::VectorXd(x.array() + 1.0); };
    ShootingSettings s;
    s.maxIterations = 20;
    const ShootingResult r = PeriodicShooting(map, one(1e-3), s).solve(one(0.0));
    EXPECT_FALSE(r.converged);
    EXPECT_NE(r.failure.find("stalled"), std::string::npos) << r.failure;
    EXPECT_LE(r.iterations, 2);
}
