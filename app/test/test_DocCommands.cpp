// Every `rockroll` command quoted in README.md and docs/*.md goes through the
// real binary, so the docs cannot quote a flag the CLI rejects.
//
// Convention for the docs (docs/validation.md, "Commands quoted in the docs"):
//  * A command is a line of a fenced code block, or an inline code span, that
//    starts with `rockroll`, `build/bin/rockroll` or `./build.sh [targets] && build/bin/rockroll`
//    (the build step is not run; a trailing `# comment` in a code block is dropped).
//  * Quoted commands are concrete: no placeholders ([--opt], <car>, A|B, or
//    all-capital words such as A or N). A placeholder fails this test.
//  * `rockroll SUB` alone names the sub-command: `rockroll SUB --help` must exit 0.
//  * A code-block command whose comment says `# exit N` must exit with N (e.g. a
//    run that overturns, exit 5); every other command must exit 0.
//  * Commands of one doc file share one directory and run in the order quoted, so
//    a command may read what an earlier one wrote (`run --from-summary`).
//  * Run for real, in that directory under the build tree with a link to
//    scenarios/: `run` (with `--duration-s 0.2` appended when it has no duration),
//    `modes`, `plot` and `steady --stability none`. Their `--json` output must be one JSON
//    document, and every history.csv they write must read back as a table.
//  * Everything else (the default case, sweeps, validate, steady with stability) is
//    parsed only: ROCKROLL_PARSE_ONLY=1 makes rockroll check the command line
//    (flags, values, files) and exit 0 without running.
#include "tests/CliRunner.h"
#include "tests/CsvReader.h"
#include "tests/TestTmp.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>
#include <sys/wait.h>

namespace fs = std::filesystem;

namespace {

using rockroll::test::CliOutcome;
using rockroll::test::readTextFile;

struct DocCommand {
    std::string file;  ///< README.md, docs/x.md
    int line = 0;
    std::string text;  ///< as quoted, whitespace collapsed, build step and comment removed
    int expectedExit = 0;  ///< from a `# exit N` comment
};

std::string collapse(const std::string& s) {
    std::istringstream in(s);
    std::string w, out;
    while (in >> w) out += (out.empty() ? "" : " ") + w;
    return out;
}

std::vector<std::string> split(const std::string& s) {
    std::istringstream in(s);
    std::vector<std::string> out;
    for (std::string w; in >> w;) out.push_back(w);
    return out;
}

/// The quoted command without its build step, or "" when `s` is not a rockroll command.
std::string asCommand(std::string s) {
    s = collapse(s);
    static const std::regex re(R"(^(?:\./build\.sh(?: [A-Za-z_]+)* && )?(?:build/bin/)?(rockroll(?: .*)?)$)");
    std::smatch m;
    return std::regex_match(s, m, re) ? m[1].str() : "";
}

std::vector<DocCommand> extractCommands(const std::string& name, const std::string& text) {
    std::vector<DocCommand> out;
    std::istringstream in(text);
    std::string line, prose;
    int lineNo = 0, proseStart = 1;
    bool fenced = false;
    auto scanProse = [&] {
        // Inline code spans may wrap across lines inside a paragraph.
        static const std::regex span("`([^`]+)`");
        for (auto it = std::sregex_iterator(prose.begin(), prose.end(), span); it != std::sregex_iterator(); ++it) {
            const std::string cmd = asCommand((*it)[1].str());
            const int at = proseStart + int(std::count(prose.begin(), prose.begin() + it->position(), '\n'));
            if (!cmd.empty()) out.push_back({name, at, cmd});
        }
        prose.clear();
    };
    while (std::getline(in, line)) {
        ++lineNo;
        if (line.rfind("```", 0) == 0) {
            if (!fenced) scanProse();
            fenced = !fenced;
            proseStart = lineNo + 1;
            continue;
        }
        if (fenced) {
            std::string l = line;
            static const std::regex comment(R"(\s+#.*$)"), exitComment(R"(#\s*exit\s+(\d+))");
            std::smatch m;
            const int expected = std::regex_search(l, m, exitComment) ? std::stoi(m[1].str()) : 0;
            l = std::regex_replace(l, comment, "");
            const std::string cmd = asCommand(l);
            if (!cmd.empty()) out.push_back({name, lineNo, cmd, expected});
        } else {
            if (prose.empty()) proseStart = lineNo;
            prose += line + "\n";
        }
    }
    scanProse();
    return out;
}

std::vector<DocCommand> extractAll() {
    const fs::path src = ROCKROLL_SOURCE_DIR;
    std::vector<fs::path> files{src / "README.md"};
    std::vector<fs::path> docs;
    for (const auto& e : fs::directory_iterator(src / "docs"))
        if (e.path().extension() == ".md") docs.push_back(e.path());
    std::sort(docs.begin(), docs.end());
    files.insert(files.end(), docs.begin(), docs.end());
    std::vector<DocCommand> all;
    for (const auto& f : files) {
        const auto c = extractCommands(fs::relative(f, src).string(), readTextFile(f));
        all.insert(all.end(), c.begin(), c.end());
    }
    return all;
}

/// Runs `args` (the text after "rockroll") through the binary in `dir`, where
/// scenarios/ links to the source tree's, as the docs' relative paths expect.
CliOutcome runDocCommand(const fs::path& dir, const std::string& args, bool parseOnly) {
    fs::create_directories(dir);
    const fs::path scen = dir / "scenarios";
    if (!fs::exists(scen)) fs::create_directory_symlink(fs::path(ROCKROLL_SOURCE_DIR) / "scenarios", scen);
    return rockroll::test::runRockroll(dir, args, parseOnly ? "ROCKROLL_PARSE_ONLY=1" : "");
}

const std::vector<std::string> kSubcommands{"run", "steady", "sweep", "modes", "validate", "plot", "study", "merge", "orbits"};

bool has(const std::vector<std::string>& t, const std::string& w) { return std::find(t.begin(), t.end(), w) != t.end(); }

std::string placeholderIn(const std::string& cmd) {
    if (cmd.find_first_of("[]<>|") != std::string::npos) return "bracket, angle bracket or |";
    static const std::regex caps("^[A-Z][A-Z0-9_]*$");
    for (const auto& t : split(cmd))
        if (std::regex_match(t, caps)) return "placeholder word " + t;
    return "";
}

}  // namespace

