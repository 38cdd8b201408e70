#pragma once
// How a run is integrated and recorded: duration, output rate, integrator and its
// accuracy, run limits. Simbody-free (the driver, mbmodel/Simulation.h, uses it).
#include "mbmodel/RunLimits.h"

#include <string>
#include <vector>

namespace rockroll {

struct IntegratorSettings {
    std::string method = "cpodes";  ///< cpodes | rkmerson | rk3 | rkf | verlet
    double accuracy = 1e-4;
    double maxStepSize = 0;         ///< 0 = integrator's default [s]
};

struct RunSettings {
    double duration = 20;           ///< [s]
    double outputRate = 500;        ///< samples per second [Hz]
    IntegratorSettings integrator;
    RunLimits limits;               ///< resolved (resolveRunLimits) before the run
};

std::vector<std::string> getIntegratorNames();

}  // namespace rockroll
