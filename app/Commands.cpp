#include "app/Commands.h"
#include "app/CommandResults.h"
#include "app/JsonWriter.h"
#include "mbmodel/Parallel.h"
#include "app/BatchOutput.h"
#include "app/Output.h"
#include "app/Progress.h"
#include "app/Provenance.h"
#include "app/ReportComparison.h"

#include "bespoke/DescribingFunction.h"
#include "mbmodel/ModalAnalysis.h"
#include "scenarios/ModelRegistry.h"
#include "scenarios/SpeedSweep.h"
#include "scenarios/ScenarioRun.h"

#include <cstdio>
#include <filesystem>
#include <cmath>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <fstream>
#include <nlohmann/json.hpp>
#include <optional>

namespace rockroll::app {

namespace fs = std::filesystem;

namespace {

/// The --set flags as scenario overrides; ScenarioError naming the flag when one is not KEY=VALUE.
std::vector<ScenarioOverride> parseSets(const std::vector<std::string>& sets) {
    std::vector<ScenarioOverride> overrides;
    for (const std::string& text : sets) {
        try {
            overrides.push_back(parseScenarioOverride(text));
        } catch (const ScenarioError&) {
            throw ScenarioError(fmt::format("--set \"{}\": expected KEY=VALUE with a scenario key, e.g. "
                                            "--set car.side_bearing_clearance=\"0.25 in\" or --set run.speed=\"14 mph\"",
                                            text));
        }
    }
    return overrides;
}

/// Names on stderr the keys the scenario sets that its model does not use (also recorded
/// as the provenance's ignored_settings; docs/cli.md, "Which model uses which key").
void reportIgnoredSettings(const Scenario& sc) {
    const std::vector<std::string> ignored = getIgnoredSettings(sc);
    if (!ignored.empty())
        fmt::print(stderr, "rockroll: model \"{}\" does not use {} (set in {} or by --set): ignored\n", sc.model,
                   fmt::join(ignored, ", "), sc.source);
}

/// A directory a run wrote before: it holds a summary.json.
bool isRunOutput(const fs::path& dir) {
    std::error_code ec;
    return fs::is_directory(dir, ec) && fs::is_regular_file(dir / "summary.json", ec);
}

/// Rethrows a loader error caused by an override with the --set flag that gave it in front.
[[noreturn]] void rethrowNamingFlag(const ScenarioError& e, const std::vector<ScenarioOverride>& overrides) {
    for (auto o = overrides.rbegin(); o != overrides.rend(); ++o) {
        std::string key;
        try {
            key = resolveScenarioKey(o->key, OverrideKeys::FullOnly);
        } catch (const ScenarioError& unknown) {
            throw ScenarioError(fmt::format("--set \"{}={}\": {}", o->key, o->value, unknown.what()));
        }
        if (std::string_view(e.what()).find("key '" + key + "'") != std::string_view::npos)
            throw ScenarioError(fmt::format("--set \"{}={}\": {}", o->key, o->value, e.what()));
    }
    throw e;
}

/// The scenario file with the --set overrides applied (through the loader's validation).
Scenario loadWithSets(const std::string& path, const std::vector<std::string>& sets) {
    const std::vector<ScenarioOverride> overrides = parseSets(sets);
    try {
        return loadScenarioFile(path, overrides);
    } catch (const ScenarioError& e) {
        rethrowNamingFlag(e, overrides);
    }
}

/// A command-line flag and a --set of the scenario key it sets may not both be given.
void checkFlagAgainstSets(bool flagGiven, const char* flag, const char* key, const std::vector<std::string>& sets) {
    if (!flagGiven) return;
    for (const ScenarioOverride& o : parseSets(sets))
        if (o.key == key)
            throw ScenarioError(fmt::format("{} and --set \"{}={}\" both set '{}': expected one of them", flag, o.key,
                                            o.value, key));
}

/// --amplitude-in sets the rectified sine's amplitude, which a measured track does not have.
void checkAmplitudeFlag(bool flagGiven, const Scenario& sc) {
    if (flagGiven && !sc.track.measured.empty())
        throw ScenarioError(fmt::format("--amplitude-in: {} has a measured track ([track] file or measured), which "
                                        "has no rectified-sine amplitude; expected no --amplitude-in",
                                        sc.source));
}

/// The --set overrides applied, as printed under a text summary.
void printOverrides(const Scenario& sc) {
    for (const auto& [key, text] : sc.overrides) fmt::print("  --set {} = {}\n", key, text);
}

void printSummary(const RunSummary& s, const Scenario& sc) {
    const std::string track = sc.track.measured.empty() ? fmt::format("{:.2f} in cross-level", s.amplitudeIn)
                                                        : std::string("measured track");
    fmt::print("rockroll — {} model, {} car, {}, {:.1f} mph, {:g} s simulated\n", s.model, s.car, track, s.speedMph,
               s.durationS);
    fmt::print("  scenario: {}\n", sc.source);
    printOverrides(sc);
    fmt::print("  regime: {}\n", s.regime);
    if (s.stoppedAtS >= 0)
        fmt::print("  STOPPED at t = {:.3f} s: {}\n  (the numbers below cover the run up to that time)\n", s.stoppedAtS,
                   s.stopReason);
    fmt::print("  max roll                         {:9.2f} deg   (steady amplitude {:.2f} deg)\n", s.maxRollDeg,
               s.steadyRollAmplitudeDeg);
    fmt::print("  max wheel lift                   {:9.2f} in\n", s.maxWheelLiftIn);
    fmt::print("  max wheel load (2 wheels, 1 side){:9.0f} lb    (raw {:.0f}, static {:.0f})\n", s.maxWheelLoadLb,
               s.rawMaxWheelLoadLb, s.staticWheelLoadLb);
    if (std::isfinite(s.maxSingleWheelLoadLb))
        fmt::print("  max single-wheel load            {:9.0f} lb\n", s.maxSingleWheelLoadLb);
    fmt::print("  min {:<29}{:9.3f}       (raw {:.3f})\n",
               s.wheelLoadBasis == "truck side" ? "truck-side (2-wheel) load ratio" : "single-wheel load ratio",
               s.minWheelLoadRatio, s.rawMinWheelLoadRatio);
    fmt::print("  max side-bearing load            {:9.0f} lb    (raw {:.0f})\n", s.maxSideBearingLoadLb,
               s.rawMaxSideBearingLoadLb);
    fmt::print("  max center-plate load            {:9.0f} lb    (raw {:.0f}, static {:.0f})\n",
               s.maxCenterPlateLoadLb, s.rawMaxCenterPlateLoadLb, s.staticCenterPlateLoadLb);
    fmt::print("  steady part (last {:.2f} s, {} forcing periods): max roll {:.2f} deg, wheel lift {:.2f} in, wheel load "
               "(2 wheels, 1 side) {:.0f} lb, side bearing {:.0f} lb, center plate {:.0f} lb\n",
               s.steady.windowS, s.steady.cycles, s.steady.rollDeg, s.steady.wheelLiftIn, s.steady.truckSideWheelLoadLb,
               s.steady.sideBearingLoadLb, s.steady.centerPlateLoadLb);
    if (std::isfinite(s.energyBalanceError))
        fmt::print("  energy balance error {:.2f} % at the end, {}\n", 100 * s.energyBalanceError,
                   std::isfinite(s.worstEnergyBalanceError)
                       ? fmt::format("{:.2f} % worst over the run", 100 * s.worstEnergyBalanceError)
                       : std::string("no worst over the run (the run ends before the audit's window, 0.5 s after the "
                                     "level lead-in, starts)"));
    fmt::print("{}", formatCriteriaTable(s));
    if (s.criteriaFromS > 0) fmt::print("  criteria judged from t = {:.2f} s (after the speed ramp or level lead-in)\n", s.criteriaFromS);
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
    fmt::print("\n{}", formatBesideSection3_1(s, run.result.history));
    fmt::print("(no parameter was tuned to these numbers; see docs/model.md)\n");
    return 0;
}

int runCommand(const RunOptions& o) {
    if (o.scenario.empty() == !o.fromSummary)
        throw ScenarioError("run: give either a scenario file or --from-summary PATH/summary.json, not both");
    Scenario sc;
    if (o.fromSummary) {
        const std::vector<ScenarioOverride> overrides = parseSets(o.sets);
        try {
            sc = loadScenarioFromSummaryWithOverrides(*o.fromSummary, overrides);
        } catch (const ScenarioError& e) {
            rethrowNamingFlag(e, overrides);
        }
    } else {
        sc = loadWithSets(o.scenario, o.sets);
    }
    checkFlagAgainstSets(o.model.has_value(), "--model", "run.model", o.sets);
    checkFlagAgainstSets(o.speedMph.has_value(), "--speed-mph", "run.speed", o.sets);
    checkFlagAgainstSets(o.amplitudeIn.has_value(), "--amplitude-in", "track.amplitude", o.sets);
    checkFlagAgainstSets(o.durationS.has_value(), "--duration-s", "run.duration", o.sets);
    checkFlagAgainstSets(o.maxWallS.has_value(), "--max-wall-s", "limits.max_wall_time", o.sets);
    checkAmplitudeFlag(o.amplitudeIn.has_value(), sc);
    if (o.model) sc.model = *o.model;
    if (o.speedMph) sc.speed = *o.speedMph * units::mph;
    if (o.amplitudeIn) sc.track.amplitude = *o.amplitudeIn * units::inch;
    if (o.durationS) sc.run.duration = *o.durationS;
    if (o.maxWallS) sc.run.limits.maxWallTime = *o.maxWallS;
    const std::string stem = fs::path(o.fromSummary ? sc.source : o.scenario).stem().string();
    // The default directory holds the latest run of its scenario and model: a previous run's
    // output there is replaced (and said so); a directory named with --out needs --force.
    const bool defaultOut = o.outDir.empty();
    const fs::path outPath = defaultOut ? fs::path("out") / fmt::format("{}-{}", stem, sc.model) : fs::path(o.outDir);
    const bool replacing = defaultOut && isRunOutput(outPath);
    OutputDirectory dir(outPath, o.force || replacing,
                        defaultOut ? "output directory (the default; choose one with --out)" : "--out");
    try {
        checkSwitchesApply(sc);  // a refused setting is an error, not also an ignored one
    } catch (const ScenarioError& e) {
        rethrowNamingFlag(e, parseSets(o.sets));
    }
    reportIgnoredSettings(sc);
    const ScenarioRun run = runScenario(sc);

    const nlohmann::ordered_json j = makeRunJson(run, sc, getCommandLine());
    dir.write("history.csv", [&](std::ostream& out) { writeHistoryCsv(out, run.result.history); });
    dir.writeJson("summary.json", j);
    dir.commit();
    if (replacing)
        fmt::print(stderr, "rockroll: replaced the previous run in {} (the default output directory; --out DIR keeps a "
                           "run elsewhere)\n",
                   outPath.string());

    if (o.json) {
        fmt::print("{}\n", j.dump());
    } else {
        printSummary(run.summary, sc);
        fmt::print("  wrote {} and {}\n", dir.getFinalPath("history.csv").string(),
                   dir.getFinalPath("summary.json").string());
    }
    if (run.result.stop) {
        fmt::print(stderr, "rockroll: the car {} at t = {:.3f} s: {}\n", run.result.stop->regime, run.result.stop->time,
                   run.result.stop->reason);
        return kExitDerailed;
    }
    return 0;
}

int steadyCommand(const SteadyOptions& o) {
    Scenario sc = loadWithSets(o.scenario, o.sets);
    checkFlagAgainstSets(o.amplitudeIn.has_value(), "--amplitude-in", "track.amplitude", o.sets);
    checkAmplitudeFlag(o.amplitudeIn.has_value(), sc);
    if (o.amplitudeIn) sc.track.amplitude = *o.amplitudeIn * units::inch;
    std::optional<OutputDirectory> dir;
    if (!o.outDir.empty()) dir.emplace(o.outDir, o.force);
    const SteadyResult r = calcSteady(sc, o);
    const nlohmann::ordered_json j = makeSteadyJson(r, sc, o, getCommandLine());
    if (dir) {
        dir->write("steady.csv", [&](std::ostream& out) { writeRecordsCsv(out, makeSteadyRecords(j)); });
        dir->writeJson("steady.json", j);
        dir->commit();
    }
    if (o.json) {
        fmt::print("{}\n", j.dump());
        return 0;
    }
    fmt::print("rockroll steady — describing function, {} car\ninput: {}\n", sc.car.name, r.inputNote);
    printOverrides(sc);
    fmt::print("\n");
    fmt::print("paths (each a continuation, and how it was started):\n");
    for (size_t k = 0; k < r.set.paths.size(); ++k) {
        const auto& p = r.set.paths[k];
        fmt::print("  path {}: {}, {} points, {} folds{}\n", k, p.start, p.points.size(),
                   p.points.empty() ? 0 : p.points.back().foldsBefore, p.closed ? ", closed (an isola)" : "");
    }
    for (const auto& c : r.set.changes)
        fmt::print("  stability changes without a fold on path {} between {:.2f} and {:.2f} mph: {}\n", c.path,
                   c.fromMph, c.toMph, c.kind);
    fmt::print("\nroll: two-harmonic amplitude; side-bearing load: mean and |1st harmonic| (harmonic balance fixes these, "
               "not peaks);\ntwin: the time-domain twin run {} periods from the solution, 20 Hz filtered maxima over "
               "its last period\n",
               o.twinPeriods);
    fmt::print("{:>5}{:>10}{:>10}{:>10}{:>12}{:>12}{:>11}{:>14}{:>14}{:>9}{:>14}\n", "path", "speed mph", "roll deg",
               "lift frac", "SB mean lb", "SB 1st lb", "twin roll", "twin wheel lb", "twin SB lb", "|mu|max",
               "stable");
    for (const auto& b : r.set.branches)
        for (const auto& p : b.points) {
            const std::string twinRoll = p.twin.computed ? fmt::format("{:.3f}{}", p.twin.rollAmplitudeDeg,
                                                                       p.twin.stayed() ? "" : "*")
                                                         : "-";
            fmt::print("{:>5}{:>10.3f}{:>10.3f}{:>10.3f}{:>12.0f}{:>12.0f}{:>11}{:>14}{:>14}{:>9.3f}{:>14}\n", b.path,
                       p.speedMph, p.rollAmplitudeDeg, p.wheelLiftFraction, p.sideBearingLoad.meanLb,
                       p.sideBearingLoad.firstLb, twinRoll,
                       p.twin.computed ? fmt::format("{:.0f}", p.twin.maxTruckSideWheelLoadLb) : "-",
                       p.twin.computed ? fmt::format("{:.0f}", p.twin.maxSideBearingLoadLb) : "-",
                       p.maxFloquetMultiplier, toString(b.stability));
        }
    if (o.twinPeriods > 0) fmt::print("* the twin left the solution (its last period does not solve back onto it)\n");
    if (dir) fmt::print("wrote {} and {}\n", dir->getFinalPath("steady.csv").string(),
                        dir->getFinalPath("steady.json").string());
    return 0;
}

int sweepCommand(const SweepOptions& o) {
    std::vector<Scenario> bases;
    for (const std::string& file : o.scenarios) {
        bases.push_back(loadWithSets(file, o.sets));
        checkFlagAgainstSets(o.model.has_value(), "--model", "run.model", o.sets);
        checkFlagAgainstSets(!o.amplitudesIn.empty(), "--amplitude-in", "track.amplitude", o.sets);
        checkFlagAgainstSets(o.durationS.has_value(), "--duration-s", "run.duration", o.sets);
        checkFlagAgainstSets(o.maxWallS.has_value(), "--max-wall-s", "limits.max_wall_time", o.sets);
        checkAmplitudeFlag(!o.amplitudesIn.empty(), bases.back());
    }
    if (o.resume && o.outDir.empty())
        throw ScenarioError("--resume: expected --out DIR, the output directory of the interrupted sweep");
    const std::vector<SweepSpec> specs = makeSweepSpecs(bases, o);
    checkSweepSpecs(specs);
    for (const Scenario& sc : bases) {
        Scenario asRun = sc;
        if (o.model) asRun.model = *o.model;
        checkSwitchesApply(asRun);
        reportIgnoredSettings(asRun);
    }
    std::optional<OutputDirectory> dir;
    if (!o.outDir.empty()) dir.emplace(o.outDir, o.force, JournaledOutput{o.resume});
    // Each finished speed goes into the journal, so that --resume continues (app/Journal.h).
    std::string command = getCommandLine();
    std::vector<std::vector<SweepPoint>> done;
    std::unique_ptr<JournalWriter> journal;
    if (dir)
        journal = openBatchJournal(*dir, "sweep", makeSweepIdentity(specs), command,
                                   [&](const ParsedJournal& j, const std::string& file) {
                                       done = collectSweepPoints(j, specs, file);
                                   });
    size_t total = 0;
    for (const auto& s : specs) total += getSweepSpeeds(s).size();
    for (const auto& d : done) total -= d.size();
    SweepProgress progress("sweep", total);
    const int jobs = resolveJobCount(o.jobs);
    const auto results = runSweepsFrom(specs, jobs, done, [&](const SweepPoint& p, size_t sweep, size_t index) {
        if (journal) journal->append(toJournalJson(p, sweep, index));
        progress(p);
    });
    size_t failed = 0;
    for (const auto& r : results)
        for (const SweepPoint& p : r) failed += p.failed ? 1 : 0;

    nlohmann::ordered_json all = nlohmann::ordered_json::array();
    for (size_t i = 0; i < specs.size(); ++i)
        for (const SweepPoint& p : results[i]) all.push_back(makeSweepPointJson(specs[i], p, command));
    if (dir) {
        dir->write("sweep.csv", [&](std::ostream& out) { writeRecordsCsv(out, makeSweepRecords(all)); });
        dir->writeJson("sweep.json", {{"points", all}, {"jumps", makeSweepJumpsJson(specs, results)}});
        journal.reset();
        commitBatch(*dir);
    }
    if (o.json) {
        fmt::print("{}\n", all.dump());
    } else {
        for (size_t i = 0; i < specs.size(); ++i) {
            const Scenario& sc = specs[i].scenario;
            fmt::print("\n{} model, {} car, {}, sweep {} ({} from the previous speed)\n", sc.model, sc.car.name,
                       sc.track.measured.empty() ? fmt::format("{:.2f} in", sc.track.amplitude / units::inch)
                                                 : std::string("measured track"),
                       specs[i].direction == SweepDirection::Up ? "up" : "down",
                       specs[i].fresh            ? std::string("each speed from rest")
                       : specs[i].rampTime > 0 ? fmt::format("state carried, speed ramped over {:g} s", specs[i].rampTime)
                                               : std::string("state carried, speed stepped at once"));
            fmt::print("{:>10}{:>12}{:>14}{:>12}{:>14}{:>14}{:>10}  {}\n", "speed mph", "max roll", "steady roll",
                       "lift in", "wheel lb", "side brg lb", "regime", "criteria");
            for (const SweepPoint& p : results[i]) {
                if (p.failed) {
                    fmt::print("{:>10.2f}  FAILED: {}\n", p.speedMph, p.error.substr(0, p.error.find('\n')));
                    continue;
                }
                const RunSummary& s = p.summary;
                fmt::print("{:>10.2f}{:>12.2f}{:>14.2f}{:>12.2f}{:>14.0f}{:>14.0f}{:>10}  {}\n", p.speedMph, s.maxRollDeg,
                           s.steadyRollAmplitudeDeg, s.maxWheelLiftIn, s.maxWheelLoadLb, s.maxSideBearingLoadLb,
                           s.regime, s.describeCriteria());
            }
        }
        printOverrides(bases.front());
        if (dir) fmt::print("wrote {} and {}\n", dir->getFinalPath("sweep.csv").string(),
                            dir->getFinalPath("sweep.json").string());
    }
    return failed ? kExitFailedPoints : kExitOk;
}

int modesCommand(const ModesOptions& o) {
    Scenario sc = loadWithSets(o.scenario, o.sets);
    checkFlagAgainstSets(o.model.has_value(), "--model", "run.model", o.sets);
    if (o.model) sc.model = *o.model;
    std::optional<OutputDirectory> dir;
    if (!o.outDir.empty()) dir.emplace(o.outDir, o.force);
    const ModesResult r = calcScenarioModes(sc);
    const nlohmann::ordered_json j = makeModesJson(r, sc, getCommandLine());
    if (dir) {
        dir->write("modes.csv", [&](std::ostream& out) { writeRecordsCsv(out, j.at("modes")); });
        dir->writeJson("modes.json", j);
        dir->commit();
    }
    if (o.json) {
        fmt::print("{}\n", j.dump());
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
    printOverrides(sc);
    if (dir) fmt::print("wrote {} and {}\n", dir->getFinalPath("modes.csv").string(),
                        dir->getFinalPath("modes.json").string());
    return 0;
}

}  // namespace rockroll::app
