// Periodic orbits by shooting (scenarios/PeriodicOrbit.h) on the eom half car, the
// fastest model: 70-ton loaded, 0.25 in, 12 mph, a light-rocking orbit.
#include "scenarios/PeriodicOrbit.h"
#include "scenarios/OrbitContinuation.h"

#include "mbmodel/Units.h"
#include "scenarios/ModelRegistry.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace rockroll;

namespace {
Scenario makeLightScenario() {
    Scenario sc = loadScenarioFile(std::string(ROCKROLL_SOURCE_DIR) + "/scenarios/70ton-loaded.toml");
    sc.model = model_names::kEom;
    sc.track.amplitude = 0.25 * units::inch;
    sc.speed = 12 * units::mph;
    sc.run.integrator.accuracy = 1e-7;
    return sc;
}

/// The end of a 20 s run from rest (the guess) and the orbit shot from it, once for the suite.
struct Fixture {
    Scenario sc = makeLightScenario();
    ScenarioRun start;
    std::unique_ptr<PeriodicOrbitSolver> solver;
    PeriodicOrbit orbit;
    Fixture() {
        Scenario s = sc;
        s.run.duration = 20;
        start = runScenario(s);
        solver = std::make_unique<PeriodicOrbitSolver>(sc, start.restart.distance);
        orbit = solver->solve(12, start.restart.y);
    }
};
const Fixture& getFixture() {
    static const Fixture f;
    return f;
}
}  // namespace

TEST(PeriodicOrbit, ShootingConvergesAndTheMapReturnsTheState) {
    const Fixture& f = getFixture();
    ASSERT_TRUE(f.orbit.converged) << f.orbit.failure;
    EXPECT_EQ(f.orbit.period, 1);
    // One more period from the orbit: back within the tolerance (5 steps: 50 µm, 0.5 mm/s, 5 µm bristles).
    const std::vector<double> back = f.solver->runPeriods(12, f.orbit.y, 1).restart.y;
    const Eigen::VectorXd d = f.solver->toShooting(back) - f.solver->toShooting(f.orbit.y);
    for (Eigen::Index i = 0; i < d.size(); ++i) {
        const double scale = f.solver->getSteps()[i] == 1e-7 ? 1e-6 : f.solver->getSteps()[i];
        EXPECT_LT(std::abs(d[i]) / scale, 5) << "coordinate " << i;
    }
}

TEST(PeriodicOrbit, MatchesALongRunsSteadyAmplitude) {
    const Fixture& f = getFixture();
    ASSERT_TRUE(f.orbit.converged);
    // The 20 s run's last 3 periods against the orbit: within 2 % (the run is not fully settled).
    EXPECT_NEAR(f.orbit.rollAmplitudeDeg, f.start.summary.steadyRollAmplitudeDeg,
                0.02 * f.start.summary.steadyRollAmplitudeDeg);
    EXPECT_GT(f.orbit.rollAmplitudeDeg, 0.05);
}

TEST(PeriodicOrbit, LightRockingOrbitIsStable) {
    const Fixture& f = getFixture();
    ASSERT_TRUE(f.orbit.converged);
    // Inside the unit circle up to the neutral multiplier of a sticking wedge (1 + FD noise).
    EXPECT_LE(f.orbit.maxMultiplier, 1.01);
    EXPECT_TRUE(f.orbit.stable);
    int neutral = 0;
    for (const auto& mu : f.orbit.multipliers) neutral += std::abs(mu) > 0.999 ? 1 : 0;
    EXPECT_LE(neutral, 2);  // the sticking wedges' anchors at most
}

TEST(PeriodicOrbit, ThreadCountDoesNotChangeTheBits) {
    const Fixture& f = getFixture();
    OrbitSettings one, two;
    one.shooting.threads = 1;
    two.shooting.threads = 2;
    one.shooting.maxIterations = two.shooting.maxIterations = 1;
    one.tryPeriodTwo = two.tryPeriodTwo = false;
    const PeriodicOrbitSolver a(f.sc, f.start.restart.distance, one), b(f.sc, f.start.restart.distance, two);
    const PeriodicOrbit pa = a.solve(12, f.start.restart.y), pb = b.solve(12, f.start.restart.y);
    ASSERT_EQ(pa.y.size(), pb.y.size());
    for (size_t i = 0; i < pa.y.size(); ++i) EXPECT_EQ(pa.y[i], pb.y[i]) << i;
    ASSERT_EQ(pa.multipliers.size(), pb.multipliers.size());
    for (Eigen::Index i = 0; i < pa.multipliers.size(); ++i) EXPECT_EQ(pa.multipliers[i], pb.multipliers[i]) << i;
    EXPECT_EQ(pa.mismatch, pb.mismatch);
}

