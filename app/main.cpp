// rockroll: freight-car rock-and-roll simulator (command line).
#include "app/Commands.h"
#include "app/Output.h"
#include "app/Provenance.h"
#include "mbmodel/Simulation.h"
#include "scenarios/ModelRegistry.h"
#include "scenarios/ScenarioLoader.h"

#include <CLI/CLI.hpp>
#include <cstdlib>
#include <fmt/format.h>
#include <fmt/ranges.h>

int main(int argc, char** argv) {
    using namespace rockroll;
    app::installInterruptHandler();  // first: before any thread starts
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
        ->check(CLI::IsMember(modelNames));
    runCmd->add_option("--speed-mph", run.speedMph, "speed [mph]")->check(CLI::PositiveNumber);
    runCmd->add_option("--amplitude-in", run.amplitudeIn, "cross-level amplitude A [in]")
        ->check(CLI::NonNegativeNumber);
    runCmd->add_option("--duration-s", run.durationS, "simulated time [s]")->check(CLI::PositiveNumber);
    addCommonOptions(runCmd, run,
                     "output directory: history.csv, summary.json (default out/<scenario>-<model>)");
    runCmd->add_option("--max-wall-s", run.maxWallS, "wall-time limit; past it the run fails (exit 3) [s]")
        ->check(CLI::PositiveNumber);
    runCmd->add_flag("--json", run.json, "print exactly one JSON summary object on stdout");

    app::SteadyOptions steady;
    CLI::App* steadyCmd = cli.add_subcommand(
        "steady", "describing-function steady state against speed (harmonic balance, arclength continuation)");
    steadyCmd->add_option("scenario", steady.scenario, "scenario file (TOML)")->required()->check(CLI::ExistingFile);
    steadyCmd->add_option("--amplitude-in", steady.amplitudeIn, "cross-level amplitude A [in]")
        ->check(CLI::PositiveNumber);
    steadyCmd->add_option("--from-mph", steady.fromMph, "lowest speed [mph]")->capture_default_str()->check(CLI::PositiveNumber);
    steadyCmd->add_option("--to-mph", steady.toMph, "highest speed [mph]")->capture_default_str()->check(CLI::PositiveNumber);
    steadyCmd->add_flag("--json", steady.json, "print exactly one JSON object on stdout");
    addCommonOptions(steadyCmd, steady, "write steady.csv and steady.json into this directory");
    steadyCmd->add_option("--stability", steady.stabilityMethod,
                          "fold: each stretch between folds by Floquet on the time-domain twin at its middle point; "
                          "floquet: every point (slow); none")
        ->capture_default_str()
        ->check(CLI::IsMember({"fold", "floquet", "none"}));

    app::SweepOptions sweep;
    CLI::App* sweepCmd = cli.add_subcommand(
        "sweep", "speed sweeps up and/or down, each speed starting from the previous one's final state");
    sweepCmd->add_option("scenario", sweep.scenarios, "scenario file(s) (TOML); one sweep set per car")
        ->required()
        ->check(CLI::ExistingFile);
    sweepCmd->add_option("--model", sweep.model, fmt::format("{} (overrides the scenarios)", fmt::join(modelNames, " | ")))
        ->check(CLI::IsMember(modelNames));
    sweepCmd->add_option("--amplitude-in", sweep.amplitudesIn, "cross-level amplitude(s) A [in]")
        ->check(CLI::PositiveNumber);
    sweepCmd->add_option("--from-mph", sweep.fromMph, "lowest speed [mph]")->required()->check(CLI::PositiveNumber);
    sweepCmd->add_option("--to-mph", sweep.toMph, "highest speed [mph]")->required()->check(CLI::PositiveNumber);
    sweepCmd->add_option("--step-mph", sweep.stepMph, "speed step [mph]")->required()->check(CLI::PositiveNumber);
    sweepCmd->add_option("--direction", sweep.direction, "up | down | both")
        ->capture_default_str()
        ->check(CLI::IsMember({"up", "down", "both"}));
    sweepCmd->add_option("--duration-s", sweep.durationS, "simulated time per speed [s]")->check(CLI::PositiveNumber);
    sweepCmd->add_option("--jobs", sweep.jobs, "parallel sweeps (default: one per core)")->check(CLI::NonNegativeNumber);
    sweepCmd->add_option("--max-wall-s", sweep.maxWallS, "wall-time limit of each speed's run [s]")
        ->check(CLI::PositiveNumber);
    sweepCmd->add_flag("--fresh", sweep.fresh, "start every speed from rest instead of the previous state");
    sweepCmd->add_flag("--json", sweep.json, "print exactly one JSON array of run summaries on stdout");
    addCommonOptions(sweepCmd, sweep, "write sweep.csv and sweep.json into this directory");

    app::ModesOptions modes;
    CLI::App* modesCmd = cli.add_subcommand(
        "modes", "natural frequencies and damping, linearized about static equilibrium, beside the report's Table 1");
    modesCmd->add_option("scenario", modes.scenario, "scenario file (TOML)")->required()->check(CLI::ExistingFile);
    modesCmd->add_option("--model", modes.model, fmt::format("{} (the multibody models)", fmt::join(multibodyNames, " | ")))
        ->check(CLI::IsMember(multibodyNames));
    modesCmd->add_flag("--json", modes.json, "print exactly one JSON object on stdout");
    addCommonOptions(modesCmd, modes, "write modes.csv and modes.json into this directory");

    app::ValidateOptions validate;
    CLI::App* validateCmd = cli.add_subcommand("validate", "regenerate results/: REPORT.md, CSV data and plots");
    validateCmd->add_flag("--quick", validate.quick, "a few minutes: reduced-model sweeps only, coarser steps");
    validateCmd->add_option("--out", validate.outDir, "output directory")->capture_default_str();
    validateCmd->add_option("--jobs", validate.jobs, "threads (default: one per core)")->check(CLI::NonNegativeNumber);
    validateCmd->add_option("--roll-limit-deg", validate.rollLimitDeg, "criteria: peak-to-peak roll limit [deg]")
        ->capture_default_str()->check(CLI::PositiveNumber);
    validateCmd->add_option("--wheel-load-limit", validate.wheelLoadLimit,
                            "criteria: minimum single-wheel load over static")
        ->capture_default_str()->check(CLI::Range(0.0, 1.0));

    cli.footer("Exit codes: 0 ok; 2 bad input (scenario file, key, value and what was expected); 3 numerical "
               "failure (integrator failure, step limit, runaway state, wall-time limit), with time and state; "
               "4 a sweep or study finished with failed points; 5 the car derailed or overturned (run stopped, "
               "history kept); 1 any other error.");
    cli.set_version_flag("--version", app::getVersionString());
    app::setCommandLine(argc, argv);
    CLI11_PARSE(cli, argc, argv);
    // ROCKROLL_PARSE_ONLY=1: check the command line and exit 0 without running (tests/test_DocCommands.cpp).
    if (const char* parseOnly = std::getenv("ROCKROLL_PARSE_ONLY"); parseOnly && std::string(parseOnly) == "1") return 0;
    try {
        if (runCmd->parsed()) return app::runCommand(run);
        if (steadyCmd->parsed()) return app::steadyCommand(steady);
        if (sweepCmd->parsed()) return app::sweepCommand(sweep);
        if (modesCmd->parsed()) return app::modesCommand(modes);
        if (validateCmd->parsed()) return app::validateCommand(validate);
        return app::runDefaultCase();
    } catch (const ScenarioError& e) {
        fmt::print(stderr, "rockroll: scenario error: {}\n", e.what());
        return app::kExitBadInput;
    } catch (const NumericalFailure& e) {
        fmt::print(stderr, "rockroll: numerical failure: {}\n", e.what());
        return app::kExitNumericalFailure;
    } catch (const std::exception& e) {
        fmt::print(stderr, "rockroll: error: {}\n", e.what());
        return 1;
    }
}
