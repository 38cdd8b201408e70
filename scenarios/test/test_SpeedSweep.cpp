// Speed sweeps: state and track distance carried between speeds, rails without
// jumps, hysteresis between up and down sweeps, and --fresh.
#include "scenarios/SpeedSweep.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace rockroll;

namespace {
Scenario makeBase(const std::string& model, double duration) {
    Scenario sc = getDefaultScenario();
    sc.model = model;
    sc.run.duration = duration;
    return sc;
}
std::vector<double> firstRow(const ScenarioRun& r) { return toVector(r.result.history.samples.front()); }
std::vector<double> lastRow(const ScenarioRun& r) { return toVector(r.result.history.samples.back()); }
}  // namespace

TEST(SpeedSweep, TrackMotionRampsWithoutJumps) {
    const TrackMotion m{20.0, 100.0, 15.0, 1.0};
    EXPECT_DOUBLE_EQ(m.calcDistance(0), 100.0);
    EXPECT_DOUBLE_EQ(m.calcSpeed(0), 15.0);
    EXPECT_NEAR(m.calcSpeed(1.0), 20.0, 1e-12);
    EXPECT_NEAR(m.calcDistance(1.0), 100.0 + 17.5, 1e-12);
    EXPECT_NEAR(m.calcDistance(3.0), 100.0 + 17.5 + 40.0, 1e-12);
    const double h = 1e-6;
    for (double t : {0.3, 0.999, 1.0, 2.0}) EXPECT_NEAR((m.calcDistance(t + h) - m.calcDistance(t - h)) / (2 * h), m.calcSpeed(t), 1e-5);
}

// A zero ramp is an instantaneous speed step: the new speed from the first instant, the
// distance continuing without a jump (a run restarted at the new speed, as the report's
// sweep points were).
TEST(SpeedSweep, ZeroRampStepsTheSpeedAtOnce) {
    const TrackMotion m{20.0, 100.0, 15.0, 0.0};
    EXPECT_DOUBLE_EQ(m.calcSpeed(0), 20.0);
    EXPECT_DOUBLE_EQ(m.calcDistance(0), 100.0);
    EXPECT_DOUBLE_EQ(m.calcDistance(2.0), 140.0);
    SweepSpec s;
    s.scenario = makeBase("eom", 2);
    s.fromMph = 14, s.toMph = 15, s.stepMph = 1;
    s.rampTime = 0;
    const auto stepped = runSweep(s);
    s.rampTime = 1;
    const auto ramped = runSweep(s);
    ASSERT_EQ(stepped.size(), 2u);
    EXPECT_EQ(stepped[1].start, "continued");
    EXPECT_EQ(stepped[1].summary.criteriaFromS, 0.0);
    EXPECT_NEAR(stepped[1].next.from->distance - stepped[0].next.from->distance, 2 * 15 * units::mph, 1e-9);
    EXPECT_NEAR(ramped[1].next.from->distance - ramped[0].next.from->distance,
                (0.5 * (14 + 15) + 15) * units::mph, 1e-9);
}

TEST(SpeedSweep, ContinuedRunStartsWhereThePreviousEnded) {
    for (const char* model : {"eom", "halfcar", "reduced"}) {
        Scenario a = makeBase(model, 4);
        a.speed = 15 * units::mph;
        const ScenarioRun first = runScenario(a);
        Scenario b = a;
        b.speed = 17 * units::mph;
        RunStart start;
        start.from = first.restart;
        start.staticReference = first.staticReference;
        const ScenarioRun second = runScenario(b, start);
        const auto end = lastRow(first), begin = firstRow(second);
        const auto& names = first.result.history.names;
        for (size_t c = 1; c < names.size(); ++c) {
            if (names[c].find("slip") != std::string::npos) continue;  // a flag, not a quantity
            if (names[c] == "energy_input_J" || names[c] == "energy_dissipated_J") {  // cumulative from each run's start
                EXPECT_EQ(begin[c], 0.0) << model << " " << names[c];
                continue;
            }
            EXPECT_NEAR(begin[c], end[c], 1e-6 * (1 + std::abs(end[c]))) << model << " " << names[c];
        }
        EXPECT_NEAR(first.restart.distance, 4 * a.speed, 1e-9);
        EXPECT_EQ(first.restart.speed, a.speed) << model;
        EXPECT_EQ(first.restart.model, model);
        EXPECT_EQ(second.summary.staticWheelLoadLb, first.summary.staticWheelLoadLb) << model;
        // The criteria leave out the continued run's speed ramp, and nothing of a run from rest
        // on the rectified sine (docs/validation.md, "Statistics").
        EXPECT_EQ(first.summary.criteriaFromS, 0.0) << model;
        EXPECT_NEAR(second.summary.criteriaFromS, start.rampTime, 0.011) << model;
    }
}

// Report §3.2: the response at a speed depends on whether the car reaches it
// from below or from above.
TEST(SpeedSweep, UpAndDownSweepsShowHysteresis) {
    SweepSpec up;
    up.scenario = makeBase("reduced", 30);
    up.fromMph = 15, up.toMph = 17, up.stepMph = 1;
    SweepSpec down = up;
    down.direction = SweepDirection::Down;
    const auto r = runSweeps({up, down}, 2);
    ASSERT_EQ(r[0].size(), 3u);
    EXPECT_EQ(r[0][0].start, "rest");
    EXPECT_EQ(r[0][1].start, "continued");
    EXPECT_DOUBLE_EQ(r[0][0].speedMph, 15);
    EXPECT_DOUBLE_EQ(r[1][0].speedMph, 17);
    const RunSummary& fromBelow = r[0][0].summary;  // 15 mph, reached from rest
    const RunSummary& fromAbove = r[1][2].summary;  // 15 mph, reached from 17 mph
    EXPECT_EQ(fromBelow.regime, "light");
    EXPECT_NE(fromAbove.regime, "light");
    EXPECT_GT(fromAbove.steadyRollAmplitudeDeg, 2 * fromBelow.steadyRollAmplitudeDeg);
}

