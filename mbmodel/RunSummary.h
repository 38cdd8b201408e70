#pragma once
// Headline numbers of one run (docs/model.md §6, "Outputs"), shared by every model.
#include "mbmodel/ChannelLayout.h"
#include "mbmodel/TimeHistory.h"

#include <limits>
#include <string>
#include <vector>

namespace rockroll {

/// Limits of the freight acceptance criteria (scenario table [criteria]). The
/// defaults are commonly applied twist-and-roll limits (peak-to-peak roll 6°, no
/// wheel below 10 % of its static load) and assumed values for L/V and the
/// car-body accelerations (docs/model.md "Criteria"): set them from the standard
/// the car is accepted under.
struct CriteriaLimits {
    double rollPeakToPeakDeg = 6;         ///< car-body roll, max − min [deg]
    double wheelUnloading = 0.9;          ///< largest (static − load)/static of any wheel
    /// Largest |L/V| of any single wheel; 0: Nadal's limit of the scenario's flange angle
    /// and μ (resolved by the scenario run, scenarios/ScenarioRun.h).
    double lOverV = 0;
    /// Largest |ΣL/ΣV| of any truck side: 0.5 (docs/model.md, "Summary: freight fields and criteria").
    double truckSideLOverV = 0.5;
    double carBodyVerticalAccelG = 0.9;   ///< largest |vertical acceleration| [g]
    double carBodyLateralAccelG = 0.75;   ///< largest |lateral acceleration| [g]
};

/// One criterion of a run: value ≤ limit passes. A criterion the model cannot
/// evaluate (L/V without lateral wheel forces) has no value and no verdict.
struct Criterion {
    std::string name;       ///< roll_peak_to_peak, wheel_unloading, l_over_v, car_body_vertical_accel, car_body_lateral_accel
    std::string unit;       ///< deg, ratio, g
    double value = 0;       ///< NaN: not evaluated by this model
    double limit = 0;
    bool evaluated() const { return value == value; }
    bool passes() const { return evaluated() && value <= limit; }
};

/// One truck's loads over a run (20 Hz filtered as the headline maxima) [lb].
struct TruckLoads {
    std::string truck;                    ///< "F" (leading) or "R"
    double maxCenterPlateLoadLb = 0, minCenterPlateLoadLb = 0;
    double maxSideBearingLoadLb[2] = {0, 0};  ///< left, right
};

struct RunSummary {
    std::string model, car;
    double speedMph = 0, amplitudeIn = 0, durationS = 0;
    double maxRollDeg = 0;
    double steadyRollAmplitudeDeg = 0;
    double peakToPeakRollDeg = 0;        ///< max − min of roll over the run
    /// Largest |pitch|, |yaw| of the car body and |twist| of a twisting car body (rear half
    /// against front) over the run, unfiltered as roll is; NaN: the model has no such motion.
    double maxPitchDeg = std::numeric_limits<double>::quiet_NaN();
    double maxYawDeg = std::numeric_limits<double>::quiet_NaN();
    double maxCarBodyTwistDeg = std::numeric_limits<double>::quiet_NaN();
    double maxWheelLiftIn = 0;
    // Filtered maxima (headline) and raw peaks.
    double maxWheelLoadLb = 0, rawMaxWheelLoadLb = 0;          ///< two wheels, one truck side
    /// One real wheel's largest load [lb]; NaN where the model has no single wheels
    /// (the half-car models' equivalent wheelset carries one truck side's two wheels).
    double maxSingleWheelLoadLb = std::numeric_limits<double>::quiet_NaN();
    double minWheelLoadRatio = 0, rawMinWheelLoadRatio = 0;    ///< lowest wheel load / static, per wheelLoadBasis
    /// What the wheel-load ratio and unloading are taken over: "single wheel" (one
    /// real wheel) or "truck side" (the two wheels of one truck side, the half-car
    /// models' equivalent wheel).
    std::string wheelLoadBasis = "single wheel";
    double maxSideBearingLoadLb = 0, rawMaxSideBearingLoadLb = 0;
    double maxCenterPlateLoadLb = 0, rawMaxCenterPlateLoadLb = 0;
    double staticWheelLoadLb = 0;        ///< two wheels, one truck side
    double staticCenterPlateLoadLb = 0;
    std::string regime;                  ///< light | moderate | severe | derailed | overturned
    /// Maxima over the steady part of the run: the last SummaryOptions::steadyCycles
    /// forcing periods (at most the second half of the run), on the same 20 Hz filtered
    /// channels as the whole-run maxima above (docs/validation.md, "Statistics").
    struct SteadyMaxima {
        double windowS = 0;                  ///< length of the window, ending at the run's end [s]
        int cycles = 0;                      ///< forcing periods asked for (the window may be shorter)
        double rollDeg = 0;                  ///< largest |roll|
        double wheelLiftIn = 0;
        double truckSideWheelLoadLb = 0;     ///< two wheels, one truck side
        double sideBearingLoadLb = 0;
        double centerPlateLoadLb = 0;
    } steady;
    /// Start of the stretch the criteria are evaluated over: the run's own time on the
    /// perturbed track, without the level lead-in and a sweep point's speed ramp [s].
    double criteriaFromS = 0;
    double centerPlateSeparationLongestS = 0;  ///< longest unbroken full unloading of a center plate [s]
    double centerPlateSeparationTotalS = 0;    ///< a center plate's total unloaded time (the larger truck) [s]
    double wheelLiftLongestS = 0;              ///< longest unbroken lift of any wheel [s]
    double stoppedAtS = -1;              ///< < 0: ran to the end; else when a run limit stopped it [s]
    std::string stopReason;              ///< what stopped it, with values and limit
    double energyBalanceError = std::numeric_limits<double>::quiet_NaN();  ///< |W − ΔE − D| / max(|W|, D) at the end; NaN: not audited
    /// The same ratio's largest value over the run, from SummaryOptions::energyWorstFromS on.
    double worstEnergyBalanceError = std::numeric_limits<double>::quiet_NaN();
    // Freight channels: filtered (headline) and raw peaks of the absolute values.
    // NaN: the model has no such channel (L/V without lateral wheel forces).
    double maxWheelUnloading = 0, rawMaxWheelUnloading = 0;  ///< (static − load)/static, filtered ≤ 1
    double maxLOverV = std::numeric_limits<double>::quiet_NaN(), rawMaxLOverV = std::numeric_limits<double>::quiet_NaN();
    double maxTruckSideLOverV = std::numeric_limits<double>::quiet_NaN(),
           rawMaxTruckSideLOverV = std::numeric_limits<double>::quiet_NaN();
    double maxCarBodyVerticalAccelG = 0, rawMaxCarBodyVerticalAccelG = 0;
    double maxCarBodyLateralAccelG = 0, rawMaxCarBodyLateralAccelG = 0;
    std::vector<TruckLoads> trucks;
    std::vector<Criterion> criteria;
    /// Every evaluated criterion passes.
    bool passesCriteria() const;
    /// "pass", or "FAIL " and the failing criteria's names, then any criterion not
    /// evaluated, e.g. "pass (not evaluated: l_over_v)" (for tables).
    std::string describeCriteria() const;
    std::string filter;
    double simTimeS = 0, wallTimeS = 0;
    long steps = 0;
    long realizations = 0;
};

struct SummaryOptions {
    double forcingPeriod = 0;    ///< L_r / V [s], for the steady window
    int steadyCycles = 3;        ///< cycles at the end used for the steady amplitude
    double filterCutoffHz = 20;
    /// Severe rocking needs a center plate fully unloaded this long without a
    /// break (a shorter bounce is not a rock-off) [s].
    double severeSeparationTime = 0.010;
    std::vector<double> staticReference;  ///< history row of the static state; empty: the run's first sample
    CriteriaLimits criteria;
    /// The criteria, their peak-to-peak roll among them, are taken over t ≥ criteriaFromS:
    /// the numerical devices before it (level lead-in, a sweep point's speed ramp) are
    /// not track the car runs on [s].
    double criteriaFromS = 0;
    /// The worst energy-balance error is taken over t ≥ this (before, W and D are still
    /// tiny and their ratio is noise) [s].
    double energyWorstFromS = 0.5;
};

/// The criteria list of a summary's values against `limits`, in a fixed order.
std::vector<Criterion> evaluateCriteria(const RunSummary& s, const CriteriaLimits& limits);
/// A run's judged criteria (RunSummary::criteria, taken over its criteria window)
/// against other limits: the same values, in evaluateCriteria's order.
std::vector<Criterion> rejudgeCriteria(const std::vector<Criterion>& judged, const CriteriaLimits& limits);

/// Longest unbroken stretch and total time with `on[i]` true, on samples spaced
/// `dt` apart: each sample stands for dt, so one sample counts dt.
struct Durations {
    double longest = 0, total = 0;
};
Durations calcDurations(const std::vector<bool>& on, double dt);

/// The report's regimes (its §1; docs/model.md, "Regimes") from durations: severe when a center
/// plate stays fully unloaded (load ≤ 0) for at least severeSeparationTime;
/// moderate when a side bearing carries load; light otherwise.
std::string classifyRegime(double centerPlateSeparationLongest, bool sideBearingContact, double severeSeparationTime);

/// Computes the summary of a run recorded with `layout` (history columns are
/// "t_s" followed by the layout's channels). Static values come from sample 0.
RunSummary summarizeRun(const RunResult& run, const ChannelLayout& layout, const SummaryOptions& options);

}  // namespace rockroll
