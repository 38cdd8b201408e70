// Runs the rockroll program from a test as a user runs it from a shell, and keeps
// what it printed: the one way the command-line tests start it.
#pragma once

#include "tests/TextFile.h"

#include <cstdlib>
#include <filesystem>
#include <string>
#include <sys/wait.h>

namespace rockroll::test {

/// The exit code in a std::system or pclose status; -1 when the process did not
/// exit (killed by a signal), so a crash never passes as a documented exit code.
inline int getExitCode(int status) { return WIFEXITED(status) ? WEXITSTATUS(status) : -1; }

struct CliOutcome {
    int exitCode = -1;
    std::string out, err;  ///< what it printed on stdout and stderr
};

/// `[ENV] rockroll ARGS` (shell words, ENV as `NAME=value ...`) run in `dir`, with its
/// stdout and stderr kept in dir/stdout.txt and dir/stderr.txt.
inline CliOutcome runRockroll(const std::filesystem::path& dir, const std::string& args, const std::string& env = "") {
    const std::string cmd = "cd '" + dir.string() + "' && " + env + " '" + ROCKROLL_BIN + "' " + args +
                            " > stdout.txt 2> stderr.txt";
    CliOutcome o;
    o.exitCode = getExitCode(std::system(cmd.c_str()));
    o.out = readTextFile(dir / "stdout.txt");
    o.err = readTextFile(dir / "stderr.txt");
    return o;
}

}  // namespace rockroll::test