TEST(SpeedSweep, FreshStartsEverySpeedFromRest) {
    SweepSpec s;
    s.scenario = makeBase("eom", 2);
    s.fromMph = 14, s.toMph = 15, s.stepMph = 1;
    s.fresh = true;
    for (const auto& p : runSweep(s)) EXPECT_EQ(p.start, "rest");
    EXPECT_EQ(getSweepSpeeds(s), (std::vector<double>{14, 15}));
    s.direction = SweepDirection::Down;
    EXPECT_EQ(getSweepSpeeds(s), (std::vector<double>{15, 14}));
}

// A speed that fails numerically is reported with its error, and the sweep goes
// on (from rest) instead of stopping or dropping it. A wall-time limit of 1 ns has
// passed by the first recorded sample, so every speed here fails.
TEST(SpeedSweep, NumericalFailureIsReportedAndTheSweepGoesOn) {
    SweepSpec s;
    s.scenario = makeBase("eom", 2);
    s.scenario.run.limits.maxWallTime = 1e-9;
    s.fromMph = 14, s.toMph = 16, s.stepMph = 1;
    const auto points = runSweep(s);
    ASSERT_EQ(points.size(), 3u);
    for (const auto& p : points) {
        EXPECT_TRUE(p.failed);
        EXPECT_NE(p.error.find("wall-time limit"), std::string::npos) << p.error;
        EXPECT_NE(p.error.find("t = "), std::string::npos) << "the error names the time";
        EXPECT_EQ(p.start, "rest");
    }
}

// The sweeps run on the program's one pool (mbmodel/Parallel.h); each sweep's result
// is stored by its index, so every number is bitwise the same for any --jobs.
TEST(SpeedSweep, ResultsAreBitwiseTheSameForAnyNumberOfJobs) {
    std::vector<SweepSpec> specs;
    for (double amplitudeIn : {0.5, 0.75, 1.0})
        for (auto dir : {SweepDirection::Up, SweepDirection::Down}) {
            SweepSpec s;
            s.scenario = makeBase("reduced", 3);
            s.scenario.track.amplitude = amplitudeIn * units::inch;
            s.fromMph = 15, s.toMph = 17, s.stepMph = 1;
            s.direction = dir;
            specs.push_back(s);
        }
    const auto one = runSweeps(specs, 1);
    for (int jobs : {2, 5}) {
        const auto many = runSweeps(specs, jobs);
        ASSERT_EQ(many.size(), one.size());
        for (size_t i = 0; i < one.size(); ++i) {
            ASSERT_EQ(many[i].size(), one[i].size());
            for (size_t k = 0; k < one[i].size(); ++k) {
                const RunSummary &a = one[i][k].summary, &b = many[i][k].summary;
                EXPECT_EQ(many[i][k].speedMph, one[i][k].speedMph);
                EXPECT_EQ(b.maxRollDeg, a.maxRollDeg) << jobs << " jobs, sweep " << i << " point " << k;
                EXPECT_EQ(b.steadyRollAmplitudeDeg, a.steadyRollAmplitudeDeg);
                EXPECT_EQ(b.maxWheelLiftIn, a.maxWheelLiftIn);
                EXPECT_EQ(b.maxWheelLoadLb, a.maxWheelLoadLb);
                EXPECT_EQ(b.maxSideBearingLoadLb, a.maxSideBearingLoadLb);
                EXPECT_EQ(b.steps, a.steps);
                EXPECT_EQ(b.regime, a.regime);
            }
        }
    }
}

// A jump is a change of more than kJumpFraction of the amplitude before it: the fullcar's
// 11 % dip coming down at 1.0 in (REPORT §2) is not one, the 0.5 in drop (73 %) is.
TEST(SpeedSweep, AJumpIsAChangeOfMoreThanThirtyPercent) {
    const SweepJump dip = findSweepJump({17.5, 17, 16.5, 16}, {4.25, 4.87, 4.33, 5.52}, SweepDirection::Down);
    EXPECT_TRUE(std::isnan(dip.speedMph));
    EXPECT_DOUBLE_EQ(dip.largestChangeMph, 16.5);
    EXPECT_NEAR(dip.changeDeg, 0.54, 1e-12);
    EXPECT_NEAR(dip.changeFraction, 0.54 / 4.87, 1e-12);
    const SweepJump drop = findSweepJump({15, 14.5, 14, 13.5}, {1.86, 1.65, 0.44, 0.43}, SweepDirection::Down);
    EXPECT_DOUBLE_EQ(drop.speedMph, 14);
    const SweepJump up = findSweepJump({16, 16.5, 17}, {1.0, 1.29, 1.35}, SweepDirection::Up);  // 29 %
    EXPECT_TRUE(std::isnan(up.speedMph));
    EXPECT_DOUBLE_EQ(findSweepJump({16, 16.5, 17}, {1.0, 1.31, 1.35}, SweepDirection::Up).speedMph, 16.5);
}
