// validate: what several sections share: the job pool, scenarios, formatting,
// and lookups into section 2's sweeps and section 5's describing function.
#include "app/ValidateSections.h"
#include "mbmodel/Parallel.h"

#include <fmt/format.h>

#include <algorithm>

namespace rockroll::app::validate_detail {

void runJobs(const std::vector<std::function<void()>>& jobs, int threads) {
    parallelFor(jobs.size(), std::max(1, threads), [&](size_t i) { jobs[i](); });
}

Scenario loadCarScenario(const std::string& car) {
    return loadScenarioFile(findDataFile("scenarios/" + car + ".toml").string());
}

Scenario makeLoaded70(const std::string& model, double amplitudeIn, double speedMph, double durationS) {
    Scenario sc = getDefaultScenario();
    sc.model = model;
    sc.track.amplitude = amplitudeIn * units::inch;
    sc.speed = speedMph * units::mph;
    sc.run.duration = durationS;
    sc.run.outputRate = 100;
    return sc;
}

double relativeChange(double a, double b, double floor) {
    const double d = std::max(std::abs(a), std::abs(b));
    return d < floor ? 0.0 : std::abs(b - a) / d;
}

std::string fmtPct(double ours, double report) {
    if (!(report != 0) || !std::isfinite(ours)) return "";
    return fmt::format("{:+.0f} %", 100 * (ours - report) / report);
}

std::string caseKey(const SweepCase& c) { return fmt::format("{}_{:.2f}in", c.car, c.amplitudeIn); }

std::string describeSweptModels(const Settings& s) {
    std::string text = fmt::format("{} (every case)", fmt::join(s.sweepModels, ", "));
    if (!s.fullCarSweepCars.empty()) text += fmt::format(" and fullcar ({})", fmt::join(s.fullCarSweepCars, ", "));
    return text;
}

std::array<double, 5> getTableValues(const RunSummary& x) {
    return {x.maxRollDeg, x.maxWheelLiftIn, x.maxWheelLoadLb, x.maxSideBearingLoadLb, x.maxCenterPlateLoadLb};
}

std::array<double, 5> getSteadyTableValues(const RunSummary& x) {
    return {x.steady.rollDeg, x.steady.wheelLiftIn, x.steady.truckSideWheelLoadLb, x.steady.sideBearingLoadLb,
            x.steady.centerPlateLoadLb};
}

const std::vector<std::string>& getComparedModels() {
    static const std::vector<std::string> models{model_names::kFullCar, model_names::kHalfCar, model_names::kEom,
                                                 model_names::kReduced};
    return models;
}

std::string describeStatistics(const Settings& s) {
    return fmt::format(
        "Each row is one run of one model on one branch: **from rest** (`rockroll run scenarios/<car>.toml --model M "
        "--amplitude-in A --speed-mph V --duration-s {}`), or the point of section 2's **up sweep** or **down sweep** "
        "nearest the report's speed (its speed is given); every cell of a row comes from that run. Two statistics, the "
        "same for every model, each in its own table: the **steady part**, the maxima over the last {} forcing periods "
        "of the run (at most its second half), and the **whole run**, the maxima from t = 0 (a sweep point's maxima include "
        "its 1 s speed ramp and any jump transient). Roll is the largest |roll|, wheel lift the largest lift of any "
        "wheel, and every load is the 20 Hz filtered maximum; the wheel load is one truck side's two wheels in every "
        "model (the half-car models' equivalent wheel; the full car's single-wheel values are in section 8). A model "
        "not swept on a case says so instead of borrowing another run. Each cell: value (difference from the "
        "report).",
        s.runDuration, SummaryOptions{}.steadyCycles);
}

Scenario makeRestScenario(const Settings& s, const Scenario& car, const RestRun& r) {
    Scenario sc = car;
    sc.model = r.model;
    sc.track.amplitude = r.amplitudeIn * units::inch;
    sc.speed = r.speedMph * units::mph;
    sc.run.duration = s.runDuration;
    sc.run.outputRate = 100;
    return sc;
}

std::map<std::string, Scenario> loadCarScenarios(const std::vector<std::string>& names) {
    std::map<std::string, Scenario> cars;
    for (const auto& n : names)
        if (!cars.count(n)) cars.emplace(n, loadCarScenario(n));
    return cars;
}

void forEachRestRun(const Settings& s, const std::vector<RestRun>& runs,
                    const std::function<void(size_t, const Scenario&)>& run) {
    std::vector<std::string> names;
    for (const auto& r : runs) names.push_back(r.car);
    const std::map<std::string, Scenario> cars = loadCarScenarios(names);  // before the threads start
    std::vector<std::function<void()>> jobs;
    for (size_t i = 0; i < runs.size(); ++i)
        jobs.push_back([&, i] { run(i, makeRestScenario(s, cars.at(runs[i].car), runs[i])); });
    runJobs(jobs, s.jobs);
}

std::vector<RunSummary> runFromRest(const Settings& s, const std::vector<RestRun>& runs) {
    std::vector<RunSummary> out(runs.size());
    forEachRestRun(s, runs, [&](size_t i, const Scenario& sc) { out[i] = runScenario(sc).summary; });
    return out;
}

std::vector<BranchRow> collectBranchRows(const std::vector<SweepResult>& sweeps, const std::string& car, double amp,
                                         double mph, const std::vector<std::string>& models,
                                         const std::vector<RunSummary>& fromRest) {
    std::vector<BranchRow> rows;
    for (const auto& m : models) {
        BranchRow rest{m, "from rest", mph, std::nullopt, "not run"};
        for (const auto& x : fromRest)
            if (x.model == m && x.car == car && std::abs(x.amplitudeIn - amp) < 1e-9 && std::abs(x.speedMph - mph) < 1e-9) {
                rest.summary = x;
                rest.missing.clear();
            }
        rows.push_back(rest);
        const SweepResult* swept = nullptr;
        for (const auto& r : sweeps)
            if (r.c.car == car && std::abs(r.c.amplitudeIn - amp) < 1e-9 && r.model == m) swept = &r;
        for (const auto& [label, list] : {std::pair{"up sweep", swept ? &swept->up : nullptr},
                                          std::pair{"down sweep", swept ? &swept->down : nullptr}}) {
            BranchRow row{m, label, NAN, std::nullopt, "not swept on this case"};
            const SweepPoint* nearest = nullptr;
            if (list)
                for (const auto& p : *list)
                    if (!nearest || std::abs(p.speedMph - mph) < std::abs(nearest->speedMph - mph)) nearest = &p;
            if (nearest) {
                row.speedMph = nearest->speedMph;
                if (nearest->failed) row.missing = "failed: " + nearest->error;
                else row.summary = nearest->summary, row.missing.clear();
            }
            rows.push_back(row);
        }
    }
    return rows;
}

std::string formatBranchTable(const std::vector<BranchRow>& rows, const std::vector<BranchColumn>& columns,
                              const std::vector<double>& published, bool steady) {
    std::string md = "| model | start | speed, mph | regime |";
    for (const auto& c : columns) md += " " + c.header + " |";
    md += "\n|---|---|---|---|";
    for (size_t k = 0; k < columns.size(); ++k) md += "---|";
    md += "\n| report | | | |";
    for (double v : published) md += fmt::format(" {:g} |", v);
    md += "\n";
    for (const auto& r : rows) {
        md += fmt::format("| {} | {} | {} |", r.model, r.start,
                          std::isfinite(r.speedMph) ? fmt::format("{:g}", r.speedMph) : "—");
        if (!r.summary) {
            md += fmt::format(" {} |", r.missing);
            for (size_t k = 0; k < columns.size(); ++k) md += " |";
            md += "\n";
            continue;
        }
        md += fmt::format(" {} |", r.summary->regime);
        const auto v = steady ? getSteadyTableValues(*r.summary) : getTableValues(*r.summary);
        for (size_t k = 0; k < columns.size(); ++k) {
            const double x = v[columns[k].index] * columns[k].scale;
            md += fmt::format(" {:.{}f} ({}) |", x, columns[k].decimals, fmtPct(x, published[k]));
        }
        md += "\n";
    }
    return md;
}

namespace {
/// Every solution of `set` at `mph` with its stability: one per crossing of a path.
std::vector<std::pair<SteadyAt, bool>> collectSteadyAt(const SteadyStateSet& set, double mph) {
    std::vector<std::pair<SteadyAt, bool>> out;
    for (const auto& path : set.paths)
        for (size_t k = 1; k < path.points.size(); ++k) {
            const SteadyStatePoint& a = path.points[k - 1];
            const SteadyStatePoint& b = path.points[k];
            if ((a.speedMph - mph) * (b.speedMph - mph) > 0 || a.speedMph == b.speedMph) continue;
            const double f = (mph - a.speedMph) / (b.speedMph - a.speedMph);
            SteadyAt v;
            v.rollAmplitudeDeg = a.rollAmplitudeDeg + f * (b.rollAmplitudeDeg - a.rollAmplitudeDeg);
            v.twin = f < 0.5 ? a.twin : b.twin;
            v.harmonics = a.harmonics + f * (b.harmonics - a.harmonics);
            v.stability = f < 0.5 ? a.stability : b.stability;
            out.push_back({v, a.stability == Stability::Stable && b.stability == Stability::Stable});
        }
    return out;
}
}  // namespace

std::optional<SteadyAt> findSteadyAt(const SteadyStateSet& set, double mph, bool stableOnly) {
    std::optional<SteadyAt> best;
    for (const auto& [v, stable] : collectSteadyAt(set, mph))
        if ((!stableOnly || stable) && (!best || v.rollAmplitudeDeg > best->rollAmplitudeDeg)) best = v;
    return best;
}

std::vector<SteadyAt> findAllSteadyAt(const SteadyStateSet& set, double mph) {
    std::vector<SteadyAt> out;
    for (const auto& [v, stable] : collectSteadyAt(set, mph)) out.push_back(v);
    std::sort(out.begin(), out.end(), [](const SteadyAt& a, const SteadyAt& b) { return a.rollAmplitudeDeg < b.rollAmplitudeDeg; });
    return out;
}

}  // namespace rockroll::app::validate_detail
