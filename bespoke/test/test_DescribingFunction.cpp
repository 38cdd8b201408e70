// Describing-function steady state: against a long run of its time-domain twin,
// and continuation through the folds of the jump resonance.
#include "bespoke/DescribingFunction.h"
#include "scenarios/ScenarioLoader.h"
#include "scenarios/ScenarioRun.h"
#include "bespoke/EomSimulation.h"
#include "mbmodel/Parallel.h"
#include "mbmodel/Units.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <optional>
#include <utility>

using namespace rockroll;

namespace {
const double kRailLength = 39 * units::foot;

DescribingFunctionModel makeModel(double amplitudeIn) {
    const CarParameters car = makeCarParameters("70ton-loaded");
    const double C =
        DescribingFunctionModel::calcFundamentalCrossLevel(amplitudeIn * units::inch, car.wheelbase, kRailLength);
    return DescribingFunctionModel(car, C, kRailLength);
}

/// Paths from both ends of [from, to] only: no stability, no sweep starts, no twin runs.
ContinuationSettings makePathSettings(double fromMph, double toMph) {
    ContinuationSettings s;
    s.fromMph = fromMph;
    s.toMph = toMph;
    s.stability = StabilityMethod::None;
    s.sweepStepMph = 0;
    s.twinPeriods = 0;
    return s;
}

/// Half peak-to-peak of car-body roll over the last 3 input periods of a long twin run.
double runTwin(const DescribingFunctionModel& df, double speedMph, double duration) {
    const EomHalfCarModel twin = df.makeTwin(speedMph);
    const RunResult r = simulateEom(twin, {duration, 200, 1e-5, RunLimits{}});
    const double period = 2 * 3.14159265358979323846 / df.calcOmega(speedMph);
    const int c = r.history.column("roll_deg");
    double lo = 1e9, hi = -1e9;
    for (const auto& row : r.history.samples)
        if (row[0] >= duration - 3 * period) {
            lo = std::min(lo, row[c]);
            hi = std::max(hi, row[c]);
        }
    return 0.5 * (hi - lo);
}
}  // namespace

TEST(DescribingFunction, FundamentalOfTheRectifiedSineCrossLevel) {
    // 8A/(3π)·cos(π·68 in / 39 ft) ≈ 0.849·0.898·A.
    const double C = DescribingFunctionModel::calcFundamentalCrossLevel(1.0, 68 * units::inch, kRailLength);
    EXPECT_NEAR(C, 8 / (3 * 3.14159265358979323846) * std::cos(3.14159265358979323846 * 68.0 / 468.0), 1e-12);
    EXPECT_NEAR(C, 0.849 * 0.898, 2e-3);
}

TEST(DescribingFunction, StaticGuessBalancesWithoutInput) {
    const DescribingFunctionModel df = makeModel(0.0);
    const Eigen::VectorXd r = df.calcResidual(df.makeStaticGuess(), 14);
    EXPECT_LT(r.norm(), 1e-6);
}

// The exact Jacobian (each law's harmonics differentiated in closed form) against central
// differences of the residual, at the path's largest rocking (the wheels lift, the
// contacts open and close, the wedges slide), on the lowest branch (12 mph), and at a
// point off the solution set.
TEST(DescribingFunction, ExactJacobianMatchesCentralDifferences) {
    const DescribingFunctionModel df = makeModel(0.75);
    const auto low = df.solveFromRest(12.0);
    ASSERT_TRUE(low);
    ContinuationSettings s = makePathSettings(12, 22);
    s.maxPoints = 250;
    const SteadyStateSet set = df.trace(s);
    ASSERT_FALSE(set.paths.empty());
    const SteadyStatePoint* severe = nullptr;  // the largest roll
    for (const auto& p : set.paths[0].points)
        if (!severe || p.rollAmplitudeDeg > severe->rollAmplitudeDeg) severe = &p;
    ASSERT_NE(severe, nullptr);
    ASSERT_GT(severe->wheelLiftFraction, 0) << "the check should see a wheel lift";
    Eigen::VectorXd off = *low;
    for (int i = 0; i < off.size(); ++i) off[i] += 0.3 * std::sin(1.7 * i);
    for (const auto& [x, mph] : {std::pair{*low, 12.0}, std::pair{severe->harmonics, severe->speedMph}, std::pair{off, 13.0}}) {
        const Eigen::MatrixXd J = df.calcResidualJacobian(x, mph, true);
        ASSERT_EQ(J.cols(), x.size() + 1);
        Eigen::MatrixXd fd(J.rows(), J.cols());
        for (int i = 0; i <= x.size(); ++i) {
            const double h = 1e-5;  // mm, mrad or mph: far below the contacts' deflections
            Eigen::VectorXd xp = x, xm = x;
            double vp = mph, vm = mph;
            if (i < x.size()) xp[i] += h, xm[i] -= h;
            else vp += h, vm -= h;
            fd.col(i) = (df.calcResidual(xp, vp) - df.calcResidual(xm, vm)) / (2 * h);
        }
        EXPECT_LT((J - fd).cwiseAbs().maxCoeff(), 1e-6 * fd.cwiseAbs().maxCoeff()) << mph << " mph";
        for (int i = 0; i <= x.size(); ++i)
            EXPECT_LT((J.col(i) - fd.col(i)).norm(), 1e-5 * std::max(1e-3, fd.col(i).norm()) + 1e-9)
                << "column " << i << " at " << mph << " mph";
    }
}

