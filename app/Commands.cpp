#include "app/Commands.h"
#include "app/JsonWriter.h"
#include "app/Output.h"
#include "app/Provenance.h"

#include "bespoke/DescribingFunction.h"
#include "mbmodel/ModalAnalysis.h"
#include "scenarios/SpeedSweep.h"
#include "scenarios/ScenarioRun.h"

#include <cstdio>
#include <thread>
#include <filesystem>
#include <fmt/format.h>
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
    nlohmann::ordered_json j = toJson(run.summary);
    j["provenance"] = makeProvenance(sc, getCommandLine());
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
    if (!(o.toMph > o.fromMph)) throw std::invalid_argument("--to-mph must exceed --from-mph");
    const double C = DescribingFunctionModel::calcFundamentalCrossLevel(sc.track.amplitude, sc.car.wheelbase,
                                                                        sc.track.railLength);
    const DescribingFunctionModel model(sc.car, C, sc.track.railLength);
    ContinuationSettings settings;
    settings.fromMph = o.fromMph;
    settings.toMph = o.toMph;
    settings.stability = o.stabilityMethod == "floquet" ? StabilityMethod::Floquet
                         : o.stabilityMethod == "none"  ? StabilityMethod::None
                                                        : StabilityMethod::FoldRule;
    const auto branches = model.trace(settings);
    if (branches.empty()) throw std::runtime_error(fmt::format("no harmonic-balance solution found at {} mph", o.fromMph));

    const std::string inputNote = fmt::format(
        "sinusoidal cross-level of amplitude {:.4f} in: the fundamental harmonic 8A/(3 pi) cos(pi wheelbase/L_r) "
        "of the {:.3f} in rectified-sine cross-level averaged over the wheelbase",
        C / units::inch, sc.track.amplitude / units::inch);
    if (o.json) {
        nlohmann::ordered_json j;
        j["car"] = sc.car.name;
        j["amplitude_in"] = sc.track.amplitude / units::inch;
        j["input_amplitude_in"] = C / units::inch;
        j["input"] = inputNote;
        j["model"] = "describing function (half car, report 4.1 simplifications)";
        j["stability"] = o.stabilityMethod == "floquet"
                             ? "Floquet multipliers of the time-domain twin's periodic orbit at every point"
                         : o.stabilityMethod == "none"
                             ? "not computed"
                             : "per stretch between folds: Floquet multipliers of the time-domain twin's periodic orbit "
                               "at the stretch's middle point";
        j["provenance"] = makeProvenance(sc, getCommandLine());
        j["provenance"]["model"] = "describing function";  // the scenario's [run] model is not used here
        j["branches"] = nlohmann::ordered_json::array();
        for (const auto& b : branches) {
            nlohmann::ordered_json jb;
            // null, never true, when nothing decided it (--stability none, or no evidence).
            jb["stable"] = b.stability == Stability::NotComputed ? nlohmann::ordered_json(nullptr)
                                                                  : nlohmann::ordered_json(b.stability == Stability::Stable);
            jb["stability"] = b.stability == Stability::Stable     ? "stable"
                              : b.stability == Stability::Unstable ? "unstable"
                                                                   : "not computed";
            jb["points"] = nlohmann::ordered_json::array();
            for (const auto& p : b.points)
                jb["points"].push_back({{"speed_mph", p.speedMph},
                                        {"roll_amplitude_deg", p.rollAmplitudeDeg},
                                        {"wheel_lift_fraction", p.wheelLiftFraction},
                                        {"max_wheel_load_lb", p.maxWheelLoadLb},
                                        {"max_side_bearing_load_lb", p.maxSideBearingLoadLb},
                                        {"min_center_plate_load_lb", p.minCenterPlateLoadLb},
                                        {"folds_before", p.foldsBefore},
                                        {"floquet_converged", p.floquetConverged},
                                        {"stability_evidence", p.stabilityEvidence},
                                        {"twin_persistence", std::isfinite(p.twinPersistence) && p.twinPersistence > 0
                                                                 ? nlohmann::ordered_json(p.twinPersistence)
                                                                 : nlohmann::ordered_json(nullptr)},
                                        {"max_floquet_multiplier",
                                         std::isfinite(p.maxFloquetMultiplier) ? nlohmann::ordered_json(p.maxFloquetMultiplier)
                                                                               : nlohmann::ordered_json(nullptr)}});
            j["branches"].push_back(jb);
        }
        fmt::print("{}\n", j.dump());
        return 0;
    }
    fmt::print("rockroll steady — describing function, {} car\ninput: {}\n\n", sc.car.name, inputNote);
    fmt::print("{:>10}{:>12}{:>12}{:>14}{:>14}{:>10}{:>14}\n", "speed mph", "roll deg", "lift frac", "wheel lb",
               "side brg lb", "|mu|max", "stable");
    for (const auto& b : branches)
        for (const auto& p : b.points)
            fmt::print("{:>10.3f}{:>12.3f}{:>12.3f}{:>14.0f}{:>14.0f}{:>10.3f}{:>14}\n", p.speedMph, p.rollAmplitudeDeg,
                       p.wheelLiftFraction, p.maxWheelLoadLb, p.maxSideBearingLoadLb, p.maxFloquetMultiplier,
                       toString(b.stability));
    return 0;
}

