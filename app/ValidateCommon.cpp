// validate: what several sections share: the job pool, scenarios, formatting,
// and lookups into section 2's sweeps and section 5's describing function.
#include "app/ValidateSections.h"
#include "mbmodel/Parallel.h"

#include <fmt/format.h>

namespace rockroll::app::validate_detail {

void runJobs(const std::vector<std::function<void()>>& jobs, int threads) {
    parallelFor(jobs.size(), std::max(1, threads), [&](size_t i) { jobs[i](); });
}

Scenario loadCar(const std::string& car) {
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

std::optional<std::array<double, 5>> findSweepValues(const std::vector<SweepResult>& sweeps, const std::string& car,
                                                     double amp, const std::string& model, double mph) {
    for (const auto& r : sweeps) {
        if (r.c.car != car || std::abs(r.c.amplitudeIn - amp) > 1e-9 || r.model != model) continue;
        std::array<double, 5> best{};
        bool any = false;
        for (const auto* l : {&r.up, &r.down}) {
            const SweepPoint* nearest = nullptr;
            for (const auto& p : *l)
                if (!p.failed && (!nearest || std::abs(p.speedMph - mph) < std::abs(nearest->speedMph - mph))) nearest = &p;
            if (!nearest) continue;
            const auto v = getTableValues(nearest->summary);
            for (int k = 0; k < 5; ++k) best[k] = std::max(best[k], v[k]);
            any = true;
        }
        if (any) return best;
    }
    return std::nullopt;
}

std::optional<std::array<double, 3>> findSteadyAt(const std::vector<SteadyStateBranch>& branches, double mph,
                                                  bool stableOnly) {
    std::vector<std::pair<bool, SteadyStatePoint>> pts;
    for (const auto& b : branches)
        for (const auto& p : b.points) pts.push_back({b.stability == Stability::Stable, p});
    std::optional<std::array<double, 3>> best;
    for (size_t k = 1; k < pts.size(); ++k) {
        const auto& a = pts[k - 1].second;
        const auto& b = pts[k].second;
        if ((a.speedMph - mph) * (b.speedMph - mph) > 0 || a.speedMph == b.speedMph) continue;
        if (stableOnly && !(pts[k - 1].first && pts[k].first)) continue;
        const double f = (mph - a.speedMph) / (b.speedMph - a.speedMph);
        const std::array<double, 3> v{a.rollAmplitudeDeg + f * (b.rollAmplitudeDeg - a.rollAmplitudeDeg),
                                      a.maxWheelLoadLb + f * (b.maxWheelLoadLb - a.maxWheelLoadLb),
                                      a.maxSideBearingLoadLb + f * (b.maxSideBearingLoadLb - a.maxSideBearingLoadLb)};
        if (!best || v[0] > (*best)[0]) best = v;
    }
    return best;
}

}  // namespace rockroll::app::validate_detail
