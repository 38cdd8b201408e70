#pragma once
// rockroll plot DIR: the plots of a run, sweep, steady, modes, study or orbits output
// directory, drawn by the project's plotting package python/rockroll_plots
// (matplotlib) into DIR/plots/, PNG and SVG. Also the runner validate draws its
// report's plots with.
#include <string>
#include <vector>

namespace rockroll::app {

struct PlotOptions {
    std::string dir;     ///< the output directory to plot
    bool force = false;  ///< replace an existing non-empty DIR/plots
};

/// The Python the plots run under: $ROCKROLL_PYTHON, else /usr/bin/python3 (Debian's,
/// with python3-matplotlib).
std::string getPlotPython();

/// Runs `python -m rockroll_plots ARGS...` with the package's folder (found by
/// mbmodel/DataFiles.h findDataFile) on PYTHONPATH; returns its exit status (2: bad
/// input, its message already printed). std::invalid_argument when the Python
/// cannot be run.
int runPlotPackage(const std::vector<std::string>& args);

/// `rockroll plot`: exit 0, or 2 (not a rockroll output, a malformed file, no
/// matplotlib, DIR/plots not empty without --force).
int plotCommand(const PlotOptions& options);

}  // namespace rockroll::app