// On the lowest branch at two speeds the steady roll amplitude of the
// describing function is within 5 % of a long run of its time-domain twin.
TEST(DescribingFunction, LowestBranchMatchesItsTimeDomainTwin) {
    const DescribingFunctionModel df = makeModel(0.75);
    for (double mph : {12.0, 14.0}) {
        const auto x = df.solveFromRest(mph);
        ASSERT_TRUE(x) << mph << " mph";
        const double dfRoll = df.describe(*x, mph).rollAmplitudeDeg;
        const double twinRoll = runTwin(df, mph, 40);
        EXPECT_NEAR(dfRoll, twinRoll, 0.05 * twinRoll) << mph << " mph";
    }
}

// Continuation passes at least one fold, and inside the fold region
// there are three or more solutions at one speed.
TEST(DescribingFunction, ContinuationTracesTheFoldsOfTheJumpResonance) {
    const DescribingFunctionModel df = makeModel(0.75);
    ContinuationSettings s = makePathSettings(12, 22);
    s.maxPoints = 250;
    const SteadyStateSet set = df.trace(s);
    ASSERT_FALSE(set.paths.empty());
    const std::vector<SteadyStatePoint>& all = set.paths[0].points;  // from rest at 12 mph
    std::vector<double> speeds;
    for (const auto& p : all) speeds.push_back(p.speedMph);
    ASSERT_GT(speeds.size(), 10u);
    int folds = 0;
    for (size_t i = 2; i < speeds.size(); ++i)
        if ((speeds[i] - speeds[i - 1]) * (speeds[i - 1] - speeds[i - 2]) < 0) ++folds;
    EXPECT_GE(folds, 1);
    const double probe = 15.0;
    int solutions = 0;
    for (size_t i = 1; i < speeds.size(); ++i)
        if ((speeds[i] - probe) * (speeds[i - 1] - probe) < 0) ++solutions;
    EXPECT_GE(solutions, 3) << "solutions at " << probe << " mph";

    // Stability evidence from the time-domain twin: started on the lowest branch
    // it stays there; started on the middle branch (after the first fold) it leaves.
    std::vector<const SteadyStatePoint*> middle;
    for (const auto& p : all)
        if (p.foldsBefore == 1) middle.push_back(&p);
    ASSERT_FALSE(middle.empty());
    const SteadyStatePoint& low = all.front();
    const SteadyStatePoint& mid = *middle[middle.size() / 2];
    EXPECT_NEAR(df.calcTwinPersistence(low.harmonics, low.speedMph, 10), 1.0, 0.15);
    EXPECT_GT(std::abs(df.calcTwinPersistence(mid.harmonics, mid.speedMph, 10) - 1.0), 0.15)
        << "middle branch at " << mid.speedMph << " mph, " << mid.rollAmplitudeDeg << " deg";
}

