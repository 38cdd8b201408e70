// rockroll validate: regenerates results/ — the cross-validation report with its
// CSV data and matplotlib plots. This is the driver: it runs the sections (one file
// each, app/ValidateSections.h) in report order, writes validation.json and REPORT.md,
// and draws the plots. Every table and plot names the command that made it.
#include "app/Commands.h"
#include "app/JsonWriter.h"
#include "app/PlotCommand.h"
#include "mbmodel/Parallel.h"
#include "app/ValidateSections.h"

#include <chrono>
#include <ctime>
#include <cstdlib>
#include <cstdio>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <functional>
#include <stdexcept>
#include <string_view>

namespace rockroll::app {

namespace fs = std::filesystem;

namespace {

std::string runShell(const std::string& cmd) {
    std::string out;
    if (FILE* p = popen(cmd.c_str(), "r")) {
        char buf[256];
        while (fgets(buf, sizeof buf, p)) out += buf;
        pclose(p);
    }
    while (!out.empty() && (out.back() == '\n' || out.back() == ' ')) out.pop_back();
    return out;
}

std::string getCommit() {
    const std::string dir = ROCKROLL_SOURCE_DIR;
    const std::string hash = runShell("git -C '" + dir + "' rev-parse HEAD 2>/dev/null");
    if (hash.empty()) return "unknown (not a git checkout)";
    const std::string dirty = runShell("git -C '" + dir + "' status --porcelain --untracked-files=no -- . ':!results' 2>/dev/null");
    return dirty.empty() ? hash : hash + " (with uncommitted changes)";
}

}  // namespace

int validateCommand(const ValidateOptions& o) {
    const auto wall0 = std::chrono::steady_clock::now();
    Settings s;
    s.quick = o.quick;
    s.out = o.outDir;
    s.jobs = resolveJobCount(o.jobs);
    s.rollLimitDeg = o.rollLimitDeg;
    s.wheelLoadLimit = o.wheelLoadLimit;
    // The full run sweeps reduced, eom and the half car on every case and the full car on the
    // report's main car, so Tables 3 and 4 compare them on every branch (from rest, up sweep,
    // down sweep); the quick run sweeps the reduced model.
    s.sweepModels = o.quick ? std::vector<std::string>{model_names::kReduced}
                            : std::vector<std::string>{model_names::kReduced, model_names::kHalfCar, model_names::kEom};
    if (!o.quick) s.fullCarSweepCars = {"70ton-loaded"};
    s.sweepStep = o.quick ? 1.0 : 0.5;
    s.sweepDuration = o.quick ? 15 : 30;
    s.runDuration = 20;
    fs::create_directories(s.out);

    const std::string python = getPlotPython();
    if (runShell(python + " -c 'import matplotlib; print(1)' 2>/dev/null") != "1")
        throw std::runtime_error("validate needs Debian's matplotlib for the plots: apt-get install python3-matplotlib "
                                 "(it runs " + python + ", not the python3 on the PATH)");
    Mit1976::get();  // the report's numbers: fail now, not after the runs, when they cannot be read

    const PreviousReport previous = readPreviousReport(s.out);  // to say what moved
    nlohmann::ordered_json meta;
    const std::string commit = getCommit();
    std::string md;
    // Each phase's wall and CPU minutes go to stderr, validation.json and the header, so a
    // slow validate shows where its time went (bench/README.md, "rockroll validate").
    std::vector<std::pair<std::string, PhaseTime>> phases;
    auto wallMinutes = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count() / 60; };
    auto cpuMinutes = [] { return double(std::clock()) / CLOCKS_PER_SEC / 60; };
    const double cpu0 = cpuMinutes();
    double phaseWall = 0, phaseCpu = cpu0;
    auto endPhase = [&] {
        if (phases.empty()) return;
        phases.back().second = {wallMinutes() - phaseWall, cpuMinutes() - phaseCpu};
    };
    auto step = [&](const char* what) {
        endPhase();
        phaseWall = wallMinutes(), phaseCpu = cpuMinutes();
        phases.push_back({what, {}});
        fmt::print(stderr, "validate: {} (at {:.1f} min)\n", what, phaseWall);
    };
    // A section that throws is reported (stderr, REPORT.md, validation.json) and the
    // others still run; validate then exits 4.
    std::vector<std::string> failedSections;
    auto section = [&](const char* name, const std::function<std::string()>& make) -> std::string {
        try {
            // Test hook (app/test/test_Validate.cpp): this section fails as a section's error would.
            if (const char* fail = std::getenv("ROCKROLL_VALIDATE_FAIL_SECTION"); fail && std::string_view(fail) == name)
                throw std::runtime_error("injected failure (ROCKROLL_VALIDATE_FAIL_SECTION)");
            return make();
        } catch (const std::exception& e) {
            failedSections.push_back(fmt::format("{}: {}", name, e.what()));
            fmt::print(stderr, "validate: section \"{}\" FAILED: {}\n", name, e.what());
            return fmt::format("## {}\n\n**This section failed:** {}\n\n", name, e.what());
        }
    };
    // Convergence first: the comparison tables of sections 1, 3 and 4 print the residual
    // uncertainty it measures; its own section keeps its place in the report.
    step("convergence");
    ResidualUncertainty uncertainty;
    const std::string convergenceMd = section("convergence", [&] { return makeConvergenceSection(s, meta, uncertainty); });
    step("time histories");
    md += section("time histories", [&] { return makeTimeHistorySection(s, meta, uncertainty); });
    md += section("changes", [&] { return makeChangesSection(previous, meta); });
    step("speed sweeps");
    const auto sweeps = runAllSweeps(s);
    md += section("speed sweeps", [&] { return makeSweepSection(s, sweeps, meta); });
    step("describing function");
    const SteadyByAmplitude steady = traceSteady(s);
    step("Tables 3 and 4");
    md += section("Table 3", [&] { return makeTable3Section(s, sweeps, steady, uncertainty, meta); });
    md += section("Table 4", [&] { return makeTable4Section(s, sweeps, uncertainty); });
    md += section("describing function", [&] { return makeDescribingFunctionSection(s, steady, sweeps, meta); });
    step("modes");
    md += section("modes", [&] { return makeModesSection(); });
    md += convergenceMd;
    step("added degrees of freedom");
    md += section("added degrees of freedom", [&] { return makeAddedDofSection(s, sweeps, meta); });
    md += section("criteria", [&] { return makeCriteriaSection(s, sweeps); });
    step("attribution");
    md += section("attribution", [&] { return makeAttributionSection(s, meta); });
    step("periodic orbits");
    md += section("periodic orbits", [&] { return makeOrbitSection(s, sweeps, steady, meta); });
    step("wheel-rail contact");
    md += section("wheel-rail contact", [&] { return makeWheelRailSection(s, sweeps, meta); });
    if (!failedSections.empty()) meta["failed_sections"] = failedSections;