TEST(DocCommands, ExtractionFindsInlineBlockAndWrappedCommands) {
    const std::string md = "Intro `rockroll run a.toml\n--json` and `ls -l`.\n\n```sh\n./build.sh rockroll && build/bin/rockroll\n"
                           "build/bin/rockroll validate --quick      # comment\nctest\n```\nSee `rockroll modes`.\n";
    const auto c = extractCommands("x.md", md);
    ASSERT_EQ(c.size(), 4u);
    EXPECT_EQ(c[0].text, "rockroll run a.toml --json");
    EXPECT_EQ(c[0].line, 1);
    EXPECT_EQ(c[1].text, "rockroll");
    EXPECT_EQ(c[1].line, 5);
    EXPECT_EQ(c[2].text, "rockroll validate --quick");
    EXPECT_EQ(c[3].text, "rockroll modes");
    EXPECT_EQ(c[3].line, 9);
    EXPECT_EQ(placeholderIn("rockroll steady s.toml [--json]"), "bracket, angle bracket or |");
    EXPECT_EQ(placeholderIn("rockroll sweep s.toml --amplitude-in A"), "placeholder word A");
    EXPECT_EQ(placeholderIn("rockroll run scenarios/70ton-loaded.toml --speed-mph 15"), "");
}

// The check can fail: a flag the CLI does not know is rejected in parse-only mode.
TEST(DocCommands, ParseOnlyRejectsAnUnknownFlag) {
    const fs::path dir = rockroll::test::makeTestTempDir();
    const CliOutcome bad = runDocCommand(dir, "steady scenarios/70ton-loaded.toml --no-stability", true);
    EXPECT_EQ(bad.exitCode, 2) << bad.err;  // every command-line error is bad input (docs/cli.md, "Exit codes")
    EXPECT_NE(bad.err.find("The following argument was not expected"), std::string::npos) << bad.err;
    const CliOutcome good = runDocCommand(dir, "steady scenarios/70ton-loaded.toml --stability none", true);
    EXPECT_EQ(good.exitCode, 0) << good.err;
    EXPECT_TRUE(good.out.empty()) << "parse-only must not run: " << good.out;
}

TEST(DocCommands, EveryQuotedCommandRuns) {
    const auto commands = extractAll();
    // The README's runnable examples alone are more than this; fewer means the extraction broke.
    ASSERT_GE(commands.size(), 8u);
    const fs::path root = rockroll::test::makeTestTempDir();
    int index = 0, ran = 0, parsed = 0, named = 0;
    for (const auto& c : commands) {
        SCOPED_TRACE(c.file + ":" + std::to_string(c.line) + ": " + c.text);
        ++index;
        std::string fileDir = c.file;
        std::replace(fileDir.begin(), fileDir.end(), '/', '_');
        const fs::path dir = root / fileDir;
        const std::string placeholder = placeholderIn(c.text);
        EXPECT_EQ(placeholder, "") << "quote a concrete command (see the convention in app/test/test_DocCommands.cpp)";
        if (!placeholder.empty()) continue;
        std::vector<std::string> t = split(c.text);
        std::string args = c.text.substr(std::string("rockroll").size());
        if (t.size() == 2 && has(kSubcommands, t[1])) {
            const CliOutcome o = runDocCommand(dir, args + " --help", false);
            EXPECT_EQ(o.exitCode, 0) << o.err;
            ++named;
            continue;
        }
        const std::string sub = t.size() > 1 ? t[1] : "";
        const bool run = sub == "run" || sub == "modes" || sub == "plot" ||
                         (sub == "steady" && c.text.find("--stability none") != std::string::npos);
        if (sub == "run" && !has(t, "--duration-s")) args += " --duration-s 0.2";
        // Long commands: their flags at least.
        const CliOutcome p = runDocCommand(dir, args, true);
        EXPECT_EQ(p.exitCode, 0) << "parse-only: " << p.err;
        if (!run) {
            ++parsed;
            continue;
        }
        const CliOutcome o = runDocCommand(dir, args, false);
        ++ran;
        EXPECT_EQ(o.exitCode, c.expectedExit) << o.err;
        if (has(t, "--json")) {
            EXPECT_TRUE(nlohmann::json::accept(o.out)) << "--json must print one JSON document:\n" << o.out;
        } else {
            EXPECT_FALSE(o.out.empty());
        }
        for (const auto& e : fs::recursive_directory_iterator(dir, fs::directory_options::none)) {
            if (e.path().filename() == "scenarios") continue;
            if (e.path().filename() != "history.csv") continue;
            try {
                const auto table = rockroll::test::parseCsvTable(readTextFile(e.path()));
                EXPECT_FALSE(table.rows.empty()) << e.path();
                for (const auto& col : table.columns) (void)table.numbers(col);
            } catch (const std::exception& x) {
                ADD_FAILURE() << e.path() << ": " << x.what();
            }
        }
    }
    std::printf("doc commands: %d run, %d parsed only, %d sub-command names checked with --help\n", ran, parsed, named);
    EXPECT_GE(ran, 3) << "the docs' short commands must actually run";
}
