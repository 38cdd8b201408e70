#pragma once
// Runs one scenario end to end: the model the registry names, its simulation,
// the summary, and the state to continue from.
#include "mbmodel/RunSummary.h"
#include "scenarios/ScenarioLoader.h"
#include "scenarios/TimeDomainModel.h"

#include <memory>
#include <optional>

namespace rockroll {

class RockingModel;  // mbmodel/RockingModel.h (Simbody): include it where the model is used

/// Where a run starts. Default: static equilibrium on level track, at speed from
/// t = 0. Continuing a speed sweep: the previous run's RestartState (its state,
/// the distance it reached and its speed, ramped to the new one over rampTime).
struct RunStart {
    std::optional<RestartState> from;     ///< empty: static equilibrium
    double rampTime = 1.0;                ///< [s]
    std::vector<double> staticReference;  ///< history row of the static state (for static loads); empty: this run's first
};

struct ScenarioRun {
    RunResult result;
    RunSummary summary;
    RestartState restart;                 ///< the end of this run, to continue from
    std::vector<double> staticReference;  ///< the static row this run's summary used
    ChannelLayout channels;               ///< the model's channel table: history columns after t_s, with units and roles
};

/// The track's s(t) for a run of `sc` from `start`.
TrackMotion makeTrackMotion(const Scenario& sc, const RunStart& start = {});
/// The Simbody model of a scenario (sc.model must be a multibody model of the registry).
std::unique_ptr<RockingModel> makeScenarioModel(const Scenario& sc, const RunStart& start = {});
/// The equation-of-motion half car of a scenario (its [eom] simplifications).
EomHalfCarModel makeScenarioEomModel(const Scenario& sc, const TrackMotion& motion);
EomHalfCarModel makeScenarioEomModel(const Scenario& sc, const RunStart& start = {});
ScenarioRun runScenario(const Scenario& sc, const RunStart& start = {});
/// ScenarioError if sc.model is not a model of the registry, a [reduced] or
/// [attribution] switch is set for a model it does not apply to (it would be
/// silently ignored), or run.output_rate is set (Scenario::settingsSet) to a rate the
/// model does not record at (ModelDescriptor::fixedOutputRateHz). runScenario calls it;
/// so does runSweeps, before its threads start.
void checkSwitchesApply(const Scenario& sc);
/// The keys the scenario sets (Scenario::settingsSet) that its model does not use
/// (ModelDescriptor::settings), in settingsSet's order; the command line prints them and
/// the provenance records them as `ignored_settings` (docs/outputs.md).
std::vector<std::string> getIgnoredSettings(const Scenario& sc);
/// The rate the run records at [Hz]: run.output_rate, or the model's fixed rate.
double getRecordedOutputRate(const Scenario& sc);

}  // namespace rockroll
