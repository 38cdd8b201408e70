// validate, section 5: the describing-function branches (report §4, Figures 31 and 34)
// over the simulated sweeps; traceSteady's solutions also feed section 3.
#include "app/ValidateSections.h"
#include "mbmodel/CsvWriter.h"

#include <fmt/format.h>

namespace rockroll::app {

using namespace validate_detail;

SteadyByAmplitude traceSteady(const Settings& s) {
    const CarParameters car = makeCarParameters("70ton-loaded");
    const double L = 39 * units::foot;
    const std::vector<double> amps = s.quick ? std::vector<double>{0.75} : std::vector<double>{0.5, 0.75, 1.0};
    std::vector<std::vector<SteadyStateBranch>> all(amps.size());
    std::vector<std::function<void()>> jobs;
    for (size_t i = 0; i < amps.size(); ++i)
        jobs.push_back([&, i] {
            const DescribingFunctionModel df(
                car, DescribingFunctionModel::calcFundamentalCrossLevel(amps[i] * units::inch, car.wheelbase, L), L);
            ContinuationSettings cs;
            cs.fromMph = 10, cs.toMph = 22;
            cs.stability = s.quick ? StabilityMethod::None : StabilityMethod::FoldRule;
            all[i] = df.trace(cs);
        });
    runJobs(jobs, s.jobs);
    SteadyByAmplitude out;
    for (size_t i = 0; i < amps.size(); ++i) out[amps[i]] = all[i];
    return out;
}

std::string makeDescribingFunctionSection(const Settings& s, const SteadyByAmplitude& steady, nlohmann::ordered_json& meta) {
    const Mit1976& ref = Mit1976::get();
    std::vector<double> amps;
    std::vector<std::vector<SteadyStateBranch>> all;
    for (const auto& [a, b] : steady) amps.push_back(a), all.push_back(b);
    std::string md = "## 5. Describing-function branches over the simulated sweeps (report Figures 31 and 34)\n\n";
    md += fmt::format("Made by `rockroll steady scenarios/70ton-loaded.toml --amplitude-in A --from-mph 10 --to-mph 22 "
                      "--stability {}`; data `steady_70ton-loaded_<A>in.csv`, plot `steady_70ton-loaded_<A>in.png` with "
                      "the sweeps' steady roll amplitudes. The input is the fundamental harmonic of the cross-level, "
                      "8A/(3π)·cos(π·wheelbase/L_r) = 0.762·A.\n\n| A, in | solutions traced | folds | speed range with ≥ 3 solutions, mph |\n|---|---|---|---|\n",
                      s.quick ? "none" : "fold");
    for (size_t i = 0; i < amps.size(); ++i) {
        const std::string file = fmt::format("steady_70ton-loaded_{:.2f}in.csv", amps[i]);
        std::vector<SteadyStatePoint> pts;
        writeAtomically(s.out / file, [&](std::ostream& o) {
            CsvWriter csv(o, {"branch", "stable", "speed_mph", "roll_amplitude_deg", "wheel_lift_fraction",
                              "max_wheel_load_lb", "max_side_bearing_load_lb", "folds_before"});
            for (size_t b = 0; b < all[i].size(); ++b)
                for (const auto& p : all[i][b].points) {
                    pts.push_back(p);
                    csv.writeRow({b, toString(all[i][b].stability), CsvCell::fixed(p.speedMph, 4),
                                  CsvCell::fixed(p.rollAmplitudeDeg, 4), CsvCell::fixed(p.wheelLiftFraction, 4),
                                  CsvCell::fixed(p.maxWheelLoadLb, 0), CsvCell::fixed(p.maxSideBearingLoadLb, 0),
                                  p.foldsBefore});
                }
        });
        const int folds = pts.empty() ? 0 : pts.back().foldsBefore;
        double lo = 1e9, hi = -1e9;
        for (double v = 10; v <= 22; v += 0.05) {
            int n = 0;
            for (size_t k = 1; k < pts.size(); ++k)
                if ((pts[k].speedMph - v) * (pts[k - 1].speedMph - v) < 0) ++n;
            if (n >= 3) lo = std::min(lo, v), hi = std::max(hi, v);
        }
        md += fmt::format("| {:.2f} | {} | {} | {} |\n", amps[i], pts.size(), folds,
                          lo <= hi ? fmt::format("{:.1f}–{:.1f}", lo, hi) : "none");
        meta["steady"].push_back({{"amplitude_in", amps[i]}, {"file", file}, {"sweep_key", fmt::format("70ton-loaded_{:.2f}in", amps[i])}});
    }
    md += fmt::format("\nThe report's describing function (§4.3, Figure 31), speed increasing from {} mph, leaves its lowest "
                      "curve at {}, {} and {} mph for 0.5, 0.75 and 1.0 in. Speed decreasing from {} mph, its highest set of "
                      "curves extends to {} mph (±{}° there); its digital simulation could not obtain that curve below {} mph "
                      "(§4.3, Figure 34). Our time-domain twin does not stay on it either (docs/bespoke.md), so we "
                      "mark it unstable.\n\n",
                      formatPublished(ref("describing_function.sweep_from", "mph")),
                      formatPublished(ref("describing_function.jump_up_0_50in", "mph")),
                      formatPublished(ref("describing_function.jump_up_0_75in", "mph")),
                      formatPublished(ref("describing_function.jump_up_1_00in", "mph")),
                      formatPublished(ref("describing_function.high_branch_from", "mph")),
                      formatPublished(ref("describing_function.high_branch_lowest_speed", "mph")),
                      formatPublished(ref("describing_function.high_branch_roll", "deg")),
                      formatPublished(ref("describing_function.simulation_high_branch_not_below", "mph")));
    for (double a : amps) md += fmt::format("![describing function, {:.2f} in](steady_70ton-loaded_{:.2f}in.png)\n", a, a);
    return md + "\n";
}

}  // namespace rockroll::app
