// validate: the report's header: provenance (commit, command, time, threads), the
// source report and the quick-or-full note.
#include "app/ValidateSections.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace rockroll::app {

std::string makeHeader(const Settings& s, const std::string& commit, double minutes,
                       const std::vector<std::pair<std::string, PhaseTime>>& phases) {
    std::vector<std::string> parts;
    for (const auto& [name, t] : phases)
        parts.push_back(fmt::format("{} {:.1f} ({:.1f} CPU)", name, t.wallMinutes, t.cpuMinutes));
    return fmt::format(
        "# rockroll cross-validation report\n\nGenerated from commit {} by `rockroll validate{}` in {:.1f} min on {} "
        "thread(s). Regenerate everything with that command from a clean build; every table and plot below names the "
        "command that made it. Source: the {} MIT report \"{}\"; models: docs/model.md (Simbody full and half car) and docs/bespoke.md "
        "(equation-of-motion half car, reduced massless-truck simulation, describing function). No parameter was tuned "
        "to match the report.\n\nWall minutes by phase (CPU minutes of this process's threads): {}.\n\n{}\n\n",
        commit, s.quick ? " --quick" : "", minutes, s.jobs, Mit1976::get().text("report.year"),
        Mit1976::get().text("report.title"), fmt::join(parts, ", "),
        s.quick ? "**Quick run**: sweeps use the reduced model only, 1 mph steps, 15 s per speed; the describing function "
                  "traces 0.75 in without stability. The full run (`rockroll validate`) adds Simbody half-car sweeps at 0.5 mph "
                  "steps, 30 s per speed, and stability."
                : "Full run.");
}

}  // namespace rockroll::app
