#pragma once
// The rockroll sub-commands.
#include <optional>
#include <string>

namespace rockroll::app {

struct RunOptions {
    std::string scenario;               ///< file path
    std::optional<std::string> model;
    std::optional<double> speedMph, amplitudeIn, durationS;
    std::string outDir;                 ///< empty: out/<scenario>-<model>
    bool json = false;
};

struct SteadyOptions {
    std::string scenario;
    std::optional<double> amplitudeIn;
    double fromMph = 10, toMph = 22;
    bool json = false;
    std::string stabilityMethod = "fold";  ///< fold | floquet | none
};

int runDefaultCase();
int steadyCommand(const SteadyOptions& options);
int runCommand(const RunOptions& options);

}  // namespace rockroll::app
