#include "app/PlotCommand.h"

#include "app/Commands.h"
#include "app/Output.h"
#include "mbmodel/DataFiles.h"

#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fmt/format.h>
#include <stdexcept>
#include <sys/wait.h>
#include <unistd.h>

namespace rockroll::app {

namespace fs = std::filesystem;

std::string getPlotPython() {
    const char* p = std::getenv("ROCKROLL_PYTHON");
    return p && *p ? std::string(p) : std::string("/usr/bin/python3");
}

int runPlotPackage(const std::vector<std::string>& args) {
    const std::string python = getPlotPython();
    if (access(python.c_str(), X_OK) != 0)
        throw std::invalid_argument(fmt::format("ROCKROLL_PYTHON {}: not an executable file; expected a Python 3 with "
                                                "matplotlib (default /usr/bin/python3, Debian's python3-matplotlib)",
                                                python));
    // <data dir>/python/rockroll_plots/__main__.py -> <data dir>/python on PYTHONPATH.
    const std::string packageDir = findDataFile("python/rockroll_plots/__main__.py").parent_path().parent_path().string();
    std::vector<std::string> argv{python, "-m", "rockroll_plots"};
    argv.insert(argv.end(), args.begin(), args.end());
    std::vector<char*> cargv;
    for (auto& a : argv) cargv.push_back(a.data());
    cargv.push_back(nullptr);
    std::fflush(stdout);
    std::fflush(stderr);
    const pid_t pid = fork();
    if (pid < 0) throw std::runtime_error(fmt::format("cannot start {}: {}", python, std::strerror(errno)));
    if (pid == 0) {
        // The parent blocks SIGINT/SIGTERM for its handler thread (installInterruptHandler);
        // the plotting process takes them as usual.
        sigset_t none;
        sigemptyset(&none);
        sigprocmask(SIG_SETMASK, &none, nullptr);
        setenv("PYTHONPATH", packageDir.c_str(), 1);
        setenv("PYTHONDONTWRITEBYTECODE", "1", 1);  // nothing written into the installed or source tree
        execv(python.c_str(), cargv.data());
        _exit(127);
    }
    int status = 0;
    while (waitpid(pid, &status, 0) < 0)
        if (errno != EINTR) throw std::runtime_error(fmt::format("waiting for {}: {}", python, std::strerror(errno)));
    if (WIFEXITED(status)) return WEXITSTATUS(status);
    throw std::runtime_error(fmt::format("{} -m rockroll_plots was killed by signal {}", python, WTERMSIG(status)));
}

int plotCommand(const PlotOptions& o) {
    OutputDirectory plots(fs::path(o.dir) / "plots", o.force, "rockroll plot: the plots directory");
    const int rc = runPlotPackage({"output", o.dir, plots.getPartialPath().string()});
    if (rc == kExitBadInput) return kExitBadInput;  // the message is printed
    if (rc != 0) throw std::runtime_error(fmt::format("plotting {} failed ({} -m rockroll_plots exit {})", o.dir,
                                                      getPlotPython(), rc));
    plots.commit();
    fmt::print("wrote {}\n", plots.getFinalPath("").string());
    return kExitOk;
}

}  // namespace rockroll::app
