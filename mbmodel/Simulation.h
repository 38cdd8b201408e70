#pragma once
// The simulation driver shared by every Simbody model: integrator choice and
// accuracy, fixed-rate recording, and failure reports with time and state.
#include "mbmodel/RockingModel.h"
#include "mbmodel/RunLimits.h"
#include "mbmodel/RunSettings.h"
#include "mbmodel/TimeHistory.h"

#include <stdexcept>
#include <string>
#include <vector>

namespace rockroll {

/// Runs `model` from its static state for settings.duration.
/// From static equilibrium, or (initialY not empty) from that flat state
/// [q, u, z] at t = 0, as a previous run's RunResult::finalState holds it.
RunResult simulate(const RockingModel& model, const RunSettings& settings,
                   const std::vector<double>& initialY = {});

}  // namespace rockroll
