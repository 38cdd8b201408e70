#include "app/OrbitsCommand.h"
#include "app/OrbitsResults.h"
#include "scenarios/SpeedSweep.h"

#include "app/Output.h"
#include "app/Provenance.h"
#include "mbmodel/Parallel.h"
#include "mbmodel/Units.h"
#include "scenarios/ModelRegistry.h"
#include "scenarios/OrbitContinuation.h"
#include "scenarios/ScenarioRun.h"

#include <chrono>
#include <cmath>
#include <fmt/format.h>
#include <nlohmann/json.hpp>
#include <stdexcept>

namespace rockroll::app {

namespace {
using json = nlohmann::ordered_json;

Scenario loadOrbitScenario(const OrbitsOptions& o) {
    std::vector<ScenarioOverride> overrides;
    for (const std::string& text : o.sets) {
        try {
            overrides.push_back(parseScenarioOverride(text));
        } catch (const ScenarioError&) {
            throw ScenarioError(fmt::format("--set \"{}\": expected KEY=VALUE with a scenario key", text));
        }
    }
    Scenario sc = loadScenarioFile(o.scenario, overrides);
    for (const ScenarioOverride& ov : overrides) {
        if (o.model && ov.key == "run.model")
            throw ScenarioError("--model and --set run.model both set 'run.model': expected one of them");
        if (o.amplitudeIn && ov.key == "track.amplitude")
            throw ScenarioError("--amplitude-in and --set track.amplitude both set 'track.amplitude': expected one of them");
    }
    if (o.amplitudeIn && !sc.track.measured.empty())
        throw ScenarioError(fmt::format("--amplitude-in: {} has a measured track, which has no rectified-sine "
                                        "amplitude; expected no --amplitude-in",
                                        sc.source));
    if (o.model) sc.model = *o.model;
    if (o.amplitudeIn) sc.track.amplitude = *o.amplitudeIn * units::inch;
    return sc;
}

}  // namespace

int orbitsCommand(const OrbitsOptions& o) {
    const Scenario sc0 = loadOrbitScenario(o);
    (void)checkOrbitsInput(sc0, o);  // before any output directory is made
    std::optional<OutputDirectory> dir;
    if (!o.outDir.empty()) dir.emplace(o.outDir, o.force);
    const OrbitsResult result = calcOrbits(sc0, o, getCommandLine());
    const json& j = result.doc;
    const OrbitBranch& branch = result.branch;
    const json& records = result.records;
    if (dir) {
        dir->write("orbits.csv", [&](std::ostream& out) { writeRecordsCsv(out, records); });
        dir->writeJson("orbits.json", j);
        dir->commit();
    }
    if (o.json) {
        fmt::print("{}\n", j.dump());
        return kExitOk;
    }
    fmt::print("rockroll orbits — {} model, {} car, {}, from {:g} to {:g} mph\n", sc0.model, sc0.car.name,
               sc0.track.measured.empty() ? fmt::format("{:.2f} in", sc0.track.amplitude / units::inch)
                                          : std::string("measured track"),
               o.fromMph, o.toMph);
    fmt::print("{:>10}{:>8}{:>11}{:>11}{:>11}{:>10}{:>10}{:>8}\n", "speed mph", "period", "roll deg", "lift frac",
               "|mu|max", "mu real+", "mu real-", "stable");
    for (const auto& p : branch.points) {
        if (!p.converged) {
            fmt::print("{:>10.4g}  no orbit: {}\n", p.speedMph, p.failure);
            continue;
        }
        fmt::print("{:>10.4g}{:>8}{:>11.3f}{:>11.3f}{:>11.4f}{:>10.4f}{:>10.4f}{:>8}\n", p.speedMph, p.period,
                   p.rollAmplitudeDeg, p.wheelLiftFraction, p.maxMultiplier, p.largestRealMultiplier,
                   p.smallestRealMultiplier, p.stable ? "yes" : "no");
    }
    for (const auto& e : branch.events)
        fmt::print("  {} between {:g} and {:g} mph: {}\n", e.kind, e.fromMph, e.toMph, e.detail);
    fmt::print("stopped: {}\n", branch.stopReason);
    if (dir)
        fmt::print("wrote {} and {}\n", dir->getFinalPath("orbits.csv").string(),
                   dir->getFinalPath("orbits.json").string());
    return kExitOk;
}

}  // namespace rockroll::app
