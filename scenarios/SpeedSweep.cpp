#include "scenarios/SpeedSweep.h"
#include "mbmodel/Parallel.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <mutex>
#include <stdexcept>

namespace rockroll {

std::vector<double> getSweepSpeeds(const SweepSpec& s) {
    const ValueRange& speed = getValueRange("run.speed");
    for (const auto& [option, mph] : {std::pair{"--from-mph", s.fromMph}, std::pair{"--to-mph", s.toMph}})
        if (!speed.contains(mph * units::mph))
            throw ScenarioError(fmt::format("sweep: {} {} mph: expected {} (as run.speed)", option, mph, speed.describe()));
    if (!(s.stepMph > 0 && std::isfinite(s.stepMph)))
        throw ScenarioError(fmt::format("sweep: --step-mph {}: expected a positive, finite speed step [mph]", s.stepMph));
    if (!(s.toMph >= s.fromMph))
        throw ScenarioError(fmt::format("sweep: --to-mph {} is below --from-mph {}: expected to ≥ from", s.toMph,
                                        s.fromMph));
    const double count = std::floor((s.toMph - s.fromMph) / s.stepMph + 1e-9) + 1;
    if (count > kMaxSweepSpeeds)
        throw ScenarioError(fmt::format("sweep: --from-mph {} --to-mph {} --step-mph {} gives {:.0f} speeds: expected at "
                                        "most {} per sweep (a larger step)",
                                        s.fromMph, s.toMph, s.stepMph, count, kMaxSweepSpeeds));
    std::vector<double> v;
    const long n = std::lround(count - 1);
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
        } catch (...) {
            p.failed = true;
            p.error = "an error that is not a std::exception";
            next = RunStart{};
        }
        out.push_back(p);
        if (onPoint) onPoint(out.back());
    }
    return out;
}

std::vector<std::vector<SweepPoint>> runSweeps(const std::vector<SweepSpec>& specs, int jobs,
                                               const std::function<void(const SweepPoint&)>& onPoint) {
    for (const auto& spec : specs) {  // a scenario error is bad input, found before any thread starts
        checkScenario(spec.scenario);
        checkSwitchesApply(spec.scenario);
        getSweepSpeeds(spec);
    }
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

SweepJump findSweepJump(const std::vector<double>& speedsMph, const std::vector<double>& steadyRollDeg,
                        SweepDirection direction) {
    SweepJump jump;
    const double sign = direction == SweepDirection::Up ? 1 : -1;
    for (size_t i = 1; i < speedsMph.size() && i < steadyRollDeg.size(); ++i) {
        const double d = sign * (steadyRollDeg[i] - steadyRollDeg[i - 1]);  // false for a NaN
        if (d > jump.changeDeg) jump.changeDeg = d, jump.speedMph = speedsMph[i];
    }
    return jump;
}

SweepJump findSweepJump(const std::vector<SweepPoint>& points, SweepDirection direction) {
    std::vector<double> speeds, amplitudes;
    for (const SweepPoint& p : points) {
        speeds.push_back(p.speedMph);
        amplitudes.push_back(p.failed ? std::numeric_limits<double>::quiet_NaN() : p.summary.steadyRollAmplitudeDeg);
    }
    return findSweepJump(speeds, amplitudes, direction);
}

}  // namespace rockroll