    step("plots");
    // The plots are drawn from validation.json, so it is written before them with the
    // phases so far; it is rewritten below with the plots' own time.
    auto writePhases = [&] {
        meta["phases"] = nlohmann::ordered_json::array();
        for (const auto& [name, t] : phases)
            meta["phases"].push_back({{"phase", name}, {"wall_min", t.wallMinutes}, {"cpu_min", t.cpuMinutes}});
        meta["wall_min"] = wallMinutes();
        meta["cpu_min"] = cpuMinutes() - cpu0;
        writeJsonFile(s.out / "validation.json", meta);
    };
    writePhases();
    if (const int rc = runPlotPackage({"validate", s.out.string()}); rc != 0)
        throw std::runtime_error(fmt::format("plotting failed: {} -m rockroll_plots validate {} exited {}", python,
                                             s.out.string(), rc));
    endPhase();
    writePhases();

    const double minutes = wallMinutes();
    const std::string header = makeHeader(s, commit, minutes, phases);
    writeAtomically(s.out / "REPORT.md", [&](std::ostream& out) { out << header << md; });
    fmt::print("wrote {} ({:.1f} min)\n", (s.out / "REPORT.md").string(), minutes);
    if (!failedSections.empty()) {
        fmt::print(stderr, "validate: {} section(s) failed: {}\n", failedSections.size(), fmt::join(failedSections, "; "));
        return kExitFailedPoints;
    }
    return kExitOk;
}

}  // namespace rockroll::app
