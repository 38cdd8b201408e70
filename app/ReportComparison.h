#pragma once
// The default case's numbers beside the 1976 report's §3.1 (Figures 8–10), as the
// bare `rockroll` command prints them, and what the report's §3.2 says of each
// roll-against-speed case (validate's section 2). The report's numbers come from
// scenarios/reference/mit1976.toml (mbmodel/Mit1976.h), never from literals here.
#include "mbmodel/Mit1976.h"
#include "mbmodel/RunSummary.h"
#include "mbmodel/TimeHistory.h"

#include <string>

namespace rockroll::app {

/// The largest raw load over the "wheels_*_lb" channels (two wheels of one truck side)
/// in [lateFrom, lateTo] over the same in [earlyFrom, earlyTo] [s]: the report's §3.1
/// growth of wheel force as the rocking builds up. NaN when the early window has no load.
double calcWheelLoadGrowth(const TimeHistory& h, double earlyFrom, double earlyTo, double lateFrom, double lateTo);

/// The table "quantity | rockroll | report" for the §3.1 case.
std::string formatBesideSection3_1(const RunSummary& s, const TimeHistory& h);

/// What the report says of one roll-against-speed case: the [[sweeps]] table of `ref` whose
/// car and amplitude match, as one sentence that starts with the case's figures, e.g. for the
/// 70-ton loaded car at 1.0 in "Figures 11, 17 (plotted: ...): speed increasing, ..." with its
/// jump speeds up and down; for a case of which the report gives no jump speed the sentence
/// says "the report gives no jump speeds". Empty when `ref` holds no such case.
std::string formatReportSweepCase(const Mit1976& ref, const std::string& car, double amplitudeIn);

}  // namespace rockroll::app
