#pragma once
// Runs one scenario end to end: model, simulation, summary.
#include "mbmodel/RockingModel.h"
#include "mbmodel/RunSummary.h"
#include "mbmodel/Simulation.h"
#include "scenarios/ScenarioLoader.h"

#include <memory>

namespace rockroll {

/// Where a run starts. Default: static equilibrium on level track, at speed from
/// t = 0. Continuing a speed sweep: the previous run's final state, the distance
/// it reached, and its speed (ramped to the new one over rampTime).
struct RunStart {
    std::vector<double> state;            ///< RunResult::finalState of the previous run; empty: static
    double distance = 0;                  ///< s at t = 0 [m]
    double speed = -1;                    ///< V₀ [m/s]; < 0: no ramp
    double rampTime = 1.0;                ///< [s]
    std::vector<double> staticReference;  ///< history row of the static state (for static loads)
};

struct ScenarioRun {
    RunResult result;
    RunSummary summary;
    double finalDistance = 0;             ///< s at the end [m]
    std::vector<double> staticReference;  ///< the static row this run's summary used
};

std::unique_ptr<RockingModel> makeScenarioModel(const Scenario& sc, const RunStart& start = {});
/// The equation-of-motion half car of a scenario (its [eom] simplifications).
EomHalfCarModel makeScenarioEomModel(const Scenario& sc, const RunStart& start = {});
ScenarioRun runScenario(const Scenario& sc, const RunStart& start = {});
/// ScenarioError if a [reduced] or [attribution] switch is set for a model it does not
/// apply to (it would be silently ignored). runScenario calls it; so does runSweeps,
/// before its threads start.
void checkSwitchesApply(const Scenario& sc);

}  // namespace rockroll
