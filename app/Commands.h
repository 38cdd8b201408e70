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

int runDefaultCase();
int runCommand(const RunOptions& options);

}  // namespace rockroll::app
