// validate, section 1: time histories of the default case (report Figures 8–10)
// beside the report's §3.1 numbers.
#include "app/ValidateSections.h"
#include "mbmodel/CsvWriter.h"

#include <fmt/format.h>

namespace rockroll::app {

using namespace validate_detail;

namespace {

const std::vector<std::string> kHistoryColumns{"t_s",          "roll_deg",           "cross_level_F_in",
                                               "car_body_vertical_in", "side_bearing_F_L_lb", "side_bearing_F_R_lb",
                                               "wheel_lift_F1_L_in",   "wheel_lift_F1_R_in",  "wheels_F_L_lb",
                                               "wheels_F_R_lb"};

}  // namespace

std::string makeTimeHistorySection(const Settings& s, nlohmann::ordered_json& meta, const ResidualUncertainty& u) {
    const Mit1976& ref = Mit1976::get();
    const std::vector<std::string> models{model_names::kFullCar, model_names::kHalfCar, model_names::kEom, model_names::kReduced};
    std::vector<ScenarioRun> runs(models.size());
    std::vector<std::function<void()>> jobs;
    for (size_t i = 0; i < models.size(); ++i)
        jobs.push_back([&, i] {
            Scenario sc = getDefaultScenario();
            sc.model = models[i];
            runs[i] = runScenario(sc);  // at the scenario's 500 Hz: regime durations need the resolution
        });
    runJobs(jobs, s.jobs);
    // The heading names the case that ran (the default scenario), the report's case of §3.1.
    const Scenario ran = getDefaultScenario();
    std::string md = fmt::format("## 1. Time histories: 70-ton loaded, {:g} in, {:g} mph (report Figures 8–10)\n\n",
                                 ran.track.amplitude / units::inch, ran.speed / units::mph);
    md += "Made by `rockroll run scenarios/70ton-loaded.toml --model M` for each model (20 s, from rest); "
          "data `timehistory_<model>.csv`, plot `timehistory.png`.\n\n";
    md += "| quantity | report §3.1 | fullcar | halfcar | eom | reduced |\n|---|---|---|---|---|---|\n";
    auto row = [&](const char* name, const std::string& report, auto get) {
        md += fmt::format("| {} | {} |", name, report);
        for (const auto& r : runs) md += fmt::format(" {} |", get(r.summary));
        md += "\n";
    };
    row("regime", ref.text("section3_1.regime"), [](const RunSummary& x) { return x.regime; });
    row("max roll, deg", "—", [](const RunSummary& x) { return fmt::format("{:.2f}", x.maxRollDeg); });
    row("max side-bearing force, lb", formatPublished(ref.value("section3_1.max_side_bearing_load", "lb")),
        [](const RunSummary& x) { return fmt::format("{:.0f}", x.maxSideBearingLoadLb); });
    row("max wheel lift, in", formatPublished(ref.value("section3_1.max_wheel_lift", "in")),
        [](const RunSummary& x) { return fmt::format("{:.2f}", x.maxWheelLiftIn); });
    row("max wheel force (2 wheels, 1 side), lb", formatPublished(ref.value("section3_1.max_wheel_load", "lb")),
        [](const RunSummary& x) { return fmt::format("{:.0f}", x.maxWheelLoadLb); });
    row("longest center-plate separation, s", "—",
        [](const RunSummary& x) { return fmt::format("{:.3f}", x.centerPlateSeparationLongestS); });
    row("longest wheel lift, s", "—", [](const RunSummary& x) { return fmt::format("{:.3f}", x.wheelLiftLongestS); });
    row("energy balance error at the end", "—", [](const RunSummary& x) {
        return std::isfinite(x.energyBalanceError) ? fmt::format("{:.2f} %", 100 * x.energyBalanceError)
                                                   : std::string("not audited");
    });
    row("energy balance error, worst over the run (from 0.5 s)", "—", [](const RunSummary& x) {
        return std::isfinite(x.worstEnergyBalanceError) ? fmt::format("{:.2f} %", 100 * x.worstEnergyBalanceError)
                                                        : std::string("not audited");
    });
    row("wall time, s", "—", [](const RunSummary& x) { return fmt::format("{:.1f}", x.wallTimeS); });
    for (size_t i = 0; i < models.size(); ++i) {
        // The CSV keeps every 5th sample (100 Hz), enough for the plots.
        TimeHistory h;
        h.names = runs[i].result.history.names;
        for (size_t k = 0; k < runs[i].result.history.samples.size(); k += 5)
            h.samples.push_back(runs[i].result.history.samples[k]);
        writeAtomically(s.out / fmt::format("timehistory_{}.csv", models[i]),
                        [&](std::ostream& o) { writeHistoryCsv(o, h, kHistoryColumns, 6); });
        meta["timehistories"].push_back({{"model", models[i]}, {"file", fmt::format("timehistory_{}.csv", models[i])}});
    }
    meta["defaultRuns"] = nlohmann::ordered_json::array();
    for (const auto& r : runs) meta["defaultRuns"].push_back(toJson(r.summary));
    if (!u.describe().empty()) md += fmt::format("\n{}\n", u.describe());
    md += "\n![time histories](timehistory.png)\n\n"
          "The reduced model, which is the report's own method, lands closest to the report's §3.1 wheel lift; the "
          "Simbody models and their hand-written twin (eom, within 0.2 % of the Simbody half car) lift a wheel far "
          "less and carry higher filtered side-bearing and wheel forces. Section 10 measures where the wheel-lift "
          "difference comes from, one factor at a time.\n\n";
    return md;
}

}  // namespace rockroll::app
