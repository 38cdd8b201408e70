// rockroll: freight-car rock-and-roll simulator (command line).
#include "app/Commands.h"
#include "app/OrbitsCommand.h"
#include "app/Output.h"
#include "app/PlotCommand.h"
#include "app/Provenance.h"
#include "mbmodel/DataFiles.h"
#include "mbmodel/Simulation.h"
#include "scenarios/ModelRegistry.h"
#include "scenarios/ScenarioLoader.h"

#include <CLI/CLI.hpp>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <new>
#include <unistd.h>

namespace {

using rockroll::ValueRange;

/// An option given in `unit` checked against a declared range (getValueRange: the same
/// range the scenario key has), so a bad value names the option, the value and the range.
CLI::Validator inRange(const ValueRange& range, const std::string& unit) {
    return CLI::Validator(
        [range, unit](std::string& text) -> std::string {
            double si = 0;
            try {
                si = rockroll::units::parseQuantity(text + " " + unit, range.dimension);
            } catch (const std::invalid_argument&) {
                return fmt::format("{} is not a finite number: expected {}", text, range.describe());
            }
            if (range.contains(si)) return "";
            return fmt::format("{} {} is out of range: expected {}{}", text, unit, range.describe(),
                               range.key.rfind("--", 0) == 0 ? "" : fmt::format(" (as the scenario key {})", range.key));
        },
        range.describe(), "");
}
CLI::Validator inRange(const std::string& key, const std::string& unit) {
    return inRange(rockroll::getValueRange(key), unit);
}

/// A choice among `names`; a bad one names the value and lists the accepted ones.
CLI::Validator oneOf(const std::vector<std::string>& names) {
    const std::string list = fmt::format("{}", fmt::join(names, ", "));
    return CLI::Validator(
        [names, list](std::string& text) -> std::string {
            for (const auto& n : names)
                if (n == text) return "";
            return fmt::format("\"{}\": expected one of: {}", text, list);
        },
        "one of: " + list, "");
}

}  // namespace

