#pragma once
// Physical limits of a run and the monitor that stops it when a limit is
// passed: derailment, overturning, runaway energy and non-finite values, and a
// wall-time guard. Simbody-free; every time-domain model calls RunGuard once
// per recorded sample. Defaults and their sources: docs/model.md, "Run limits".
#include "contacts/WheelRailLaws.h"
#include "mbmodel/CarParameters.h"
#include "mbmodel/ChannelLayout.h"
#include "mbmodel/TimeHistory.h"

#include <array>
#include <chrono>
#include <string>
#include <vector>

namespace rockroll {

struct RunLimits {
    bool enabled = true;
    /// Wheel flange height above the tread and the lateral travel of a wheelset
    /// to flange contact: the scenario's [wheel_rail] values, copied here by
    /// resolveRunLimits (WheelRailSettings; docs/model.md, "Wheel–rail contact").
    double flangeHeight = WheelRailSettings{}.flangeHeight;
    double flangeClearance = WheelRailSettings{}.flangewayClearance;
    /// A wheel in flange contact whose own L/V stays above Nadal's limit longer
    /// than this has climbed its rail: 50 ms, the AAR's wheel-climb duration
    /// (docs/model.md, "Run limits").
    double flangeClimbTime = 0.05;
    /// Nadal's limit of the scenario's flange angle and μ (resolveRunLimits); 0:
    /// the model has no single-wheel lateral force, and the climb rule is off.
    double nadalLimit = 0;
    /// Both wheels of a wheelset off their rails longer than this is a
    /// derailment. 0 = the free-flight time for the flanges to rise clear of
    /// the rail heads and fall back, 2·√(2·h_f/g) (0.144 s for h_f = 1 in).
    double wheelsOffTime = 0;
    /// Car-body roll that puts its centre of gravity over the rail:
    /// 0 = the static rollover angle atan((gauge/2)/h_cg) from the car geometry.
    double rolloverAngle = 0;
    /// Runaway: stored energy exceeding the rails' work less dissipation by more
    /// than this fraction of max(|work|, dissipated, floor).
    double energyRunawayFraction = 0.5;
    /// Energy floor of the runaway test [J]; resolveRunLimits sets it to the
    /// car-body weight × 1 in. Left 0 (limits not resolved for a car, as in the
    /// describing function's internal twin runs) the energy test is off.
    double energyRunawayFloor = 0;
    /// Wall-clock limit of one run [s]; past it the run fails numerically.
    double maxWallTime = 3600;
};

/// Static rollover angle of the car body: its centre of gravity (at rest, springs
/// compressed) directly above one rail, atan((gauge/2) / h_cg) [rad].
double calcStaticRolloverAngle(const CarParameters& car);

/// Bytes the recorded history of a run takes: duration × output rate + 1 rows, each a
/// vector of (time + channels) doubles with its own heap block.
double estimateHistoryBytes(double duration, double outputRate, size_t channels);
/// The most one run's recorded history may take [bytes]: the environment variable
/// ROCKROLL_MAX_MEMORY_MB (a positive number of MiB), else 2048 MiB. std::invalid_argument
/// when the variable is set to anything else.
double getMemoryLimitBytes();

/// Replaces the "from the car" zeros with their values for this car, and copies the
/// flange data of the wheel–rail settings (Nadal's limit only for the creep-and-flange
/// contact: the restraint gives every wheel of a wheelset the same L/V).
RunLimits resolveRunLimits(RunLimits limits, const CarParameters& car, const WheelRailSettings& wheelRail);

/// Watches a run's recorded samples. Derailment and overturning stop the run
/// (RunResult::stop is set, the history is kept); non-finite values, runaway
/// energy and the wall-time limit throw NumericalFailure.
class RunGuard {
public:
    RunGuard(const ChannelLayout& layout, const RunLimits& limits);

    /// After each recorded row (row[0] = t, then the layout's channels).
    /// Returns true when the run must stop; the reason is in `result.stop`.
    bool check(std::span<const double> row, RunResult& result);
    /// Throws NumericalFailure once the wall-time limit has passed.
    void checkWallTime(double simTime) const;

private:
    const ChannelLayout& layout_;
    const RunLimits limits_;
    const std::chrono::steady_clock::time_point start_;
    std::vector<double> airborneSince_;  ///< per wheelset; NaN while a wheel is on its rail
    std::vector<std::array<double, 2>> climbingSince_;  ///< per wheel; NaN while below Nadal's limit
    double energy0_ = 0;
    bool first_ = true;
};

}  // namespace rockroll
