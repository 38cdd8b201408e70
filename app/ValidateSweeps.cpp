// validate, section 2: roll against speed, swept up and down (report Figures 11, 14,
// 17, 18, 21, 24), with the jump speeds and the hysteresis band. The sweeps' results
// also feed sections 3, 4 and 9.
#include "app/Progress.h"
#include "app/ReportComparison.h"
#include "app/ValidateSections.h"
#include "mbmodel/CsvWriter.h"

#include <fmt/format.h>

namespace rockroll::app {

using namespace validate_detail;

namespace {

// `figure`: the report's roll-against-speed figures of the case (§3.2): Figure 17 holds the
// 70-ton car at 0.5, 0.75 and 1.0 in, Figure 14 the 0.75 in case alone, Figure 11 the 1.0 in
// case alone; Figure 18 the empty car, Figures 21 and 24 the 100-ton car at 0.75 and 1.0 in.
const std::vector<SweepCase> kSweepCases{{"70ton-loaded", 0.5, 10, 22, "17"},  {"70ton-loaded", 0.75, 10, 22, "14, 17"},
                                         {"70ton-loaded", 1.0, 10, 22, "11, 17"},  {"70ton-empty", 0.75, 24, 40, "18"},
                                         {"100ton-loaded", 0.75, 8, 18, "21"}, {"100ton-loaded", 1.0, 8, 18, "24"}};

void writeSweepCsv(const Settings& s, const SweepResult& r) {
    writeAtomically(s.out / fmt::format("sweep_{}_{}.csv", caseKey(r.c), r.model), [&](std::ostream& o) {
        CsvWriter csv(o, {"direction", "start", "speed_mph", "failed", "max_roll_deg", "steady_roll_amplitude_deg",
                          "peak_to_peak_roll_deg", "max_wheel_lift_in", "max_wheel_load_lb", "min_wheel_load_ratio",
                          "max_side_bearing_load_lb", "max_center_plate_load_lb", "regime", "steady_window_s",
                          "steady_max_roll_deg", "steady_max_wheel_lift_in", "steady_max_truck_side_wheel_load_lb",
                          "steady_max_side_bearing_load_lb", "steady_max_center_plate_load_lb"});
        for (const auto* list : {&r.up, &r.down})
            for (const auto& p : *list) {
                const RunSummary& x = p.summary;
                if (p.failed) {
                    const CsvCell none = CsvCell::empty();
                    csv.writeRow({p.direction, p.start, p.speedMph, 1, none, none, none, none, none, none, none, none,
                                  "failed", none, none, none, none, none, none});
                    continue;
                }
                csv.writeRow({p.direction, p.start, p.speedMph, 0, CsvCell::fixed(x.maxRollDeg, 4),
                              CsvCell::fixed(x.steadyRollAmplitudeDeg, 4), CsvCell::fixed(x.peakToPeakRollDeg, 4),
                              CsvCell::fixed(x.maxWheelLiftIn, 4), CsvCell::fixed(x.maxWheelLoadLb, 0),
                              CsvCell::fixed(x.minWheelLoadRatio, 4), CsvCell::fixed(x.maxSideBearingLoadLb, 0),
                              CsvCell::fixed(x.maxCenterPlateLoadLb, 0), x.regime, CsvCell::fixed(x.steady.windowS, 3),
                              CsvCell::fixed(x.steady.rollDeg, 4), CsvCell::fixed(x.steady.wheelLiftIn, 4),
                              CsvCell::fixed(x.steady.truckSideWheelLoadLb, 0), CsvCell::fixed(x.steady.sideBearingLoadLb, 0),
                              CsvCell::fixed(x.steady.centerPlateLoadLb, 0)});
            }
    });
}

}  // namespace

std::string validate_detail::describeLargest(const SweepResult& r, SweepDirection direction, double (*value)(const RunSummary&)) {
    const std::vector<SweepPoint>& l = direction == SweepDirection::Up ? r.up : r.down;
    const SweepPoint* best = nullptr;
    for (const auto& p : l)
        if (!p.failed && (!best || value(p.summary) > value(best->summary))) best = &p;
    if (!best) return "—";
    const std::string at = fmt::format("{:.2f}° at {:g} mph", value(best->summary), best->speedMph);
    const bool neverDrops = direction == SweepDirection::Down && !std::isfinite(r.jumpDownMph);
    return neverDrops && best == &l.back() ? "stays on the upper branch to the lowest speed swept (" + at + ")" : at;
}

void validate_detail::findJumps(SweepResult& r) {
    r.jumpUpMph = findSweepJump(r.up, SweepDirection::Up).speedMph;
    r.jumpDownMph = findSweepJump(r.down, SweepDirection::Down).speedMph;
}

SweepSpec validate_detail::makeSweepSpec(const Settings& s, const Scenario& car, const SweepCase& c, const std::string& model,
                                         SweepDirection direction) {
    SweepSpec spec;
    spec.scenario = car;
    spec.scenario.model = model;
    spec.scenario.track.amplitude = c.amplitudeIn * units::inch;
    spec.scenario.run.duration = s.sweepDuration;
    spec.scenario.run.outputRate = 100;
    spec.fromMph = c.fromMph, spec.toMph = c.toMph, spec.stepMph = s.sweepStep;
    spec.direction = direction;
    return spec;
}

std::vector<SweepResult> runAllSweeps(const Settings& s) {
    std::vector<SweepSpec> specs;
    std::vector<SweepResult> results;
    std::vector<std::pair<std::string, SweepCase>> pairs;
    for (const auto& m : s.sweepModels)
        for (const auto& c : kSweepCases) pairs.emplace_back(m, c);
    for (const auto& c : kSweepCases)
        if (std::count(s.fullCarSweepCars.begin(), s.fullCarSweepCars.end(), c.car)) pairs.emplace_back(model_names::kFullCar, c);
    for (const auto& [m, c] : pairs) {
        SweepResult r;
        r.c = c;
        r.model = m;
        const Scenario car = loadCarScenario(c.car);
        r.criteria = resolveCriteriaLimits(car);
        results.push_back(r);
        for (auto dir : {SweepDirection::Up, SweepDirection::Down}) specs.push_back(makeSweepSpec(s, car, c, m, dir));
    }
    size_t total = 0;
    for (const auto& sp : specs) total += getSweepSpeeds(sp).size();
    // parallelFor takes jobs in index order, so the longest go first: otherwise the
    // full car's sweep sets, listed last, finish alone on one thread. Each set's cost
    // is its simulated time over its model's speed (bench/README.md: the full car runs
    // about 3x slower than the half car, the half car about 2x slower than eom, and eom
    // slower than the reduced model).
    // The results do not depend on the order (each set is independent; stored by index).
    auto costOf = [](const SweepSpec& sp) {
        const std::string& m = sp.scenario.model;
        const double speed = m == model_names::kFullCar ? 4 : m == model_names::kHalfCar ? 12 : m == model_names::kEom ? 24 : 100;
        return double(getSweepSpeeds(sp).size()) * sp.scenario.run.duration / speed;
    };
    std::vector<size_t> order(specs.size());
    for (size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return costOf(specs[a]) > costOf(specs[b]); });
    std::vector<SweepSpec> longestFirst;
    for (size_t i : order) longestFirst.push_back(specs[i]);
    SweepProgress progress("validate: sweeps", total);
    const auto sorted = runSweeps(longestFirst, s.jobs, [&progress](const SweepPoint& p) { progress(p); });
    std::vector<std::vector<SweepPoint>> out(specs.size());
    for (size_t k = 0; k < order.size(); ++k) out[order[k]] = sorted[k];
    for (size_t i = 0; i < results.size(); ++i) {
        results[i].up = out[2 * i];
        results[i].down = out[2 * i + 1];
        findJumps(results[i]);
    }
    return results;
}

