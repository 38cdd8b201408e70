// validate, section 11: where the upper branch ends. Periodic orbits of eom and the
// Simbody half car (70-ton loaded; scenarios/PeriodicOrbit.h, docs/orbits.md),
// continued down in speed from section 2's down sweeps, beside the sweeps' drops,
// sweeps whose speed steps at once, the speed step that knocks an orbit off its
// branch, and the describing function (report §4.3, Figure 31; §3.2, Figure 11).
#include "app/ValidateSections.h"
#include "mbmodel/CsvWriter.h"
#include "scenarios/OrbitContinuation.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace rockroll::app {

using namespace validate_detail;

namespace {
constexpr double kLowestMph = 8;
/// The stepped sweeps' and the basin runs' time at each speed [s].
constexpr double kStepRunS = 30;
/// A run ends on the branch when its steady roll amplitude is within this fraction of
/// the branch's orbit at its speed (the continuation's own "another branch" rule).
constexpr double kOnBranchFraction = 0.3;

struct OrbitCase {
    std::string car;
    double amplitudeIn;
    std::string model;
    double startMph, stepMph;
    double toMph = kLowestMph;  ///< where the continuation stops at the latest
    /// "70ton-loaded_0.75in": section 2's case key (the sweep, its plots and the orbits' CSV).
    std::string getKey() const { return fmt::format("{}_{:.2f}in", car, amplitudeIn); }
};

struct OrbitCaseResult {
    OrbitCase c;
    std::string start;          ///< where the start state came from
    OrbitBranch branch;
    std::string failure;        ///< the case could not start
    bool swept = false;         ///< section 2 swept this model and amplitude
    double sweepDropMph = NAN;  ///< section 2's down sweep's (ramped) jump, NaN: none (kJumpFraction)
    double sweepLargestFallDeg = 0, sweepLargestFallMph = NAN;  ///< its largest fall between neighbouring speeds
    double sweepLowestMph = NAN;  ///< the down sweep's last (lowest) speed
    /// Per orbit speed (eom): the smallest instantaneous speed step down, of kBasinSteps,
    /// after which the run ends off the branch; NaN: none of them; −1: no step tried (no
    /// orbit at any new speed to compare with).
    std::vector<std::pair<double, double>> basin;
    /// The reduced model: from each state of section 2's down sweep, from the start speed
    /// down to its drop, the map iterated (OrbitMethod::Iteration): what it settles on.
    std::vector<PeriodicOrbit> settled;
    std::vector<double> settledSweepAmplitude;  ///< the sweep's steady roll amplitude there [deg]
};

const std::vector<double> kBasinSteps{0.5, 1.0, 2.0};

/// Iteration leaves the real multipliers undefined (NaN): an empty cell.
CsvCell fixedOrEmpty(double x) { return std::isfinite(x) ? CsvCell::fixed(x, 4) : CsvCell::empty(); }

/// The branch's converged orbits, in speed order (descending).
std::vector<const PeriodicOrbit*> convergedOrbits(const OrbitBranch& b) {
    std::vector<const PeriodicOrbit*> v;
    for (const auto& p : b.points)
        if (p.converged) v.push_back(&p);
    std::sort(v.begin(), v.end(), [](auto a, auto c) { return a->speedMph > c->speedMph; });
    return v;
}

/// The branch's roll amplitude at mph, linear between its orbits; NaN outside them.
double branchAmplitudeAt(const OrbitBranch& b, double mph) {
    const auto v = convergedOrbits(b);
    for (size_t i = 0; i + 1 < v.size(); ++i)
        if (mph <= v[i]->speedMph + 1e-9 && mph >= v[i + 1]->speedMph - 1e-9) {
            const double f = (v[i]->speedMph - mph) / (v[i]->speedMph - v[i + 1]->speedMph);
            return v[i]->rollAmplitudeDeg + f * (v[i + 1]->rollAmplitudeDeg - v[i]->rollAmplitudeDeg);
        }
    if (v.size() == 1 && std::abs(v[0]->speedMph - mph) < 1e-9) return v[0]->rollAmplitudeDeg;
    return NAN;
}

std::string describeEnd(const OrbitCaseResult& r) {
    if (!r.failure.empty()) return "not computed: " + r.failure;
    const OrbitBranch& b = r.branch;
    if (b.stopReason.rfind("fold", 0) == 0 && b.endBracketMph)
        return fmt::format("fold between {:.2f} and {:.2f} mph", b.endBracketMph->second, b.endBracketMph->first);
    if (b.endBracketMph)
        return fmt::format("branch end between {:.2f} and {:.2f} mph (not a fold: {})", b.endBracketMph->second,
                           b.endBracketMph->first, b.stopReason);
    if (b.stopReason == "no orbit at the start speed") return "no orbit at the start speed: " + b.points.front().failure;
    return fmt::format("no fold down to {:g} mph", r.c.toMph);
}

/// One down-sweep state iterated: what it settles on, against the sweep's own steady amplitude.
std::string describeSettledPoint(const PeriodicOrbit& o, double sweepDeg) {
    if (!o.converged) return fmt::format("none in {} periods (sweep {:.2f}°)", o.mapEvaluations, sweepDeg);
    const bool same = std::abs(o.rollAmplitudeDeg - sweepDeg) <= kOnBranchFraction * sweepDeg;
    return fmt::format("period {}, {:.2f}° after {} periods (sweep {:.2f}°: {})", o.period, o.rollAmplitudeDeg,
                       o.mapEvaluations, sweepDeg, same ? "its orbit" : "another orbit");
}

/// The reduced model's down-sweep states iterated, counted: on an orbit of their own amplitude,
/// settling on another one, or on none within the iteration limit.
std::string describeSettled(const OrbitCaseResult& r) {
    if (r.settled.empty()) return "no down-sweep state iterated";
    int own = 0, other = 0, none = 0;
    for (size_t i = 0; i < r.settled.size(); ++i) {
        const PeriodicOrbit& o = r.settled[i];
        if (!o.converged) ++none;
        else if (std::abs(o.rollAmplitudeDeg - r.settledSweepAmplitude[i]) <= kOnBranchFraction * r.settledSweepAmplitude[i])
            ++own;
        else ++other;
    }
    return fmt::format("of its down-sweep states from {:g} to {:g} mph, iterated at their own speed: {} on a period-1 or "
                       "-2 orbit of their amplitude, {} settle onto another orbit, {} on none within the limit (the table "
                       "below)",
                       r.settled.front().speedMph, r.settled.back().speedMph, own, other, none);
}

std::string describeBasin(double dv) {
    return dv < 0 ? std::string("—") : std::isfinite(dv) ? fmt::format("{:g} mph", dv) : std::string("none");
}

/// The lowest speed of the branch's stable orbits, reached from the start without an unstable orbit between.
std::string describeOrbitStability(const OrbitBranch& b) {
    const auto v = convergedOrbits(b);
    if (v.empty()) return "—";
    std::vector<std::string> parts;
    size_t i = 0;
    while (i < v.size()) {
        size_t j = i;
        while (j + 1 < v.size() && v[j + 1]->stable == v[i]->stable) ++j;
        parts.push_back(fmt::format("{} {:.2f}–{:.2f}", v[i]->stable ? "stable" : "unstable", v[i]->speedMph, v[j]->speedMph));
        i = j + 1;
    }
    return fmt::format("{}", fmt::join(parts, "; "));
}

/// A down sweep's drop: its jump (scenarios/SpeedSweep.h, kJumpFraction); NaN: none.
double findDrop(const std::vector<SweepPoint>& down) { return findSweepJump(down, SweepDirection::Down).speedMph; }

const SweepResult* findSweep(const std::vector<SweepResult>& sweeps, const std::string& car, const std::string& model,
                             double amp) {
    for (const auto& r : sweeps)
        if (r.c.car == car && r.model == model && std::abs(r.c.amplitudeIn - amp) < 1e-9) return &r;
    return nullptr;
}
}  // namespace