TEST(PeriodicOrbit, RefusesATrackThatDoesNotRepeat) {
    Scenario sc = makeLightScenario();
    sc.track.rails = 4;
    EXPECT_THROW(PeriodicOrbitSolver::calcTrackPeriod(sc), ScenarioError);
    sc.track.rails = 0;
    EXPECT_DOUBLE_EQ(PeriodicOrbitSolver::calcTrackPeriod(sc), sc.track.railLength);
}

// The reduced model: its truck mode is held during Newton and never interpolated; an
// orbit returns to the mode it started in. Newton and iteration (y ← P(y)) find the
// same light-rocking orbit (0.25 in, 12 mph), and a continuation step by iteration
// keeps the mode entries whole numbers (the secant predictor leaves them alone).
TEST(PeriodicOrbit, TheReducedModelIsShotByNewtonAndByIteration) {
    Scenario sc = makeLightScenario();
    sc.model = model_names::kReduced;
    Scenario s = sc;
    s.run.duration = 20;
    const ScenarioRun start = runScenario(s);
    const PeriodicOrbitSolver newton(sc, start.restart.distance);
    OrbitSettings it;
    it.method = OrbitMethod::Iteration;
    const PeriodicOrbitSolver iteration(sc, start.restart.distance, it);
    // Ten periods on from the run's end: Newton's finite-difference monodromy needs a start near the orbit.
    const std::vector<double> settled = newton.runPeriods(12, start.restart.y, 10).restart.y;
    const PeriodicOrbit a = newton.solve(12, settled), b = iteration.solve(12, start.restart.y);
    ASSERT_TRUE(a.converged) << a.failure;
    ASSERT_TRUE(b.converged) << b.failure;
    EXPECT_EQ(a.period, 1);
    EXPECT_EQ(b.period, 1);
    EXPECT_EQ(b.method, OrbitMethod::Iteration);
    EXPECT_TRUE(b.stable);
    EXPECT_EQ(b.multipliers.size(), 0);
    EXPECT_TRUE(std::isnan(b.largestRealMultiplier));
    EXPECT_GT(b.maxMultiplier, 0.0);
    EXPECT_LT(b.maxMultiplier, 1.0);
    EXPECT_NEAR(a.rollAmplitudeDeg, b.rollAmplitudeDeg, 1e-3 * a.rollAmplitudeDeg);
    // One more period from either orbit: the same truck mode, the state back within the tolerance.
    for (const PeriodicOrbit* o : {&a, &b}) {
        const std::vector<double> back = newton.runPeriods(12, o->y, 1).restart.y;
        for (int i : newton.getDiscreteIndices()) EXPECT_EQ(back[size_t(i)], o->y[size_t(i)]) << i;
        const Eigen::VectorXd d = newton.toShooting(back) - newton.toShooting(o->y);
        for (Eigen::Index i = 0; i < d.size(); ++i) {
            const double scale = newton.getSteps()[i] == 1e-7 ? 1e-6 : newton.getSteps()[i];
            EXPECT_LT(std::abs(d[i]) / scale, 5) << "coordinate " << i;
        }
    }
    EXPECT_EQ(newton.getDiscreteIndices().size(), 8u);

    OrbitContinuationSettings cs;
    cs.fromMph = 12, cs.toMph = 11.5, cs.stepMph = 0.25;
    const OrbitBranch br = OrbitContinuation(iteration, cs).trace(start.restart.y);
    ASSERT_EQ(br.points.size(), 3u);
    for (const PeriodicOrbit& p : br.points) {
        EXPECT_TRUE(p.converged) << p.speedMph << ": " << p.failure;
        for (int i : iteration.getDiscreteIndices()) EXPECT_EQ(p.y[size_t(i)], std::floor(p.y[size_t(i)]));
    }
    EXPECT_EQ(br.stopReason, "minimum speed reached");
}

// --fd-step-scale scales the finite-difference steps and nothing else: the mismatch of a
// state is measured in the unscaled steps, so the convergence tolerance does not move.
TEST(PeriodicOrbit, StepScaleScalesTheStepsOnly) {
    const Scenario sc = makeLightScenario();
    OrbitSettings half;
    half.stepScale = 0.5;
    const PeriodicOrbitSolver a(sc, 0.0), b(sc, 0.0, half);
    ASSERT_EQ(a.getSteps().size(), b.getSteps().size());
    for (Eigen::Index i = 0; i < a.getSteps().size(); ++i) EXPECT_DOUBLE_EQ(b.getSteps()[i], 0.5 * a.getSteps()[i]);
    OrbitSettings zero;
    zero.stepScale = 0;
    EXPECT_THROW(PeriodicOrbitSolver(sc, 0.0, zero), std::invalid_argument);
}
