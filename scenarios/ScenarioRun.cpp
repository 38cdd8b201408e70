#include "scenarios/ScenarioRun.h"

#include "bespoke/EomSimulation.h"
#include "bespoke/ReducedHalfCarModel.h"
#include "bespoke/StiffIntegrator.h"

#include <cmath>
#include <fmt/format.h>

namespace rockroll {

namespace {
TrackMotion makeMotion(const Scenario& sc, const RunStart& start) {
    TrackMotion m;
    m.speed = sc.speed;
    m.startDistance = start.distance;
    m.startSpeed = start.speed;
    m.rampTime = start.rampTime;
    return m;
}
}  // namespace

std::unique_ptr<RockingModel> makeScenarioModel(const Scenario& sc, const RunStart& start) {
    ModelOptions options{sc.speed, sc.entry, makeMotion(sc, start), sc.attribution};
    return makeRockingModel(sc.model, sc.car, TrackInput(sc.track), options);
}

EomHalfCarModel makeScenarioEomModel(const Scenario& sc, const RunStart& start) {
    return EomHalfCarModel(
        sc.car, makeEquivalentWheelsetInput(TrackInput(sc.track), makeMotion(sc, start), sc.car.wheelbase), sc.eom);
}

namespace {
template <class Model>
ScenarioRun summarize(RunResult result, const Model& model, const SummaryOptions& opt) {
    ScenarioRun run;
    run.result = std::move(result);
    run.summary = summarizeRun(run.result, model.getChannels(), opt);
    run.staticReference = opt.staticReference.empty() ? run.result.history.samples.front() : opt.staticReference;
    return run;
}

ScenarioRun runModel(const Scenario& sc, const RunStart& start, const SummaryOptions& opt) {
    try {
        if (sc.model == "eom") {
            const EomHalfCarModel model = makeScenarioEomModel(sc, start);
            const EomRunSettings settings{sc.run.duration, sc.run.outputRate, sc.run.integrator.accuracy,
                                          resolveRunLimits(sc.run.limits, sc.car)};
            if (start.state.empty()) return summarize(simulateEom(model, settings), model, opt);
            return summarize(simulateEom(model, settings, Eigen::Map<const EomHalfCarModel::State>(start.state.data())),
                             model, opt);
        }
        if (sc.model == "reduced") {
            const ReducedHalfCarModel model(
                sc.car, makeEquivalentWheelsetInput(TrackInput(sc.track), makeMotion(sc, start), sc.car.wheelbase),
                sc.reduced);
            return summarize(
                simulateReduced(model, sc.run.duration, nullptr, start.state, resolveRunLimits(sc.run.limits, sc.car)),
                model, opt);
        }
    } catch (const IntegrationFailure& e) {
        throw NumericalFailure(e.what(), e.getTime());
    }
    const auto model = makeScenarioModel(sc, start);
    RunSettings settings = sc.run;
    settings.limits = resolveRunLimits(sc.run.limits, sc.car);
    return summarize(simulate(*model, settings, start.state), *model, opt);
}
}  // namespace

void checkSwitchesApply(const Scenario& sc) {
    const bool simbody = sc.model == "halfcar" || sc.model == "fullcar";
    if (sc.reduced.truckWeight && sc.model != "reduced")
        throw ScenarioError(fmt::format("{}: key 'reduced.truck_weight' = true: expected model reduced, not \"{}\" "
                                        "(the Simbody and eom models always carry the truck's weight)",
                                        sc.source, sc.model));
    if (!simbody && !sc.attribution.truckGravity)
        throw ScenarioError(fmt::format("{}: key 'attribution.truck_gravity' = false: expected model halfcar or "
                                        "fullcar, not \"{}\"", sc.source, sc.model));
    if (!simbody && sc.attribution.truckMassScale != 1)
        throw ScenarioError(fmt::format("{}: key 'attribution.truck_mass_scale' = {}: expected model halfcar or "
                                        "fullcar, not \"{}\"", sc.source, sc.attribution.truckMassScale, sc.model));
}

ScenarioRun runScenario(const Scenario& sc, const RunStart& start) {
    checkSwitchesApply(sc);
    SummaryOptions opt;
    opt.forcingPeriod = sc.track.railLength / sc.speed;
    opt.filterCutoffHz = sc.filterCutoffHz;
    opt.staticReference = start.staticReference;
    opt.severeSeparationTime = sc.severeSeparationTime;
    ScenarioRun run = runModel(sc, start, opt);
    run.finalDistance = makeMotion(sc, start).calcDistance(run.result.simTime);
    run.summary.model = sc.model;
    run.summary.car = sc.car.name;
    // Inputs echoed in the units they were given, without conversion round-off.
    auto echo = [](double x) { return std::round(x * 1e9) / 1e9; };
    run.summary.speedMph = echo(sc.speed / units::mph);
    run.summary.amplitudeIn = echo(sc.track.amplitude / units::inch);
    run.summary.durationS = sc.run.duration;
    return run;
}

}  // namespace rockroll