std::string makeOrbitSection(const Settings& s, const std::vector<SweepResult>& sweeps, const SteadyByAmplitude& steady,
                             nlohmann::ordered_json& meta) {
    std::string md = "## 11. Where the upper branch ends: periodic orbits against the sweeps (report Figure 11)\n\n";
    // Start speeds: on the down sweeps' upper branch at every amplitude (section 2).
    std::vector<OrbitCase> cases;
    if (s.quick) {
        cases.push_back({"70ton-loaded", 0.75, model_names::kEom, 14, 0.5, 13});
    } else {
        for (const auto& [amp, v0] : std::vector<std::pair<double, double>>{{0.5, 16}, {0.75, 14}, {1.0, 14}}) {
            // eom at 0.75 in in 1 mph steps like the half car: its branch runs to the lowest speed, and
            // 0.5 mph steps there keep validate above its 30 min (docs/validation.md, "Run time").
            cases.push_back({"70ton-loaded", amp, model_names::kEom, v0, amp == 0.75 ? 1.0 : 0.5});
            // The half car, eom's twin, where the two are held to the same branch end (0.75 and 1.0 in);
            // elsewhere eom's branch stands for it, which keeps validate within its 30 min
            // (docs/validation.md, "Run time").
            if (amp != 0.5) cases.push_back({"70ton-loaded", amp, model_names::kHalfCar, v0, 1.0});
            // Found by iteration (docs/orbits.md, "Iteration"): its map jumps at the finite-difference steps.
            cases.push_back({"70ton-loaded", amp, model_names::kReduced, amp == 0.5 ? 16.0 : 18.0, 0.5});
        }
        // The empty car's drop (section 2: 26 → 25.5 mph), its branch down to the lowest speed swept.
        cases.push_back({"70ton-empty", 0.75, model_names::kEom, 27, 1.0, 24});
    }
    std::map<std::string, Scenario> cars;
    for (const auto& c : cases)
        if (!cars.count(c.car)) cars.emplace(c.car, loadCarScenario(c.car));
    const Scenario& car = cars.at("70ton-loaded");
    std::vector<OrbitCaseResult> results(cases.size());
    std::vector<std::function<void()>> jobs;
    for (size_t i = 0; i < cases.size(); ++i)
        jobs.push_back([&, i] {
            OrbitCaseResult& r = results[i];
            r.c = cases[i];
            Scenario sc = cars.at(r.c.car);
            sc.model = r.c.model;
            sc.track.amplitude = r.c.amplitudeIn * units::inch;
            std::optional<RestartState> from;
            const SweepResult* sw = findSweep(sweeps, r.c.car, r.c.model, r.c.amplitudeIn);
            if (sw) {
                r.swept = true;
                const SweepJump j = findSweepJump(sw->down, SweepDirection::Down);
                r.sweepLargestFallDeg = j.changeDeg, r.sweepLargestFallMph = j.largestChangeMph;
                r.sweepDropMph = j.speedMph;
                if (!sw->down.empty()) r.sweepLowestMph = sw->down.back().speedMph;
                for (const auto& p : sw->down)
                    if (std::abs(p.speedMph - r.c.startMph) < 1e-9 && !p.failed && p.next.from) from = p.next.from;
                r.start = fmt::format("section 2's down sweep at {:g} mph", r.c.startMph);
            } else {
                // The quick run sweeps only the reduced model: a short down sweep of its own.
                SweepSpec spec;
                spec.scenario = sc;
                spec.scenario.run.duration = 15;
                spec.fromMph = r.c.startMph, spec.toMph = 16.5, spec.stepMph = 0.5;
                spec.direction = SweepDirection::Down;
                const auto pts = runSweep(spec);
                if (!pts.empty() && !pts.back().failed && pts.back().next.from) from = pts.back().next.from;
                r.start = fmt::format("a down sweep 16.5 → {:g} mph (0.5 mph steps, 15 s a speed)", r.c.startMph);
            }
            if (!from) {
                r.failure = fmt::format("no down-sweep state at {:g} mph", r.c.startMph);
                return;
            }
            OrbitSettings os;
            os.shooting.threads = 1;  // the cases run in parallel; the bits do not depend on it
            os.shooting.maxIterations = 20;
            const bool reduced = r.c.model == model_names::kReduced;
            if (reduced) os.method = OrbitMethod::Iteration;
            const PeriodicOrbitSolver solver(sc, from->distance, os);
            if (reduced && sw) {
                // Each down-sweep state from the start speed to the drop, iterated at its own speed.
                for (const auto& p : sw->down) {
                    if (p.speedMph > r.c.startMph + 1e-9 || p.failed || !p.next.from) continue;
                    if (std::isfinite(r.sweepDropMph) && p.speedMph < r.sweepDropMph - 1e-9) break;
                    if (!std::isfinite(r.sweepDropMph) && p.speedMph < r.c.startMph - 4 + 1e-9) break;
                    const PeriodicOrbitSolver at(sc, p.next.from->distance, os);
                    r.settled.push_back(at.solve(p.speedMph, p.next.from->y));
                    r.settledSweepAmplitude.push_back(p.summary.steadyRollAmplitudeDeg);
                }
            }
            OrbitContinuationSettings cs;
            cs.fromMph = r.c.startMph;
            cs.toMph = r.c.toMph;
            cs.stepMph = r.c.stepMph;
            cs.refinements = r.c.model == model_names::kHalfCar ? 1 : 2;
            cs.branchNewtonSteps = 10;
            r.branch = OrbitContinuation(solver, cs).trace(from->y);
            if (r.c.model != model_names::kEom) return;
            // The basin along the branch: from each orbit, the speed stepped down at once by Δ.
            for (const PeriodicOrbit* o : convergedOrbits(r.branch)) {
                double smallest = -1;
                for (double dv : kBasinSteps) {
                    const double target = branchAmplitudeAt(r.branch, o->speedMph - dv);
                    if (!std::isfinite(target)) break;
                    smallest = NAN;
                    Scenario run = sc;
                    run.speed = (o->speedMph - dv) * units::mph;
                    run.run.duration = kStepRunS;
                    RunStart start;
                    start.from = RestartState{sc.model, o->y, from->distance, o->speedMph * units::mph};
                    start.rampTime = 0;
                    const ScenarioRun out = runScenario(run, start);
                    const double a = out.result.stop ? 0.0 : out.summary.steadyRollAmplitudeDeg;
                    if (std::abs(a - target) > kOnBranchFraction * target) {
                        smallest = dv;
                        break;
                    }
                }
                r.basin.emplace_back(o->speedMph, smallest);
            }
        });
    runJobs(jobs, s.jobs);

    // Down sweeps whose speed steps at once, beside section 2's ramped ones.
    struct Stepped {
        std::string model;
        double amp, stepMph, dropMph = NAN, lowestRollDeg = NAN;
    };
    std::vector<Stepped> stepped;
    std::vector<SweepSpec> specs;
    if (!s.quick)
        for (const char* m : {model_names::kEom, model_names::kHalfCar})
            for (double amp : {0.75, 1.0})
                for (double step : {0.5, 1.0}) {
                    if (std::string(m) == model_names::kHalfCar && step == 0.5) continue;  // eom's column stands for it
                    SweepSpec spec;
                    spec.scenario = car;
                    spec.scenario.model = m;
                    spec.scenario.track.amplitude = amp * units::inch;
                    spec.scenario.run.duration = kStepRunS;
                    spec.scenario.run.outputRate = 100;
                    spec.fromMph = 10, spec.toMph = 22, spec.stepMph = step;
                    spec.direction = SweepDirection::Down;
                    spec.rampTime = 0;
                    specs.push_back(spec);
                    stepped.push_back({m, amp, step});
                }
    const auto steppedPoints = runSweeps(specs, s.jobs);
    for (size_t i = 0; i < stepped.size(); ++i) {
        stepped[i].dropMph = findDrop(steppedPoints[i]);
        if (!steppedPoints[i].empty() && !steppedPoints[i].back().failed)
            stepped[i].lowestRollDeg = steppedPoints[i].back().summary.steadyRollAmplitudeDeg;
    }

    // The reduced model's down sweeps at several times a speed: its severe response is not
    // periodic (the settle table), so where a sweep leaves it may depend on the dwell.
    struct Dwell {
        double amp, dwellS, dropMph = NAN;
    };
    std::vector<Dwell> dwells;
    std::vector<SweepSpec> dwellSpecs;
    if (!s.quick)
        for (double amp : {0.75, 1.0})
            for (double dwell : {15.0, 30.0, 60.0, 120.0}) {
                SweepSpec spec;
                spec.scenario = car;
                spec.scenario.model = model_names::kReduced;
                spec.scenario.track.amplitude = amp * units::inch;
                spec.scenario.run.duration = dwell;
                spec.fromMph = 10, spec.toMph = 22, spec.stepMph = 0.5;
                spec.direction = SweepDirection::Down;
                dwellSpecs.push_back(spec);
                dwells.push_back({amp, dwell});
            }
    const auto dwellPoints = runSweeps(dwellSpecs, s.jobs);
    for (size_t i = 0; i < dwells.size(); ++i) dwells[i].dropMph = findDrop(dwellPoints[i]);
    auto describeDwells = [&](double amp) {
        std::vector<std::string> parts;
        for (const auto& d : dwells)
            if (d.amp == amp)
                parts.push_back(fmt::format("{:g} s: {}", d.dwellS,
                                            std::isfinite(d.dropMph) ? fmt::format("{:.1f} mph", d.dropMph) : "none"));
        return fmt::format("{}", fmt::join(parts, "; "));
    };

    // Data: one CSV per case, one row per orbit point computed.
    for (const auto& r : results) {
        const std::string file = fmt::format("orbits_{}_{}.csv", r.c.getKey(), r.c.model);
        writeAtomically(s.out / file, [&](std::ostream& o) {
            CsvWriter csv(o, {"speed_mph", "converged", "period", "roll_amplitude_deg", "wheel_lift_fraction",
                              "max_multiplier", "largest_real_multiplier", "smallest_real_multiplier", "stable"});
            for (const auto& p : r.branch.points)
                if (p.converged)
                    csv.writeRow({CsvCell::fixed(p.speedMph, 4), 1, p.period, CsvCell::fixed(p.rollAmplitudeDeg, 4),
                                  CsvCell::fixed(p.wheelLiftFraction, 4), fixedOrEmpty(p.maxMultiplier),
                                  fixedOrEmpty(p.largestRealMultiplier), fixedOrEmpty(p.smallestRealMultiplier),
                                  p.stable ? "yes" : "no"});
                else
                    csv.writeRow({CsvCell::fixed(p.speedMph, 4), 0, 0, "", "", "", "", "", ""});
        });
        meta["orbits"].push_back({{"car", r.c.car}, {"amplitude_in", r.c.amplitudeIn}, {"key", r.c.getKey()},
                                  {"model", r.c.model}, {"file", file},
                                  {"end", describeEnd(r)}, {"stop_reason", r.branch.stopReason}});
    }

    md += fmt::format(
        "Made like `rockroll orbits scenarios/<car>.toml --model M --amplitude-in A --from-mph V0 --to-mph V1 "
        "--step-mph S` (docs/orbits.md), except that the first shooting starts from {}. Shooting on the one-period map "
        "at accuracy 1e-7, up to 20 Newton steps for the first orbit and 10 for each after it (on P, then on P∘P), each "
        "shooting after the first a chord Newton from the previous orbit's monodromy, step halved twice at a failure (eom and reduced; the half car once); stable when "
        "|μ|max ≤ 1.01 (a sticking wedge's neutral multiplier). The reduced model's orbits are found by iterating the map "
        "(`--iterate`, at most 300 periods: attracting orbits only, |μ|max the contraction per period, its ends not told "
        "fold from loss of stability), since its fixed 5 ms steps make the map jump at the finite-difference steps. A branch ends at a fold when its last orbit's largest real "
        "multiplier is near +1 or a real multiplier crossed +1 between its last two orbits. Data "
        "`orbits_<car>_<A>in_<model>.csv`; the 70-ton loaded car's orbits are drawn on the describing-function plots of "
        "section 5 (`steady_70ton-loaded_<A>in.png`). The down sweep's drop (section 2: 0.5 mph steps, 30 s a speed, the "
        "speed ramped over 1 s) is its jump: its largest fall of the steady roll amplitude between neighbouring speeds "
        "when that is more than {:g} % of the amplitude before it.\n\n",
        s.quick ? "a short down sweep of eom's own (the quick run sweeps only the reduced model)"
                : "the state section 2's down sweep reached at V0 (accuracy 1e-4)",
        100 * kJumpFraction);
    md += "| car | A, in | model | V0 → V1, mph | S, mph | orbits converged | speeds covered, mph | roll amplitude, deg | "
          "stability, mph | where the branch ends | multiplier events | down sweep drops at (section 2) | the drop beside "
          "the branch | shooting, min (one core) |\n|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    // A sweep's drop beside a branch: the drop lies between its speed before (drop + step)
    // and the drop speed (findSweepJump: the lower speed of the pair).
    auto describeDropBeside = [&](double dropMph, const OrbitCaseResult& r) {
        const auto v = convergedOrbits(r.branch);
        if (v.empty()) return std::string("no orbit to compare");
        const bool folded = r.branch.stopReason.rfind("fold", 0) == 0 && r.branch.endBracketMph;
        const double before = dropMph + s.sweepStep;
        const bool ends = r.branch.endBracketMph.has_value();
        // The fall-off interval [drop, before] against the end bracket: overlapping, the drop is at
        // the end; wholly below it, the sweep held a response below the branch's last orbit.
        const bool atEnd = ends && dropMph <= r.branch.endBracketMph->first + 1e-9;
        const bool below = ends && before < r.branch.endBracketMph->second - 1e-9;
        std::string verdict = fmt::format("the sweep falls off between {:g} and {:g} mph; ", before, dropMph);
        verdict += ends ? fmt::format("the branch {} between {:.2f} and {:.2f} mph", folded ? "folds" : "ends",
                                      r.branch.endBracketMph->second, r.branch.endBracketMph->first)
                        : fmt::format("the branch has orbits down to {:.2f} mph", v.back()->speedMph);
        if (below)
            verdict += fmt::format(": the sweep stays up {:g} mph below the continuation's last orbit{}",
                                   r.branch.endBracketMph->first - before,
                                   r.settled.empty() ? ""
                                                     : " (iteration finds attracting orbits only; what the sweep's "
                                                       "states there settle on: the table below)");
        else
            verdict += atEnd ? ": the drop is at or just below the branch's end"
                             : ": the sweep leaves the branch above its end";
        // Where it leaves above the end: the basin there (measured on eom only).
        if (!atEnd)
            for (const auto& e : results)
                if (e.c.model == model_names::kEom && e.c.getKey() == r.c.getKey())
                    for (const auto& [sp, dv] : e.basin)
                        if (std::abs(sp - before) < 1e-9)
                            verdict += fmt::format("; from eom's orbit at {:g} mph the smallest instantaneous speed "
                                                   "step down that leaves the branch: {}",
                                                   sp, describeBasin(dv));
        return verdict;
    };
    std::string foldSentence;
    for (const auto& r : results) {
        const auto v = convergedOrbits(r.branch);
        std::vector<std::string> events;
        for (const auto& e : r.branch.events)
            if (e.kind != "fold" && e.kind != "branch end")
                events.push_back(fmt::format("{} {:.2f}–{:.2f}", e.kind, e.fromMph, e.toMph));
        const bool folded = r.branch.stopReason.rfind("fold", 0) == 0 && r.branch.endBracketMph;
        std::string verdict;
        if (v.empty()) {
            verdict = "no orbit to compare";
        } else if (std::isfinite(r.sweepDropMph)) {
            verdict = describeDropBeside(r.sweepDropMph, r);
        } else if (!r.swept) {
            verdict = "not swept in this run";
        } else {
            // A branch that ends (a fold or not) below the sweep's lowest speed does not contradict it.
            const auto& end = r.branch.endBracketMph;
            if (!end)
                verdict = "the sweep never drops and the branch does not end: consistent";
            else if (end->first < r.sweepLowestMph)
                verdict = fmt::format("the sweep never drops; the branch {} between {:.2f} and {:.2f} mph, below the "
                                      "lowest speed swept ({:g} mph): consistent",
                                      folded ? "folds" : "ends", end->second, end->first, r.sweepLowestMph);
            else
                verdict = fmt::format("the sweep never drops, yet the branch {} between {:.2f} and {:.2f} mph",
                                      folded ? "folds" : "ends", end->second, end->first);
        }
        double shootingS = 0;
        for (const auto& p : r.branch.points) shootingS += p.wallTimeS;
        md += fmt::format("| {} | {:.2f} | {} | {:g} → {:g} | {:g} | {} of {} | {} | {} | {} | {} | {} | {} | {} | {:.1f} |\n",
                          r.c.car, r.c.amplitudeIn, r.c.model, r.c.startMph, r.c.toMph, r.c.stepMph, v.size(),
                          r.branch.points.size(),
                          v.empty() ? "—" : fmt::format("{:.2f}–{:.2f}", v.back()->speedMph, v.front()->speedMph),
                          v.empty() ? "—" : fmt::format("{:.2f}–{:.2f}", v.front()->rollAmplitudeDeg, v.back()->rollAmplitudeDeg),
                          describeOrbitStability(r.branch), describeEnd(r),
                          events.empty() ? "none" : fmt::format("{}", fmt::join(events, "; ")),
                          !r.swept                      ? std::string("—")
                          : std::isfinite(r.sweepDropMph) ? fmt::format("{:.1f} mph", r.sweepDropMph)
                          : std::isfinite(r.sweepLargestFallMph)
                              ? fmt::format("never (largest fall {:.2f}° at {:g} mph)", r.sweepLargestFallDeg,
                                            r.sweepLargestFallMph)
                              : std::string("never"),
                          verdict, shootingS / 60);
    }

    // Every drop of section 2, beside the branch it leaves: the model's own when computed here,
    // else its twin's (eom), else why there is none.
    if (!s.quick) {
        md += "\n**Every drop of section 2 beside the branch it leaves** (its down sweep's jump; the branch is the same "
              "model's when computed above, otherwise eom's on the same case, which solves the same car's equations "
              "to within 1 % of the half car):\n\n| car | A, in | model | drops at, mph | the branch beside it | "
              "the drop beside the branch |\n|---|---|---|---|---|---|\n";
        for (const auto& sw : sweeps) {
            const double drop = findDrop(sw.down);
            if (!std::isfinite(drop)) continue;
            const std::string key = fmt::format("{}_{:.2f}in", sw.c.car, sw.c.amplitudeIn);
            const OrbitCaseResult *own = nullptr, *twin = nullptr;
            for (const auto& r : results) {
                if (r.c.getKey() != key) continue;
                if (r.c.model == sw.model) own = &r;
                else if (r.c.model == model_names::kEom) twin = &r;
            }
            const OrbitCaseResult* b = own ? own : twin;
            std::string beside, verdict;
            if (b) {
                beside = fmt::format("{} ({})", b->c.model, describeEnd(*b));
                verdict = describeDropBeside(drop, *b);
            } else {
                beside = "none computed on this case";
                verdict = "not explained here";
            }
            if (b && b != own)
                beside += fmt::format("; {}'s own orbits are not computed in validate (docs/validation.md, "
                                      "\"Section 11\")", sw.model);
            if (own && sw.model == model_names::kReduced) verdict += "; " + describeSettled(*own);
            md += fmt::format("| {} | {:.2f} | {} | {:.1f} | {} | {} |\n", sw.c.car, sw.c.amplitudeIn, sw.model, drop,
                              beside, verdict);
        }
    }

    // eom against the half car: the fold (or the lowest orbit) of each.
    md += "\n**eom against the Simbody half car** (its twin): ";
    std::vector<std::string> twins;
    for (const auto& e0 : results) {
        if (e0.c.model != model_names::kEom) continue;
        const OrbitCaseResult *e = &e0, *h = nullptr;
        for (const auto& r : results)
            if (r.c.getKey() == e->c.getKey() && r.c.model == model_names::kHalfCar) h = &r;
        if (!h) continue;
        twins.push_back(fmt::format("{} {:.2f} in: eom {}, half car {}", e->c.car, e->c.amplitudeIn, describeEnd(*e),
                                    describeEnd(*h)));
        // Roll amplitude at the speeds both have.
        double worst = 0;
        for (const PeriodicOrbit* p : convergedOrbits(h->branch)) {
            const double a = branchAmplitudeAt(e->branch, p->speedMph);
            if (std::isfinite(a)) worst = std::max(worst, std::abs(p->rollAmplitudeDeg - a) / a);
        }
        twins.back() += fmt::format(" (roll amplitudes at the half car's speeds within {:.2f} %)", 100 * worst);
    }
    md += twins.empty() ? "not computed in the quick run.\n\n" : fmt::format("{}.\n\n", fmt::join(twins, "; "));

    // The basin along the branch.
    md += fmt::format("**How easily a speed step knocks an orbit off the upper branch (eom).** From each orbit, the speed "
                      "steps down at once by Δ = {} mph and the run goes on {:g} s; it counts as off the branch when its "
                      "steady roll amplitude differs from the branch's orbit at the new speed by more than {:g} %. The "
                      "cell gives the smallest such Δ (\"none\": it stays on the branch for every Δ tried, \"—\": no orbit "
                      "at the new speed to compare with).\n\n| car | A, in | speed mph: smallest Δ that drops |\n|---|---|---|\n",
                      fmt::join(kBasinSteps, ", "), kStepRunS, 100 * kOnBranchFraction);
    for (const auto& r : results) {
        if (r.c.model != model_names::kEom) continue;
        std::vector<std::string> cells;
        for (const auto& [v, dv] : r.basin)
            cells.push_back(fmt::format("{:g}: {}", v, describeBasin(dv)));
        md += fmt::format("| {} | {:.2f} | {} |\n", r.c.car, r.c.amplitudeIn,
                          cells.empty() ? "—" : fmt::format("{}", fmt::join(cells, "; ")));
    }

    // The reduced model's down-sweep states, iterated.
    bool anySettled = false;
    for (const auto& r : results) anySettled = anySettled || !r.settled.empty();
    if (anySettled) {
        md += "\n**What the reduced model's down-sweep states settle on.** From section 2's down-sweep state at each "
              "speed, from V0 down to its drop (or 4 mph below V0 when it never drops), the one-period map iterated at "
              "that speed until it repeats after 1 or 2 periods within the shooting tolerance, at most 300 periods: "
              "the orbit it settles on, beside the sweep's steady roll amplitude there (\"its orbit\" when within "
              "30 %).\n\n| car | A, in | speed mph: what the state settles on |\n|---|---|---|\n";
        for (const auto& r : results) {
            if (r.settled.empty()) continue;
            std::vector<std::string> cells;
            for (size_t i = 0; i < r.settled.size(); ++i)
                cells.push_back(fmt::format("{:g}: {}", r.settled[i].speedMph,
                                            describeSettledPoint(r.settled[i], r.settledSweepAmplitude[i])));
            md += fmt::format("| {} | {:.2f} | {} |\n", r.c.car, r.c.amplitudeIn, fmt::join(cells, "; "));
        }
    }

    // Stepped sweeps.
    if (!stepped.empty()) {
        md += fmt::format("\n**Down sweeps whose speed steps at once** (`rockroll sweep scenarios/70ton-loaded.toml --model M "
                          "--amplitude-in A --from-mph 10 --to-mph 22 --step-mph S --duration-s {:g} --direction down "
                          "--speed-ramp-s 0`), the way a run restarted at a new speed from the last state changes speed, "
                          "beside section 2's ramped sweeps:\n\n| A, in | model | ramped, 0.5 mph steps: drop | stepped, 0.5 mph: "
                          "drop | stepped, 1 mph: drop | steady roll at 10 mph, stepped 0.5 / 1 mph, deg |\n|---|---|---|---|---|---|\n",
                          kStepRunS);
        for (const char* m : {model_names::kEom, model_names::kHalfCar})
            for (double amp : {0.75, 1.0}) {
                const SweepResult* sw = findSweep(sweeps, "70ton-loaded", m, amp);
                const Stepped *half = nullptr, *one = nullptr;
                for (const auto& st : stepped)
                    if (st.model == m && st.amp == amp) (st.stepMph == 0.5 ? half : one) = &st;
                auto drop = [](double v) { return std::isfinite(v) ? fmt::format("{:.1f} mph", v) : std::string("none"); };
                md += fmt::format("| {:.2f} | {} | {} | {} | {} | {} / {:.2f} |\n", amp, m,
                                  sw ? drop(findDrop(sw->down)) : "—", half ? drop(half->dropMph) : "not run",
                                  drop(one->dropMph), half ? fmt::format("{:.2f}", half->lowestRollDeg) : "—",
                                  one->lowestRollDeg);
            }
    }

    // The describing function against eom's exact orbits, speed by speed.
    {
        md += "\n**The describing function against eom's orbits** (section 5's solution set; the roll amplitude of each "
              "is half its peak-to-peak roll). At each whole-mph speed of eom's upper branch: the describing-function "
              "solution nearest the orbit's amplitude, its labelled stability, and the amplitude of its time-domain "
              "twin's last period when the twin stayed on it (5 periods from the solution: the describing function's "
              "own truncation error, without eom's §4.1 differences). A dash: no solution at that speed.\n\n"
              "| A, in | speed, mph | eom orbit, deg (stability) | describing function nearest, deg (stability) | "
              "difference | its twin, deg | truncation (DF − twin) / twin |\n|---|---|---|---|---|---|---|\n";
        int rows = 0;
        for (const auto& r : results) {
            if (r.c.model != model_names::kEom || r.c.car != "70ton-loaded" || !steady.count(r.c.amplitudeIn)) continue;
            const SteadyStateSet& set = steady.at(r.c.amplitudeIn);
            for (const PeriodicOrbit* p : convergedOrbits(r.branch)) {
                if (std::abs(p->speedMph - std::round(p->speedMph)) > 1e-9) continue;
                std::optional<SteadyAt> nearest;
                for (const SteadyAt& v : findAllSteadyAt(set, p->speedMph))
                    if (!nearest || std::abs(v.rollAmplitudeDeg - p->rollAmplitudeDeg) <
                                        std::abs(nearest->rollAmplitudeDeg - p->rollAmplitudeDeg))
                        nearest = v;
                const std::string orbit =
                    fmt::format("{:.2f} ({})", p->rollAmplitudeDeg, p->stable ? "stable" : "unstable");
                ++rows;
                if (!nearest) {
                    md += fmt::format("| {:.2f} | {:g} | {} | — | — | — | — |\n", r.c.amplitudeIn, p->speedMph, orbit);
                    continue;
                }
                const bool twin = nearest->twin.computed && nearest->twin.stayed();
                md += fmt::format("| {:.2f} | {:g} | {} | {:.2f} ({}) | {:+.1f} % | {} | {} |\n", r.c.amplitudeIn,
                                  p->speedMph, orbit, nearest->rollAmplitudeDeg, describeStability(nearest->stability),
                                  100 * (nearest->rollAmplitudeDeg - p->rollAmplitudeDeg) / p->rollAmplitudeDeg,
                                  twin ? fmt::format("{:.2f}", nearest->twin.rollAmplitudeDeg) : "left it or not run",
                                  twin ? fmt::format("{:+.1f} %", 100 * (nearest->rollAmplitudeDeg -
                                                                         nearest->twin.rollAmplitudeDeg) /
                                                                      nearest->twin.rollAmplitudeDeg)
                                       : "—");
            }
        }
        if (rows == 0) md += "| — | — | no eom orbit at a whole-mph speed | — | — | — | — |\n";
    }

    // The report's 13.5 mph drop (Figure 11, 1.0 in), from the numbers above.
    for (const auto& r : results)
        if (r.c.car == "70ton-loaded" && std::abs(r.c.amplitudeIn - 1.0) < 1e-9 && r.c.model == model_names::kEom) {
            const auto v = convergedOrbits(r.branch);
            double stableBelow = NAN;
            for (const PeriodicOrbit* p : v) {
                if (!p->stable) break;
                stableBelow = p->speedMph;
            }
            double basin135 = NAN;
            bool have135 = false;
            for (const auto& [sp, dv] : r.basin)
                if (std::abs(sp - 13.5) < 1e-9 && !(dv < 0)) have135 = true, basin135 = dv;
            foldSentence = fmt::format(
                "\n**The report's drop at 13.5 mph (Figure 11, 1.0 in).** eom's upper branch at 1.0 in: {}; its orbits are "
                "stable from {:g} down to {} mph without a break{}. So in this model the drop at 13.5 mph is not the "
                "end of the branch. {}",
                describeEnd(r), r.c.startMph, std::isfinite(stableBelow) ? fmt::format("{:.2f}", stableBelow) : "—",
                v.empty() ? "" : fmt::format(" (roll amplitude {:.2f}° at {:g} mph)", v.front()->rollAmplitudeDeg, v.front()->speedMph),
                have135 ? (std::isfinite(basin135)
                               ? fmt::format("From its orbit at 13.5 mph, a speed step of {:g} mph at once knocks it off "
                                             "the branch, so a run restarted at a speed {:g} mph lower can drop there.",
                                             basin135, basin135)
                               : fmt::format("From its orbit at 13.5 mph, no speed step up to {:g} mph at once knocks it "
                                             "off the branch.",
                                             kBasinSteps.back()))
                        : std::string(""));
            for (const auto& st : stepped)
                if (st.model == std::string(model_names::kEom) && st.amp == 1.0)
                    foldSentence += fmt::format(" Swept down with the speed stepped at once in {:g} mph steps it {}.",
                                                st.stepMph,
                                                std::isfinite(st.dropMph) ? fmt::format("drops at {:.1f} mph", st.dropMph)
                                                                          : "never drops");
            foldSentence += " The report's Figure 11 comes from its §2.2 digital simulation, the reduced model's "
                            "formulation (§3, \"Digital simulation runs\"), and plots \"the maximum car body roll angle "
                            "occurring in a simulation time history\"; its §3.1 says that a severe-rocking response "
                            "computed for longer \"exhibits a series of 'beats' with successive growing and decaying "
                            "cycles\".";
            for (const auto& red : results)
                if (red.c.model == model_names::kReduced && red.c.amplitudeIn == 1.0)
                    foldSentence += fmt::format(" The reduced model at 1.0 in, by iteration from its down sweep's state at "
                                                "{:g} mph: {}; {}.",
                                                red.c.startMph, describeEnd(red), describeSettled(red));
            if (!dwells.empty())
                foldSentence += fmt::format(
                    " Its down sweeps from 22 mph (0.5 mph steps, the 1 s ramp) with different times at each speed drop "
                    "at: 1.0 in: {}; 0.75 in: {}.",
                    describeDwells(1.0), describeDwells(0.75));
            foldSentence += " So where the report's simulation left severe rocking is not the end of a branch of "
                            "periodic orbits: in its formulation the severe response there is not periodic, and where a "
                            "run of finite length leaves it depends on how long it runs at each speed and the state it "
                            "starts from; the report does not give either for Figure 11 (its §3.2 says only that points "
                            "were computed \"from initial conditions of lower speed ... as well as from higher speed\").\n";
        }
    md += foldSentence;
    return md + "\n";
}

}  // namespace rockroll::app
