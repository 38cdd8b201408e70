// Speed of the Simbody models on the default case (70-ton loaded, 0.75 in,
// 16.5 mph), for each integrator compared: simulated seconds per wall second,
// with the max roll each gives, and the ratios taken in the same run.
//
//   build/bin/rockroll_bench [--sim-seconds=T] [google-benchmark flags]
#include "mbmodel/HugePageMemory.h"
#include "mbmodel/RockingModel.h"
#include "scenarios/ModelRegistry.h"
#include "scenarios/ScenarioRun.h"

#include "app/CommandResults.h"
#include "bespoke/ReducedHalfCarModel.h"
#include "scenarios/OrbitContinuation.h"
#include "scenarios/PeriodicOrbit.h"
#include "scenarios/SpeedSweep.h"

#include <benchmark/benchmark.h>
#include <chrono>
#include <ctime>
#include <cstring>
#include <algorithm>
#include <fmt/format.h>
#include <map>
#include <random>
#include <sys/resource.h>
#include <utility>
#include <vector>

using namespace rockroll;

namespace {
double gSimSeconds = 20;
struct Measured {
    double realTimeFactor = 0, maxRoll = 0;
    long steps = 0, realizations = 0;
    double wallS = 0, simS = 0;
    double getMicrosPerRealization() const { return 1e6 * wallS / double(realizations); }
    double getRealizationsPerSimSecond() const { return double(realizations) / simS; }
};
std::map<std::string, Measured> gMeasured;
// One recorded run per model, to time the run monitor on its own samples.
struct Recorded {
    RunResult result;
    ChannelLayout layout;
    RunLimits limits;
};
std::map<std::string, Recorded> gRecorded;

void runCase(benchmark::State& state, const std::string& model, const std::string& method, double accuracy) {
    Scenario sc = getDefaultScenario();
    sc.model = model;
    sc.run.duration = gSimSeconds;
    sc.run.integrator.method = method;
    sc.run.integrator.accuracy = accuracy;
    ScenarioRun run;
    // Minor page faults of the runs (model made, run, summarized): on a virtual machine each
    // first touch of a fresh 4 KB page costs about 11 µs (mbmodel/HugePageMemory.h).
    rusage before{}, after{};
    ::getrusage(RUSAGE_SELF, &before);
    for (auto _ : state) run = runScenario(sc);
    ::getrusage(RUSAGE_SELF, &after);
    const RunSummary& r = run.summary;
    if (!gRecorded.count(model)) {
        const ChannelLayout layout =
            ModelRegistry::get().getModel(model).make(sc, makeTrackMotion(sc))->getChannels();
        gRecorded[model] = {run.result, layout, resolveRunLimits(sc.run.limits, sc.car, sc.wheelRail)};
    }
    Measured m{r.simTimeS / r.wallTimeS, r.maxRollDeg, r.steps, r.realizations, r.wallTimeS, r.simTimeS};
    gMeasured[fmt::format("{} {} {:g}", model, method, accuracy)] = m;
    state.counters["sim_s_per_wall_s"] = m.realTimeFactor;
    state.counters["max_roll_deg"] = m.maxRoll;
    state.counters["steps"] = double(m.steps);
    state.counters["realizations"] = double(m.realizations);
    state.counters["page_faults"] = double(after.ru_minflt - before.ru_minflt) / double(state.iterations());
}
// Cost of one periodic-orbit point (docs/orbits.md): shooting on the upper branch at
// 13.5 mph, 70-ton loaded, 0.75 in, from the state a down sweep 16.5 → 14 mph reached
// (0.5 mph steps, 20 s a speed; outside the timing), one thread for the monodromy.
std::map<std::string, double> gOrbitCpuS;
void orbitPoint(benchmark::State& state, const std::string& model) {
    Scenario sc = getDefaultScenario();
    sc.model = model;
    SweepSpec spec;
    spec.scenario = sc;
    spec.scenario.run.duration = 20;
    spec.fromMph = 14, spec.toMph = 16.5, spec.stepMph = 0.5;
    spec.direction = SweepDirection::Down;
    const std::vector<SweepPoint> sweep = runSweep(spec);
    const RestartState start = *sweep.back().next.from;
    OrbitSettings os;
    os.shooting.threads = 1;
    os.shooting.maxIterations = 20;
    const PeriodicOrbitSolver solver(sc, start.distance, os);
    PeriodicOrbit o;
    const std::clock_t c0 = std::clock();
    for (auto _ : state) o = solver.solve(13.5, start.y);
    gOrbitCpuS[model] = double(std::clock() - c0) / CLOCKS_PER_SEC / double(state.iterations());
    state.counters["converged"] = o.converged ? 1 : 0;
    state.counters["roll_amplitude_deg"] = o.rollAmplitudeDeg;
    state.counters["newton_steps"] = o.iterations;
    state.counters["map_evaluations"] = o.mapEvaluations;
    state.counters["cpu_s_per_map"] = gOrbitCpuS[model] / o.mapEvaluations;
}
// Cost of a branch (docs/orbits.md, "Newton"): eom's upper branch continued 14 → 12 mph
// in 0.5 mph steps (70-ton loaded, 0.75 in, one thread), every shooting from a fresh
// monodromy against a chord Newton from the previous orbit's. Same start as orbitPoint.
struct BranchCost {
    double cpuS = 0;
    long maps = 0;
    std::vector<double> amplitudes;
};
std::map<bool, BranchCost> gBranch;
void orbitBranch(benchmark::State& state, bool reuse) {
    Scenario sc = getDefaultScenario();
    sc.model = model_names::kEom;
    SweepSpec spec;
    spec.scenario = sc;
    spec.scenario.run.duration = 20;
    spec.fromMph = 14, spec.toMph = 16.5, spec.stepMph = 0.5;
    spec.direction = SweepDirection::Down;
    const RestartState start = *runSweep(spec).back().next.from;
    OrbitSettings os;
    os.shooting.threads = 1;
    os.shooting.maxIterations = 20;
    const PeriodicOrbitSolver solver(sc, start.distance, os);
    OrbitContinuationSettings cs;
    cs.fromMph = 14, cs.toMph = 12, cs.stepMph = 0.5;
    cs.reuseMonodromy = reuse;
    OrbitBranch b;
    const std::clock_t c0 = std::clock();
    for (auto _ : state) b = OrbitContinuation(solver, cs).trace(start.y);
    BranchCost& c = gBranch[reuse];
    c.cpuS = double(std::clock() - c0) / CLOCKS_PER_SEC / double(state.iterations());
    c.maps = 0;
    c.amplitudes.clear();
    for (const auto& p : b.points) {
        c.maps += p.mapEvaluations;
        if (p.converged) c.amplitudes.push_back(p.rollAmplitudeDeg);
    }
    state.counters["orbits"] = double(c.amplitudes.size());
    state.counters["map_evaluations"] = double(c.maps);
}
// The workflows a parametric study runs (bench/README.md, "Sweeps and studies"), 70-ton
// loaded, 0.75 in, 20 s a speed: the full car swept 10-35 mph in 0.5 mph steps up and
// down (102 points, the two sweeps on two threads), and the reduced model swept
// 10-29.8 mph in 0.2 mph steps up (100 points, one thread). Wall and CPU seconds of the
// whole workflow, and simulated seconds per CPU second.
void sweepWorkflow(benchmark::State& state, const std::string& model, double fromMph, double toMph, double stepMph,
                   bool bothWays) {
    SweepSpec spec;
    spec.scenario = getDefaultScenario();
    spec.scenario.model = model;
    spec.scenario.run.duration = 20;
    spec.fromMph = fromMph, spec.toMph = toMph, spec.stepMph = stepMph;
    std::vector<SweepSpec> specs{spec};
    if (bothWays) {
        specs.push_back(spec);
        specs.back().direction = SweepDirection::Down;
    }
    std::vector<std::vector<SweepPoint>> sweeps;
    const std::clock_t c0 = std::clock();
    for (auto _ : state) sweeps = runSweeps(specs, int(specs.size()));
    const double cpu = double(std::clock() - c0) / CLOCKS_PER_SEC / double(state.iterations());
    double simulated = 0;
    long points = 0, failed = 0;
    for (const auto& sweep : sweeps)
        for (const SweepPoint& p : sweep) {
            ++points;
            if (p.failed) ++failed;
            else simulated += p.summary.simTimeS;
        }
    state.counters["points"] = double(points);
    state.counters["failed"] = double(failed);
    state.counters["cpu_s"] = cpu;
    state.counters["sim_s_per_cpu_s"] = simulated / cpu;
}

/// Every matrix class of the default car's truck factored into a fresh TruckModeCache (its
/// factorization, the screen's rows and the arena's first touch): the cost a single
/// reduced run pays for each class it meets.
void factorEveryTruckClass(benchmark::State& state) {
    const TruckGeometry g(getDefaultScenario().car);
    std::vector<TruckMode> classes;
    for (const TruckMode& m : enumerateTruckModes())
        if (TruckModeCache::getMatrixClass(m) == m) classes.push_back(m);
    for (auto _ : state) {
        const TruckModeCache cache(g);
        for (const TruckMode& m : classes) benchmark::DoNotOptimize(&cache.getFactor(m, TruckInputs{}));
    }
    state.counters["classes"] = double(classes.size());
    state.counters["per_class"] = benchmark::Counter(double(classes.size()) * double(state.iterations()),
                                                     benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

// One describing-function branch set as `rockroll steady scenarios/70ton-loaded.toml
// --amplitude-in 0.75 --from-mph 10 --to-mph 25 --stability none --twin-periods 0
// --no-sweep-starts` computes it (app/CommandResults.h calcSteady): the harmonic balance
// alone, paths from rest at both ends of the range. Wall and CPU seconds, points, folds.
void describingBranchSet(benchmark::State& state) {
    app::SteadyOptions o;
    o.fromMph = 10, o.toMph = 25;
    o.stabilityMethod = "none";
    o.twinPeriods = 0;
    o.sweepStarts = false;
    const Scenario sc = getDefaultScenario();
    app::SteadyResult r;
    const std::clock_t c0 = std::clock();
    for (auto _ : state) r = app::calcSteady(sc, o);
    const double cpu = double(std::clock() - c0) / CLOCKS_PER_SEC / double(state.iterations());
    long points = 0, folds = 0;
    for (const SteadyStatePath& path : r.set.paths) {
        points += long(path.points.size());
        if (!path.points.empty()) folds += path.points.back().foldsBefore;
    }
    state.counters["cpu_s"] = cpu;
    state.counters["paths"] = double(r.set.paths.size());
    state.counters["points"] = double(points);
    state.counters["folds"] = double(folds);
}

// Cost of one right-hand-side evaluation: realize a perturbed state through
// Acceleration, with every force element enabled or with all of them disabled
// (Simbody's own floor for the same bodies and mobilities).
void realizeCost(benchmark::State& state, const std::string& model, bool withForces) {
    Scenario sc = getDefaultScenario();
    sc.model = model;
    auto m = makeScenarioModel(sc);
    const SimTK::MultibodySystem& sys = m->getSystem();
    SimTK::State s = m->makeStaticState();
    if (!withForces) {
        const SimTK::GeneralForceSubsystem& forces = m->getForces();
        for (int i = 0; i < forces.getNumForces(); ++i) forces.getForce(SimTK::ForceIndex(i)).disable(s);
    }
    double t = 0;
    for (auto _ : state) {
        t += 1e-4;
        s.setTime(t);
        s.updQ()[0] += 1e-9;  // invalidates Position and above, as an integrator stage does
        sys.realize(s, SimTK::Stage::Acceleration);
        benchmark::DoNotOptimize(s.getUDot()[0]);
    }
    state.counters["us_per_realization"] =
        benchmark::Counter(double(state.iterations()), benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
// The machine's state beside the figures (bench/README.md, "The search's memory"): a chain of
// 20 million dependent multiply-adds in registers (the core's speed), a pointer chase over
// 4 MB (the shared cache's latency, which other tenants of the machine can triple), and the
// first touch of four fresh 2 MB huge-page blocks (mbmodel/HugePageMemory.h), as a run's
// caches and history take them.
double gRegisterChainMs = 0, gChaseNs = 0, gHugePageUs = 0;
void hugePageTouch(benchmark::State& state) {
    constexpr int kBlocks = 4;
    double seconds = 0;
    for (auto _ : state) {
        char* p = static_cast<char*>(allocateLargeBuffer(kBlocks * kHugePageBytes));
        const auto t0 = std::chrono::steady_clock::now();
        for (int i = 0; i < kBlocks; ++i) p[std::size_t(i) * kHugePageBytes] = 1;
        seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        benchmark::DoNotOptimize(p[0]);
        std::free(p);
    }
    gHugePageUs = 1e6 * seconds / double(kBlocks * state.iterations());
    state.counters["us_per_block"] = gHugePageUs;
}
void registerChain(benchmark::State& state) {
    double a = 0;
    const auto t0 = std::chrono::steady_clock::now();
    for (auto _ : state) {
        for (long i = 0; i < 20000000; ++i) a = a * 1.0000001 + 1e-9;
        benchmark::DoNotOptimize(a);
    }
    gRegisterChainMs = 1e3 * std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() /
                       double(state.iterations());
    state.counters["ms"] = gRegisterChainMs;
}
void cacheChase(benchmark::State& state) {
    const std::size_t n = (std::size_t(4) << 20) / sizeof(std::uint32_t);
    std::vector<std::uint32_t> order(n), next(n);
    for (std::size_t i = 0; i < n; ++i) order[i] = std::uint32_t(i);
    std::shuffle(order.begin(), order.end(), std::mt19937(1));
    for (std::size_t i = 0; i < n; ++i) next[order[i]] = order[(i + 1) % n];  // one cycle through all
    std::uint32_t p = 0;
    for (std::size_t i = 0; i < n; ++i) p = next[p];  // in the caches it fits
    const long steps = 4000000;
    const auto t0 = std::chrono::steady_clock::now();
    for (auto _ : state) {
        for (long i = 0; i < steps; ++i) p = next[p];
        benchmark::DoNotOptimize(p);
    }
    gChaseNs = 1e9 * std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() /
               double(steps * state.iterations());
    state.counters["ns_per_step"] = gChaseNs;
}
}  // namespace

int main(int argc, char** argv) {
    for (int i = 1; i < argc; ++i)
        if (std::strncmp(argv[i], "--sim-seconds=", 14) == 0) gSimSeconds = std::atof(argv[i] + 14);
    using Probe = std::pair<const char*, void (*)(benchmark::State&)>;
    for (const auto& [name, probe] : {Probe{"machine/register_chain", registerChain},
                                      Probe{"machine/cache_chase_4MB", cacheChase},
                                      Probe{"machine/huge_page_touch", hugePageTouch}})
        benchmark::RegisterBenchmark(name, probe)->Iterations(1)->Unit(benchmark::kMillisecond);
    // The hand-written models on the same case: eom (CVODE BDF) and the reduced model (RK4, 5 ms).
    const ModelRegistry& registry = ModelRegistry::get();
    std::vector<std::string> ownIntegrator;
    for (const auto& d : registry.getModels())
        if (!d.isMultibody()) ownIntegrator.push_back(d.name);
    for (const std::string& model : ownIntegrator)
        benchmark::RegisterBenchmark(fmt::format("{}/own/acc0.0001", model).c_str(),
                                     [m = model](benchmark::State& s) { runCase(s, m, "own", 1e-4); })
            ->Iterations(1)
            ->Unit(benchmark::kSecond);
    for (const std::string& model : registry.getMultibodyNames())
        for (const auto& [method, acc] : std::vector<std::pair<std::string, double>>{
                 {"cpodes", 1e-4}, {"cpodes", 1e-3}, {"rkmerson", 1e-4}, {"rkmerson", 1e-3}})
            benchmark::RegisterBenchmark(fmt::format("{}/{}/acc{:g}", model, method, acc).c_str(),
                                         [m = model, method = method, acc = acc](benchmark::State& s) {
                                             runCase(s, m, method, acc);
                                         })
                ->Iterations(1)
                ->Unit(benchmark::kSecond);
    for (const std::string& model : registry.getMultibodyNames())
        for (bool withForces : {true, false})
            benchmark::RegisterBenchmark(
                fmt::format("realize/{}/{}", model, withForces ? "all_elements" : "elements_disabled").c_str(),
                [m = model, withForces](benchmark::State& s) { realizeCost(s, m, withForces); });
    for (const char* model : {model_names::kEom, model_names::kHalfCar})
        benchmark::RegisterBenchmark(fmt::format("orbit/{}", model).c_str(),
                                     [m = std::string(model)](benchmark::State& s) { orbitPoint(s, m); })
            ->Iterations(1)
            ->Unit(benchmark::kSecond);
    benchmark::RegisterBenchmark("workflow/fullcar_sweep_102", [](benchmark::State& s) {
        sweepWorkflow(s, model_names::kFullCar, 10, 35, 0.5, true);
    })->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();
    benchmark::RegisterBenchmark("workflow/reduced_study_100", [](benchmark::State& s) {
        sweepWorkflow(s, model_names::kReduced, 10, 29.8, 0.2, false);
    })->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();
    benchmark::RegisterBenchmark("reduced/factor_every_class", factorEveryTruckClass)
        ->Iterations(3)
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime();
    benchmark::RegisterBenchmark("describing/branch_set_10_25mph", describingBranchSet)
        ->Iterations(3)
        ->Unit(benchmark::kSecond)
        ->UseRealTime();
    for (bool reuse : {false, true})
        benchmark::RegisterBenchmark(reuse ? "orbitbranch/eom/chord" : "orbitbranch/eom/fresh",
                                     [reuse](benchmark::State& s) { orbitBranch(s, reuse); })
            ->Iterations(1)
            ->Unit(benchmark::kSecond);
    benchmark::Initialize(&argc, argv);
    benchmark::RunSpecifiedBenchmarks();

    // The target a model must reach, and the wall time per realization that target
    // allows at the realization count the integrator actually needed.
    using namespace model_names;
    const std::map<std::string, double> target{{kHalfCar, 200}, {kFullCar, 50}, {kEom, 200}, {kReduced, 200}};
    fmt::print("\n{:<28}{:>16}{:>14}{:>10}{:>14}{:>12}{:>14}{:>16}\n", "case", "sim s / wall s", "max roll deg",
               "steps", "realizations", "real./step", "us / real.", "us/real. target");
    for (const auto& [name, m] : gMeasured) {
        const double allowed = 1e6 / (target.at(name.substr(0, name.find(' '))) * m.getRealizationsPerSimSecond());
        fmt::print("{:<28}{:>16.1f}{:>14.2f}{:>10}{:>14}{:>12.1f}{:>14.1f}{:>16.2f}\n", name, m.realTimeFactor,
                   m.maxRoll, m.steps, m.realizations, double(m.realizations) / double(m.steps),
                   m.getMicrosPerRealization(), allowed);
    }
    auto ratio = [](const std::string& a, const std::string& b) {
        if (gMeasured.count(a) && gMeasured.count(b))
            fmt::print("  {} / {}: {:.2f}x\n", a, b, gMeasured[a].realTimeFactor / gMeasured[b].realTimeFactor);
    };
    // The run monitor (RunGuard) fed every recorded sample of the run again: its
    // share of that run's wall time.
    fmt::print("\nrun monitor cost (RunGuard on every recorded sample, as in the run):\n");
    for (auto& [model, rec] : gRecorded) {
        const auto t0 = std::chrono::steady_clock::now();
        const int repeats = 20;
        for (int k = 0; k < repeats; ++k) {
            RunGuard guard(rec.layout, rec.limits);
            RunResult sink;
            for (const auto& row : rec.result.history.samples) benchmark::DoNotOptimize(guard.check(row, sink));
        }
        const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() / repeats;
        fmt::print("  {:<10} {:>8.3f} ms for {} samples = {:.3f} % of the run's {:.2f} s wall\n", model, 1e3 * s,
                   rec.result.history.samples.size(), 100 * s / rec.result.wallTime, rec.result.wallTime);
    }
    // The reduced model's truck-mode search on the same case (bespoke/TruckEquilibrium.h):
    // how many modes it solved and how many the choice bounds ruled out unsolved.
    {
        Scenario sc = getDefaultScenario();
        sc.run.duration = gSimSeconds;
        const ReducedHalfCarModel model(
            sc.car, makeEquivalentWheelsetInput(TrackInput(sc.track), makeTrackMotion(sc), sc.car.wheelbase), sc.reduced);
        ReducedRunStatistics st;
        const auto t0 = std::chrono::steady_clock::now();
        const std::clock_t c0 = std::clock();
        const RunResult r = simulateReduced(model, gSimSeconds, &st, {}, resolveRunLimits(sc.run.limits, sc.car, sc.wheelRail));
        const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        const double cpu = double(std::clock() - c0) / CLOCKS_PER_SEC;
        fmt::print("\nreduced truck-mode search ({} s simulated, {:.3f} s wall, {:.3f} s CPU, {:.0f} sim s / CPU s):\n"
                   "  {} searches, {} modes solved ({:.2f} per search), {} ruled out unsolved by their choice bounds, "
                   "{} by their contacts' kinematics, {} by the screen, {} enumerations of every mode\n",
                   r.simTime, wall, cpu, r.simTime / cpu, st.modes.searches, st.modes.solves,
                   double(st.modes.solves) / double(st.modes.searches), st.modes.skipped, st.modes.kinematic,
                   st.modes.screened, st.modes.enumerations);
    }
    if (gOrbitCpuS.count(model_names::kEom) && gOrbitCpuS.count(model_names::kHalfCar))
        fmt::print("\norbit point at 13.5 mph (CPU s): eom {:.2f}, halfcar {:.2f}; halfcar / eom {:.2f}x\n",
                   gOrbitCpuS[model_names::kEom], gOrbitCpuS[model_names::kHalfCar],
                   gOrbitCpuS[model_names::kHalfCar] / gOrbitCpuS[model_names::kEom]);
    if (gBranch.count(false) && gBranch.count(true)) {
        const BranchCost &f = gBranch[false], &c = gBranch[true];
        double diff = 0;
        for (size_t i = 0; i < std::min(f.amplitudes.size(), c.amplitudes.size()); ++i)
            diff = std::max(diff, std::abs(c.amplitudes[i] / f.amplitudes[i] - 1));
        fmt::print("\neom branch 14 -> 12 mph (CPU s, maps, orbits): fresh monodromy {:.1f}, {}, {}; chord Newton {:.1f}, "
                   "{}, {}; fresh / chord {:.2f}x; roll amplitudes differ by at most {:.2g}\n",
                   f.cpuS, f.maps, f.amplitudes.size(), c.cpuS, c.maps, c.amplitudes.size(), f.cpuS / c.cpuS, diff);
    }
    if (gRegisterChainMs > 0 || gChaseNs > 0 || gHugePageUs > 0)
        fmt::print("\nmachine state (same run): register chain {:.1f} ms, 4 MB pointer chase {:.1f} ns a step, "
                   "first touch of a 2 MB huge-page block {:.0f} µs\n",
                   gRegisterChainMs, gChaseNs, gHugePageUs);
    fmt::print("\nratios (same run):\n");
    ratio("halfcar cpodes 0.0001", "fullcar cpodes 0.0001");
    ratio("halfcar cpodes 0.0001", "halfcar rkmerson 0.0001");
    ratio("fullcar cpodes 0.0001", "fullcar rkmerson 0.0001");
    ratio("fullcar cpodes 0.001", "fullcar cpodes 0.0001");
    ratio("eom own 0.0001", "halfcar cpodes 0.0001");
    ratio("reduced own 0.0001", "halfcar cpodes 0.0001");
    return 0;
}
