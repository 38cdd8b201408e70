#include "scenarios/ScenarioRun.h"

#include "mbmodel/RockingModel.h"
#include "mbmodel/TrackInput.h"
#include "scenarios/ModelRegistry.h"
#include "scenarios/models/SimbodyTimeDomainModel.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <fmt/ranges.h>

namespace rockroll {

TrackMotion makeTrackMotion(const Scenario& sc, const RunStart& start) {
    TrackMotion m;
    m.speed = sc.speed;
    if (start.from) {
        m.startDistance = start.from->distance;
        m.startSpeed = start.from->speed;
    }
    m.rampTime = start.rampTime;
    return m;
}

namespace {
const ModelDescriptor& getScenarioModel(const Scenario& sc) {
    const ModelRegistry& registry = ModelRegistry::get();
    if (const ModelDescriptor* d = registry.find(sc.model)) return *d;
    throw ScenarioError(fmt::format("{}: key 'run.model' = \"{}\": expected one of {}", sc.source, sc.model,
                                    fmt::join(registry.getNames(), ", ")));
}
}  // namespace

std::unique_ptr<RockingModel> makeScenarioModel(const Scenario& sc, const RunStart& start) {
    const ModelDescriptor& d = getScenarioModel(sc);
    if (!d.isMultibody())
        throw ScenarioError(fmt::format("{}: model \"{}\" is not a multibody model; expected one of {}", sc.source,
                                        sc.model, fmt::join(ModelRegistry::get().getMultibodyNames(), ", ")));
    return d.makeMultibody(sc.car, TrackInput(sc.track), makeModelOptions(sc, makeTrackMotion(sc, start)));
}

EomHalfCarModel makeScenarioEomModel(const Scenario& sc, const TrackMotion& motion) {
    return EomHalfCarModel(sc.car, makeEquivalentWheelsetInput(TrackInput(sc.track), motion, sc.car.wheelbase), sc.eom,
                           sc.wheelRail);
}

EomHalfCarModel makeScenarioEomModel(const Scenario& sc, const RunStart& start) {
    return makeScenarioEomModel(sc, makeTrackMotion(sc, start));
}

void checkSwitchesApply(const Scenario& sc) {
    const ModelDescriptor& d = getScenarioModel(sc);
    const ModelRegistry& registry = ModelRegistry::get();
    if (sc.reduced.truckWeight && !d.masslessTruck) {
        std::vector<std::string> massless;
        for (const auto& m : registry.getModels())
            if (m.masslessTruck) massless.push_back(m.name);
        throw ScenarioError(fmt::format("{}: key 'reduced.truck_weight' = true: expected model {}, not \"{}\" "
                                        "(the other models always carry the truck's weight)",
                                        sc.source, fmt::join(massless, " or "), sc.model));
    }
    if (d.fixedOutputRateHz > 0 && sc.run.outputRate != d.fixedOutputRateHz &&
        std::binary_search(sc.settingsSet.begin(), sc.settingsSet.end(), "run.output_rate"))
        throw ScenarioError(fmt::format("{}: key 'run.output_rate' = {} Hz: expected {} Hz for model \"{}\", which records "
                                        "every step of its fixed time step, or the key left out (docs/cli.md, \"Which "
                                        "model uses which key\")",
                                        sc.source, sc.run.outputRate, d.fixedOutputRateHz, sc.model));
    if (sc.eom.equalLateralShares && sc.wheelRail.lateral != LateralWheelRail::Restraint)
        throw ScenarioError(fmt::format("{}: key 'eom.equal_lateral_shares' = true: expected wheel_rail.lateral = "
                                        "\"restraint\", not \"{}\" (it splits the restraint's force; the creep and "
                                        "flange contact gives each wheel its own)",
                                        sc.source, getLateralWheelRailName(sc.wheelRail.lateral)));
    const std::string multibody = fmt::format("{}", fmt::join(registry.getMultibodyNames(), " or "));
    if (!d.isMultibody() && !sc.attribution.unsprungGravity)
        throw ScenarioError(fmt::format("{}: key 'attribution.unsprung_gravity' = false: expected model {}, not \"{}\"",
                                        sc.source, multibody, sc.model));
    if (!d.isMultibody() && sc.attribution.unsprungMassScale != 1)
        throw ScenarioError(fmt::format("{}: key 'attribution.unsprung_mass_scale' = {}: expected model {}, not \"{}\"",
                                        sc.source, sc.attribution.unsprungMassScale, multibody, sc.model));
}

std::vector<std::string> getIgnoredSettings(const Scenario& sc) {
    const ModelDescriptor& d = getScenarioModel(sc);
    std::vector<std::string> ignored;
    for (const std::string& key : sc.settingsSet)
        if (!d.usesSetting(key)) ignored.push_back(key);
    return ignored;
}

double getRecordedOutputRate(const Scenario& sc) {
    const ModelDescriptor& d = getScenarioModel(sc);
    return d.fixedOutputRateHz > 0 ? d.fixedOutputRateHz : sc.run.outputRate;
}

ScenarioRun runScenario(const Scenario& given, const RunStart& start) {
    checkSwitchesApply(given);
    // The checks (the filter below the Nyquist frequency, the memory estimate) at the rate recorded.
    Scenario resolved;
    const bool fixedRate = getRecordedOutputRate(given) != given.run.outputRate;
    if (fixedRate) {
        resolved = given;
        resolved.run.outputRate = getRecordedOutputRate(given);
    }
    const Scenario& sc = fixedRate ? resolved : given;
    checkScenario(sc);  // command-line options and Python keywords change a loaded scenario
    const ModelDescriptor& d = getScenarioModel(sc);
    if (start.from && start.from->model != d.name)
        throw ScenarioError(fmt::format("{}: cannot continue a \"{}\" state with model \"{}\"", sc.source,
                                        start.from->model, d.name));
    SummaryOptions opt;
    opt.forcingPeriod = sc.track.railLength / sc.speed;
    opt.filterCutoffHz = sc.filterCutoffHz;
    opt.staticReference = start.staticReference;
    opt.severeSeparationTime = sc.severeSeparationTime;
    opt.criteria = resolveCriteriaLimits(sc);
    const TrackMotion motion = makeTrackMotion(sc, start);
    // Criteria leave out the numerical devices only: a sweep point's speed ramp and
    // the level lead-in before the leading wheelset reaches the perturbation
    // (docs/validation.md, "Statistics").
    const double leadInTime = std::max(0.0, TrackInput(sc.track).calcLeadInDistance() - motion.startDistance) / sc.speed;
    opt.criteriaFromS = std::max(start.from ? start.rampTime : 0.0, leadInTime);
    // On level lead-in track the rails do no work and nothing dissipates: the worst energy
    // error is taken from 0.5 s after the perturbation starts, as a run from s = 0 takes it.
    opt.energyWorstFromS += leadInTime;

    const std::unique_ptr<TimeDomainModel> model = d.make(sc, motion);
    checkMemoryEstimate(sc, model->getChannels().names.size());
    ScenarioRun run;
    run.result = model->simulate(sc, start.from ? start.from->y : std::vector<double>{});
    run.summary = summarizeRun(run.result, model->getChannels(), opt);
    run.channels = model->getChannels();
    run.staticReference =
        opt.staticReference.empty() ? toVector(run.result.history.samples.front()) : opt.staticReference;
    run.restart = RestartState{d.name, run.result.finalState, motion.calcDistance(run.result.simTime), sc.speed};
    run.summary.model = d.name;
    run.summary.car = sc.car.name;
    // Inputs echoed in the units they were given, without conversion round-off.
    auto echo = [](double x) { return std::round(x * 1e9) / 1e9; };
    run.summary.speedMph = echo(sc.speed / units::mph);
    run.summary.amplitudeIn = echo(sc.track.amplitude / units::inch);
    run.summary.durationS = sc.run.duration;
    return run;
}

}  // namespace rockroll
