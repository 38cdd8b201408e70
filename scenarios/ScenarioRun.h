#pragma once
// Runs one scenario end to end: model, simulation, summary.
#include "mbmodel/RockingModel.h"
#include "mbmodel/RunSummary.h"
#include "mbmodel/Simulation.h"
#include "scenarios/ScenarioLoader.h"

#include <memory>

namespace rockroll {

struct ScenarioRun {
    RunResult result;
    RunSummary summary;
};

std::unique_ptr<RockingModel> makeScenarioModel(const Scenario& sc);
/// The equation-of-motion half car of a scenario (its [eom] simplifications).
EomHalfCarModel makeScenarioEomModel(const Scenario& sc);
ScenarioRun runScenario(const Scenario& sc);

}  // namespace rockroll
