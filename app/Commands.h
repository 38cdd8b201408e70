#pragma once
// The rockroll sub-commands.
#include <optional>
#include <string>
#include <vector>

namespace rockroll::app {

/// Exit codes (documented in --help and docs/cli.md, "Exit codes").
inline constexpr int kExitOk = 0;
inline constexpr int kExitBadInput = 2;
inline constexpr int kExitNumericalFailure = 3;
inline constexpr int kExitFailedPoints = 4;
inline constexpr int kExitDerailed = 5;  ///< derailed or overturned

/// What every command that reads a scenario shares: `--set KEY=VALUE` overrides of
/// scenario keys (applied in order, through the loader's validation) and the output
/// directory (`--out DIR`, replaced only with `--force`; app/Output.h OutputDirectory).
struct CommonOptions {
    std::vector<std::string> sets;      ///< each "KEY=VALUE" as given to --set
    std::string outDir;                 ///< empty: run writes out/<scenario>-<model>, the others nothing
    bool force = false;                 ///< replace an existing non-empty output directory
};

struct RunOptions : CommonOptions {
    std::string scenario;               ///< file path
    std::optional<std::string> model;
    std::optional<double> speedMph, amplitudeIn, durationS;
    std::optional<double> maxWallS;     ///< wall-time limit of the run [s]
    std::optional<std::string> fromSummary;  ///< rerun the run a summary.json describes
    bool json = false;
};

struct SteadyOptions : CommonOptions {
    std::string scenario;
    std::optional<double> amplitudeIn;
    double fromMph = 10, toMph = 22;
    bool json = false;
    std::string stabilityMethod = "fold";  ///< fold | floquet | none
    int twinPeriods = 5;      ///< the twin's run per point for its maxima; 0: none
    bool sweepStarts = true;  ///< also start paths from the twin's swept steady states
};

struct SweepOptions : CommonOptions {
    std::vector<std::string> scenarios;
    std::optional<std::string> model;
    std::vector<double> amplitudesIn;
    double fromMph = 0, toMph = 0, stepMph = 0;
    std::string direction = "both";
    std::optional<double> durationS;
    std::optional<double> maxWallS;  ///< wall-time limit of each speed's run [s]
    int jobs = 0;  ///< 0: one per core
    bool json = false, fresh = false;
    /// The speed change between sweep points: a linear ramp over this time; 0 steps the
    /// speed at once, as a run restarted at the new speed from the last state does [s].
    double rampS = 1.0;
    bool resume = false;  ///< continue from the journal in --out DIR.partial (app/Journal.h)
};

struct ModesOptions : CommonOptions {
    std::string scenario;
    std::optional<std::string> model;
    bool json = false;
};

struct ValidateOptions {
    bool quick = false;
    std::string outDir = "results";
    int jobs = 0;
    double rollLimitDeg = 6;      ///< peak-to-peak roll limit of the criteria table
    double wheelLoadLimit = 0.10; ///< minimum single-wheel load / static
};

/// rockroll study STUDY.toml --out DIR [--shard K/N] [--jobs J] [--resume] [--force] (app/Study.h).
struct StudyOptions {
    std::string study;
    std::string outDir;
    std::string shard = "1/1";  ///< K/N: the points i with i mod N = K − 1
    int jobs = 0;               ///< 0: one per core
    bool resume = false, force = false;
};

/// rockroll merge DIR... --out DIR [--force].
struct MergeOptions {
    std::vector<std::string> dirs;
    std::string outDir;
    bool force = false;
};

int studyCommand(const StudyOptions& options);
int mergeCommand(const MergeOptions& options);
int runDefaultCase();
int validateCommand(const ValidateOptions& options);
int modesCommand(const ModesOptions& options);
int sweepCommand(const SweepOptions& options);
int steadyCommand(const SteadyOptions& options);
int runCommand(const RunOptions& options);

}  // namespace rockroll::app
