#include "app/ReportComparison.h"

#include "mbmodel/Mit1976.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <optional>
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
    std::string out = fmt::format("Beside the {} report (its §3.1, Figs 8–10: 70-ton loaded, {} in, {} mph):\n",
                                  ref.text("report.year"), formatPublished(ref("section3_1.amplitude", "in")),
                                  formatPublished(ref("section3_1.speed", "mph")));
    out += fmt::format("  {:<44}{:>14}{:>22}\n", "quantity", "rockroll", "report");
    out += fmt::format("  {:<44}{:>14}{:>22}\n", "regime", s.regime, ref.text("section3_1.regime"));
    out += fmt::format("  {:<44}{:>11.0f} lb{:>22}\n", "max side-bearing force", s.maxSideBearingLoadLb,
                       formatPublished(ref.value("section3_1.max_side_bearing_load", "lb"), true));
    out += fmt::format("  {:<44}{:>11.2f} in{:>22}\n", "max wheel lift", s.maxWheelLiftIn,
                       formatPublished(ref.value("section3_1.max_wheel_lift", "in"), true));
    out += fmt::format("  {:<44}{:>11.0f} lb{:>22}\n", "max wheel force (2 wheels, 1 side)", s.maxWheelLoadLb,
                       formatPublished(ref.value("section3_1.max_wheel_load", "lb"), true));
    // The report's "almost two times" compares the 10–14 s wheel forces with those of
    // 0–4 s (low roll angles), not with the static load; the windows are the report's.
    const double earlyFrom = ref("section3_1.early_window_from", "s"), earlyTo = ref("section3_1.early_window_to", "s");
    const double lateFrom = ref("section3_1.late_window_from", "s"), lateTo = ref("section3_1.late_window_to", "s");
    out += fmt::format("  {:<44}{:>14.2f}{:>22}\n",
                       fmt::format("max wheel force {}–{} s / max {}–{} s (raw)", formatPublished(lateFrom),
                                   formatPublished(lateTo), formatPublished(earlyFrom), formatPublished(earlyTo)),
                       calcWheelLoadGrowth(h, earlyFrom, earlyTo, lateFrom, lateTo),
                       formatPublished(ref.value("section3_1.wheel_load_growth", "ratio")));
    return out;
}

namespace {

std::optional<std::string> findSweepCase(const Mit1976& ref, const std::string& car, double amplitudeIn) {
    for (size_t i = 0; i < ref.count("sweeps"); ++i) {
        const std::string k = fmt::format("sweeps[{}].", i);
        if (ref.text(k + "car") == car && std::abs(ref(k + "amplitude", "in") - amplitudeIn) < 1e-9) return k;
    }
    return std::nullopt;
}

}  // namespace

std::string formatReportSweepCase(const Mit1976& ref, const std::string& car, double amplitudeIn) {
    const auto found = findSweepCase(ref, car, amplitudeIn);
    if (!found) return "";
    const std::string& k = *found;
    auto has = [&](const char* name) { return ref.has(k + name); };
    auto mph = [&](const char* name) { return formatPublished(ref.value(k + name, "mph")) + " mph"; };
    auto deg = [&](const char* name) { return formatPublished(ref.value(k + name, "deg")) + "°"; };
    const std::string figures = ref.text(k + "figures");
    std::string out = fmt::format("{} {}", figures.find(',') == std::string::npos ? "Figure" : "Figures", figures);
    if (ref.hasText(k + "statistic")) out += " (plotted: " + ref.text(k + "statistic") + ")";
    out += ": ";
    std::vector<std::string> parts;
    // Speed increasing: light rocking, the jumps up, how far severe rocking persists.
    std::vector<std::string> jumps;
    if (has("jump_up_moderate")) jumps.push_back(fmt::format("at {} (to moderate)", mph("jump_up_moderate")));
    if (has("jump_up_severe")) jumps.push_back(fmt::format("at {} (to severe)", mph("jump_up_severe")));
    std::string up;
    if (has("light_roll")) up = fmt::format("light rocking (roll {})", deg("light_roll"));
    if (!jumps.empty()) up += fmt::format("{}jumps up {}", up.empty() ? "" : ", then ", fmt::join(jumps, " and "));
    if (!up.empty()) parts.push_back("speed increasing, " + up);
    if (has("severe_until_speed") && has("severe_until_roll"))
        parts.push_back(fmt::format("severe rocking persists at lower amplitude to {} at {}", deg("severe_until_roll"),
                                    mph("severe_until_speed")));
    // Speed decreasing: the jump down, then light rocking.
    std::vector<std::string> down;
    if (has("jump_down"))
        down.push_back(has("jump_down_from_roll") && has("jump_down_to_roll")
                           ? fmt::format("the roll drops from {} to {} at {} (severe to moderate)",
                                         deg("jump_down_from_roll"), deg("jump_down_to_roll"), mph("jump_down"))
                           : fmt::format("jumps down at {}", mph("jump_down")));
    if (has("light_below_down")) down.push_back(fmt::format("light rocking below {}", mph("light_below_down")));
    if (!down.empty())
        parts.push_back(fmt::format("speed decreasing{}, {}", has("down_from_speed") ? " from " + mph("down_from_speed") : "",
                                    fmt::join(down, ", then ")));
    if (has("jump_resonance"))
        parts.push_back(fmt::format("a jump resonance at {} (the report does not say whether speed was rising or falling)",
                                    mph("jump_resonance")));
    if (!has("jump_up_moderate") && !has("jump_up_severe") && !has("jump_down") && !has("jump_resonance"))
        parts.push_back("the report gives no jump speeds");
    if (has("max_response_speed")) parts.push_back("maximum response at " + mph("max_response_speed"));
    if (has("max_roll"))
        parts.push_back(fmt::format("maximum roll {}{}", deg("max_roll"),
                                    has("max_roll_speed") ? " at " + mph("max_roll_speed") : ""));
    return out + fmt::format("{}", fmt::join(parts, "; "));
}

}  // namespace rockroll::app