// The twin's monodromy columns run in parallel (nested in the enclosing pool); each is
// a one-period flow of its own, so the Floquet result is the same bits on one thread
// as on two (the program's rule: results do not depend on --jobs).
TEST(DescribingFunction, TwinFloquetIsTheSameOnOneThreadAsOnTwo) {
    const DescribingFunctionModel df = makeModel(0.75);
    const auto x = df.solveFromRest(12.0);
    ASSERT_TRUE(x);
    TwinFloquet f[2];
    for (int threads : {1, 2})
        parallelFor(1, threads, [&](size_t) { f[threads - 1] = df.calcTwinFloquet(*x, 12.0); });
    EXPECT_TRUE(f[0].converged);
    EXPECT_EQ(f[0].converged, f[1].converged);
    EXPECT_EQ(f[0].mismatch, f[1].mismatch);
    EXPECT_EQ(f[0].maxMultiplier, f[1].maxMultiplier);
    EXPECT_EQ(f[0].rollAmplitudeDeg, f[1].rollAmplitudeDeg);
}

namespace {
/// The solution at `mph` (over 10-22 mph, both ends' paths) nearest in roll amplitude to
/// `rollDeg` that its time-domain twin stays on, with its twin maxima.
std::optional<std::pair<SteadyStatePoint, TwinMaxima>> solveNearestStayedAt(const DescribingFunctionModel& df,
                                                                           double mph, double rollDeg) {
    const SteadyStateSet set = df.trace(makePathSettings(10, 22));
    std::optional<std::pair<SteadyStatePoint, TwinMaxima>> best;
    for (const auto& path : set.paths)
        for (size_t i = 1; i < path.points.size(); ++i) {
            const auto &a = path.points[i - 1], &b = path.points[i];
            if ((a.speedMph - mph) * (b.speedMph - mph) > 0 || a.speedMph == b.speedMph) continue;
            const double f = (mph - a.speedMph) / (b.speedMph - a.speedMph);
            const auto x = df.solve(mph, a.harmonics + f * (b.harmonics - a.harmonics));
            if (!x) continue;
            const SteadyStatePoint p = df.describe(*x, mph);
            const TwinMaxima t = df.calcTwinMaxima(*x, mph, 5);
            if (t.stayed() && (!best || std::abs(p.rollAmplitudeDeg - rollDeg) <
                                            std::abs(best->first.rollAmplitudeDeg - rollDeg)))
                best = {{p, t}};
        }
    return best;
}
}  // namespace

/// The Simbody half car from rest at 1.0 in, 15 mph, 20 s (validate's Table 3, from rest):
/// its steady-part side-bearing and wheel maxima [lb] and steady roll amplitude [deg].
std::array<double, 3> runHalfCar(double sideBearingScale, double wheelScale) {
    Scenario sc = loadScenarioFile(std::string(ROCKROLL_SCENARIO_DIR) + "/70ton-loaded.toml");
    sc.model = "halfcar";
    sc.track.amplitude = 1.0 * units::inch;
    sc.speed = 15 * units::mph;
    sc.run.duration = 20;
    sc.car.sideBearingStiffness *= sideBearingScale;
    sc.car.wheelRailStiffness *= wheelScale;
    const ScenarioRun r = runScenario(sc);
    return {r.summary.steady.sideBearingLoadLb, r.summary.steady.truckSideWheelLoadLb, r.summary.steadyRollAmplitudeDeg};
}

