// validate, section 3: the report's Table 3 (maximum response at selected speeds)
// beside every time-domain model on every branch, and the describing function.
#include "app/ValidateSections.h"

#include <fmt/format.h>

namespace rockroll::app {

using namespace validate_detail;

std::vector<Table3Row> validate_detail::loadTable3(const Mit1976& ref) {
    std::vector<Table3Row> rows;
    for (size_t i = 0; i < ref.count("table3"); ++i) {
        const std::string k = fmt::format("table3[{}].", i);
        rows.push_back({ref.text(k + "label"), ref.text(k + "car"), ref(k + "amplitude", "in"), ref(k + "speed", "mph"),
                        {ref(k + "max_roll", "deg"), ref(k + "max_wheel_lift", "in"), ref(k + "max_wheel_load", "lb"),
                         ref(k + "max_side_bearing_load", "lb"), ref(k + "max_center_plate_load", "lb")},
                        ref.hasText(k + "branch") ? ref.text(k + "branch") : std::string()});
    }
    return rows;
}

std::string makeTable3Section(const Settings& s, const std::vector<SweepResult>& sweeps, const SteadyByAmplitude& steady,
                              const ResidualUncertainty& u, nlohmann::ordered_json& meta) {
    const Mit1976& ref = Mit1976::get();
    const std::vector<Table3Row> table3 = loadTable3(ref);
    const std::vector<std::string>& models = getComparedModels();
    std::vector<RestRun> restRuns;
    for (const auto& row : table3)
        for (const auto& m : models) restRuns.push_back({row.car, row.amplitudeIn, row.speedMph, m});
    const std::vector<RunSummary> fromRest = runFromRest(s, restRuns);

    const std::vector<BranchColumn> columns{{"roll, deg", 0, 1, 2},
                                            {"wheel lift, in", 1, 1, 2},
                                            {"wheel load (2 wheels, 1 side), lb", 2, 1, 0},
                                            {"side bearing, lb", 3, 1, 0},
                                            {"center plate, lb", 4, 1, 0}};
    std::string md = "## 3. The report's Table 3 (maximum response at selected speeds) beside every model\n\n";
    md += describeStatistics(s) + "\n\n";
    if (!u.describe().empty()) md += u.describe() + "\n\n";
    if (ref.hasText("table3_basis.statistic"))
        md += fmt::format("What the report's numbers are: {}\n\n", ref.text("table3_basis.statistic"));
    for (const auto& row : table3) {
        const std::vector<BranchRow> rows = collectBranchRows(sweeps, row.car, row.amplitudeIn, row.speedMph, models, fromRest);
        const std::vector<double> published(row.report.begin(), row.report.end());
        md += fmt::format("**{} at {:g} mph**", row.label, row.speedMph);
        if (!row.branch.empty()) md += fmt::format(" — the report's number is most likely on {}", row.branch);
        md += "\n\nSteady part:\n\n" + formatBranchTable(rows, columns, published, true);
        // The describing function's largest (stable, in the full run) solution at this speed:
        // its roll amplitude, and the loads of its time-domain twin run from it (20 Hz
        // filtered maxima over the twin's last period, a steady-part value like the rows
        // above). Harmonic balance itself fixes a force's mean and first two harmonics, not its peak.
        if (row.car == "70ton-loaded")
            for (const auto& [a, set] : steady)
                if (std::abs(a - row.amplitudeIn) < 1e-9) {
                    if (const auto df = findSteadyAt(set, row.speedMph, !s.quick)) {
                        // The twin run from the solution at exactly this speed.
                        const CarParameters car = makeCarParameters(row.car);
                        const double L = 39 * units::foot;
                        const DescribingFunctionModel model(
                            car, DescribingFunctionModel::calcFundamentalCrossLevel(a * units::inch, car.wheelbase, L), L);
                        const auto x = model.solve(row.speedMph, df->harmonics);
                        const TwinMaxima t = x ? model.calcTwinMaxima(*x, row.speedMph, ContinuationSettings{}.twinPeriods)
                                               : TwinMaxima{};
                        const bool loads = t.stayed();
                        auto load = [&](double x, double report) {
                            return loads ? fmt::format("{:.0f} ({}) twin", x, fmtPct(x, report))
                                         : std::string(t.computed ? "twin left the solution" : "twin not run");
                        };
                        md += fmt::format("| describing function | {} | {:g} | — | {:.2f} ({}) | — | {} | {} | {} |\n",
                                          s.quick ? "largest solution" : "largest stable solution", row.speedMph,
                                          df->rollAmplitudeDeg, fmtPct(df->rollAmplitudeDeg, row.report[0]),
                                          load(t.maxTruckSideWheelLoadLb, row.report[2]),
                                          load(t.maxSideBearingLoadLb, row.report[3]),
                                          load(t.maxCenterPlateLoadLb, row.report[4]));
                    } else {
                        md += fmt::format("| describing function | no {}solution traced at this speed | {:g} | | | | | | |\n",
                                          s.quick ? "" : "stable ", row.speedMph);
                    }
                }
        md += "\nWhole run:\n\n" + formatBranchTable(rows, columns, published, false) + "\n";
        for (const auto& r : rows) {
            if (!r.summary) continue;
            const auto st = getSteadyTableValues(*r.summary), whole = getTableValues(*r.summary);
            for (int q = 0; q < 5; ++q)
                meta["table3"].push_back({{"condition", row.label}, {"quantity", columns[q].header}, {"model", r.model},
                                          {"start", r.start}, {"speed_mph", r.speedMph}, {"steady", st[q]},
                                          {"whole_run", whole[q]}, {"report", row.report[q]}});
        }
    }
    md += "The describing-function row is its largest solution at the report's speed (section 5): roll is its harmonic "
          "amplitude (half peak-to-peak); its loads (marked twin) are the 20 Hz filtered maxima over the last period of "
          "its time-domain twin run from the solution (" + std::to_string(ContinuationSettings{}.twinPeriods) +
          " forcing periods), shown only where the twin stays on the solution. Harmonic balance determines a force's mean and first two harmonics, not its peak: the pointwise "
          "peak of the two-harmonic series pressed into a stiff one-sided contact is an artifact of the method (it "
          "grows with the contact stiffness, docs/bespoke.md) and is not shown.\n\n";
    md += "Where the models differ from the report: (1) wheel lift — the reduced model (ours and the report's) lifts "
          "a wheel by inches, the Simbody models and the eom twin by tenths of an inch; section 10 attributes the "
          "difference by changing one factor at a time. (2) Forces — how much they move with the assumed contact "
          "stiffness is measured in section 7. (3) Roll at a given speed depends on the branch: compare the rows "
          "on the branch the report's number is on. No parameter was tuned to any of these numbers.\n\n";
    return md;
}

}  // namespace rockroll::app
