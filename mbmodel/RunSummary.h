#pragma once
// Headline numbers of one run (brief §7), shared by every model.
#include "mbmodel/ChannelLayout.h"
#include "mbmodel/TimeHistory.h"

#include <limits>
#include <string>
#include <vector>

namespace rockroll {

struct RunSummary {
    std::string model, car;
    double speedMph = 0, amplitudeIn = 0, durationS = 0;
    double maxRollDeg = 0;
    double steadyRollAmplitudeDeg = 0;
    double peakToPeakRollDeg = 0;        ///< max − min of roll over the run
    double maxWheelLiftIn = 0;
    // Filtered maxima (headline) and raw peaks.
    double maxWheelLoadLb = 0, rawMaxWheelLoadLb = 0;          ///< two wheels, one truck side
    double minWheelLoadRatio = 0, rawMinWheelLoadRatio = 0;    ///< single wheel / static
    double maxSideBearingLoadLb = 0, rawMaxSideBearingLoadLb = 0;
    double maxCenterPlateLoadLb = 0, rawMaxCenterPlateLoadLb = 0;
    double staticWheelLoadLb = 0;        ///< two wheels, one truck side
    double staticCenterPlateLoadLb = 0;
    std::string regime;                  ///< light | moderate | severe | derailed | overturned
    double centerPlateSeparationLongestS = 0;  ///< longest unbroken full unloading of a center plate [s]
    double centerPlateSeparationTotalS = 0;    ///< a center plate's total unloaded time (the larger truck) [s]
    double wheelLiftLongestS = 0;              ///< longest unbroken lift of any wheel [s]
    double stoppedAtS = -1;              ///< < 0: ran to the end; else when a run limit stopped it [s]
    std::string stopReason;              ///< what stopped it, with values and limit
    double energyBalanceError = std::numeric_limits<double>::quiet_NaN();  ///< |W − ΔE − D| / max(|W|, D); NaN: not audited
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
};

/// Longest unbroken stretch and total time with `on[i]` true, on samples spaced
/// `dt` apart: each sample stands for dt, so one sample counts dt.
struct Durations {
    double longest = 0, total = 0;
};
Durations calcDurations(const std::vector<bool>& on, double dt);

/// The report's regimes (its §1; brief §7) from durations: severe when a center
/// plate stays fully unloaded (load ≤ 0) for at least severeSeparationTime;
/// moderate when a side bearing carries load; light otherwise.
std::string classifyRegime(double centerPlateSeparationLongest, bool sideBearingContact, double severeSeparationTime);

/// Computes the summary of a run recorded with `layout` (history columns are
/// "t_s" followed by the layout's channels). Static values come from sample 0.
RunSummary summarizeRun(const RunResult& run, const ChannelLayout& layout, const SummaryOptions& options);

}  // namespace rockroll
