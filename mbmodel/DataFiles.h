#pragma once
// Where rockroll finds the data files it ships (the report's numbers, the built-in
// scenarios, the plotting package python/rockroll_plots): an installed program in its own prefix,
// a build-tree program in the source tree it was configured from. No Simbody.
#include <filesystem>
#include <stdexcept>
#include <vector>

namespace rockroll {

/// The folders searched, in order, each holding the source tree's layout
/// ("scenarios/reference/mit1976.toml", "python/rockroll_plots/__main__.py"):
///  1. $ROCKROLL_DATA_DIR, when set;
///  2. <prefix>/share/rockroll, where <prefix> is two folders above the executable
///     (an installed program uses its own prefix's files first);
///  3. the source tree this build was configured from;
///  4. two folders above the executable's folder (build/bin/rockroll inside a source
///     tree that moved after configuring).
std::vector<std::filesystem::path> getDataDirs();

/// A shipped data file that is missing or cannot be read (the install, ROCKROLL_DATA_DIR,
/// ROCKROLL_MIT1976): bad input, exit 2 at the command line (docs/cli.md, "Exit codes").
class DataFileError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// The first data folder holding `relative`; DataFileError naming every path tried
/// when none does.
std::filesystem::path findDataFile(const std::filesystem::path& relative);

}  // namespace rockroll
