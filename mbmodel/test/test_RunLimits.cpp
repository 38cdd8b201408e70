// The run monitor (derailment, overturning, runaway, wall time) and the regime
// classifier, fed constructed histories.
#include "mbmodel/RunLimits.h"
#include "mbmodel/RunSummary.h"
#include "scenarios/ScenarioLoader.h"
#include "tests/TestCases.h"

#include <cmath>
#include <gtest/gtest.h>
#include <limits>

namespace rockroll {
namespace {

/// A layout with roll, one center plate, one side bearing, one wheelset (two
/// lifts, a lateral), and the three energy channels.
struct Layout {
    ChannelLayout c;
    Layout() {
        using R = ChannelRole;
        c.add({"roll", "deg", R::Roll, ""});
        c.add({"center_plate_F", "lb", R::CenterPlate, ""});
        c.add({"side_bearing_F_L", "lb", R::SideBearing, ""});
        for (const char* side : {"L", "R"})
            c.add({std::string("wheels_F_") + side, "lb", R::TruckSideWheelLoad | R::SingleWheelLoad, ""});
        ChannelLayout::Wheelset w;
        w.liftLeft = c.add({"wheel_lift_F1_L", "in", R::WheelLift, ""});
        w.liftRight = c.add({"wheel_lift_F1_R", "in", R::WheelLift, ""});
        w.lateral = c.add({"wheelset_lateral_F1", "in", R::WheelsetLateral, ""});
        c.wheelsets.push_back(w);
        c.add({"energy_stored", "J", R::EnergyStored, ""});
        c.add({"energy_input", "J", R::EnergyInput, ""});
        c.add({"energy_dissipated", "J", R::EnergyDissipated, ""});
    }
    /// t, roll, plate, side bearing, wheels L/R, lifts L/R, lateral, E, W, D
    std::vector<double> row(double t, double roll = 0, double liftL = 0, double liftR = 0, double lateral = 0,
                            double E = 1e5, double W = 0, double D = 0, double plate = 50000) const {
        return {t, roll, plate, 0, 40000, 40000, liftL, liftR, lateral, E, W, D};
    }
};

RunLimits resolvedLimits() { return resolveRunLimits(RunLimits{}, makeCarParameters("70ton-loaded"), WheelRailSettings{}); }

TEST(RunLimits, StaticRolloverAngleFromGeometry) {
    const CarParameters car = makeCarParameters("70ton-loaded");
    const double a = calcStaticRolloverAngle(car);
    // CG height: spring top above rail less the static compression, plus the
    // center plate height and the CG above it; tan(a) = (gauge/2) / height.
    const double h = (car.gauge / 2) / std::tan(a);
    EXPECT_GT(h, car.centerPlateAboveSprings + car.cgAboveCenterPlate);
    EXPECT_LT(h, car.springTopAboveRail + car.centerPlateAboveSprings + car.cgAboveCenterPlate);
    EXPECT_GT(a / units::degree, 10);
    EXPECT_LT(a / units::degree, 30);
    // The empty car's CG is lower: it tips later.
    EXPECT_GT(calcStaticRolloverAngle(makeCarParameters("70ton-empty")), a);
}

TEST(RunLimits, WheelsOffTimeIsTheFlangesFreeFlight) {
    const RunLimits l = resolvedLimits();
    EXPECT_NEAR(l.wheelsOffTime, 2 * std::sqrt(2 * 0.0254 / 9.80665), 1e-12);
    EXPECT_NEAR(l.wheelsOffTime, 0.144, 0.001);
}

TEST(RunLimits, QuietRunIsNotStopped) {
    Layout L;
    RunGuard g(L.c, resolvedLimits());
    RunResult r;
    for (int k = 0; k < 1000; ++k)
        ASSERT_FALSE(g.check(L.row(k * 0.002, 5 * std::sin(k * 0.01), k % 50 < 25 ? 1.5 : 0, 0, 0.2, 1e5 + 10 * k,
                                   20 * k, 10 * k),
                             r));
    EXPECT_FALSE(r.stop);
}

TEST(RunLimits, RollPastRolloverIsOverturned) {
    Layout L;
    const RunLimits l = resolvedLimits();
    RunGuard g(L.c, l);
    RunResult r;
    EXPECT_FALSE(g.check(L.row(0, 0.99 * l.rolloverAngle / units::degree), r));
    EXPECT_TRUE(g.check(L.row(0.002, -1.01 * l.rolloverAngle / units::degree), r));
    ASSERT_TRUE(r.stop);
    EXPECT_EQ(r.stop->regime, "overturned");
    EXPECT_DOUBLE_EQ(r.stop->time, 0.002);
}

TEST(RunLimits, LiftAboveFlangeWithLateralPastFlangeContactIsDerailed) {
    Layout L;
    RunGuard g(L.c, resolvedLimits());
    RunResult r;
    // Lifted 1.5 in but held laterally: no derailment (the report's own severe runs).
    EXPECT_FALSE(g.check(L.row(0, 3, 1.5, 0, 0.1), r));
    // Lateral past flange contact toward the other rail: the lifted left flange
    // moves away from its rail, no derailment.
    EXPECT_FALSE(g.check(L.row(0.002, 3, 1.5, 0, -0.5), r));
    // Lifted 0.9 in (below the 1 in flange) and past flange contact: none.
    EXPECT_FALSE(g.check(L.row(0.004, 3, 0.9, 0, 0.5), r));
    EXPECT_TRUE(g.check(L.row(0.006, 3, 1.1, 0, 0.5), r));
    ASSERT_TRUE(r.stop);
    EXPECT_EQ(r.stop->regime, "derailed");
    EXPECT_NE(r.stop->reason.find("wheel_lift_F1_L_in"), std::string::npos) << r.stop->reason;
}

TEST(RunLimits, AirborneWheelsetDriftingPastFlangeContactIsDerailed) {
    Layout L;
    RunGuard g(L.c, resolvedLimits());
    RunResult r;
    // Both wheels above the flanges but centred: not yet.
    EXPECT_FALSE(g.check(L.row(0, 3, 1.2, 1.1, 0.2), r));
    EXPECT_TRUE(g.check(L.row(0.002, 3, 1.2, 1.1, -0.6), r));
    ASSERT_TRUE(r.stop);
    EXPECT_EQ(r.stop->regime, "derailed");
}

TEST(RunLimits, BothWheelsOffLongerThanTheLimitIsDerailed) {
    Layout L;
    const RunLimits l = resolvedLimits();
    RunGuard g(L.c, l);
    RunResult r;
    double t = 0;
    // Airborne for less than the limit, then down: not derailed, and the timer restarts.
    for (; t < 0.8 * l.wheelsOffTime; t += 0.002) ASSERT_FALSE(g.check(L.row(t, 1, 0.1, 0.1), r));
    ASSERT_FALSE(g.check(L.row(t, 1, 0, 0.1), r));
    const double t0 = t + 0.002;
    for (t = t0; t < t0 + 0.8 * l.wheelsOffTime; t += 0.002) ASSERT_FALSE(g.check(L.row(t, 1, 0.1, 0.1), r));
    bool stopped = false;
    for (; t < t0 + 2 * l.wheelsOffTime && !stopped; t += 0.002) stopped = g.check(L.row(t, 1, 0.1, 0.1), r);
    ASSERT_TRUE(stopped);
    EXPECT_EQ(r.stop->regime, "derailed");
    EXPECT_GT(r.stop->time - t0, l.wheelsOffTime);
    EXPECT_LT(r.stop->time - t0, l.wheelsOffTime + 0.0041);
}

TEST(RunLimits, NonFiniteAndRunawayEnergyAreNumericalFailures) {
    Layout L;
    {
        RunGuard g(L.c, resolvedLimits());
        RunResult r;
        EXPECT_THROW(g.check(L.row(0, std::numeric_limits<double>::quiet_NaN()), r), NumericalFailure);
    }
    {
        RunGuard g(L.c, resolvedLimits());
        RunResult r;
        ASSERT_FALSE(g.check(L.row(0, 0, 0, 0, 0, 1e5, 0, 0), r));
        // Stored energy up by 1e6 J with 1e4 J of work in: growth without a source.
        EXPECT_THROW(g.check(L.row(0.002, 0, 0, 0, 0, 1.1e6, 1e4, 0), r), NumericalFailure);
    }
}

TEST(RunLimits, DisabledLimitsStillCatchNonFiniteValues) {
    Layout L;
    RunLimits l = resolvedLimits();
    l.enabled = false;
    RunGuard g(L.c, l);
    RunResult r;
    EXPECT_FALSE(g.check(L.row(0, 170), r));
    EXPECT_THROW(g.check(L.row(0.002, INFINITY), r), NumericalFailure);
}

TEST(RunLimits, WallTimeLimitThrows) {
    Layout L;
    RunLimits l = resolvedLimits();
    l.maxWallTime = 1e-9;
    RunGuard g(L.c, l);
    EXPECT_THROW(g.checkWallTime(0.5), NumericalFailure);
}

TEST(Regime, DurationsCountSamples) {
    const Durations d = calcDurations({false, true, true, false, true, true, true, false}, 0.002);
    EXPECT_NEAR(d.longest, 0.006, 1e-15);
    EXPECT_NEAR(d.total, 0.010, 1e-15);
}

/// A 2 s history at 500 Hz of a plate load with the given separation and a side bearing.
RunResult makePlateHistory(int separatedSamples, bool sideBearing) {
    Layout L;
    RunResult r;
    r.history.names = {"t_s"};
    for (const auto& n : L.c.names) r.history.names.push_back(n);
    for (int k = 0; k <= 1000; ++k) {
        const bool open = k >= 500 && k < 500 + separatedSamples;
        auto row = L.row(k * 0.002, 1.0, 0, 0, 0, 1e5, 0, 0, open ? 0.0 : 50000 + 1000 * std::sin(k * 0.1));
        row[3] = sideBearing && k > 200 ? 20000 : 0;
        r.history.samples.push_back(row);
    }
    r.simTime = 2;
    return r;
}

TEST(Regime, OneSampleDipIsNotSevere) {
    Layout L;
    SummaryOptions opt;
    opt.forcingPeriod = 1.6;
    const RunSummary s = summarizeRun(makePlateHistory(1, true), L.c, opt);
    EXPECT_EQ(s.regime, "moderate");
    EXPECT_NEAR(s.centerPlateSeparationLongestS, 0.002, 1e-12);
    const RunSummary light = summarizeRun(makePlateHistory(1, false), L.c, opt);
    EXPECT_EQ(light.regime, "light");
}

TEST(Regime, LongSeparationIsSevere) {
    Layout L;
    SummaryOptions opt;
    opt.forcingPeriod = 1.6;
    const RunSummary s = summarizeRun(makePlateHistory(40, true), L.c, opt);
    EXPECT_EQ(s.regime, "severe");
    EXPECT_NEAR(s.centerPlateSeparationLongestS, 0.080, 1e-12);
    EXPECT_NEAR(s.centerPlateSeparationTotalS, 0.080, 1e-12);
    // Four samples (8 ms) is below the 10 ms default; five is at it.
    EXPECT_EQ(summarizeRun(makePlateHistory(4, true), L.c, opt).regime, "moderate");
    EXPECT_EQ(summarizeRun(makePlateHistory(5, true), L.c, opt).regime, "severe");
    opt.severeSeparationTime = 0.1;
    EXPECT_EQ(summarizeRun(makePlateHistory(40, true), L.c, opt).regime, "moderate");
}

TEST(Regime, StoppedRunCarriesItsStop) {
    Layout L;
    SummaryOptions opt;
    opt.forcingPeriod = 1.6;
    RunResult r = makePlateHistory(40, true);
    r.stop = RunStop{"overturned", "roll past the limit", 1.5};
    const RunSummary s = summarizeRun(r, L.c, opt);
    EXPECT_EQ(s.regime, "overturned");
    EXPECT_DOUBLE_EQ(s.stoppedAtS, 1.5);
    EXPECT_EQ(s.stopReason, "roll past the limit");
}

std::string withLimits(const std::string& limits) {
    std::string text = test_cases::replaceOnce(test_cases::kMinimalScenarioToml, "duration = \"20 s\"", "duration = \"1 s\"");
    text = test_cases::replaceOnce(text, "model = \"fullcar\"", "model = \"halfcar\"");
    return text + "[limits]\n" + limits + "\n";
}

TEST(RunLimits, LimitsTableIsReadAndRangeChecked) {
    const Scenario sc = parseScenario(
        withLimits("flange_climb_time = \"25 ms\"\nwheels_off_time = \"200 ms\"\n"
                   "rollover_angle = \"15 deg\"\nmax_wall_time = \"60 s\"\nsevere_separation = \"20 ms\"\n"
                   "energy_runaway_fraction = 0.25\nenabled = true"),
        "limits.toml");
    EXPECT_DOUBLE_EQ(sc.run.limits.flangeClimbTime, 0.025);
    EXPECT_DOUBLE_EQ(sc.run.limits.wheelsOffTime, 0.2);
    EXPECT_DOUBLE_EQ(sc.run.limits.rolloverAngle, 15 * units::degree);
    EXPECT_DOUBLE_EQ(sc.run.limits.maxWallTime, 60);
    EXPECT_DOUBLE_EQ(sc.severeSeparationTime, 0.02);
    EXPECT_DOUBLE_EQ(sc.run.limits.energyRunawayFraction, 0.25);
    for (const char* bad : {"flange_climb_time = \"-1 s\"", "flange_climb_time = \"0 s\"", "flange_climb_time = \"11 s\"",
                            "rollover_angle = \"95 deg\"", "wheels_off_time = \"0 s\"", "max_wall_time = \"-5 s\"",
                            "severe_separation = \"2 s\"", "energy_runaway_fraction = nan",
                            "energy_runaway_fraction = 0", "flange_climb_time = 1", "flange_clmb_time = \"1 s\""}) {
        try {
            parseScenario(withLimits(bad), "limits.toml");
            ADD_FAILURE() << "accepted " << bad;
        } catch (const ScenarioError& e) {
            const std::string key = std::string(bad).substr(0, std::string(bad).find(' '));
            EXPECT_NE(std::string(e.what()).find("limits.toml"), std::string::npos) << e.what();
            EXPECT_NE(std::string(e.what()).find("limits." + key), std::string::npos) << e.what();
        }
    }
}

}  // namespace
}  // namespace rockroll
