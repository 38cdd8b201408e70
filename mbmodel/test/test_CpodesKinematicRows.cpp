// CPodes' Newton matrix factored with its kinematic rows eliminated (Simbody patch
// third_party/simbody/patches/0006-cpodes-eliminate-kinematic-rows-before-lu.patch,
// bench/README.md "Built: the Newton matrix factored with the q rows eliminated").
//
// The Simbody models integrate y = [q u z] with CPodes, and CPodesIntegrator declares the
// q rows kinematic, so every Newton correction goes through the Schur complement of
// I - gamma*J on (u, z). These tests integrate a linear system with that structure,
// y' = J y with q' = u + P q and u' = -K q - D u, whose exact solution is exp(J t) y0,
// once with one dense LU and once with the q rows eliminated, and check that both reach
// the exact solution and that the Newton iteration converges as fast with either: a wrong
// elimination still converges to the implicit step's solution when it converges at all,
// but needs more Newton iterations to get there.
#include <gtest/gtest.h>

#include <Simbody.h>
#include <simmath/internal/SimTKcpodes.h>

#include <Eigen/Dense>
#include <unsupported/Eigen/MatrixFunctions>

namespace {

constexpr int kNq = 3;
constexpr int kN = 2 * kNq;
// A copy: gtest's macros take their arguments by reference, and CPodes declares its
// status constants in the class without a definition to bind to.
constexpr int kSuccess = SimTK::CPodes::Success;

// J of y' = J y. P has an entry below and one above the diagonal, so LU(A) of
// A = I - gamma*P has off-diagonal entries in both its L and U factors; K spans four
// decades, so the problem is stiff for an explicit method.
Eigen::Matrix<double, kN, kN> getJacobian() {
  Eigen::Matrix<double, kNq, kNq> P = Eigen::Matrix<double, kNq, kNq>::Zero();
  P(0, 1) = 0.3;
  P(2, 0) = -0.2;
  Eigen::Matrix<double, kNq, kNq> K;
  K << 1.0e4, -1.0e3, 0.0,
       -1.0e3, 4.0e2, -20.0,
       0.0, -20.0, 3.0;
  const Eigen::Matrix<double, kNq, kNq> D = 0.02 * K + 0.5 * Eigen::Matrix<double, kNq, kNq>::Identity();
  Eigen::Matrix<double, kN, kN> J;
  J << P, Eigen::Matrix<double, kNq, kNq>::Identity(), -K, -D;
  return J;
}

class LinearKinematicSystem : public SimTK::CPodesSystem {
public:
  int explicitODE(SimTK::Real, const SimTK::Vector& y, SimTK::Vector& ydot) const override {
    for (int i = 0; i < kN; ++i) {
      double sum = 0.0;
      for (int j = 0; j < kN; ++j) sum += J_(i, j) * y[j];
      ydot[i] = sum;
    }
    return kSuccess;
  }

private:
  Eigen::Matrix<double, kN, kN> J_ = getJacobian();
};

struct Integration {
  Eigen::Matrix<double, kN, 1> y;
  int steps = 0;
  int newtonIterations = 0;
  int newtonFailures = 0;
};

Eigen::Matrix<double, kN, 1> getInitialState() {
  Eigen::Matrix<double, kN, 1> y0;
  y0 << 0.01, -0.02, 0.05, 0.0, 0.3, -0.1;
  return y0;
}

Integration integrate(bool eliminateKinematicRows, double tEnd) {
  LinearKinematicSystem system;
  SimTK::CPodes cpodes(SimTK::CPodes::ExplicitODE, SimTK::CPodes::BDF, SimTK::CPodes::Newton);
  SimTK::Vector y(kN), ydot(kN);
  const Eigen::Matrix<double, kN, 1> y0 = getInitialState();
  for (int i = 0; i < kN; ++i) y[i] = y0(i);
  system.explicitODE(0.0, y, ydot);
  double absTol = 1e-9;
  EXPECT_EQ(cpodes.init(system, 0.0, y, ydot, SimTK::CPodes::ScalarScalar, 1e-7, &absTol),
            kSuccess);
  EXPECT_EQ(cpodes.lapackDense(kN), kSuccess);
  cpodes.setNonlinConvCoef(0.01);  // as Simbody's CPodesIntegrator sets it
  if (eliminateKinematicRows) {
    EXPECT_EQ(cpodes.lapackDenseKinematicRows(kNq), kSuccess);
  }
  cpodes.setMaxNumSteps(1000000);
  SimTK::Real tReturned = 0.0;
  EXPECT_EQ(cpodes.step(tEnd, &tReturned, y, ydot, SimTK::CPodes::Normal), kSuccess);
  EXPECT_EQ(tReturned, tEnd);
  Integration out;
  for (int i = 0; i < kN; ++i) out.y(i) = y[i];
  cpodes.getNumSteps(&out.steps);
  cpodes.getNumNonlinSolvIters(&out.newtonIterations);
  cpodes.getNumNonlinSolvConvFails(&out.newtonFailures);
  return out;
}

}  // namespace

TEST(CpodesKinematicRows, BothFactorizationsReachTheExactSolution) {
  const double tEnd = 2.0;
  const Eigen::Matrix<double, kN, 1> exact = (getJacobian() * tEnd).exp() * getInitialState();
  // A decaying solution: every eigenvalue of J in the left half plane.
  EXPECT_LT(getJacobian().eigenvalues().real().maxCoeff(), 0.0);
  const Integration dense = integrate(false, tEnd);
  const Integration eliminated = integrate(true, tEnd);
  const double scale = getInitialState().cwiseAbs().maxCoeff();
  for (int i = 0; i < kN; ++i) {
    SCOPED_TRACE(i);
    EXPECT_NEAR(dense.y(i), exact(i), 1e-5 * scale);
    EXPECT_NEAR(eliminated.y(i), exact(i), 1e-5 * scale);
  }
  EXPECT_GT(dense.steps, 100);  // many implicit steps: the factorization is exercised
}

TEST(CpodesKinematicRows, NewtonConvergesAsFastAsWithOneLu) {
  const Integration dense = integrate(false, 2.0);
  const Integration eliminated = integrate(true, 2.0);
  // The two Newton matrices are the same up to rounding, so the step sequences agree to
  // within a few steps and each step needs the same number of iterations.
  EXPECT_NEAR(eliminated.steps, dense.steps, 0.02 * dense.steps + 2);
  EXPECT_NEAR(eliminated.newtonIterations, dense.newtonIterations, 0.02 * dense.newtonIterations + 2);
  EXPECT_LE(eliminated.newtonFailures, dense.newtonFailures + 1);
  EXPECT_LT(eliminated.newtonIterations, 3 * eliminated.steps);
}

TEST(CpodesKinematicRows, RefusesAKinematicBlockAsLargeAsTheSystem) {
  LinearKinematicSystem system;
  SimTK::CPodes cpodes(SimTK::CPodes::ExplicitODE, SimTK::CPodes::BDF, SimTK::CPodes::Newton);
  SimTK::Vector y(kN, 0.0), ydot(kN, 0.0);
  double absTol = 1e-9;
  ASSERT_EQ(cpodes.init(system, 0.0, y, ydot, SimTK::CPodes::ScalarScalar, 1e-7, &absTol),
            kSuccess);
  ASSERT_EQ(cpodes.lapackDense(kN), kSuccess);
  EXPECT_NE(cpodes.lapackDenseKinematicRows(kN), kSuccess);
  EXPECT_NE(cpodes.lapackDenseKinematicRows(-1), kSuccess);
  EXPECT_EQ(cpodes.lapackDenseKinematicRows(0), kSuccess);
}
