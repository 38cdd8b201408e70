#pragma once
// Runs the equation-of-motion half car with CVODE BDF and records its channels
// at a fixed output rate, as the Simbody driver does.
#include "bespoke/EomHalfCarModel.h"
#include "mbmodel/RunLimits.h"
#include "mbmodel/TimeHistory.h"

namespace rockroll {

struct EomRunSettings {
    double duration = 0;      ///< [s]
    double outputRate = 500;  ///< [Hz]
    double accuracy = 1e-4;   ///< CVODE relative tolerance
    RunLimits limits;         ///< resolved (resolveRunLimits) before the run
};

/// Absolute tolerances per state: accuracy × a length, speed or deflection scale.
std::vector<double> getEomAbsoluteTolerances(double accuracy);

/// Integrates from `y0` at t = 0 (default: static equilibrium). Throws
/// NumericalFailure with the time and the state.
RunResult simulateEom(const EomHalfCarModel& model, const EomRunSettings& settings);
RunResult simulateEom(const EomHalfCarModel& model, const EomRunSettings& settings,
                      const EomHalfCarModel::State& y0);

}  // namespace rockroll
