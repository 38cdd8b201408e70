// validate, section 4: the report's Table 4 (70-ton loaded: the AAR detailed model
// against the report's reduced model) beside every model.
#include "app/ValidateSections.h"

#include <fmt/format.h>

namespace rockroll::app {

using namespace validate_detail;

std::string makeTable4Section(const Settings& s, const std::vector<SweepResult>& sweeps) {
    const Mit1976& ref = Mit1976::get();
    const std::string car = ref.text("table4.car");
    const double amplitudeIn = ref("table4.amplitude", "in");
    const std::array<double, 2> speeds{ref("table4.aar_speed", "mph"), ref("table4.reduced_speed", "mph")};
    const std::vector<std::string> allModels{model_names::kFullCar, model_names::kHalfCar, model_names::kEom, model_names::kReduced};
    std::string md = fmt::format("## 4. The report's Table 4 ({}, {:g} in: AAR detailed model against its reduced model)\n\n",
                                 car == "70ton-loaded" ? "70-ton loaded" : car, amplitudeIn);
    md += fmt::format("Same sources as Table 3, at {:g} mph (the AAR model's speed) and {:g} mph (the reduced model's).\n\n",
                      speeds[0], speeds[1]);
    md += fmt::format("| quantity | AAR, {:g} mph | report reduced, {:g} mph |", speeds[0], speeds[1]);
    for (const auto& m : allModels) md += fmt::format(" {} {:g} / {:g} |", m, speeds[0], speeds[1]);
    md += "\n|---|---|---|";
    for (size_t k = 0; k < allModels.size(); ++k) md += "---|";
    md += "\n";
    // t4[model][speed]: a sweep's maxima there, or one run from rest at the scenario's amplitude.
    std::vector<std::array<std::array<double, 5>, 2>> t4(allModels.size());
    std::vector<std::function<void()>> jobs;
    for (size_t m = 0; m < allModels.size(); ++m)
        for (int k = 0; k < 2; ++k) {
            const double mph = speeds[k];
            if (auto v = findSweepValues(sweeps, car, amplitudeIn, allModels[m], mph)) {
                t4[m][k] = *v;
                continue;
            }
            jobs.push_back([&, m, k, mph] {
                Scenario sc = loadCar(car);
                sc.model = allModels[m];
                sc.speed = mph * units::mph;
                sc.run.duration = s.runDuration;
                sc.run.outputRate = 100;
                t4[m][k] = getTableValues(runScenario(sc).summary);
            });
        }
    runJobs(jobs, s.jobs);
    struct Row {
        const char* label;
        int q;            ///< index into getTableValues
        const char* key;  ///< table4.aar_<key> and table4.reduced_<key>
        const char* unit;
    };
    const std::array<Row, 4> rows{{{"roll, deg", 0, "max_roll", "deg"},
                                   {"wheel force, 10³ lb", 2, "max_wheel_load", "kip"},
                                   {"center plate force, 10³ lb", 4, "max_center_plate_load", "kip"},
                                   {"side bearing force, 10³ lb", 3, "max_side_bearing_load", "kip"}}};
    for (const auto& row : rows) {
        const int q = row.q;
        const double scale = q == 0 ? 1 : 1e-3;
        const std::array<double, 2> published{ref(fmt::format("table4.aar_{}", row.key), row.unit),
                                              ref(fmt::format("table4.reduced_{}", row.key), row.unit)};
        md += fmt::format("| {} | {:g} | {:g} |", row.label, published[0], published[1]);
        for (size_t m = 0; m < allModels.size(); ++m)
            md += fmt::format(" {:.1f} ({}) / {:.1f} ({}) |", t4[m][0][q] * scale, fmtPct(t4[m][0][q] * scale, published[0]),
                              t4[m][1][q] * scale, fmtPct(t4[m][1][q] * scale, published[1]));
        md += "\n";
    }
    md += fmt::format("\nThe report found its two programs within {} % on forces in severe rocking; differences per cell above are "
                      "against the AAR column at {:g} mph and the report's reduced model at {:g} mph.\n\n",
                      formatPublished(ref("table4.force_agreement", "%")), speeds[0], speeds[1]);
    return md;
}

}  // namespace rockroll::app
