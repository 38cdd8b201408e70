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

namespace {
// A smooth 3-D map with one fixed point and multipliers inside the unit circle:
// P(x) = A·x + 0.2·sin(x) + b.
Eigen::Matrix3d makeA(double scale) {
    Eigen::Matrix3d A;
    A << 0.5, 0.2, 0.0, -0.1, 0.3, 0.1, 0.05, 0.0, -0.4;
    return scale * A;
}
PeriodicShooting::Map makeSmoothMap(double scale) {
    return [A = makeA(scale)](const Eigen::VectorXd& x) {
        const Eigen::Vector3d b(1.0, -2.0, 0.5);
        return Eigen::VectorXd(A * x + 0.2 * x.array().sin().matrix() + b);
    };
}
}  // namespace

// A neighbouring orbit's monodromy (a map 5 % away) starts a chord Newton: it finds the
// fixed point fresh Newton finds, with fewer maps, and the multipliers are the orbit's own
// (a fresh M at the orbit), not the reused ones.
TEST(PeriodicShooting, ChordNewtonFromANeighboursMonodromyFindsTheSameOrbitWithFewerMaps) {
    ShootingSettings s;
    s.maxIterations = 20;
    s.tolerance = 1e-2;
    const Eigen::VectorXd h = Eigen::VectorXd::Constant(3, 1e-4);
    const Eigen::VectorXd guess = Eigen::VectorXd::Zero(3);
    const PeriodicShooting neighbour(makeSmoothMap(1.05), h, s);
    const ShootingResult n = neighbour.solve(guess);
    ASSERT_TRUE(n.converged) << n.failure;

    const PeriodicShooting shooting(makeSmoothMap(1.0), h, s);
    const ShootingResult fresh = shooting.solve(guess);
    const ShootingResult chord = shooting.solve(guess, n.monodromy);
    ASSERT_TRUE(fresh.converged) << fresh.failure;
    ASSERT_TRUE(chord.converged) << chord.failure;
    EXPECT_EQ(fresh.chordSteps, 0);
    EXPECT_GT(chord.chordSteps, 0);
    EXPECT_LT(chord.mapEvaluations, fresh.mapEvaluations);
    // Both within the tolerance of the fixed point: |F| < 1e-2·h = 1e-6, |x − x*| ≤ ‖(I − M)⁻¹‖·|F| ≈ 2e-6.
    EXPECT_LT((chord.x - fresh.x).cwiseAbs().maxCoeff(), 1e-5);
    // The orbit's own M, not the neighbour's: equal to fresh Newton's to finite-difference noise.
    EXPECT_LT((chord.monodromy - fresh.monodromy).cwiseAbs().maxCoeff(), 1e-4);
    EXPECT_GT((n.monodromy - fresh.monodromy).cwiseAbs().maxCoeff(), 1e-2);
}

// A monodromy that points the wrong way gives a chord step that does not lower the
// mismatch: a fresh M replaces it and Newton converges as from scratch.
TEST(PeriodicShooting, ChordNewtonFallsBackToAFreshMonodromyWhenTheReusedOneDoesNotContract) {
    ShootingSettings s;
    s.maxIterations = 20;
    s.tolerance = 1e-2;
    const Eigen::VectorXd h = Eigen::VectorXd::Constant(3, 1e-4);
    const PeriodicShooting shooting(makeSmoothMap(1.0), h, s);
    const ShootingResult fresh = shooting.solve(Eigen::VectorXd::Zero(3));
    const Eigen::MatrixXd wrong = 5.0 * Eigen::MatrixXd::Identity(3, 3);  // M − I = 4·I: a step against F
    const ShootingResult chord = shooting.solve(Eigen::VectorXd::Zero(3), wrong);
    ASSERT_TRUE(chord.converged) << chord.failure;
    EXPECT_EQ(chord.chordSteps, 0);
    EXPECT_LT((chord.x - fresh.x).cwiseAbs().maxCoeff(), 1e-7);
    EXPECT_THROW(shooting.solve(Eigen::VectorXd::Zero(3), Eigen::MatrixXd::Identity(2, 2)), std::invalid_argument);
}
