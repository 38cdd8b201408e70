#include "app/Commands.h"
#include "app/CommandResults.h"
#include "app/JsonWriter.h"
#include "app/Output.h"
#include "app/Provenance.h"

#include "bespoke/DescribingFunction.h"
#include "mbmodel/ModalAnalysis.h"
#include "scenarios/ModelRegistry.h"
#include "scenarios/SpeedSweep.h"
#include "scenarios/ScenarioRun.h"

#include <cstdio>
#include <thread>
#include <filesystem>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <fstream>
#include <nlohmann/json.hpp>

namespace rockroll::app {

namespace fs = std::filesystem;

namespace {

void printSummary(const RunSummary& s, const Scenario& sc) {
    fmt::print("rockroll — {} model, {} car, {:.2f} in cross-level, {:.1f} mph, {:g} s simulated\n", s.model, s.car,
               s.amplitudeIn, s.speedMph, s.durationS);
    fmt::print("  scenario: {}\n", sc.source);
    fmt::print("  regime: {}\n", s.regime);
    if (s.stoppedAtS >= 0)
        fmt::print("  STOPPED at t = {:.3f} s: {}\n  (the numbers below cover the run up to that time)\n", s.stoppedAtS,
                   s.stopReason);
    fmt::print("  max roll                         {:9.2f} deg   (steady amplitude {:.2f} deg)\n", s.maxRollDeg,
               s.steadyRollAmplitudeDeg);
    fmt::print("  max wheel lift                   {:9.2f} in\n", s.maxWheelLiftIn);
    fmt::print("  max wheel load (2 wheels, 1 side){:9.0f} lb    (raw {:.0f}, static {:.0f})\n", s.maxWheelLoadLb,
               s.rawMaxWheelLoadLb, s.staticWheelLoadLb);
    fmt::print("  min single-wheel load ratio      {:9.3f}       (raw {:.3f})\n", s.minWheelLoadRatio,
               s.rawMinWheelLoadRatio);
    fmt::print("  max side-bearing load            {:9.0f} lb    (raw {:.0f})\n", s.maxSideBearingLoadLb,
               s.rawMaxSideBearingLoadLb);
    fmt::print("  max center-plate load            {:9.0f} lb    (raw {:.0f}, static {:.0f})\n",
               s.maxCenterPlateLoadLb, s.rawMaxCenterPlateLoadLb, s.staticCenterPlateLoadLb);
    fmt::print("{}", formatCriteriaTable(s));
    fmt::print("  force maxima filtered: {}\n", s.filter);
    fmt::print("  {} integrator steps, {:.1f} s simulated in {:.2f} s wall ({:.1f}x real time)\n", s.steps,
               s.simTimeS, s.wallTimeS, s.simTimeS / s.wallTimeS);
}

}  // namespace

int runDefaultCase() {
    const Scenario sc = getDefaultScenario();
    const ScenarioRun run = runScenario(sc);
    const RunSummary& s = run.summary;
    printSummary(s, sc);
    if (run.result.stop) {
        fmt::print(stderr, "rockroll: the car {} at t = {:.3f} s: {}\n", run.result.stop->regime, run.result.stop->time,
                   run.result.stop->reason);
        return kExitDerailed;
    }
    fmt::print("\nBeside the 1976 report (its §3.1, Figs 8–10: 70-ton loaded, 0.75 in, 16.5 mph):\n");
    fmt::print("  {:<36}{:>14}{:>18}\n", "quantity", "rockroll", "report");
    fmt::print("  {:<36}{:>14}{:>18}\n", "regime", s.regime, "severe");
    fmt::print("  {:<36}{:>11.0f} lb{:>18}\n", "max side-bearing force", s.maxSideBearingLoadLb, "up to 90,000 lb");
    fmt::print("  {:<36}{:>11.2f} in{:>18}\n", "max wheel lift", s.maxWheelLiftIn, "approaching 2 in");
    fmt::print("  {:<36}{:>11.0f} lb{:>18}\n", "max wheel force (2 wheels, 1 side)", s.maxWheelLoadLb,
               "about 100,000 lb");
    fmt::print("  {:<36}{:>14.2f}{:>18}\n", "max wheel force / static", s.maxWheelLoadLb / s.staticWheelLoadLb,
               "almost 2");
    fmt::print("(no parameter was tuned to these numbers; see docs/model.md)\n");
    return 0;
}

int runCommand(const RunOptions& o) {
    if (o.scenario.empty() == !o.fromSummary)
        throw ScenarioError("run: give either a scenario file or --from-summary PATH/summary.json, not both");
    Scenario sc = o.fromSummary ? loadScenarioFromSummary(*o.fromSummary) : loadScenarioFile(o.scenario);
    if (o.model) sc.model = *o.model;
    if (o.speedMph) sc.speed = *o.speedMph * units::mph;
    if (o.amplitudeIn) sc.track.amplitude = *o.amplitudeIn * units::inch;
    if (o.durationS) sc.run.duration = *o.durationS;
    if (o.maxWallS) sc.run.limits.maxWallTime = *o.maxWallS;
    const ScenarioRun run = runScenario(sc);

    const std::string stem = fs::path(o.fromSummary ? sc.source : o.scenario).stem().string();
    const fs::path dir = o.outDir.empty() ? fs::path("out") / fmt::format("{}-{}", stem, sc.model) : fs::path(o.outDir);
    fs::create_directories(dir);
    const nlohmann::ordered_json j = makeRunJson(run, sc, getCommandLine());
    writeAtomically(dir / "history.csv", [&](std::ostream& out) { writeHistoryCsv(out, run.result.history); });
    writeJsonFile(dir / "summary.json", j);

    if (o.json) {
        fmt::print("{}\n", j.dump());
    } else {
        printSummary(run.summary, sc);
        fmt::print("  wrote {} and {}\n", (dir / "history.csv").string(), (dir / "summary.json").string());
    }
    if (run.result.stop) {
        fmt::print(stderr, "rockroll: the car {} at t = {:.3f} s: {}\n", run.result.stop->regime, run.result.stop->time,
                   run.result.stop->reason);
        return kExitDerailed;
    }
    return 0;
}

int steadyCommand(const SteadyOptions& o) {
    Scenario sc = loadScenarioFile(o.scenario);
    if (o.amplitudeIn) sc.track.amplitude = *o.amplitudeIn * units::inch;
    const SteadyResult r = calcSteady(sc, o);
    if (o.json) {
        fmt::print("{}\n", makeSteadyJson(r, sc, o, getCommandLine()).dump());
        return 0;
    }
    fmt::print("rockroll steady — describing function, {} car\ninput: {}\n\n", sc.car.name, r.inputNote);
    fmt::print("{:>10}{:>12}{:>12}{:>14}{:>14}{:>10}{:>14}\n", "speed mph", "roll deg", "lift frac", "wheel lb",
               "side brg lb", "|mu|max", "stable");
    for (const auto& b : r.branches)
        for (const auto& p : b.points)
            fmt::print("{:>10.3f}{:>12.3f}{:>12.3f}{:>14.0f}{:>14.0f}{:>10.3f}{:>14}\n", p.speedMph, p.rollAmplitudeDeg,
                       p.wheelLiftFraction, p.maxWheelLoadLb, p.maxSideBearingLoadLb, p.maxFloquetMultiplier,
                       toString(b.stability));
    return 0;
}

int sweepCommand(const SweepOptions& o) {
    std::vector<Scenario> bases;
    for (const std::string& file : o.scenarios) bases.push_back(loadScenarioFile(file));
    const std::vector<SweepSpec> specs = makeSweepSpecs(bases, o);
    size_t total = 0, done = 0, failed = 0;
    for (const auto& s : specs) total += getSweepSpeeds(s).size();
    auto progress = [&](const SweepPoint& p) {
        ++done;
        failed += p.failed ? 1 : 0;
        const int width = 30, filled = int(width * done / std::max<size_t>(total, 1));
        fmt::print(stderr, "\r[{}{}] {}/{} speeds{}", std::string(filled, '#'), std::string(width - filled, '-'), done,
                   total, failed ? fmt::format(", {} failed", failed) : "");
        if (done == total) fmt::print(stderr, "\n");
    };
    const int jobs = o.jobs > 0 ? o.jobs : int(std::max(1u, std::thread::hardware_concurrency()));
    const auto results = runSweeps(specs, jobs, progress);

    nlohmann::ordered_json all = nlohmann::ordered_json::array();
    for (size_t i = 0; i < specs.size(); ++i)
        for (const SweepPoint& p : results[i]) all.push_back(makeSweepPointJson(specs[i], p, getCommandLine()));
    if (o.json) {
        fmt::print("{}\n", all.dump());
    } else {
        for (size_t i = 0; i < specs.size(); ++i) {
            const Scenario& sc = specs[i].scenario;
            fmt::print("\n{} model, {} car, {:.2f} in, sweep {} ({} from the previous speed)\n", sc.model, sc.car.name,
                       sc.track.amplitude / units::inch, specs[i].direction == SweepDirection::Up ? "up" : "down",
                       specs[i].fresh ? "each speed from rest" : "state carried");
            fmt::print("{:>10}{:>12}{:>14}{:>12}{:>14}{:>14}{:>10}  {}\n", "speed mph", "max roll", "steady roll",
                       "lift in", "wheel lb", "side brg lb", "regime", "criteria");
            for (const SweepPoint& p : results[i]) {
                if (p.failed) {
                    fmt::print("{:>10.2f}  numerical failure: {}\n", p.speedMph, p.error.substr(0, p.error.find('\n')));
                    continue;
                }
                const RunSummary& s = p.summary;
                fmt::print("{:>10.2f}{:>12.2f}{:>14.2f}{:>12.2f}{:>14.0f}{:>14.0f}{:>10}  {}\n", p.speedMph, s.maxRollDeg,
                           s.steadyRollAmplitudeDeg, s.maxWheelLiftIn, s.maxWheelLoadLb, s.maxSideBearingLoadLb,
                           s.regime, s.describeCriteria());
            }
        }
    }
    return failed ? 4 : 0;
}

int modesCommand(const ModesOptions& o) {
    Scenario sc = loadScenarioFile(o.scenario);
    if (o.model) sc.model = *o.model;
    const ModesResult r = calcScenarioModes(sc);
    if (o.json) {
        fmt::print("{}\n", makeModesJson(r, sc, getCommandLine()).dump());
        return 0;
    }
    fmt::print("rockroll modes — {} model, {} car: linearized about static equilibrium, every contact closed,\n"
               "Coulomb friction removed; beside the report's Table 1 uncoupled estimates\n\n",
               sc.model, sc.car.name);
    fmt::print("{:<34}{:>10}{:>10}{:>10}{:>18}{:>16}\n", "mode", "f Hz", "zeta", "share", "Table 1 formula", "Table 1 report");
    for (const Mode& m : r.modes) {
        const auto* e = r.findEstimate(m);
        fmt::print("{:<34}{:>10.3f}{:>10.3f}{:>10.2f}{:>18}{:>16}\n", m.name, m.frequencyHz, m.dampingRatio, m.energyShare,
                   e ? fmt::format("{:.2f}", e->frequencyHz) : "", e && e->reportHz > 0 ? fmt::format("{:.2f}", e->reportHz) : "");
    }
    return 0;
}

}  // namespace rockroll::app
