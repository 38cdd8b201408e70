// validate, section 8: what the added degrees of freedom show (full car against half
// car: pitch, yaw and single-wheel loads).
#include "app/ValidateSections.h"

#include <fmt/format.h>

namespace rockroll::app {

using namespace validate_detail;

std::string makeAddedDofSection(const Settings& s) {
    struct Case { std::string car; double amp, mph; };
    const std::vector<Case> cases{{"70ton-loaded", 0.75, 16.5}, {"100ton-loaded", 0.75, 13}};
    std::vector<std::array<RunSummary, 2>> res(cases.size());
    std::vector<std::array<std::array<double, 2>, 2>> angles(cases.size());  // [model][pitch, yaw]
    std::vector<std::function<void()>> jobs;
    for (size_t i = 0; i < cases.size(); ++i)
        for (int m = 0; m < 2; ++m)
            jobs.push_back([&, i, m] {
                Scenario sc = loadCarScenario(cases[i].car);
                sc.model = m == 0 ? model_names::kFullCar : model_names::kHalfCar;
                sc.track.amplitude = cases[i].amp * units::inch;
                sc.speed = cases[i].mph * units::mph;
                sc.run.duration = s.runDuration;
                sc.run.outputRate = 100;
                const ScenarioRun run = runScenario(sc);
                res[i][m] = run.summary;
                const auto& h = run.result.history;
                for (int a = 0; a < 2; ++a) {
                    const int c = h.column(a == 0 ? "pitch_deg" : "yaw_deg");
                    double mx = 0;
                    for (const auto& row : h.samples) mx = std::max(mx, std::abs(row[c]));
                    angles[i][m][a] = mx;
                }
            });
    runJobs(jobs, s.jobs);
    std::string md = "## 8. What the added degrees of freedom show\n\nMade by `rockroll run scenarios/<car>.toml --model "
                     "fullcar|halfcar --speed-mph V`. The 100-ton car's truck spacing (39.5 ft) differs from the rail "
                     "length (39 ft), so its two trucks see slightly different phases and the body pitches and yaws; "
                     "the full car also gives single-wheel loads, where the half car's equivalent wheelset lumps two "
                     "wheels. The lowest wheel load over its static value is one real wheel's in the full car and one truck "
                     "side's (two wheels) in the half car; the largest single-wheel load exists only in the full car."
                     "\n\n| case | model | max roll, deg | max pitch, deg | max yaw, deg | min wheel load / static | taken over | "
                     "max single-wheel load, lb | max truck-side wheel load (2 wheels), lb |\n|---|---|---|---|---|---|---|---|---|\n";
    for (size_t i = 0; i < cases.size(); ++i)
        for (int m = 0; m < 2; ++m)
            md += fmt::format("| {} {:.2f} in {:g} mph | {} | {:.2f} | {:.3f} | {:.3f} | {:.3f} | {} | {} | {:.0f} |\n",
                              cases[i].car, cases[i].amp, cases[i].mph, m == 0 ? model_names::kFullCar : model_names::kHalfCar,
                              res[i][m].maxRollDeg, angles[i][m][0], angles[i][m][1], res[i][m].minWheelLoadRatio,
                              res[i][m].wheelLoadBasis,
                              std::isfinite(res[i][m].maxSingleWheelLoadLb) ? fmt::format("{:.0f}", res[i][m].maxSingleWheelLoadLb) : "—",
                              res[i][m].maxWheelLoadLb);
    return md + "\nThe half car is planar, so its pitch and yaw are zero by construction.\n\n";
}

}  // namespace rockroll::app
