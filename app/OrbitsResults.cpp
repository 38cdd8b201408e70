// What `rockroll orbits` computes and prints as JSON, shared by the command and the
// Python module (python/rockroll_module.cpp).
#include "app/OrbitsResults.h"

#include "app/Provenance.h"
#include "mbmodel/Units.h"
#include "scenarios/ModelRegistry.h"
#include "scenarios/ScenarioRun.h"
#include "scenarios/SpeedSweep.h"

#include <chrono>
#include <cmath>
#include <fmt/format.h>
#include <stdexcept>

namespace rockroll::app {

namespace {
using json = nlohmann::ordered_json;

json numberOrNull(double x) { return std::isfinite(x) ? json(x) : json(nullptr); }

json makePointJson(const PeriodicOrbit& p) {
    json j;
    j["speed_mph"] = p.speedMph;
    j["converged"] = p.converged;
    j["period"] = p.converged ? json(p.period) : json(nullptr);
    j["mismatch_steps"] = numberOrNull(p.mismatch);
    j["newton_steps"] = p.iterations;
    j["map_evaluations"] = p.mapEvaluations;
    j["wall_time_s"] = p.wallTimeS;
    if (!p.converged) {
        j["failure"] = p.failure;
        return j;
    }
    const RunSummary& s = p.run.summary;
    j["roll_amplitude_deg"] = p.rollAmplitudeDeg;
    j["wheel_lift_fraction"] = p.wheelLiftFraction;
    j["max_roll_deg"] = s.maxRollDeg;
    j["max_wheel_lift_in"] = s.maxWheelLiftIn;
    j["max_wheel_load_lb"] = s.maxWheelLoadLb;
    j["min_wheel_load_ratio"] = s.minWheelLoadRatio;
    j["max_side_bearing_load_lb"] = s.maxSideBearingLoadLb;
    j["max_center_plate_load_lb"] = s.maxCenterPlateLoadLb;
    j["regime"] = s.regime;
    j["max_multiplier"] = numberOrNull(p.maxMultiplier);
    j["largest_real_multiplier"] = numberOrNull(p.largestRealMultiplier);
    j["smallest_real_multiplier"] = numberOrNull(p.smallestRealMultiplier);
    j["stable"] = p.stable;
    json mu = json::array();
    for (Eigen::Index i = 0; i < p.multipliers.size() && i < 8; ++i)
        mu.push_back({{"re", p.multipliers[i].real()}, {"im", p.multipliers[i].imag()}, {"abs", std::abs(p.multipliers[i])}});
    j["multipliers"] = mu;  // the 8 largest by modulus
    return j;
}

/// One flat record per point, for orbits.csv.
json makeRecord(const json& p) {
    json r;
    r["speed_mph"] = p["speed_mph"];
    r["branch"] = 1;
    r["converged"] = p["converged"];
    r["period"] = p["period"];
    for (const char* k : {"roll_amplitude_deg", "wheel_lift_fraction", "max_roll_deg", "max_wheel_lift_in",
                          "max_wheel_load_lb", "min_wheel_load_ratio", "max_side_bearing_load_lb",
                          "max_center_plate_load_lb", "max_multiplier", "largest_real_multiplier",
                          "smallest_real_multiplier"})
        r[k] = p.contains(k) ? p[k] : json(nullptr);
    r["stable"] = p.contains("stable") ? json(p["stable"].get<bool>() ? "yes" : "no") : json(nullptr);
    r["mismatch_steps"] = p["mismatch_steps"];
    r["newton_steps"] = p["newton_steps"];
    r["wall_time_s"] = p["wall_time_s"];
    return r;
}
}  // namespace

OrbitSettings checkOrbitsInput(const Scenario& sc0, const OrbitsOptions& o) {
    if (o.fromMph == o.toMph)
        throw ScenarioError("--from-mph and --to-mph are equal: expected a speed range to continue over");
    (void)PeriodicOrbitSolver::calcTrackPeriod(sc0);  // ScenarioError when the track does not repeat
    // Settings the computation would not use are refused, not dropped.
    const OrbitsOptions defaults;
    if (o.iterate && (o.newtonSteps != defaults.newtonSteps || o.fdStepScale != defaults.fdStepScale))
        throw ScenarioError("--iterate finds orbits without Newton or a monodromy: --newton-steps and --fd-step-scale "
                            "have no effect with it; expected one or the other");
    if (!ModelRegistry::get().getModel(sc0.model).usesSetting("integrator.accuracy") && o.accuracy != defaults.accuracy)
        throw ScenarioError(fmt::format("--accuracy {:g}: model \"{}\" integrates with fixed steps and does not use it",
                                        o.accuracy, sc0.model));
    OrbitSettings settings;
    settings.accuracy = o.accuracy;
    settings.shooting.threads = o.jobs;
    settings.shooting.maxIterations = o.newtonSteps;
    settings.stepScale = o.fdStepScale;
    settings.method = o.iterate ? OrbitMethod::Iteration : OrbitMethod::Newton;
    { const PeriodicOrbitSolver check(sc0, 0.0, settings); }  // ScenarioError: a model whose state cannot be shot
    return settings;
}

OrbitsResult calcOrbits(const Scenario& sc0, const OrbitsOptions& o, const std::string& command) {
    const OrbitSettings settings = checkOrbitsInput(sc0, o);

    // The start: a run from rest at --from-mph, or a speed sweep ending there, at the
    // orbit's accuracy.
    Scenario start = sc0;
    start.speed = o.fromMph * units::mph;
    start.run.duration = o.startDurationS;
    start.run.integrator.accuracy = o.accuracy;
    const auto wall0 = std::chrono::steady_clock::now();
    RestartState startState;
    RunSummary startSummary;
    std::string startKind = fmt::format("a {:g} s run from rest", o.startDurationS);
    if (o.startSweepFromMph) {
        const double v0 = *o.startSweepFromMph;
        if (v0 == o.fromMph)
            throw ScenarioError(fmt::format("--start-sweep-from-mph {:g} equals --from-mph: expected the speed the start "
                                            "sweep comes from",
                                            v0));
        SweepSpec spec;
        spec.scenario = start;
        spec.fromMph = std::min(v0, o.fromMph);
        spec.toMph = std::max(v0, o.fromMph);
        spec.stepMph = std::abs(o.stepMph);
        spec.direction = v0 > o.fromMph ? SweepDirection::Down : SweepDirection::Up;
        spec.rampTime = o.startRampS;
        startKind = fmt::format("a {} sweep from {:g} mph ({:g} mph steps, {:g} s a speed, {})",
                                v0 > o.fromMph ? "down" : "up", v0, spec.stepMph, o.startDurationS,
                                o.startRampS > 0 ? fmt::format("speed ramped over {:g} s", o.startRampS)
                                                 : std::string("speed stepped at once"));
        const std::vector<SweepPoint> sweep = runSweep(spec, [&](const SweepPoint& p) {
            if (!o.json)
                fmt::print(stderr, "orbits: start sweep {:g} mph: {}\n", p.speedMph,
                           p.failed ? "failed: " + p.error
                                    : fmt::format("{}, steady roll amplitude {:.3f} deg", p.summary.regime,
                                                  p.summary.steadyRollAmplitudeDeg));
        });
        const SweepPoint& last = sweep.back();
        if (last.failed)
            throw std::runtime_error(fmt::format("the start sweep failed at {:g} mph: {}", last.speedMph, last.error));
        if (!last.next.from)
            throw std::runtime_error(fmt::format("the start sweep stopped at {:g} mph: the car {}", last.speedMph,
                                                 last.summary.regime));
        startState = *last.next.from;
        startSummary = last.summary;
    } else {
        const ScenarioRun startRun = runScenario(start);
        if (startRun.result.stop)
            throw std::runtime_error(fmt::format("the start run at {:g} mph stopped: the car {} at t = {:.3f} s",
                                                 o.fromMph, startRun.result.stop->regime, startRun.result.stop->time));
        startState = startRun.restart;
        startSummary = startRun.summary;
    }
    const double startWall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();

    const PeriodicOrbitSolver solver(sc0, startState.distance, settings);
    OrbitContinuationSettings cs;
    cs.fromMph = o.fromMph;
    cs.toMph = o.toMph;
    cs.stepMph = o.stepMph;
    cs.refinements = o.refinements;
    cs.settlePeriods = o.settlePeriods;
    const OrbitContinuation continuation(solver, cs);
    OrbitsResult result;
    result.branch = continuation.trace(startState.y, [&](const PeriodicOrbit& p) {
        if (!o.json)
            fmt::print(stderr, "orbits: {:.4g} mph {} ({:.1f} s)\n", p.speedMph,
                       p.converged ? fmt::format("period {}, roll {:.3f} deg, |mu|max {:.4f}", p.period,
                                                 p.rollAmplitudeDeg, p.maxMultiplier)
                                   : "no orbit: " + p.failure,
                       p.wallTimeS);
    });
    if (result.branch.stopReason == "no orbit at the start speed")
        throw std::runtime_error(fmt::format("no periodic orbit at --from-mph {:g} from the end of {} ({} rocking, "
                                             "steady roll amplitude {:.3f} deg): {} (a longer --start-duration-s, or "
                                             "another start speed)",
                                             o.fromMph, startKind, startSummary.regime,
                                             startSummary.steadyRollAmplitudeDeg, result.branch.points.front().failure));

    json& j = result.doc;
    j["command"] = "orbits";
    j["model"] = sc0.model;
    j["car"] = sc0.car.name;
    j["amplitude_in"] = sc0.track.measured.empty() ? json(sc0.track.amplitude / units::inch) : json(nullptr);
    j["method"] = "shooting on the one-period map P(y) = phi_T(y), T = L/V, Newton with a finite-difference "
                  "monodromy (a chord Newton from the previous orbit's along the branch); natural-parameter continuation in "
                  "speed with a secant predictor (docs/orbits.md)";
    j["orbit_method"] = o.iterate ? "iteration" : "newton";
    // null: the model integrates with fixed steps (the reduced model) and uses no accuracy.
    j["accuracy"] = ModelRegistry::get().getModel(sc0.model).usesSetting("integrator.accuracy") ? json(o.accuracy)
                                                                                              : json(nullptr);
    j["fd_step_scale"] = o.fdStepScale;
    j["settle_periods"] = o.settlePeriods;
    j["start"] = {{"speed_mph", o.fromMph},
                  {"kind", startKind},
                  {"sweep_from_mph", o.startSweepFromMph ? json(*o.startSweepFromMph) : json(nullptr)},
                  {"sweep_ramp_time_s", o.startSweepFromMph ? json(o.startRampS) : json(nullptr)},
                  {"duration_s", o.startDurationS},
                  {"distance_m", startState.distance},
                  {"steady_roll_amplitude_deg", startSummary.steadyRollAmplitudeDeg},
                  {"regime", startSummary.regime},
                  {"wall_time_s", startWall}};
    j["stop_reason"] = result.branch.stopReason;
    j["end_bracket_mph"] = result.branch.endBracketMph
                               ? json::array({result.branch.endBracketMph->first, result.branch.endBracketMph->second})
                               : json(nullptr);
    json events = json::array();
    for (const auto& e : result.branch.events)
        events.push_back({{"kind", e.kind}, {"from_mph", e.fromMph}, {"to_mph", e.toMph}, {"detail", e.detail}});
    j["events"] = events;
    json points = json::array(), records = json::array();
    for (const auto& p : result.branch.points) {
        points.push_back(makePointJson(p));
        records.push_back(makeRecord(points.back()));
    }
    j["points"] = points;
    j["provenance"] = makeProvenance(sc0, command);
    result.records = records;
    return result;
}

}  // namespace rockroll::app
