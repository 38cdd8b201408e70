#include "mbmodel/RunSummary.h"

#include "mbmodel/EnergyAudit.h"
#include "mbmodel/LowPassFilter.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rockroll {

namespace {
std::vector<double> getColumn(const TimeHistory& h, int channel) {
    std::vector<double> c;
    c.reserve(h.samples.size());
    for (const auto& row : h.samples) c.push_back(row[channel + 1]);
    return c;
}

/// Extremes of the samples from index `from` on (the whole record is filtered first,
/// so a window's values are the filtered record's, not a restarted filter's).
double maxOf(const std::vector<double>& v, size_t from = 0) { return *std::max_element(v.begin() + from, v.end()); }
double minOf(const std::vector<double>& v, size_t from = 0) { return *std::min_element(v.begin() + from, v.end()); }

struct Extremes {
    double filteredMax = -std::numeric_limits<double>::infinity();
    double rawMax = -std::numeric_limits<double>::infinity();
};

Extremes maxOverChannels(const TimeHistory& h, const std::vector<int>& channels, const LowPassFilter& f, size_t from = 0) {
    Extremes e;
    for (int c : channels) {
        const auto x = getColumn(h, c);
        e.rawMax = std::max(e.rawMax, maxOf(x, from));
        e.filteredMax = std::max(e.filteredMax, maxOf(f.apply(x), from));
    }
    return e;
}

/// Largest absolute value over the channels, filtered and raw; NaN for no channel.
Extremes maxAbsOverChannels(const TimeHistory& h, const std::vector<int>& channels, const LowPassFilter& f,
                            size_t from = 0) {
    if (channels.empty())
        return {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN()};
    Extremes e{0, 0};
    for (int c : channels) {
        const auto x = getColumn(h, c);
        const auto y = f.apply(x);
        e.rawMax = std::max({e.rawMax, maxOf(x, from), -minOf(x, from)});
        e.filteredMax = std::max({e.filteredMax, maxOf(y, from), -minOf(y, from)});
    }
    return e;
}

/// The first sample at or after time t (the last sample when none is).
size_t findSample(const TimeHistory& h, double t) {
    size_t i = 0;
    while (i + 1 < h.samples.size() && h.samples[i][0] < t) ++i;
    return i;
}

/// The unloading maxima of a layout's channels from sample `from` on (NaN without channels).
Extremes calcUnloading(const TimeHistory& h, const ChannelLayout& layout, const LowPassFilter& filter, size_t from) {
    if (layout.wheelUnloading.empty())
        return {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN()};
    Extremes e = maxOverChannels(h, layout.wheelUnloading, filter, from);
    // A load cannot be negative, so unloading cannot exceed 1; the filter's overshoot can.
    e.filteredMax = std::min(1.0, e.filteredMax);
    return e;
}
}  // namespace

Durations calcDurations(const std::vector<bool>& on, double dt) {
    Durations d;
    long run = 0;
    for (bool b : on) {
        run = b ? run + 1 : 0;
        d.total += b ? dt : 0;
        d.longest = std::max(d.longest, double(run) * dt);
    }
    return d;
}

std::string classifyRegime(double separationLongest, bool sideBearingContact, double severeSeparationTime) {
    if (separationLongest >= severeSeparationTime * (1 - 1e-9)) return "severe";
    return sideBearingContact ? "moderate" : "light";
}

