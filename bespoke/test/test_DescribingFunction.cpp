// Describing-function steady state: against a long run of its time-domain twin,
// and continuation through the folds of the jump resonance.
#include "bespoke/DescribingFunction.h"
#include "scenarios/ScenarioLoader.h"
#include "bespoke/EomSimulation.h"
#include "mbmodel/Parallel.h"
#include "mbmodel/Units.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace rockroll;

namespace {
const double kRailLength = 39 * units::foot;

DescribingFunctionModel makeModel(double amplitudeIn) {
    const CarParameters car = makeCarParameters("70ton-loaded");
    const double C =
        DescribingFunctionModel::calcFundamentalCrossLevel(amplitudeIn * units::inch, car.wheelbase, kRailLength);
    return DescribingFunctionModel(car, C, kRailLength);
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
    ContinuationSettings s;
    s.fromMph = 12;
    s.toMph = 22;
    s.maxPoints = 250;
    s.stability = StabilityMethod::None;
    const auto branches = df.trace(s);
    ASSERT_FALSE(branches.empty());
    std::vector<double> speeds;
    for (const auto& b : branches)
        for (const auto& p : b.points) speeds.push_back(p.speedMph);
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
    std::vector<SteadyStatePoint> all;
    for (const auto& b : branches) all.insert(all.end(), b.points.begin(), b.points.end());
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
