#include "scenarios/ScenarioRun.h"

#include <cmath>

namespace rockroll {

std::unique_ptr<RockingModel> makeScenarioModel(const Scenario& sc) {
    return makeRockingModel(sc.model, sc.car, TrackInput(sc.track), ModelOptions{sc.speed, sc.entry});
}

ScenarioRun runScenario(const Scenario& sc) {
    const auto model = makeScenarioModel(sc);
    ScenarioRun run;
    run.result = simulate(*model, sc.run);
    SummaryOptions opt;
    opt.forcingPeriod = sc.track.railLength / sc.speed;
    opt.filterCutoffHz = sc.filterCutoffHz;
    run.summary = summarizeRun(run.result, model->getChannels(), opt);
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
