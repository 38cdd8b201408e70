#pragma once
// Speed sweeps with hysteresis (report §3.2): each speed starts from the final
// state of the previous one, and the track input continues from the distance the
// car reached, ramping the speed so the rails never jump. Independent sweeps
// (up and down, several amplitudes, several cars) run in parallel.
#include "scenarios/ScenarioRun.h"

#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace rockroll {

enum class SweepDirection { Up, Down };

struct SweepSpec {
    Scenario scenario;      ///< car, track, model, run duration per speed
    double fromMph = 0, toMph = 0, stepMph = 0;
    SweepDirection direction = SweepDirection::Up;
    bool fresh = false;     ///< every speed from rest instead of carrying state
    double rampTime = 1.0;  ///< speed ramp between speeds [s]
};

struct SweepPoint {
    double speedMph = 0;
    std::string direction;   ///< "up" | "down"
    std::string start;       ///< "rest" | "continued"
    bool failed = false;
    std::string error;       ///< the numerical failure, when failed
    RunSummary summary;      ///< valid unless failed
    /// Where the sweep's next speed starts after this one (rest after a failure, a
    /// derailment or with `fresh`): what a resumed sweep continues from (app/Journal.h).
    RunStart next;
};

/// The most speeds one sweep visits (so that a tiny --step-mph is refused, not run for days).
inline constexpr double kMaxSweepSpeeds = 10000;

/// The speeds a sweep visits, in order (inclusive of both ends, to 1e-9 mph).
/// ScenarioError when an end speed is outside run.speed's range, the step is not
/// positive, the ends are reversed or there would be more than kMaxSweepSpeeds.
std::vector<double> getSweepSpeeds(const SweepSpec& spec);

/// ScenarioError for a sweep that cannot run (its scenario, switches or speeds): bad
/// input, found before anything runs (runSweeps and runSweepsFrom call it first).
void checkSweepSpecs(const std::vector<SweepSpec>& specs);

/// One sweep. onPoint is called after every speed (from this thread).
std::vector<SweepPoint> runSweep(const SweepSpec& spec, const std::function<void(const SweepPoint&)>& onPoint = {});

/// A jump: between neighbouring speeds the steady roll amplitude changes by more than
/// this fraction of the amplitude before the change (rising on the way up, falling on
/// the way down). Smaller changes stay on a branch: the largest falls on section 2's
/// down sweeps that do not leave the upper branch are 1–16 % (docs/validation.md).
constexpr double kJumpFraction = 0.3;

/// A sweep's jump: the largest rise (up) or fall (down) of the steady roll amplitude
/// between neighbouring speeds, counted as a jump when it is more than kJumpFraction of
/// the amplitude before it.
struct SweepJump {
    double speedMph = std::numeric_limits<double>::quiet_NaN();  ///< after the jump; NaN: no jump
    double changeDeg = 0;       ///< the largest change (>= 0), a jump or not
    double changeFraction = 0;  ///< changeDeg over the amplitude before it
    double largestChangeMph = std::numeric_limits<double>::quiet_NaN();  ///< the speed after the largest change
};
/// The jump of amplitudes [deg] at speeds [mph], in the order visited; a NaN amplitude
/// (a failed point) takes no part: neither pair it belongs to counts.
SweepJump findSweepJump(const std::vector<double>& speedsMph, const std::vector<double>& steadyRollDeg,
                        SweepDirection direction);
/// The jump of one sweep's points (failed points take no part).
SweepJump findSweepJump(const std::vector<SweepPoint>& points, SweepDirection direction);

/// Several sweeps on up to `jobs` threads; results in the order of `specs`.
std::vector<std::vector<SweepPoint>> runSweeps(const std::vector<SweepSpec>& specs, int jobs,
                                               const std::function<void(const SweepPoint&)>& onPoint = {});

/// runSweeps for a resumed batch: `done` (one list per spec, each maybe empty) holds
/// each sweep's first points, already run; every sweep continues from its last done
/// point's `next`, exactly as it would have gone on. onPoint gets each new point with
/// its sweep's index in `specs` and its own index in that sweep (under a lock).
std::vector<std::vector<SweepPoint>> runSweepsFrom(
    const std::vector<SweepSpec>& specs, int jobs, const std::vector<std::vector<SweepPoint>>& done,
    const std::function<void(const SweepPoint&, size_t sweep, size_t index)>& onPoint);

}  // namespace rockroll