int sweepCommand(const SweepOptions& o) {
    std::vector<SweepSpec> specs;
    for (const std::string& file : o.scenarios) {
        Scenario base = loadScenarioFile(file);
        if (o.model) base.model = *o.model;
        if (o.durationS) base.run.duration = *o.durationS;
        if (o.maxWallS) base.run.limits.maxWallTime = *o.maxWallS;
        std::vector<double> amplitudes = o.amplitudesIn;
        if (amplitudes.empty()) amplitudes.push_back(base.track.amplitude / units::inch);
        for (double a : amplitudes)
            for (const char* dir : {"up", "down"}) {
                if (o.direction != "both" && o.direction != dir) continue;
                SweepSpec s;
                s.scenario = base;
                s.scenario.track.amplitude = a * units::inch;
                s.fromMph = o.fromMph;
                s.toMph = o.toMph;
                s.stepMph = o.stepMph;
                s.direction = std::string(dir) == "up" ? SweepDirection::Up : SweepDirection::Down;
                s.fresh = o.fresh;
                specs.push_back(s);
            }
    }
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
        for (const SweepPoint& p : results[i]) {
            nlohmann::ordered_json j;
            if (p.failed) {
                j["model"] = specs[i].scenario.model;
                j["car"] = specs[i].scenario.car.name;
                j["speed_mph"] = p.speedMph;
                j["amplitude_in"] = specs[i].scenario.track.amplitude / units::inch;
                j["failed"] = true;
                j["error"] = p.error;
            } else {
                j = toJson(p.summary);
                j["failed"] = false;
            }
            j["direction"] = p.direction;
            j["start"] = p.start;
            Scenario at = specs[i].scenario;
            at.speed = p.speedMph * units::mph;
            j["provenance"] = makeProvenance(at, getCommandLine());
            j["provenance"]["sweep"] = {{"from_mph", specs[i].fromMph}, {"to_mph", specs[i].toMph},
                                        {"step_mph", specs[i].stepMph}, {"direction", p.direction},
                                        {"fresh", specs[i].fresh}, {"ramp_time_s", specs[i].rampTime}};
            all.push_back(j);
        }
    if (o.json) {
        fmt::print("{}\n", all.dump());
    } else {
        for (size_t i = 0; i < specs.size(); ++i) {
            const Scenario& sc = specs[i].scenario;
            fmt::print("\n{} model, {} car, {:.2f} in, sweep {} ({} from the previous speed)\n", sc.model, sc.car.name,
                       sc.track.amplitude / units::inch, specs[i].direction == SweepDirection::Up ? "up" : "down",
                       specs[i].fresh ? "each speed from rest" : "state carried");
            fmt::print("{:>10}{:>12}{:>14}{:>12}{:>14}{:>14}{:>10}\n", "speed mph", "max roll", "steady roll",
                       "lift in", "wheel lb", "side brg lb", "regime");
            for (const SweepPoint& p : results[i]) {
                if (p.failed) {
                    fmt::print("{:>10.2f}  numerical failure: {}\n", p.speedMph, p.error.substr(0, p.error.find('\n')));
                    continue;
                }
                const RunSummary& s = p.summary;
                fmt::print("{:>10.2f}{:>12.2f}{:>14.2f}{:>12.2f}{:>14.0f}{:>14.0f}{:>10}\n", p.speedMph, s.maxRollDeg,
                           s.steadyRollAmplitudeDeg, s.maxWheelLiftIn, s.maxWheelLoadLb, s.maxSideBearingLoadLb,
                           s.regime);
            }
        }
    }
    return failed ? 4 : 0;
}

