// Accuracy against cost (bench/README.md, "Accuracy against cost"): integrator method and accuracy against
// wall time and against the change in the summary's headline results, on three cases:
//   light    70-ton loaded, 0.75 in, 12 mph, half car
//   severe   70-ton loaded, 0.75 in, 16.5 mph, half car (the default case)
//   fullcar  the default case with the full car
// For each case the reference is CPodes at the tightest accuracy (1e-6); every row
// prints its change against that reference, in %, for max roll, filtered max wheel
// load, filtered max side-bearing and center-plate loads and max wheel lift, and the
// worst of them. Runs are sequential (one at a time), so wall times compare within
// one run of this program; each setting runs --repeats times and keeps its smallest
// wall time. Output: one markdown table per case, then the cheapest
// setting (by wall time) whose worst change is below 1 % and below 0.1 %.
//
//   build/bin/rockroll_accuracy [--sim-seconds=10] [--methods=cpodes,rkmerson,rk3,rkf,verlet]
//                               [--accuracies=1e-3,1e-4,1e-5,1e-6] [--cases=light,severe,fullcar]
//                               [--max-wall-s=600] [--repeats=3]
#include "scenarios/ModelRegistry.h"
#include "scenarios/ScenarioRun.h"

#include "mbmodel/Units.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <fmt/format.h>
#include <limits>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

using namespace rockroll;

namespace {

struct Case {
    std::string name, label;
    std::string model;
    double speedMph;
};

struct Row {
    std::string method;
    double accuracy = 0;
    bool ok = false;
    std::string error;
    double cpuS = 0;  ///< process CPU time of the run (std::clock), smallest over the repeats [s]
    RunSummary summary;
};

// The five compared quantities, in the order printed.
constexpr int kQuantities = 5;
const char* const kNames[kQuantities] = {"max roll deg", "wheel load lbf", "side bearing lbf", "center plate lbf",
                                         "wheel lift in"};
double getQuantity(const RunSummary& s, int i) {
    switch (i) {
        case 0: return s.maxRollDeg;
        case 1: return s.maxWheelLoadLb;
        case 2: return s.maxSideBearingLoadLb;
        case 3: return s.maxCenterPlateLoadLb;
        default: return s.maxWheelLiftIn;
    }
}

/// |value − ref| / |ref| in %; 0 when both are 0; +inf when only ref is 0.
double calcChangePercent(double value, double ref) {
    if (ref == 0) return value == 0 ? 0 : std::numeric_limits<double>::infinity();
    return 100 * std::abs(value - ref) / std::abs(ref);
}

std::vector<std::string> splitList(const std::string& text) {
    std::vector<std::string> out;
    std::stringstream ss(text);
    for (std::string item; std::getline(ss, item, ',');)
        if (!item.empty()) out.push_back(item);
    return out;
}

std::string formatChange(double pct) {
    if (std::isinf(pct)) return "inf";
    return fmt::format("{:.3g}", pct);
}

/// Runs the setting `repeats` times (results are deterministic; checked) and keeps the
/// smallest wall time, which is the least disturbed by other work on a shared machine.
Row runOne(const Case& c, const std::string& method, double accuracy, double simSeconds, double maxWallS,
           int repeats) {
    Scenario sc = getDefaultScenario();
    sc.model = c.model;
    sc.speed = c.speedMph * units::mph;
    sc.track.amplitude = 0.75 * units::inch;
    sc.run.duration = simSeconds;
    sc.run.integrator.method = method;
    sc.run.integrator.accuracy = accuracy;
    sc.run.limits.maxWallTime = maxWallS;
    Row row;
    row.method = method;
    row.accuracy = accuracy;
    try {
        for (int k = 0; k < repeats; ++k) {
            const std::clock_t c0 = std::clock();
            const RunSummary s = runScenario(sc).summary;
            const double cpu = double(std::clock() - c0) / CLOCKS_PER_SEC;
            row.cpuS = k == 0 ? cpu : std::min(row.cpuS, cpu);
            if (k == 0) row.summary = s;
            else if (s.steps != row.summary.steps || s.maxRollDeg != row.summary.maxRollDeg ||
                     s.maxWheelLiftIn != row.summary.maxWheelLiftIn)
                throw std::runtime_error("repeat gave a different result");
            else row.summary.wallTimeS = std::min(row.summary.wallTimeS, s.wallTimeS);
        }
        row.ok = true;
    } catch (const std::exception& e) {
        row.error = e.what();
        row.error = row.error.substr(0, row.error.find('\n'));
    }
    return row;
}

}  // namespace

