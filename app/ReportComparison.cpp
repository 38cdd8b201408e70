#include "app/ReportComparison.h"

#include "mbmodel/Mit1976.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <vector>

namespace rockroll::app {

double calcWheelLoadGrowth(const TimeHistory& h, double earlyFrom, double earlyTo, double lateFrom, double lateTo) {
    std::vector<size_t> columns;
    const std::string prefix = "wheels_", suffix = "_lb";
    for (size_t c = 0; c < h.names.size(); ++c) {
        const std::string& n = h.names[c];
        if (n.size() > prefix.size() + suffix.size() && n.compare(0, prefix.size(), prefix) == 0 &&
            n.compare(n.size() - suffix.size(), suffix.size(), suffix) == 0)
            columns.push_back(c);
    }
    double early = 0, late = 0;
    for (const auto& row : h.samples)
        for (size_t c : columns) {
            if (row[0] >= earlyFrom && row[0] <= earlyTo) early = std::max(early, row[c]);
            if (row[0] >= lateFrom && row[0] <= lateTo) late = std::max(late, row[c]);
        }
    return early > 0 ? late / early : NAN;
}

std::string formatBesideSection3_1(const RunSummary& s, const TimeHistory& h) {
    const Mit1976& ref = Mit1976::get();
    std::string out = "Beside the 1976 report (its §3.1, Figs 8–10: 70-ton loaded, 0.75 in, 16.5 mph):\n";
    out += fmt::format("  {:<44}{:>14}{:>22}\n", "quantity", "rockroll", "report");
    out += fmt::format("  {:<44}{:>14}{:>22}\n", "regime", s.regime, ref.text("section3_1.regime"));
    out += fmt::format("  {:<44}{:>11.0f} lb{:>22}\n", "max side-bearing force", s.maxSideBearingLoadLb,
                       formatPublished(ref.value("section3_1.max_side_bearing_load", "lb"), true));
    out += fmt::format("  {:<44}{:>11.2f} in{:>22}\n", "max wheel lift", s.maxWheelLiftIn,
                       formatPublished(ref.value("section3_1.max_wheel_lift", "in"), true));
    out += fmt::format("  {:<44}{:>11.0f} lb{:>22}\n", "max wheel force (2 wheels, 1 side)", s.maxWheelLoadLb,
                       formatPublished(ref.value("section3_1.max_wheel_load", "lb"), true));
    // The report's "almost two times" compares the 10–14 s wheel forces with those of
    // 0–4 s (low roll angles), not with the static load.
    out += fmt::format("  {:<44}{:>14.2f}{:>22}\n", "max wheel force 10–14 s / max 0–4 s (raw)",
                       calcWheelLoadGrowth(h, 0, 4, 10, 14),
                       formatPublished(ref.value("section3_1.wheel_load_growth", "ratio")));
    return out;
}

}  // namespace rockroll::app
