#include "scenarios/SpeedSweep.h"
#include "mbmodel/Parallel.h"

#include <algorithm>
#include <cmath>
#include <mutex>
#include <stdexcept>

namespace rockroll {

std::vector<double> getSweepSpeeds(const SweepSpec& s) {
    if (!(s.stepMph > 0)) throw std::invalid_argument("sweep step must be positive");
    if (!(s.toMph >= s.fromMph)) throw std::invalid_argument("sweep: --to-mph must not be below --from-mph");
    std::vector<double> v;
    const long n = std::lround(std::floor((s.toMph - s.fromMph) / s.stepMph + 1e-9));
    for (long k = 0; k <= n; ++k) v.push_back(s.fromMph + k * s.stepMph);
    if (s.direction == SweepDirection::Down) std::reverse(v.begin(), v.end());
    return v;
}

std::vector<SweepPoint> runSweep(const SweepSpec& spec, const std::function<void(const SweepPoint&)>& onPoint) {
    std::vector<SweepPoint> out;
    RunStart next;  // rest
    std::vector<double> staticReference;
    for (double mph : getSweepSpeeds(spec)) {
        Scenario sc = spec.scenario;
        sc.speed = mph * units::mph;
        SweepPoint p;
        p.speedMph = mph;
        p.direction = spec.direction == SweepDirection::Up ? "up" : "down";
        p.start = next.from ? "continued" : "rest";
        next.staticReference = staticReference;
        try {
            const ScenarioRun run = runScenario(sc, next);
            p.summary = run.summary;
            if (staticReference.empty()) staticReference = run.staticReference;
            if (spec.fresh || run.result.stop) {
                // A derailed or overturned car is a result; the next speed starts from rest.
                next = RunStart{};
            } else {
                next.from = run.restart;
                next.rampTime = spec.rampTime;
            }
        } catch (const std::exception& e) {
            // Numerical failures (and any other error of this point) are reported,
            // not dropped; the next speed starts again from rest.
            p.failed = true;
            p.error = e.what();
            next = RunStart{};
        }
        out.push_back(p);
        if (onPoint) onPoint(out.back());
    }
    return out;
}

std::vector<std::vector<SweepPoint>> runSweeps(const std::vector<SweepSpec>& specs, int jobs,
                                               const std::function<void(const SweepPoint&)>& onPoint) {
    for (const auto& spec : specs) checkSwitchesApply(spec.scenario);  // a scenario error must not end a thread
    std::vector<std::vector<SweepPoint>> results(specs.size());
    std::mutex callback;
    auto report = [&](const SweepPoint& p) {
        if (!onPoint) return;
        std::lock_guard<std::mutex> lock(callback);
        onPoint(p);
    };
    parallelFor(specs.size(), std::max(1, jobs), [&](size_t i) { results[i] = runSweep(specs[i], report); });
    return results;
}

}  // namespace rockroll
