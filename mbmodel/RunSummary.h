#pragma once
// Headline numbers of one run (brief §7), shared by every model.
#include "mbmodel/ChannelLayout.h"
#include "mbmodel/TimeHistory.h"

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
    std::string regime;                  ///< light | moderate | severe
    std::string filter;
    double simTimeS = 0, wallTimeS = 0;
    long steps = 0;
    long realizations = 0;
};

struct SummaryOptions {
    double forcingPeriod = 0;    ///< L_r / V [s], for the steady window
    int steadyCycles = 3;        ///< cycles at the end used for the steady amplitude
    double filterCutoffHz = 20;
    std::vector<double> staticReference;  ///< history row of the static state; empty: the run's first sample
};

/// Computes the summary of a run recorded with `layout` (history columns are
/// "t_s" followed by the layout's channels). Static values come from sample 0.
RunSummary summarizeRun(const RunResult& run, const ChannelLayout& layout, const SummaryOptions& options);

}  // namespace rockroll