std::string makeSweepSection(const Settings& s, const std::vector<SweepResult>& sweeps, nlohmann::ordered_json& meta) {
    const Mit1976& ref = Mit1976::get();
    std::string md = "## 2. Roll against speed, swept up and down (report Figures 11, 14, 17, 18, 21, 24)\n\n";
    md += fmt::format(
        "Made by `rockroll sweep scenarios/<car>.toml --model M --amplitude-in A --from-mph V1 --to-mph V2 "
        "--step-mph {} --duration-s {} --direction both` for models: {}. Each speed starts from the final state of "
        "the previous one; the speed ramps over 1 s so the rails never jump. Data `sweep_<car>_<A>in_<model>.csv`, "
        "plots `sweep_<car>_<A>in.png` (roll) and `sweep_loads_<car>_<A>in.png` (wheel lift and loads).\n\n",
        s.sweepStep, s.sweepDuration, describeSweptModels(s));
    md += fmt::format(
        "Steady roll amplitude: half the peak-to-peak roll over each point's last 3 forcing periods. A jump is the "
        "largest rise (up sweep) or fall (down sweep) of the steady roll amplitude between neighbouring speeds when it "
        "is more than {:g} % of the amplitude before it (\"none\": no change that large; section 11 sets each drop beside "
        "the branch it leaves). The largest amplitude of a sweep is given with its speed; a down sweep that never drops "
        "and is largest at its lowest speed has no maximum in the range swept: it stays on the upper branch to the "
        "lowest speed swept.\n\n",
        100 * kJumpFraction);
    md += "| car | A, in | model | jump up, mph (up sweep) | jump down, mph (down sweep) | hysteresis band, mph | "
          "largest steady roll, up sweep | largest steady roll, down sweep |\n"
          "|---|---|---|---|---|---|---|---|\n";
    auto steadyRoll = [](const RunSummary& x) { return x.steadyRollAmplitudeDeg; };
    for (const auto& r : sweeps) {
        writeSweepCsv(s, r);
        const std::string upCell = describeLargest(r, SweepDirection::Up, steadyRoll);
        const std::string downCell = describeLargest(r, SweepDirection::Down, steadyRoll);
        const bool band = std::isfinite(r.jumpUpMph) && std::isfinite(r.jumpDownMph) && r.jumpDownMph < r.jumpUpMph;
        md += fmt::format("| {} | {:.2f} | {} | {} | {} | {} | {} | {} |\n", r.c.car, r.c.amplitudeIn, r.model,
                          std::isfinite(r.jumpUpMph) ? fmt::format("{:.1f}", r.jumpUpMph) : "none",
                          std::isfinite(r.jumpDownMph) ? fmt::format("{:.1f}", r.jumpDownMph) : "none",
                          band ? fmt::format("{:.1f}–{:.1f}", r.jumpDownMph, r.jumpUpMph) : "—", upCell, downCell);
        meta["sweeps"].push_back({{"car", r.c.car}, {"amplitude_in", r.c.amplitudeIn}, {"model", r.model},
                                  {"file", fmt::format("sweep_{}_{}.csv", caseKey(r.c), r.model)},
                                  {"key", caseKey(r.c)}, {"figure", r.c.figure},
                                  {"jump_up_mph", std::isfinite(r.jumpUpMph) ? nlohmann::ordered_json(r.jumpUpMph) : nlohmann::ordered_json(nullptr)},
                                  {"jump_down_mph", std::isfinite(r.jumpDownMph) ? nlohmann::ordered_json(r.jumpDownMph) : nlohmann::ordered_json(nullptr)}});
    }
    // What the down sweeps reach at their lowest speed, per model (the high branch or not).
    md += "\nDown sweeps at their lowest speed (steady roll amplitude): ";
    std::vector<std::string> ends;
    for (const auto& r : sweeps)
        if (!r.down.empty() && !r.down.back().failed && !r.up.empty() && !r.up.front().failed)
            ends.push_back(fmt::format("{} {:.2f} in {}: {:.2f}° (up sweep there {:.2f}°)", r.c.car, r.c.amplitudeIn,
                                       r.model, r.down.back().summary.steadyRollAmplitudeDeg,
                                       r.up.front().summary.steadyRollAmplitudeDeg));
    md += fmt::format("{}. Where the down sweep ends far above the up sweep, the model holds the high-amplitude branch "
                      "all the way down, as the report's describing function does (§4.3, Figure 31: its highest set of "
                      "curves extends to {} mph, ±{}° there) but its digital simulation did not: \"For speeds below {} mph, "
                      "digital simulation program solutions could not be obtained for the highest level of response "
                      "curve\" (§4.3, Figure 34).\n",
                      fmt::join(ends, "; "),
                      formatPublished(ref("describing_function.high_branch_lowest_speed", "mph")),
                      formatPublished(ref("describing_function.high_branch_roll", "deg")),
                      formatPublished(ref("describing_function.simulation_high_branch_not_below", "mph")));
    // Each swept case beside what the report's §3.2 says of the figure that holds it
    // (mit1976.toml [[sweeps]]). Figure 11 plots the maximum roll of each run, so the
    // largest max roll of the swept runs is given beside the jump speeds.
    md += "\nEach swept case beside what the report's §3.2 says of the figure that holds it. \"Here\" gives each "
          "model's jump speeds (as in the table above; the band between them is the hysteresis) and, for each sweep on its own, the largest max roll "
          "of its runs, the statistic Figure 11 plots (a point's whole run, its speed ramp and any jump transient "
          "included).\n\n";
    for (const auto& c : kSweepCases) {
        const std::string report = formatReportSweepCase(ref, c.car, c.amplitudeIn);
        std::vector<std::string> ours;
        for (const auto& r : sweeps) {
            if (r.c.car != c.car || r.c.amplitudeIn != c.amplitudeIn) continue;
            auto maxRoll = [](const RunSummary& x) { return x.maxRollDeg; };
            ours.push_back(fmt::format("{} jumps up {}, down {}; largest max roll up {}, down {}", r.model,
                                       std::isfinite(r.jumpUpMph) ? fmt::format("{:.1f} mph", r.jumpUpMph) : "none",
                                       std::isfinite(r.jumpDownMph) ? fmt::format("{:.1f} mph", r.jumpDownMph) : "none",
                                       describeLargest(r, SweepDirection::Up, maxRoll),
                                       describeLargest(r, SweepDirection::Down, maxRoll)));
        }
        md += fmt::format("- **{} {:.2f} in.** {}. Here: {}.\n", c.car, c.amplitudeIn,
                          report.empty() ? fmt::format("Figure {}: mit1976.toml holds nothing of this case", c.figure) : report,
                          ours.empty() ? std::string("not swept") : fmt::format("{}", fmt::join(ours, "; ")));
    }
    md += "\n";
    for (const auto& c : kSweepCases)
        md += fmt::format("![roll against speed, {} {:.2f} in](sweep_{}.png)\n![loads, {} {:.2f} in](sweep_loads_{}.png)\n\n",
                          c.car, c.amplitudeIn, caseKey(c), c.car, c.amplitudeIn, caseKey(c));
    return md;
}

}  // namespace rockroll::app
