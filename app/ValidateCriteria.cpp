// validate, section 9: twist-and-roll criteria per sweep (from section 2's data).
#include "app/ValidateSections.h"

#include <fmt/format.h>

namespace rockroll::app {

std::string makeCriteriaSection(const Settings& s, const std::vector<SweepResult>& sweeps) {
    std::string md = fmt::format("## 9. Twist-and-roll criteria per sweep\n\nLimits (configurable: `rockroll validate "
                                 "--roll-limit-deg {:g} --wheel-load-limit {:g}`): peak-to-peak roll at most {:g}°, no "
                                 "single wheel below {:.0f} % of its static load (filtered). Speeds that fail, per sweep "
                                 "(from section 2's data).\n\n| car | A, in | model | direction | fail roll p-p | fail wheel load |\n|---|---|---|---|---|---|\n",
                                 s.rollLimitDeg, s.wheelLoadLimit, s.rollLimitDeg, 100 * s.wheelLoadLimit);
    for (const auto& r : sweeps)
        for (const auto* l : {&r.up, &r.down}) {
            std::vector<std::string> roll, wheel;
            for (const auto& p : *l) {
                if (p.failed) continue;
                if (p.summary.peakToPeakRollDeg > s.rollLimitDeg) roll.push_back(fmt::format("{:g}", p.speedMph));
                if (p.summary.minWheelLoadRatio < s.wheelLoadLimit) wheel.push_back(fmt::format("{:g}", p.speedMph));
            }
            md += fmt::format("| {} | {:.2f} | {} | {} | {} | {} |\n", r.c.car, r.c.amplitudeIn, r.model,
                              l->empty() ? "" : l->front().direction, roll.empty() ? "none" : fmt::format("{}", fmt::join(roll, ", ")),
                              wheel.empty() ? "none" : fmt::format("{}", fmt::join(wheel, ", ")));
        }
    return md + "\n";
}

}  // namespace rockroll::app