// Harmonic balance fixes a force's mean and first two harmonics, and the describing
// function reports those; its peaks come from the time-domain twin (docs/bespoke.md,
// "Forces: harmonics, not peaks"). At 1.0 in, 15 mph, on the solution of the half car's
// branch from rest (3.1°; the twin stays on it), ×4 side-bearing or
// wheel-rail stiffness moves the twin's side-bearing and wheel maxima by less than 15 %
// and by no more than it moves the Simbody half car's (+ 2 percentage points), where the
// pointwise peak of the two-harmonic series moved by 60 % (k^(1/3)).
TEST(DescribingFunction, TwinMaximaMoveWithContactStiffnessNoMoreThanTheHalfCars) {
    const CarParameters base = makeCarParameters("70ton-loaded");
    const double C = DescribingFunctionModel::calcFundamentalCrossLevel(1.0 * units::inch, base.wheelbase, kRailLength);
    const auto [halfSb0, halfWheel0, halfRoll] = runHalfCar(1, 1);
    for (int which : {0, 1}) {  // 0: side bearing ×4, 1: wheel-rail ×4
        double sb[2] = {0, 0}, wheel[2] = {0, 0}, roll[2] = {0, 0};
        for (int k = 0; k < 2; ++k) {
            CarParameters car = base;
            if (k == 1) (which == 0 ? car.sideBearingStiffness : car.wheelRailStiffness) *= 4;
            const DescribingFunctionModel df(car, C, kRailLength);
            const auto found = solveNearestStayedAt(df, 15.0, halfRoll);
            ASSERT_TRUE(found) << "which " << which << ", stiffness x" << (k ? 4 : 1);
            const auto& [p, t] = *found;
            sb[k] = t.maxSideBearingLoadLb, wheel[k] = t.maxTruckSideWheelLoadLb, roll[k] = p.rollAmplitudeDeg;
            EXPECT_GT(t.maxSideBearingLoadLb, p.sideBearingLoad.meanLb);
        }
        const auto [halfSb1, halfWheel1, halfRoll1] = runHalfCar(which == 0 ? 4 : 1, which == 1 ? 4 : 1);
        (void)halfRoll1;
        const double dfSb = std::abs(sb[1] / sb[0] - 1), dfWheel = std::abs(wheel[1] / wheel[0] - 1);
        const double halfSb = std::abs(halfSb1 / halfSb0 - 1), halfWheel = std::abs(halfWheel1 / halfWheel0 - 1);
        std::printf("%s x4 at 1.0 in, 15 mph: twin side bearing %.0f -> %.0f lb (%.1f %%), wheel %.0f -> %.0f lb "
                    "(%.1f %%), roll %.3f -> %.3f deg; half car side bearing %.1f %%, wheel %.1f %%\n",
                    which == 0 ? "side-bearing" : "wheel-rail", sb[0], sb[1], 100 * dfSb, wheel[0], wheel[1],
                    100 * dfWheel, roll[0], roll[1], 100 * halfSb, 100 * halfWheel);
        EXPECT_LT(std::abs(roll[1] / roll[0] - 1), 0.1) << "not the same branch";
        EXPECT_LT(dfSb, 0.15);
        EXPECT_LT(dfWheel, 0.15);
        EXPECT_LE(dfSb, halfSb + 0.02);
        EXPECT_LE(dfWheel, halfWheel + 0.02);
    }
}

// The solution set at 1.0 in is not one curve: the path from rest at 22 mph is the
// severe response every time-domain model shows at 16-22 mph, and the path from
// 10 mph, turning at its folds, never reaches it (docs/bespoke.md, "Starts").
TEST(DescribingFunction, FindsTheSevereBranchFromTheTopOfTheRange) {
    const DescribingFunctionModel df = makeModel(1.0);
    const SteadyStateSet set = df.trace(makePathSettings(10, 22));
    ASSERT_GE(set.paths.size(), 2u);
    EXPECT_EQ(set.paths[1].start, "rest at 22 mph");
    double fastestOfPath0 = 0;
    for (const auto& p : set.paths[0].points) fastestOfPath0 = std::max(fastestOfPath0, p.speedMph);
    EXPECT_LT(fastestOfPath0, 18.0);
    double rollAt18 = 0;
    for (const auto& p : set.paths[1].points)
        if (std::abs(p.speedMph - 18.0) < 0.3) rollAt18 = std::max(rollAt18, p.rollAmplitudeDeg);
    EXPECT_GT(rollAt18, 2.0);
}

// The twin's swept state, projected on two harmonics, solves back to the solution the
// twin sits on: on the lowest branch at 12 mph, 0.75 in.
TEST(DescribingFunction, TwinStateProjectsOntoTheSolutionItSitsOn) {
    const DescribingFunctionModel df = makeModel(0.75);
    const auto x = df.solveFromRest(12.0);
    ASSERT_TRUE(x);
    const Eigen::VectorXd guess = df.projectTwinState(df.makeTwinState(*x, 12.0), 12.0, 10);
    const auto back = df.solve(12.0, guess);
    ASSERT_TRUE(back);
    EXPECT_NEAR(df.describe(*back, 12.0).rollAmplitudeDeg, df.describe(*x, 12.0).rollAmplitudeDeg,
                0.01 * df.describe(*x, 12.0).rollAmplitudeDeg);
}
