// validate, section 4: the report's Table 4 (70-ton loaded: the AAR detailed model
// against the report's reduced model) beside every model.
#include "app/ValidateSections.h"

#include <fmt/format.h>

namespace rockroll::app {

using namespace validate_detail;

std::string makeTable4Section(const Settings& s, const std::vector<SweepResult>& sweeps, const ResidualUncertainty& u) {
    const Mit1976& ref = Mit1976::get();
    const std::string car = ref.text("table4.car");
    const double amplitudeIn = ref("table4.amplitude", "in");
    const std::array<double, 2> speeds{ref("table4.aar_speed", "mph"), ref("table4.reduced_speed", "mph")};
    const std::array<const char*, 2> sources{"AAR detailed model", "report's reduced model"};
    const std::array<const char*, 2> prefixes{"aar", "reduced"};
    const std::vector<std::string>& models = getComparedModels();
    std::string md = fmt::format("## 4. The report's Table 4 ({}, {:g} in: AAR detailed model against its reduced model)\n\n",
                                 car == "70ton-loaded" ? "70-ton loaded" : car, amplitudeIn);
    md += fmt::format("At {:g} mph (the AAR model's speed) and {:g} mph (the report's reduced model's), each against the "
                      "published column of that speed. {}\n\n",
                      speeds[0], speeds[1], describeStatistics(s));
    if (!u.describe().empty()) md += u.describe() + "\n\n";
    std::vector<RestRun> restRuns;
    for (double mph : speeds)
        for (const auto& m : models) restRuns.push_back({car, amplitudeIn, mph, m});
    const std::vector<RunSummary> fromRest = runFromRest(s, restRuns);
    // Table 4's rows, in its order: roll, wheel, center plate, side bearing (10³ lb).
    const std::vector<BranchColumn> columns{{"roll, deg", 0, 1, 1},
                                            {"wheel force (2 wheels, 1 side), 10³ lb", 2, 1e-3, 1},
                                            {"center plate force, 10³ lb", 4, 1e-3, 1},
                                            {"side bearing force, 10³ lb", 3, 1e-3, 1}};
    const std::array<std::pair<const char*, const char*>, 4> keys{
        {{"max_roll", "deg"}, {"max_wheel_load", "kip"}, {"max_center_plate_load", "kip"}, {"max_side_bearing_load", "kip"}}};
    for (int k = 0; k < 2; ++k) {
        std::vector<double> published;
        for (const auto& [key, unit] : keys) published.push_back(ref(fmt::format("table4.{}_{}", prefixes[k], key), unit));
        const std::vector<BranchRow> rows = collectBranchRows(sweeps, car, amplitudeIn, speeds[k], models, fromRest);
        md += fmt::format("**{:g} mph, against the {}**\n\nSteady part:\n\n{}\nWhole run:\n\n{}\n", speeds[k], sources[k],
                          formatBranchTable(rows, columns, published, true), formatBranchTable(rows, columns, published, false));
    }
    md += fmt::format("The report found its two programs within {} % on forces in severe rocking.\n\n",
                      formatPublished(ref("table4.force_agreement", "%")));
    return md;
}

}  // namespace rockroll::app
