// Speed of the Simbody models on the default case (70-ton loaded, 0.75 in,
// 16.5 mph), for each integrator compared: simulated seconds per wall second,
// with the max roll each gives, and the ratios taken in the same run.
//
//   build/bin/rockroll_bench [--sim-seconds=T] [google-benchmark flags]
#include "scenarios/ScenarioRun.h"

#include <benchmark/benchmark.h>
#include <cstring>
#include <fmt/format.h>
#include <map>

using namespace rockroll;

namespace {
double gSimSeconds = 20;
struct Measured {
    double realTimeFactor = 0, maxRoll = 0;
    long steps = 0;
};
std::map<std::string, Measured> gMeasured;

void runCase(benchmark::State& state, const std::string& model, const std::string& method, double accuracy) {
    Scenario sc = getDefaultScenario();
    sc.model = model;
    sc.run.duration = gSimSeconds;
    sc.run.integrator.method = method;
    sc.run.integrator.accuracy = accuracy;
    ScenarioRun run;
    for (auto _ : state) run = runScenario(sc);
    Measured m{run.summary.simTimeS / run.summary.wallTimeS, run.summary.maxRollDeg, run.summary.steps};
    gMeasured[fmt::format("{} {} {:g}", model, method, accuracy)] = m;
    state.counters["sim_s_per_wall_s"] = m.realTimeFactor;
    state.counters["max_roll_deg"] = m.maxRoll;
    state.counters["steps"] = double(m.steps);
}
}  // namespace

int main(int argc, char** argv) {
    for (int i = 1; i < argc; ++i)
        if (std::strncmp(argv[i], "--sim-seconds=", 14) == 0) gSimSeconds = std::atof(argv[i] + 14);
    for (const char* model : {"halfcar", "fullcar"})
        for (const auto& [method, acc] : std::vector<std::pair<std::string, double>>{
                 {"cpodes", 1e-4}, {"cpodes", 1e-3}, {"rkmerson", 1e-4}, {"rkmerson", 1e-3}})
            benchmark::RegisterBenchmark(fmt::format("{}/{}/acc{:g}", model, method, acc).c_str(),
                                         [m = std::string(model), method = method, acc = acc](benchmark::State& s) {
                                             runCase(s, m, method, acc);
                                         })
                ->Iterations(1)
                ->Unit(benchmark::kSecond);
    benchmark::Initialize(&argc, argv);
    benchmark::RunSpecifiedBenchmarks();

    fmt::print("\n{:<28}{:>16}{:>14}{:>10}\n", "case", "sim s / wall s", "max roll deg", "steps");
    for (const auto& [name, m] : gMeasured)
        fmt::print("{:<28}{:>16.1f}{:>14.2f}{:>10}\n", name, m.realTimeFactor, m.maxRoll, m.steps);
    auto ratio = [](const std::string& a, const std::string& b) {
        if (gMeasured.count(a) && gMeasured.count(b))
            fmt::print("  {} / {}: {:.2f}x\n", a, b, gMeasured[a].realTimeFactor / gMeasured[b].realTimeFactor);
    };
    fmt::print("\nratios (same run):\n");
    ratio("halfcar cpodes 0.0001", "fullcar cpodes 0.0001");
    ratio("halfcar cpodes 0.0001", "halfcar rkmerson 0.0001");
    ratio("fullcar cpodes 0.0001", "fullcar rkmerson 0.0001");
    ratio("fullcar cpodes 0.001", "fullcar cpodes 0.0001");
    return 0;
}
