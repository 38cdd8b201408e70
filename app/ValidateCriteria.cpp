// validate, section 9: the freight criteria per sweep (from section 2's data). Each
// point is judged by the same criteria as every run's summary (evaluateCriteria,
// mbmodel/RunSummary.h), with the [criteria] limits of each sweep's own scenario
// and validate's two limit options in place of theirs.
#include "app/ValidateSections.h"

#include <algorithm>
#include <fmt/format.h>
#include <fmt/ranges.h>

namespace rockroll::app {

std::string makeCriteriaSection(const Settings& s, const std::vector<SweepResult>& sweeps) {
    // A sweep is judged by its own car's [criteria], as its points' summaries are,
    // with validate's two options in place of the first two limits.
    auto limitsOf = [&](const SweepResult& r) {
        CriteriaLimits limits = r.criteria;
        limits.rollPeakToPeakDeg = s.rollLimitDeg;
        limits.wheelUnloading = 1 - s.wheelLoadLimit;  // a wheel keeping at least that share of its static load
        return limits;
    };
    const CriteriaLimits headerLimits = limitsOf(sweeps.empty() ? SweepResult{} : sweeps.front());
    const std::vector<Criterion> names = evaluateCriteria(RunSummary{}, headerLimits);

    std::string md = fmt::format(
        "## 9. Freight criteria per sweep\n\nEach point is judged by the criteria every run's summary carries "
        "(filtered values, `criteria` in summary.json, taken over each point's time on the perturbed track after its "
        "1 s speed ramp: docs/validation.md, \"Statistics\"): a value above its limit fails. Limits: each sweep's own "
        "scenario file's `[criteria]` table (a car marked * differs from the header's), with `rockroll validate --roll-limit-deg {:g} --wheel-load-limit {:g}` "
        "setting the first two. Speeds that fail, per sweep and criterion (from section 2's data); "
        "\"n/e\": the model does not evaluate it.\n\n| car | A, in | model | direction |",
        s.rollLimitDeg, s.wheelLoadLimit);
    for (const Criterion& c : names) md += fmt::format(" {} ≤ {:g} {} |", c.name, c.limit, c.unit);
    md += "\n|---|---|---|---|";
    for (size_t i = 0; i < names.size(); ++i) md += "---|";
    md += "\n";
    std::vector<std::string> otherLimits;  // cars whose limits differ from the header's
    for (const auto& r : sweeps) {
        const CriteriaLimits limits = limitsOf(r);
        const std::vector<Criterion> own = evaluateCriteria(RunSummary{}, limits);
        std::string differs;
        for (size_t i = 0; i < own.size(); ++i)
            if (own[i].limit != names[i].limit) differs += fmt::format(" {} ≤ {:g} {};", own[i].name, own[i].limit, own[i].unit);
        const std::string mark = differs.empty() ? "" : "*";
        if (!differs.empty()) {
            const std::string note = fmt::format("{}:{}", r.c.car, differs);
            if (std::find(otherLimits.begin(), otherLimits.end(), note) == otherLimits.end()) otherLimits.push_back(note);
        }
        for (const auto* l : {&r.up, &r.down}) {
            std::vector<std::vector<std::string>> fails(names.size());
            std::vector<bool> evaluated(names.size(), false);
            for (const auto& p : *l) {
                if (p.failed) continue;
                const std::vector<Criterion> c = rejudgeCriteria(p.summary.criteria, limits);
                for (size_t i = 0; i < c.size(); ++i) {
                    if (!c[i].evaluated()) continue;
                    evaluated[i] = true;
                    if (!c[i].passes()) fails[i].push_back(fmt::format("{:g}", p.speedMph));
                }
            }
            md += fmt::format("| {}{} | {:.2f} | {} | {} |", r.c.car, mark, r.c.amplitudeIn, r.model,
                              l->empty() ? "" : l->front().direction);
            for (size_t i = 0; i < names.size(); ++i) {
                if (!evaluated[i]) md += " n/e |";
                else if (fails[i].empty()) md += " none |";
                else md += fmt::format(" {} |", fmt::join(fails[i], ", "));
            }
            md += "\n";
        }
    }
    if (!otherLimits.empty())
        md += fmt::format("\n\\* Judged by its own car file's `[criteria]`, where they differ from the header's: {}\n",
                          fmt::join(otherLimits, " "));
    return md + "\n";
}

}  // namespace rockroll::app