int main(int argc, char** argv) {
    using namespace rockroll;
    // SIGINT/SIGTERM remove temporaries and exit 130 (app/Output.h).
    app::installInterruptHandler();  // first: before any thread starts
    // Every error is caught below; should one escape (a thread), exit 3, never abort.
    std::set_terminate([] {
        fmt::print(stderr, "rockroll: internal error: an exception escaped its handler\n");
        _exit(app::kExitNumericalFailure);
    });
    const ValueRange stepRange{"--step-mph", units::Dimension::Speed, 0, 150 * units::mph, true, false, "mph"};
    const ValueRange jobsRange{"--jobs", units::Dimension::Dimensionless, 0, 1024, false, false, "", true};
    const ValueRange rollLimitRange{"--roll-limit-deg", units::Dimension::Angle, 0, 90 * units::degree, true, false, "deg"};
    const ValueRange wheelLoadLimitRange{"--wheel-load-limit", units::Dimension::Dimensionless, 0, 1, false, false, ""};
    CLI::App cli{"rockroll — freight-car rock and roll on staggered jointed track (Simbody models).\n"
                 "With no sub-command: the default case, 70-ton loaded car, 0.75 in, 16.5 mph, full car, 20 s."};
    cli.require_subcommand(0, 1);

    const ModelRegistry& registry = ModelRegistry::get();
    const std::vector<std::string> modelNames = registry.getNames(), multibodyNames = registry.getMultibodyNames();
    std::string modelHelp;
    for (const auto& m : registry.getModels()) modelHelp += fmt::format("  {:<9} {}\n", m.name, m.description);

    // --set KEY=VALUE (repeatable) and --out DIR / --force, the same on run, steady, sweep and modes.
    auto addCommonOptions = [](CLI::App* cmd, app::CommonOptions& common, const std::string& outHelp) {
        cmd->add_option("--set", common.sets,
                        "KEY=VALUE: override a scenario key (repeatable), with its unit, e.g. "
                        "--set car.side_bearing_clearance=\"0.25 in\" --set run.speed=\"14 mph\"")
            ->expected(1)
            ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
        cmd->add_option("--out", common.outDir, outHelp);
        cmd->add_flag("--force", common.force, "replace an existing non-empty output directory");
    };

    app::RunOptions run;
    CLI::App* runCmd = cli.add_subcommand("run", "run a scenario; write history.csv and summary.json");
    runCmd->add_option("scenario", run.scenario, "scenario file (TOML)")->check(CLI::ExistingFile);
    runCmd->add_option("--from-summary", run.fromSummary,
                       "rerun exactly the run a summary.json describes (its provenance), instead of a scenario file")
        ->check(CLI::ExistingFile);
    runCmd->add_option("--model", run.model, "the model (overrides the scenario's):\n" + modelHelp)
        ->check(oneOf(modelNames));
    runCmd->add_option("--speed-mph", run.speedMph, "speed [mph]")->check(inRange("run.speed", "mph"));
    runCmd->add_option("--amplitude-in", run.amplitudeIn, "cross-level amplitude A [in]")
        ->check(inRange("track.amplitude", "in"));
    runCmd->add_option("--duration-s", run.durationS, "simulated time [s]")->check(inRange("run.duration", "s"));
    addCommonOptions(runCmd, run,
                     "output directory: history.csv, summary.json (default out/<scenario>-<model>, where a "
                     "rerun replaces the earlier run)");
    runCmd->add_option("--max-wall-s", run.maxWallS, "wall-time limit; past it the run fails (exit 3) [s]")
        ->check(inRange("limits.max_wall_time", "s"));
    runCmd->add_flag("--json", run.json, "print exactly one JSON summary object on stdout");

    app::SteadyOptions steady;
    CLI::App* steadyCmd = cli.add_subcommand(
        "steady", "describing-function steady state against speed (harmonic balance, arclength continuation)");
    steadyCmd->add_option("scenario", steady.scenario, "scenario file (TOML)")->required()->check(CLI::ExistingFile);
    steadyCmd->add_option("--amplitude-in", steady.amplitudeIn, "cross-level amplitude A [in]")
        ->check(inRange("track.amplitude", "in"));
    steadyCmd->add_option("--from-mph", steady.fromMph, "lowest speed [mph]")->capture_default_str()->check(inRange("run.speed", "mph"));
    steadyCmd->add_option("--to-mph", steady.toMph, "highest speed [mph]")->capture_default_str()->check(inRange("run.speed", "mph"));
    steadyCmd->add_flag("--json", steady.json, "print exactly one JSON object on stdout");
    addCommonOptions(steadyCmd, steady, "write steady.csv and steady.json into this directory");
    steadyCmd->add_option("--stability", steady.stabilityMethod,
                          "fold: each stretch between folds checked near both ends and in the middle (Floquet on the "
                          "time-domain twin's orbit and a persistence run), bisected where checks disagree; "
                          "floquet: every point (slow); none")
        ->capture_default_str()
        ->check(oneOf({"fold", "floquet", "none"}));
    steadyCmd->add_option("--twin-periods", steady.twinPeriods,
                          "forcing periods the time-domain twin runs from each solution for its 20 Hz filtered maxima "
                          "over the last one; 0: no twin maxima")
        ->capture_default_str()
        ->check(CLI::Range(0, 100));
    steadyCmd->add_flag("!--no-sweep-starts", steady.sweepStarts,
                        "start paths only from both ends of the range, not from the twin's swept steady states");

    app::SweepOptions sweep;
    CLI::App* sweepCmd = cli.add_subcommand(
        "sweep", "speed sweeps up and/or down, each speed starting from the previous one's final state");
    sweepCmd->add_option("scenario", sweep.scenarios, "scenario file(s) (TOML); one sweep set per car")
        ->required()
        ->check(CLI::ExistingFile);
    sweepCmd->add_option("--model", sweep.model, fmt::format("{} (overrides the scenarios)", fmt::join(modelNames, " | ")))
        ->check(oneOf(modelNames));
    sweepCmd->add_option("--amplitude-in", sweep.amplitudesIn, "cross-level amplitude(s) A [in]")
        ->check(inRange("track.amplitude", "in"));
    sweepCmd->add_option("--from-mph", sweep.fromMph, "lowest speed [mph]")->required()->check(inRange("run.speed", "mph"));
    sweepCmd->add_option("--to-mph", sweep.toMph, "highest speed [mph]")->required()->check(inRange("run.speed", "mph"));
    sweepCmd->add_option("--step-mph", sweep.stepMph, "speed step [mph]")->required()->check(inRange(stepRange, "mph"));
    sweepCmd->add_option("--direction", sweep.direction, "up | down | both")
        ->capture_default_str()
        ->check(oneOf({"up", "down", "both"}));
    sweepCmd->add_option("--duration-s", sweep.durationS, "simulated time per speed [s]")->check(inRange("run.duration", "s"));
    sweepCmd->add_option("--jobs", sweep.jobs, "parallel sweeps (default: one per core)")->check(inRange(jobsRange, ""));
    sweepCmd->add_option("--max-wall-s", sweep.maxWallS, "wall-time limit of each speed's run [s]")
        ->check(inRange("limits.max_wall_time", "s"));
    CLI::Option* freshFlag =
        sweepCmd->add_flag("--fresh", sweep.fresh, "start every speed from rest instead of the previous state");
    sweepCmd->add_option("--speed-ramp-s", sweep.rampS,
                         "the speed changes between points over this linear ramp; 0: an instantaneous step [s]")
        ->capture_default_str()
        ->check(CLI::Range(0.0, 60.0))
        ->excludes(freshFlag);  // --fresh starts every speed from rest: no speed change to ramp
    sweepCmd->add_flag("--json", sweep.json, "print exactly one JSON array of run summaries on stdout");
    addCommonOptions(sweepCmd, sweep, "write sweep.csv and sweep.json into this directory");
    sweepCmd->add_flag("--resume", sweep.resume,
                       "continue the interrupted sweep whose journal is in --out DIR.partial (docs/outputs.md, \"Journals and resume\")");

    app::ModesOptions modes;
    CLI::App* modesCmd = cli.add_subcommand(
        "modes", "natural frequencies and damping, linearized about static equilibrium, beside the report's Table 1");
    modesCmd->add_option("scenario", modes.scenario, "scenario file (TOML)")->required()->check(CLI::ExistingFile);
    modesCmd->add_option("--model", modes.model, fmt::format("{} (the multibody models)", fmt::join(multibodyNames, " | ")))
        ->check(oneOf(multibodyNames));
    modesCmd->add_flag("--json", modes.json, "print exactly one JSON object on stdout");
    addCommonOptions(modesCmd, modes, "write modes.csv and modes.json into this directory");

    app::StudyOptions study;
    CLI::App* studyCmd = cli.add_subcommand(
        "study", "a parameter study: the points of a study file's [vary] table, sharded and resumable "
                 "(docs/studies.md)");
    studyCmd->add_option("study", study.study, "study file (TOML)")->required()->check(CLI::ExistingFile);
    studyCmd->add_option("--out", study.outDir, "write study.csv and study.json into this directory")->required();
    studyCmd->add_option("--shard", study.shard, "K/N: run the points i with i mod N = K-1 (merge the shards with "
                                                 "rockroll merge)")
        ->capture_default_str();
    studyCmd->add_option("--jobs", study.jobs, "points in parallel (default: one per core)")->check(inRange(jobsRange, ""));
    studyCmd->add_flag("--resume", study.resume, "continue the interrupted study whose journal is in --out DIR.partial");
    studyCmd->add_flag("--force", study.force, "replace an existing non-empty output directory");

    app::MergeOptions merge;
    CLI::App* mergeCmd = cli.add_subcommand("merge", "merge the shard directories of one study into study.csv and study.json");
    mergeCmd->add_option("dirs", merge.dirs, "shard output directories")->required();
    mergeCmd->add_option("--out", merge.outDir, "write the merged study.csv and study.json into this directory")
        ->required();
    mergeCmd->add_flag("--force", merge.force, "replace an existing non-empty output directory");

    app::ValidateOptions validate;
    CLI::App* validateCmd = cli.add_subcommand("validate", "regenerate results/: REPORT.md, CSV data and plots");
    validateCmd->add_flag("--quick", validate.quick, "a few minutes: reduced-model sweeps only, coarser steps");
    validateCmd->add_option("--out", validate.outDir, "output directory")->capture_default_str();
    validateCmd->add_option("--jobs", validate.jobs, "threads (default: one per core)")->check(inRange(jobsRange, ""));
    validateCmd->add_option("--roll-limit-deg", validate.rollLimitDeg, "criteria: peak-to-peak roll limit [deg]")
        ->capture_default_str()->check(inRange(rollLimitRange, "deg"));
    validateCmd->add_option("--wheel-load-limit", validate.wheelLoadLimit,
                            "criteria: minimum single-wheel load over static")
        ->capture_default_str()->check(inRange(wheelLoadLimitRange, ""));

    app::OrbitsOptions orbits;
    CLI::App* orbitsCmd = cli.add_subcommand(
        "orbits", "periodic orbits of a time-domain model by shooting, continued in speed, with Floquet multipliers "
                  "(docs/orbits.md)");
    orbitsCmd->add_option("scenario", orbits.scenario, "scenario file (TOML)")->required()->check(CLI::ExistingFile);
    orbitsCmd->add_option("--model", orbits.model, fmt::format("{} (overrides the scenario's)", fmt::join(modelNames, " | ")))
        ->check(oneOf(modelNames));
    orbitsCmd->add_option("--amplitude-in", orbits.amplitudeIn, "cross-level amplitude A [in]")
        ->check(inRange("track.amplitude", "in"));
    orbitsCmd->add_option("--from-mph", orbits.fromMph, "start speed [mph]")->required()->check(inRange("run.speed", "mph"));
    orbitsCmd->add_option("--to-mph", orbits.toMph, "speed the continuation stops at [mph]")
        ->required()
        ->check(inRange("run.speed", "mph"));
    orbitsCmd->add_option("--step-mph", orbits.stepMph, "speed step [mph]")->capture_default_str()->check(inRange(stepRange, "mph"));
    orbitsCmd->add_option("--start-duration-s", orbits.startDurationS,
                          "the run from rest at --from-mph whose end the first shooting starts from [s]")
        ->capture_default_str()
        ->check(inRange("run.duration", "s"));
    CLI::Option* startSweep = orbitsCmd->add_option("--start-sweep-from-mph", orbits.startSweepFromMph,
                          "start from a speed sweep from this speed to --from-mph (--step-mph steps, "
                          "--start-duration-s each) instead of a run from rest [mph]")
        ->check(inRange("run.speed", "mph"));
    orbitsCmd->add_option("--start-speed-ramp-s", orbits.startRampS,
                          "the start sweep's speed ramp between speeds; 0: an instantaneous step [s]")
        ->capture_default_str()
        ->check(CLI::Range(0.0, 60.0))
        ->needs(startSweep);  // a start from rest has no speed change
    orbitsCmd->add_option("--accuracy", orbits.accuracy, "integrator accuracy of the one-period map")
        ->capture_default_str()
        ->check(CLI::Range(1e-12, 1e-3));
    orbitsCmd->add_option("--refinements", orbits.refinements, "step halvings at a failure before the branch ends")
        ->capture_default_str()
        ->check(CLI::Range(0, 8));
    orbitsCmd->add_option("--newton-steps", orbits.newtonSteps, "Newton steps per shooting, on P and then on P∘P")
        ->capture_default_str()
        ->check(CLI::Range(1, 100));
    orbitsCmd->add_flag("--iterate", orbits.iterate,
                        "find each orbit by iterating the one-period map (attracting orbits only, no Floquet "
                        "multipliers) instead of Newton: for the reduced model (docs/orbits.md)");
    orbitsCmd->add_option("--settle-periods", orbits.settlePeriods,
                          "forcing periods the start runs at --from-mph before the first shooting")
        ->capture_default_str()
        ->check(CLI::Range(0, 1000));
    orbitsCmd->add_option("--fd-step-scale", orbits.fdStepScale,
                          "scales the monodromy's finite-difference steps; the convergence tolerance stays")
        ->capture_default_str()
        ->check(CLI::Range(0.01, 100.0));
    orbitsCmd->add_option("--jobs", orbits.jobs, "threads for the monodromy's columns (default: one per core)")
        ->check(inRange(jobsRange, ""));
    orbitsCmd->add_flag("--json", orbits.json, "print exactly one JSON object on stdout");
    addCommonOptions(orbitsCmd, orbits, "write orbits.csv and orbits.json into this directory");

    app::PlotOptions plot;
    CLI::App* plotCmd = cli.add_subcommand(
        "plot", "plot a run, sweep, steady, modes, study or orbits output directory into DIR/plots/ (PNG and SVG, matplotlib "
                "under ROCKROLL_PYTHON, default /usr/bin/python3)");
    plotCmd->add_option("dir", plot.dir, "the output directory (written by --out)")->required()->check(CLI::ExistingDirectory);
    plotCmd->add_flag("--force", plot.force, "replace an existing non-empty DIR/plots");

    cli.footer("Exit codes (no others): 0 ok; 2 bad input: scenario file (and line), key or option, value and the "
               "accepted range, an input file over its size limit, an output that cannot be written, or a data "
               "file that is missing or unreadable; 3 numerical failure (integrator failure, step "
               "limit, runaway state, wall-time limit) with time and state, or any other failure of the computation; "
               "4 a sweep or study finished with failed points (each reported); 5 the car derailed or overturned (run "
               "stopped, history kept); 130 interrupted (SIGINT or SIGTERM).\n"
               "Memory: a run whose recorded history would exceed ROCKROLL_MAX_MEMORY_MB (default 2048) is refused "
               "(exit 2) with its estimate.");
    cli.set_version_flag("--version", app::getVersionString());
    app::setCommandLine(argc, argv);
    try {
        cli.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        // --help and --version exit 0; every command-line error is bad input.
        return cli.exit(e) == 0 ? app::kExitOk : app::kExitBadInput;
    }
    // ROCKROLL_PARSE_ONLY=1: check the command line and exit 0 without running (app/test/test_DocCommands.cpp).
    if (const char* parseOnly = std::getenv("ROCKROLL_PARSE_ONLY"); parseOnly && std::string(parseOnly) == "1") return 0;
    try {
        if (runCmd->parsed()) return app::runCommand(run);
        if (steadyCmd->parsed()) return app::steadyCommand(steady);
        if (sweepCmd->parsed()) return app::sweepCommand(sweep);
        if (modesCmd->parsed()) return app::modesCommand(modes);
        if (validateCmd->parsed()) return app::validateCommand(validate);
        if (plotCmd->parsed()) return app::plotCommand(plot);
        if (studyCmd->parsed()) return app::studyCommand(study);
        if (mergeCmd->parsed()) return app::mergeCommand(merge);
        if (orbitsCmd->parsed()) return app::orbitsCommand(orbits);
        return app::runDefaultCase();
    } catch (const ScenarioError& e) {
        fmt::print(stderr, "rockroll: scenario error: {}\n", e.what());
        return app::kExitBadInput;
    } catch (const NumericalFailure& e) {
        fmt::print(stderr, "rockroll: numerical failure: {}\n", e.what());
        return app::kExitNumericalFailure;
    } catch (const app::OutputError& e) {
        fmt::print(stderr, "rockroll: cannot write the output: {}\n", e.what());
        return app::kExitBadInput;
    } catch (const std::filesystem::filesystem_error& e) {
        fmt::print(stderr, "rockroll: cannot write the output: {}\n", e.what());
        return app::kExitBadInput;
    } catch (const std::invalid_argument& e) {
        fmt::print(stderr, "rockroll: bad input: {}\n", e.what());
        return app::kExitBadInput;
    } catch (const DataFileError& e) {
        fmt::print(stderr, "rockroll: data file error: {}\n", e.what());
        return app::kExitBadInput;
    } catch (const std::bad_alloc&) {
        fmt::print(stderr, "rockroll: out of memory (lower ROCKROLL_MAX_MEMORY_MB, the duration or the output rate)\n");
        return app::kExitNumericalFailure;
    } catch (const std::exception& e) {
        fmt::print(stderr, "rockroll: computation failed: {}\n", e.what());
        return app::kExitNumericalFailure;
    } catch (...) {
        fmt::print(stderr, "rockroll: computation failed (an error that is not a std::exception)\n");
        return app::kExitNumericalFailure;
    }
}
