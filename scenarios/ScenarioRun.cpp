#include "scenarios/ScenarioRun.h"

#include "bespoke/EomSimulation.h"
#include "bespoke/ReducedHalfCarModel.h"
#include "bespoke/StiffIntegrator.h"

#include <cmath>

namespace rockroll {

std::unique_ptr<RockingModel> makeScenarioModel(const Scenario& sc) {
    return makeRockingModel(sc.model, sc.car, TrackInput(sc.track), ModelOptions{sc.speed, sc.entry});
}

EomHalfCarModel makeScenarioEomModel(const Scenario& sc) {
    return EomHalfCarModel(sc.car, makeEquivalentWheelsetInput(TrackInput(sc.track), sc.speed, sc.car.wheelbase),
                           sc.eom);
}

namespace {
ScenarioRun runEom(const Scenario& sc, const SummaryOptions& opt) {
    const EomHalfCarModel model = makeScenarioEomModel(sc);
    ScenarioRun run;
    try {
        run.result = simulateEom(model, {sc.run.duration, sc.run.outputRate, sc.run.integrator.accuracy});
    } catch (const IntegrationFailure& e) {
        throw NumericalFailure(e.what(), e.getTime());
    }
    run.summary = summarizeRun(run.result, model.getChannels(), opt);
    return run;
}
ScenarioRun runReduced(const Scenario& sc, const SummaryOptions& opt) {
    const ReducedHalfCarModel model(sc.car,
                                    makeEquivalentWheelsetInput(TrackInput(sc.track), sc.speed, sc.car.wheelbase));
    ScenarioRun run;
    try {
        run.result = simulateReduced(model, sc.run.duration);
    } catch (const IntegrationFailure& e) {
        throw NumericalFailure(e.what(), e.getTime());
    }
    run.summary = summarizeRun(run.result, model.getChannels(), opt);
    return run;
}
}  // namespace

ScenarioRun runScenario(const Scenario& sc) {
    SummaryOptions opt;
    opt.forcingPeriod = sc.track.railLength / sc.speed;
    opt.filterCutoffHz = sc.filterCutoffHz;
    ScenarioRun run;
    if (sc.model == "eom") {
        run = runEom(sc, opt);
    } else if (sc.model == "reduced") {
        run = runReduced(sc, opt);
    } else {
        const auto model = makeScenarioModel(sc);
        run.result = simulate(*model, sc.run);
        run.summary = summarizeRun(run.result, model->getChannels(), opt);
    }
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
