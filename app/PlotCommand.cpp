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
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

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
    // The environment, with the package's folder on PYTHONPATH and no bytecode written
    // into the installed or source tree.
    std::vector<std::string> env{"PYTHONPATH=" + packageDir, "PYTHONDONTWRITEBYTECODE=1"};
    for (char** e = environ; *e; ++e)
        if (std::strncmp(*e, "PYTHONPATH=", 11) != 0 && std::strncmp(*e, "PYTHONDONTWRITEBYTECODE=", 24) != 0)
            env.emplace_back(*e);
    auto pointers = [](std::vector<std::string>& v) {
        std::vector<char*> p;
        for (auto& x : v) p.push_back(x.data());
        p.push_back(nullptr);
        return p;
    };
    std::vector<char*> cargv = pointers(argv), cenv = pointers(env);
    // This process blocks SIGINT/SIGTERM for its handler thread (installInterruptHandler);
    // the plotting process takes them as usual.
    posix_spawnattr_t attr;
    posix_spawnattr_init(&attr);
    sigset_t none;
    sigemptyset(&none);
    posix_spawnattr_setsigmask(&attr, &none);
    posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETSIGMASK);
    std::fflush(stdout);
    std::fflush(stderr);
    pid_t pid = 0;
    const int spawned = posix_spawn(&pid, python.c_str(), nullptr, &attr, cargv.data(), cenv.data());
    posix_spawnattr_destroy(&attr);
    if (spawned != 0)
        throw std::invalid_argument(fmt::format("ROCKROLL_PYTHON {}: cannot be run: {}", python, std::strerror(spawned)));
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