RunSummary summarizeRun(const RunResult& run, const ChannelLayout& layout, const SummaryOptions& opt) {
    const TimeHistory& h = run.history;
    if (h.samples.size() < 4) throw std::invalid_argument("run too short to summarise");
    RunSummary r;
    const double dt = h.samples[1][0] - h.samples[0][0];
    const LowPassFilter filter(opt.filterCutoffHz, 1 / dt);
    r.filter = filter.getDescription();

    const auto roll = getColumn(h, layout.roll);
    r.maxRollDeg = std::max(std::abs(maxOf(roll)), std::abs(minOf(roll)));
    r.peakToPeakRollDeg = maxOf(roll) - minOf(roll);
    const double tEnd = h.samples.back()[0];
    const double window = std::min(opt.steadyCycles * opt.forcingPeriod, tEnd / 2);
    const size_t steadyFrom = findSample(h, tEnd - window);
    r.steadyRollAmplitudeDeg = (maxOf(roll, steadyFrom) - minOf(roll, steadyFrom)) / 2;
    r.steady.windowS = tEnd - h.samples[steadyFrom][0];
    r.steady.cycles = opt.steadyCycles;
    r.steady.rollDeg = std::max(std::abs(maxOf(roll, steadyFrom)), std::abs(minOf(roll, steadyFrom)));
    for (int c : layout.wheelLift) r.steady.wheelLiftIn = std::max(r.steady.wheelLiftIn, maxOf(getColumn(h, c), steadyFrom));
    r.steady.truckSideWheelLoadLb = maxOverChannels(h, layout.truckSideWheelLoad, filter, steadyFrom).filteredMax;
    r.steady.sideBearingLoadLb = maxOverChannels(h, layout.sideBearing, filter, steadyFrom).filteredMax;
    r.steady.centerPlateLoadLb = maxOverChannels(h, layout.centerPlate, filter, steadyFrom).filteredMax;

    for (int c : layout.wheelLift) r.maxWheelLiftIn = std::max(r.maxWheelLiftIn, maxOf(getColumn(h, c)));
    auto maxAbs = [&h](int c) {
        if (c < 0) return std::numeric_limits<double>::quiet_NaN();
        const auto x = getColumn(h, c);
        return std::max(std::abs(maxOf(x)), std::abs(minOf(x)));
    };
    r.maxPitchDeg = maxAbs(layout.pitch);
    r.maxYawDeg = maxAbs(layout.yaw);
    r.maxCarBodyTwistDeg = maxAbs(layout.carBodyTwist);

    const Extremes wheels = maxOverChannels(h, layout.truckSideWheelLoad, filter);
    r.maxWheelLoadLb = wheels.filteredMax;
    r.rawMaxWheelLoadLb = wheels.rawMax;
    const Extremes sb = maxOverChannels(h, layout.sideBearing, filter);
    r.maxSideBearingLoadLb = sb.filteredMax;
    r.rawMaxSideBearingLoadLb = sb.rawMax;
    const Extremes cp = maxOverChannels(h, layout.centerPlate, filter);
    r.maxCenterPlateLoadLb = cp.filteredMax;
    r.rawMaxCenterPlateLoadLb = cp.rawMax;

    // Static values: the given reference row (a run continuing a sweep does not
    // start static), else the first sample.
    const std::span<const double> staticRow =
        opt.staticReference.empty() ? h.samples.front() : std::span<const double>(opt.staticReference);
    r.minWheelLoadRatio = r.rawMinWheelLoadRatio = std::numeric_limits<double>::infinity();
    for (int c : layout.singleWheelLoad) {
        const auto x = getColumn(h, c);
        const double staticLoad = staticRow[c + 1];
        r.rawMinWheelLoadRatio = std::min(r.rawMinWheelLoadRatio, minOf(x) / staticLoad);
        // A load cannot be negative; the filter's undershoot near zero can.
        r.minWheelLoadRatio = std::min(r.minWheelLoadRatio, std::max(0.0, minOf(filter.apply(x))) / staticLoad);
    }
    // Real single wheels carry SingleWheelLoad alone; the half-car models' equivalent
    // wheel is one truck side's two wheels, and says so.
    std::vector<int> realWheels;
    for (int c : layout.singleWheelLoad)
        if (!hasRole(layout.channels[c].roles, ChannelRole::TruckSideWheelLoad)) realWheels.push_back(c);
    r.wheelLoadBasis = realWheels.empty() && !layout.singleWheelLoad.empty() ? "truck side" : "single wheel";
    if (!realWheels.empty()) r.maxSingleWheelLoadLb = maxOverChannels(h, realWheels, filter).filteredMax;
    r.staticWheelLoadLb = staticRow[layout.truckSideWheelLoad.front() + 1];
    r.staticCenterPlateLoadLb = staticRow[layout.centerPlate.front() + 1];

    const bool sideBearingContact = sb.rawMax > 0;
    for (int c : layout.centerPlate) {
        const auto x = getColumn(h, c);
        std::vector<bool> open(x.size());
        for (size_t i = 0; i < x.size(); ++i) open[i] = x[i] <= 0;
        const Durations d = calcDurations(open, dt);
        r.centerPlateSeparationLongestS = std::max(r.centerPlateSeparationLongestS, d.longest);
        r.centerPlateSeparationTotalS = std::max(r.centerPlateSeparationTotalS, d.total);
    }
    for (int c : layout.wheelLift) {
        const auto x = getColumn(h, c);
        std::vector<bool> lifted(x.size());
        for (size_t i = 0; i < x.size(); ++i) lifted[i] = x[i] > 0;
        r.wheelLiftLongestS = std::max(r.wheelLiftLongestS, calcDurations(lifted, dt).longest);
    }
    r.energyBalanceError = calcEnergyBalanceError(h, layout);
    r.worstEnergyBalanceError = calcWorstEnergyBalanceError(h, layout, opt.energyWorstFromS);

    const Extremes unloading = calcUnloading(h, layout, filter, 0);
    r.maxWheelUnloading = unloading.filteredMax;
    r.rawMaxWheelUnloading = unloading.rawMax;
    const Extremes lv = maxAbsOverChannels(h, layout.lOverV, filter);
    r.maxLOverV = lv.filteredMax;
    r.rawMaxLOverV = lv.rawMax;
    const Extremes tlv = maxAbsOverChannels(h, layout.truckSideLOverV, filter);
    r.maxTruckSideLOverV = tlv.filteredMax;
    r.rawMaxTruckSideLOverV = tlv.rawMax;
    const Extremes av = maxAbsOverChannels(h, layout.carBodyVerticalAccel, filter);
    r.maxCarBodyVerticalAccelG = av.filteredMax;
    r.rawMaxCarBodyVerticalAccelG = av.rawMax;
    const Extremes al = maxAbsOverChannels(h, layout.carBodyLateralAccel, filter);
    r.maxCarBodyLateralAccelG = al.filteredMax;
    r.rawMaxCarBodyLateralAccelG = al.rawMax;
    for (int c : layout.centerPlate) {
        TruckLoads t;
        t.truck = layout.channels[c].truck;
        const auto x = filter.apply(getColumn(h, c));
        t.maxCenterPlateLoadLb = maxOf(x);
        t.minCenterPlateLoadLb = std::max(0.0, minOf(x));  // a contact load cannot be negative; the filter's undershoot can
        int side = 0;  // each truck declares its left side bearing, then its right
        for (int b : layout.sideBearing)
            if (layout.channels[b].truck == t.truck && side < 2)
                t.maxSideBearingLoadLb[side++] = maxOf(filter.apply(getColumn(h, b)));
        r.trucks.push_back(t);
    }
    // The criteria: the same values over the run's time on the perturbed track only.
    const size_t criteriaFrom = findSample(h, opt.criteriaFromS);
    r.criteriaFromS = h.samples[criteriaFrom][0];
    RunSummary judged = r;
    judged.peakToPeakRollDeg = maxOf(roll, criteriaFrom) - minOf(roll, criteriaFrom);
    judged.maxWheelUnloading = calcUnloading(h, layout, filter, criteriaFrom).filteredMax;
    // A wheel's own L/V is judged only where each wheel has its own lateral force (the
    // creep and flange contact, whose wheelsets record flange forces): the restraint
    // shares one force by load, so both wheels of a wheelset show the same ratio.
    bool ownLateral = false;
    for (const auto& w : layout.wheelsets) ownLateral = ownLateral || w.flange[0] >= 0;
    judged.maxLOverV = ownLateral ? maxAbsOverChannels(h, layout.lOverV, filter, criteriaFrom).filteredMax
                                  : std::numeric_limits<double>::quiet_NaN();
    judged.maxTruckSideLOverV = maxAbsOverChannels(h, layout.truckSideLOverV, filter, criteriaFrom).filteredMax;
    judged.maxCarBodyVerticalAccelG = maxAbsOverChannels(h, layout.carBodyVerticalAccel, filter, criteriaFrom).filteredMax;
    judged.maxCarBodyLateralAccelG = maxAbsOverChannels(h, layout.carBodyLateralAccel, filter, criteriaFrom).filteredMax;
    r.criteria = evaluateCriteria(judged, opt.criteria);
    r.regime = classifyRegime(r.centerPlateSeparationLongestS, sideBearingContact, opt.severeSeparationTime);
    if (run.stop) {
        r.regime = run.stop->regime;
        r.stoppedAtS = run.stop->time;
        r.stopReason = run.stop->reason;
    }

    r.simTimeS = run.simTime;
    r.wallTimeS = run.wallTime;
    r.steps = run.steps;
    r.realizations = run.realizations;
    return r;
}

