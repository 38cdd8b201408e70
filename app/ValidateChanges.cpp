// validate: "What moved since the previous report": the default-case numbers of the
// report this run replaces beside this run's, so a regenerated REPORT.md says what moved.
#include "app/ValidateSections.h"

#include <fmt/format.h>
#include <fstream>

namespace rockroll::app {

PreviousReport readPreviousReport(const std::filesystem::path& out) {
    PreviousReport p;
    std::ifstream oldMeta(out / "validation.json");
    if (oldMeta) {
        try {
            p.defaultRuns = nlohmann::json::parse(oldMeta).value("defaultRuns", nlohmann::json());
        } catch (const nlohmann::json::exception&) {
        }
    }
    std::ifstream oldReport(out / "REPORT.md");
    std::string line;
    if (oldReport && std::getline(oldReport, line) && std::getline(oldReport, line) && std::getline(oldReport, line)) {
        const auto at = line.find("commit ");
        if (at != std::string::npos) p.commit = line.substr(at + 7, line.find(' ', at + 7) - at - 7);
    }
    return p;
}

std::string makeChangesSection(const PreviousReport& previousReport, const nlohmann::ordered_json& meta) {
    const nlohmann::json& previous = previousReport.defaultRuns;
    const std::string& previousCommit = previousReport.commit;
    if (!previous.is_array() || previous.empty() || !meta.contains("defaultRuns")) return "";
    std::string md = fmt::format(
        "## What moved since the previous report\n\nThe default case (section 1) beside the report this one replaced "
        "({}). A change above 0.1 % is in bold.\n\n| model | quantity | previous | now | change |\n|---|---|---|---|---|\n",
        previousCommit.empty() ? "commit unknown" : "commit " + previousCommit);
    const std::vector<std::pair<const char*, const char*>> keys{
        {"regime", "regime"},
        {"max_roll_deg", "max roll, deg"},
        {"max_wheel_lift_in", "max wheel lift, in"},
        {"max_wheel_load_lb", "max wheel load, lb"},
        {"max_side_bearing_load_lb", "max side-bearing load, lb"},
        {"max_center_plate_load_lb", "max center-plate load, lb"}};
    for (const auto& now : meta["defaultRuns"])
        for (const auto& old : previous) {
            if (old.value("model", "") != now.value("model", "")) continue;
            for (const auto& [key, label] : keys) {
                if (!old.contains(key) || !now.contains(key)) continue;
                if (old[key].is_string()) {
                    const std::string a = old[key], b = now[key];
                    md += fmt::format("| {} | {} | {} | {} | {} |\n", now["model"].get<std::string>(), label, a, b,
                                      a == b ? "same" : "**changed**");
                    continue;
                }
                const double a = old[key], b = now[key];
                const double pct = a != 0 ? 100 * (b - a) / std::abs(a) : 0;
                const std::string change = fmt::format("{:+.2f} %", pct);
                md += fmt::format("| {} | {} | {:.4g} | {:.4g} | {} |\n", now["model"].get<std::string>(), label, a, b,
                                  std::abs(pct) > 0.1 ? "**" + change + "**" : change);
            }
        }
    md += "\nWhat else changed in how this report is made (the default-case summaries above use the same statistics "
          "as before): Tables 3 and 4 give one row per model and start (from rest, up sweep, down sweep), every cell "
          "of a row from one run, in a steady-part table and a whole-run table; before, a swept model's cell took the "
          "larger of its up- and down-sweep maxima quantity by quantity, and eom ran only from rest. eom is now swept "
          "on every case (section 2); the full car is swept on the 70-ton loaded car, as before, and runs only from "
          "rest on the others. Section 2 gives each "
          "sweep's largest value per direction, and a down sweep that never drops has no maximum. The criteria "
          "(section 9) leave out each sweep point's 1 s speed ramp, so a value judged there can only be lower than "
          "the whole-run value judged before. Table 3 no longer shows the describing "
          "function's loads, which were the pointwise peaks of its two-harmonic series (docs/bespoke.md). The report's numbers are "
          "traced to the figure or table that prints them (scenarios/reference/mit1976.toml): the jump speeds once "
          "attributed to Figure 11 at 0.75 in are not in the report, and Figure 11 is the 1.0 in case.\n\n";
    return md;
}

}  // namespace rockroll::app
