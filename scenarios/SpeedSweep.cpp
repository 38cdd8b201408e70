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

namespace {
/// One sweep from its `done` points on; onPoint(point, index in the sweep).
std::vector<SweepPoint> continueSweep(const SweepSpec& spec, std::vector<SweepPoint> done,
                                      const std::function<void(const SweepPoint&, size_t)>& onPoint) {
    const std::vector<double> speeds = getSweepSpeeds(spec);
    if (done.size() > speeds.size())
        throw std::logic_error(fmt::format("continueSweep: {} points done of a sweep of {}", done.size(), speeds.size()));
    std::vector<SweepPoint> out = std::move(done);
    RunStart next = out.empty() ? RunStart{} : out.back().next;  // rest, or where the last point left the car
    std::vector<double> staticReference = next.staticReference;
    for (size_t k = out.size(); k < speeds.size(); ++k) {
        const double mph = speeds[k];
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
        p.next = next;
        p.next.staticReference = staticReference;
        out.push_back(p);
        if (onPoint) onPoint(out.back(), k);
    }
    return out;
}
}  // namespace

void checkSweepSpecs(const std::vector<SweepSpec>& specs) {
    for (const auto& spec : specs) {
        checkScenario(spec.scenario);
        checkSwitchesApply(spec.scenario);
        getSweepSpeeds(spec);
    }
}

std::vector<SweepPoint> runSweep(const SweepSpec& spec, const std::function<void(const SweepPoint&)>& onPoint) {
    return continueSweep(spec, {}, [&onPoint](const SweepPoint& p, size_t) {
        if (onPoint) onPoint(p);
    });
}

std::vector<std::vector<SweepPoint>> runSweeps(const std::vector<SweepSpec>& specs, int jobs,
                                               const std::function<void(const SweepPoint&)>& onPoint) {
    return runSweepsFrom(specs, jobs, {}, [&onPoint](const SweepPoint& p, size_t, size_t) {
        if (onPoint) onPoint(p);
    });
}

std::vector<std::vector<SweepPoint>> runSweepsFrom(
    const std::vector<SweepSpec>& specs, int jobs, const std::vector<std::vector<SweepPoint>>& done,
    const std::function<void(const SweepPoint&, size_t sweep, size_t index)>& onPoint) {
    checkSweepSpecs(specs);  // a scenario error is bad input, found before any thread starts
    if (!done.empty() && done.size() != specs.size())
        throw std::logic_error("runSweepsFrom: expected one list of done points per sweep");
    std::vector<std::vector<SweepPoint>> results(specs.size());
    std::mutex callback;
    parallelFor(specs.size(), std::max(1, jobs), [&](size_t i) {
        results[i] = continueSweep(specs[i], done.empty() ? std::vector<SweepPoint>{} : done[i],
                                   [&](const SweepPoint& p, size_t k) {
                                       if (!onPoint) return;
                                       std::lock_guard<std::mutex> lock(callback);
                                       onPoint(p, i, k);
                                   });
    });
    return results;
}

SweepJump findSweepJump(const std::vector<double>& speedsMph, const std::vector<double>& steadyRollDeg,
                        SweepDirection direction) {
    SweepJump jump;
    const double sign = direction == SweepDirection::Up ? 1 : -1;
    for (size_t i = 1; i < speedsMph.size() && i < steadyRollDeg.size(); ++i) {
        const double d = sign * (steadyRollDeg[i] - steadyRollDeg[i - 1]);  // false for a NaN
        if (d > jump.changeDeg) {
            jump.changeDeg = d;
            jump.largestChangeMph = speedsMph[i];
            jump.changeFraction = steadyRollDeg[i - 1] > 0 ? d / steadyRollDeg[i - 1]
                                                           : std::numeric_limits<double>::infinity();
        }
    }
    if (jump.changeFraction > kJumpFraction) jump.speedMph = jump.largestChangeMph;
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