std::vector<Criterion> evaluateCriteria(const RunSummary& s, const CriteriaLimits& l) {
    return {{"roll_peak_to_peak", "deg", s.peakToPeakRollDeg, l.rollPeakToPeakDeg},
            {"wheel_unloading", "ratio", s.maxWheelUnloading, l.wheelUnloading},
            {"l_over_v", "ratio", s.maxLOverV, l.lOverV},
            {"truck_side_l_over_v", "ratio", s.maxTruckSideLOverV, l.truckSideLOverV},
            {"car_body_vertical_accel", "g", s.maxCarBodyVerticalAccelG, l.carBodyVerticalAccelG},
            {"car_body_lateral_accel", "g", s.maxCarBodyLateralAccelG, l.carBodyLateralAccelG}};
}

std::vector<Criterion> rejudgeCriteria(const std::vector<Criterion>& judged, const CriteriaLimits& limits) {
    std::vector<Criterion> out = evaluateCriteria(RunSummary{}, limits);
    for (Criterion& c : out) {
        c.value = std::numeric_limits<double>::quiet_NaN();
        for (const Criterion& j : judged)
            if (j.name == c.name) c.value = j.value;
    }
    return out;
}

bool RunSummary::passesCriteria() const {
    for (const Criterion& c : criteria)
        if (c.evaluated() && !c.passes()) return false;
    return true;
}

std::string RunSummary::describeCriteria() const {
    std::string failed, unevaluated;
    for (const Criterion& c : criteria) {
        if (!c.evaluated()) unevaluated += (unevaluated.empty() ? "" : ",") + c.name;
        else if (!c.passes()) failed += (failed.empty() ? "" : ",") + c.name;
    }
    return (failed.empty() ? "pass" : "FAIL " + failed) +
           (unevaluated.empty() ? "" : " (not evaluated: " + unevaluated + ")");
}

}  // namespace rockroll
