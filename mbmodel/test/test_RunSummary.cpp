// The run summary's statistics on constructed histories: the steady-part maxima,
// the criteria window, the wheel-load basis and the worst energy balance
// (docs/validation.md, "Statistics").
#include "mbmodel/RunSummary.h"

#include <cmath>
#include <gtest/gtest.h>
#include <numbers>

namespace rockroll {
namespace {

/// Roll, one center plate, one side bearing, the wheel channels and the energies.
/// `realWheels`: two single wheels per truck side beside the truck-side totals (the
/// full car); otherwise the truck side is the equivalent wheel (the half car).
ChannelLayout makeLayout(bool realWheels) {
    using R = ChannelRole;
    ChannelLayout c;
    c.add({"roll", "deg", R::Roll, ""});
    c.add({"center_plate_F", "lb", R::CenterPlate, ""});
    c.add({"side_bearing_F_L", "lb", R::SideBearing, ""});
    c.add({"wheel_lift_F1_L", "in", R::WheelLift, ""});
    if (realWheels) {
        c.add({"wheels_F_L", "lb", R::TruckSideWheelLoad, ""});
        c.add({"wheel_F1_L", "lb", R::SingleWheelLoad, ""});
        c.add({"wheel_F2_L", "lb", R::SingleWheelLoad, ""});
    } else {
        c.add({"wheels_F_L", "lb", R::TruckSideWheelLoad | R::SingleWheelLoad, ""});
    }
    c.add({"energy_stored", "J", R::EnergyStored, ""});
    c.add({"energy_input", "J", R::EnergyInput, ""});
    c.add({"energy_dissipated", "J", R::EnergyDissipated, ""});
    return c;
}

constexpr double kPeriod = 1.0;  // forcing period [s]
constexpr double kRate = 500;    // samples per second

/// 10 s: a transient of 8° roll, 3 in lift and doubled loads for t < 2 s, then a
/// steady 1° roll at the forcing period with a 60 000 lb truck-side load peak.
RunResult makeHistory(const ChannelLayout& layout, double energyError = 0) {
    RunResult r;
    r.history.names = {"t_s"};
    for (const auto& n : layout.names) r.history.names.push_back(n);
    for (int k = 0; k <= 10 * int(kRate); ++k) {
        const double t = k / kRate;
        const bool transient = t > 0.1 && t < 2;
        const double wave = std::sin(2 * std::numbers::pi * t / kPeriod);
        std::vector<double> row{t, transient ? 8 * wave : wave, 50000, transient ? 40000 : 20000 * (1 + wave),
                                transient ? 3.0 : 0.0};
        const double side = 40000 + 20000 * wave * (transient ? 2 : 1);
        row.push_back(side);
        if (layout.singleWheelLoad.size() == 2) row.insert(row.end(), {side / 2 + 1000, side / 2 - 1000});
        // W = 1000·t, D = 900·t, ΔE = 100·t·(1 − energyError), and 200 J more at t = 1 s alone.
        const double W = 1000 * t, D = 900 * t, dE = 100 * t * (1 - energyError) + (std::abs(t - 1) < 1e-9 ? 200 : 0);
        row.insert(row.end(), {1e5 + dE, W, D});
        r.history.samples.push_back(row);
    }
    r.simTime = 10;
    return r;
}

SummaryOptions makeOptions() {
    SummaryOptions o;
    o.forcingPeriod = kPeriod;
    o.filterCutoffHz = 20;
    return o;
}

TEST(RunSummary, SteadyMaximaAreTheLastCyclesAlone) {
    const ChannelLayout layout = makeLayout(false);
    const RunSummary s = summarizeRun(makeHistory(layout), layout, makeOptions());
    EXPECT_NEAR(s.maxRollDeg, 8, 1e-3);  // the whole run holds the transient
    EXPECT_EQ(s.steady.cycles, 3);
    EXPECT_NEAR(s.steady.windowS, 3 * kPeriod, 1 / kRate);
    EXPECT_NEAR(s.steady.rollDeg, 1, 1e-3);
    EXPECT_NEAR(s.steadyRollAmplitudeDeg, 1, 1e-3);
    EXPECT_EQ(s.steady.wheelLiftIn, 0);
    EXPECT_NEAR(s.maxWheelLiftIn, 3, 1e-12);
    // Filtered at 20 Hz, a 1 Hz sine keeps its peak to a fraction of a percent.
    EXPECT_NEAR(s.steady.truckSideWheelLoadLb, 60000, 300);
    EXPECT_NEAR(s.maxWheelLoadLb, 80000, 1500);
    EXPECT_NEAR(s.steady.sideBearingLoadLb, 40000, 300);
    EXPECT_NEAR(s.maxSideBearingLoadLb, 40000, 1000);  // the filter overshoots the step at 0.1 s
    EXPECT_NEAR(s.steady.centerPlateLoadLb, 50000, 1);
}

TEST(RunSummary, CriteriaLeaveOutTheRampOnly) {
    const ChannelLayout layout = makeLayout(false);
    SummaryOptions o = makeOptions();
    const RunSummary all = summarizeRun(makeHistory(layout), layout, o);
    auto criterion = [](const RunSummary& s, const std::string& name) -> double {
        for (const Criterion& c : s.criteria)
            if (c.name == name) return c.value;
        return NAN;
    };
    EXPECT_EQ(all.criteriaFromS, 0);
    EXPECT_NEAR(criterion(all, "roll_peak_to_peak"), 16, 1e-2);  // the build-up is judged
    // A sweep point's 1 s speed ramp is left out; the build-up after it is still judged.
    o.criteriaFromS = 1.0;
    const RunSummary ramp = summarizeRun(makeHistory(layout), layout, o);
    EXPECT_NEAR(ramp.criteriaFromS, 1.0, 1e-12);
    EXPECT_NEAR(criterion(ramp, "roll_peak_to_peak"), 16, 1e-2);
    // Past the build-up, only the steady roll is left; the headline keeps the whole run.
    o.criteriaFromS = 2.5;
    const RunSummary late = summarizeRun(makeHistory(layout), layout, o);
    EXPECT_NEAR(criterion(late, "roll_peak_to_peak"), 2, 1e-2);
    EXPECT_NEAR(late.peakToPeakRollDeg, 16, 1e-2);
    EXPECT_DOUBLE_EQ(late.maxRollDeg, all.maxRollDeg);
}

TEST(RunSummary, WheelLoadBasisNamesTruckSideOrSingleWheel) {
    const ChannelLayout half = makeLayout(false);
    const RunSummary h = summarizeRun(makeHistory(half), half, makeOptions());
    EXPECT_EQ(h.wheelLoadBasis, "truck side");
    EXPECT_TRUE(std::isnan(h.maxSingleWheelLoadLb));
    const ChannelLayout full = makeLayout(true);
    const RunSummary f = summarizeRun(makeHistory(full), full, makeOptions());
    EXPECT_EQ(f.wheelLoadBasis, "single wheel");
    // The transient's truck-side peak, 80 000 lb, split unevenly: 41 000 lb on one wheel.
    EXPECT_NEAR(f.maxSingleWheelLoadLb, 41000, 600);
    EXPECT_NEAR(f.maxWheelLoadLb, h.maxWheelLoadLb, 1e-9);
}

TEST(RunSummary, WorstEnergyBalanceIsReportedBesideTheEnd) {
    const ChannelLayout layout = makeLayout(false);
    const RunSummary s = summarizeRun(makeHistory(layout, 0.01), layout, makeOptions());
    // At the end |W − ΔE − D| / W = 100·t·0.01 / (1000·t) = 0.1 %; at t = 1 s, |1000 − 299 − 900| / 1000.
    EXPECT_NEAR(s.energyBalanceError, 0.001, 1e-9);
    EXPECT_NEAR(s.worstEnergyBalanceError, 0.199, 1e-9);
}

}  // namespace
}  // namespace rockroll