int main(int argc, char** argv) {
    double simSeconds = 10, maxWallS = 600;
    int repeats = 3;
    std::vector<std::string> methods{"cpodes", "rkmerson", "rk3", "rkf", "verlet"};
    std::vector<double> accuracies{1e-3, 1e-4, 1e-5, 1e-6};
    std::vector<std::string> caseNames{"light", "severe", "fullcar"};
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto value = [&](const char* key) -> std::optional<std::string> {
            const std::string k = std::string(key) + "=";
            if (a.rfind(k, 0) == 0) return a.substr(k.size());
            return std::nullopt;
        };
        if (auto v = value("--sim-seconds")) simSeconds = std::atof(v->c_str());
        else if (auto v = value("--max-wall-s")) maxWallS = std::atof(v->c_str());
        else if (auto v = value("--repeats")) repeats = std::max(1, std::atoi(v->c_str()));
        else if (auto v = value("--methods")) methods = splitList(*v);
        else if (auto v = value("--accuracies")) {
            accuracies.clear();
            for (const auto& s : splitList(*v)) accuracies.push_back(std::atof(s.c_str()));
        } else if (auto v = value("--cases")) caseNames = splitList(*v);
        else {
            std::fprintf(stderr,
                         "usage: rockroll_accuracy [--sim-seconds=10] [--methods=cpodes,rkmerson,rk3,rkf,verlet] "
                         "[--accuracies=1e-3,1e-4,1e-5,1e-6] [--cases=light,severe,fullcar] [--max-wall-s=600] [--repeats=3]\n");
            return 2;
        }
    }
    const std::vector<Case> allCases{
        {"light", "light: 70-ton loaded, 0.75 in, 12 mph, halfcar", model_names::kHalfCar, 12.0},
        {"severe", "severe: 70-ton loaded, 0.75 in, 16.5 mph, halfcar (default case)", model_names::kHalfCar, 16.5},
        {"fullcar", "fullcar: 70-ton loaded, 0.75 in, 16.5 mph, fullcar (default case)", model_names::kFullCar, 16.5},
    };
    const double refAccuracy = *std::min_element(accuracies.begin(), accuracies.end());

    fmt::print("# Accuracy against cost: {} s simulated per run, runs sequential, each setting run {} times "
               "(wall s: the smallest), wall-time limit {} s per run\n",
               simSeconds, repeats, maxWallS);
    fmt::print("Reference per case: cpodes at accuracy {:g}. Changes are |x - ref| / |ref| in %.\n", refAccuracy);

    for (const auto& name : caseNames) {
        auto it = std::find_if(allCases.begin(), allCases.end(), [&](const Case& c) { return c.name == name; });
        if (it == allCases.end()) {
            std::fprintf(stderr, "rockroll_accuracy: unknown case '%s' (light, severe, fullcar)\n", name.c_str());
            return 2;
        }
        const Case& c = *it;
        // Reference first, then every other setting, one run at a time.
        std::vector<Row> rows;
        auto run = [&](const std::string& m, double acc) {
            std::fprintf(stderr, "%s %s %g ... ", c.name.c_str(), m.c_str(), acc);
            std::fflush(stderr);
            rows.push_back(runOne(c, m, acc, simSeconds, maxWallS, repeats));
            const Row& r = rows.back();
            if (r.ok) std::fprintf(stderr, "%.2f s wall\n", r.summary.wallTimeS);
            else std::fprintf(stderr, "failed: %s\n", r.error.c_str());
        };
        run("cpodes", refAccuracy);
        const Row ref = rows.front();
        for (const auto& m : methods)
            for (double acc : accuracies)
                if (!(m == "cpodes" && acc == refAccuracy)) run(m, acc);
        std::stable_sort(rows.begin(), rows.end(), [&](const Row& a, const Row& b) {
            const auto ia = std::find(methods.begin(), methods.end(), a.method) - methods.begin();
            const auto ib = std::find(methods.begin(), methods.end(), b.method) - methods.begin();
            return ia != ib ? ia < ib : a.accuracy > b.accuracy;
        });

        fmt::print("\n### {}\n\n", c.label);
        if (!ref.ok) {
            fmt::print("Reference run failed: {}\n", ref.error);
            continue;
        }
        fmt::print("Reference (cpodes {:g}): max roll {:.4f} deg, wheel load {:.1f} lbf, side bearing {:.1f} lbf, "
                   "center plate {:.1f} lbf, wheel lift {:.5f} in, regime {}.\n\n",
                   refAccuracy, ref.summary.maxRollDeg, ref.summary.maxWheelLoadLb, ref.summary.maxSideBearingLoadLb,
                   ref.summary.maxCenterPlateLoadLb, ref.summary.maxWheelLiftIn, ref.summary.regime);
        fmt::print("| method | accuracy | wall s | CPU s | sim s / wall s | steps | realizations | regime |");
        for (const char* q : kNames) fmt::print(" {} (Δ %) |", q);
        fmt::print(" worst Δ % |\n|---|---|---|---|---|---|---|---|");
        for (int q = 0; q < kQuantities; ++q) fmt::print("---|");
        fmt::print("---|\n");
        struct Best {
            const Row* row = nullptr;
            double worst = 0;
        } best1, best01, cpu1, cpu01;
        for (const Row& r : rows) {
            if (!r.ok) {
                fmt::print("| {} | {:g} | failed: {} ||||||||||||\n", r.method, r.accuracy, r.error);
                continue;
            }
            const RunSummary& s = r.summary;
            fmt::print("| {} | {:g} | {:.2f} | {:.2f} | {:.1f} | {} | {} | {} |", r.method, r.accuracy, s.wallTimeS,
                       r.cpuS, s.simTimeS / s.wallTimeS, s.steps, s.realizations, s.regime);
            double worst = 0;
            for (int q = 0; q < kQuantities; ++q) {
                const double v = getQuantity(s, q), pct = calcChangePercent(v, getQuantity(ref.summary, q));
                worst = std::max(worst, pct);
                fmt::print(fmt::runtime(q == 4 ? " {:.4f} ({}) |" : (q == 0 ? " {:.3f} ({}) |" : " {:.0f} ({}) |")), v,
                           formatChange(pct));
            }
            fmt::print(" {} |\n", formatChange(worst));
            const bool isRef = &r == &*std::find_if(rows.begin(), rows.end(), [&](const Row& x) {
                return x.method == "cpodes" && x.accuracy == refAccuracy;
            });
            if (isRef) continue;  // the reference does not compete with itself
            if (worst < 1 && (!best1.row || s.wallTimeS < best1.row->summary.wallTimeS)) best1 = {&r, worst};
            if (worst < 0.1 && (!best01.row || s.wallTimeS < best01.row->summary.wallTimeS)) best01 = {&r, worst};
            if (worst < 1 && (!cpu1.row || r.cpuS < cpu1.row->cpuS)) cpu1 = {&r, worst};
            if (worst < 0.1 && (!cpu01.row || r.cpuS < cpu01.row->cpuS)) cpu01 = {&r, worst};
        }
        auto printBest = [&](const Best& b, const char* by, const char* bound) {
            if (b.row)
                fmt::print("- cheapest by {} with worst change < {} %: {} {:g} ({:.2f} s wall, {:.2f} s CPU, "
                           "{:.1f} sim s / wall s, worst {} %)\n",
                           by, bound, b.row->method, b.row->accuracy, b.row->summary.wallTimeS, b.row->cpuS,
                           b.row->summary.simTimeS / b.row->summary.wallTimeS, formatChange(b.worst));
            else fmt::print("- cheapest by {} with worst change < {} %: none besides the reference\n", by, bound);
        };
        fmt::print("\n");
        printBest(best1, "wall time", "1");
        printBest(best01, "wall time", "0.1");
        printBest(cpu1, "CPU time", "1");
        printBest(cpu01, "CPU time", "0.1");
        std::fflush(stdout);
    }
    return 0;
}