int modesCommand(const ModesOptions& o) {
    Scenario sc = loadScenarioFile(o.scenario);
    if (o.model) sc.model = *o.model;
    if (sc.model != "halfcar" && sc.model != "fullcar")
        throw ScenarioError(fmt::format("{}: modes need a Simbody model with truck masses: halfcar or fullcar, not \"{}\"",
                                        sc.source, sc.model));
    TrackSpec level = sc.track;
    level.amplitude = 0;
    level.measured.clear();
    const auto model = makeRockingModel(sc.model, makeModalCar(sc.car), TrackInput(level), ModelOptions{sc.speed, sc.entry});
    const std::vector<Mode> modes = calcModes(*model);
    const std::vector<UncoupledEstimate> table1 = calcTable1Estimates(sc.car);
    auto findEstimate = [&](const Mode& m) -> const UncoupledEstimate* {
        const std::string& base = m.body;
        std::string motion = m.motion;
        if (motion == "sway-roll") motion = m.name.find("lower") != std::string::npos ? "roll" : "sway";
        for (const auto& e : table1)
            if (e.body == base && e.motion == motion) return &e;
        return nullptr;
    };
    if (o.json) {
        nlohmann::ordered_json j;
        j["model"] = sc.model;
        j["car"] = sc.car.name;
        j["linearization"] = "about static equilibrium, every contact closed, Coulomb friction removed";
        j["provenance"] = makeProvenance(sc, getCommandLine());
        j["modes"] = nlohmann::ordered_json::array();
        for (const Mode& m : modes) {
            nlohmann::ordered_json jm{{"name", m.name},           {"frequency_hz", m.frequencyHz},
                                      {"damping_ratio", m.dampingRatio}, {"body", m.body},
                                      {"motion", m.motion},       {"energy_share", m.energyShare}};
            if (const auto* e = findEstimate(m)) {
                jm["table1_formula_hz"] = e->frequencyHz;
                jm["table1_report_hz"] = e->reportHz > 0 ? nlohmann::ordered_json(e->reportHz) : nlohmann::ordered_json(nullptr);
            }
            j["modes"].push_back(jm);
        }
        j["table1"] = nlohmann::ordered_json::array();
        for (const auto& e : table1)
            j["table1"].push_back({{"body", e.body}, {"motion", e.motion}, {"formula_hz", e.frequencyHz},
                                   {"report_hz", e.reportHz > 0 ? nlohmann::ordered_json(e.reportHz) : nlohmann::ordered_json(nullptr)}});
        fmt::print("{}\n", j.dump());
        return 0;
    }
    fmt::print("rockroll modes — {} model, {} car: linearized about static equilibrium, every contact closed,\n"
               "Coulomb friction removed; beside the report's Table 1 uncoupled estimates\n\n",
               sc.model, sc.car.name);
    fmt::print("{:<34}{:>10}{:>10}{:>10}{:>18}{:>16}\n", "mode", "f Hz", "zeta", "share", "Table 1 formula", "Table 1 report");
    for (const Mode& m : modes) {
        const auto* e = findEstimate(m);
        fmt::print("{:<34}{:>10.3f}{:>10.3f}{:>10.2f}{:>18}{:>16}\n", m.name, m.frequencyHz, m.dampingRatio, m.energyShare,
                   e ? fmt::format("{:.2f}", e->frequencyHz) : "", e && e->reportHz > 0 ? fmt::format("{:.2f}", e->reportHz) : "");
    }
    return 0;
}

}  // namespace rockroll::app
