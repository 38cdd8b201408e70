// validate, section 9: the freight criteria per sweep (from section 2's data). Each
// point is judged by the same criteria as every run's summary (evaluateCriteria,
// mbmodel/RunSummary.h), with the [criteria] limits of the scenarios and validate's
// two limit options in place of theirs.
#include "app/ValidateSections.h"

#include "scenarios/ScenarioLoader.h"

#include <fmt/format.h>

namespace rockroll::app {

std::string makeCriteriaSection(const Settings& s, const std::vector<SweepResult>& sweeps) {
    CriteriaLimits limits = getDefaultScenario().criteria;
    limits.rollPeakToPeakDeg = s.rollLimitDeg;
    limits.wheelUnloading = 1 - s.wheelLoadLimit;  // a wheel keeping at least that share of its static load
    const std::vector<Criterion> names = evaluateCriteria(RunSummary{}, limits);

    std::string md = fmt::format(
        "## 9. Freight criteria per sweep\n\nEach point is judged by the criteria every run's summary carries "
        "(filtered values, `criteria` in summary.json): a value above its limit fails. Limits: the scenario "
        "files' `[criteria]` table, with `rockroll validate --roll-limit-deg {:g} --wheel-load-limit {:g}` "
        "setting the first two. Speeds that fail, per sweep and criterion (from section 2's data); "
        "\"n/e\": the model does not evaluate it.\n\n| car | A, in | model | direction |",
        s.rollLimitDeg, s.wheelLoadLimit);
    for (const Criterion& c : names) md += fmt::format(" {} ≤ {:g} {} |", c.name, c.limit, c.unit);
    md += "\n|---|---|---|---|";
    for (size_t i = 0; i < names.size(); ++i) md += "---|";
    md += "\n";
    for (const auto& r : sweeps)
        for (const auto* l : {&r.up, &r.down}) {
            std::vector<std::vector<std::string>> fails(names.size());
            std::vector<bool> evaluated(names.size(), false);
            for (const auto& p : *l) {
                if (p.failed) continue;
                const std::vector<Criterion> c = evaluateCriteria(p.summary, limits);
                for (size_t i = 0; i < c.size(); ++i) {
                    if (!c[i].evaluated()) continue;
                    evaluated[i] = true;
                    if (!c[i].passes()) fails[i].push_back(fmt::format("{:g}", p.speedMph));
                }
            }
            md += fmt::format("| {} | {:.2f} | {} | {} |", r.c.car, r.c.amplitudeIn, r.model,
                              l->empty() ? "" : l->front().direction);
            for (size_t i = 0; i < names.size(); ++i) {
                if (!evaluated[i]) md += " n/e |";
                else if (fails[i].empty()) md += " none |";
                else md += fmt::format(" {} |", fmt::join(fails[i], ", "));
            }
            md += "\n";
        }
    return md + "\n";
}

}  // namespace rockroll::app
