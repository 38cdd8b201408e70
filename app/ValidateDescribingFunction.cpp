// validate, section 5: the describing-function solution set (report §4, Figures 31 and 34)
// over the simulated sweeps; traceSteady's solutions also feed section 3.
#include "app/ValidateSections.h"
#include "mbmodel/CsvWriter.h"

#include <fmt/format.h>

#include <algorithm>

namespace rockroll::app {

using namespace validate_detail;

namespace {
constexpr double kFromMph = 10, kToMph = 22;
/// A sweep point is "near" a describing-function solution when their roll amplitudes
/// differ by at most this fraction (the describing function is ~10 % off its own twin
/// near resonance, docs/bespoke.md).
constexpr double kNearFraction = 0.2;

/// "stable 10.0–14.9, unstable 14.9–13.1, …": the path's stretches of one stability.
std::string describeStretches(const SteadyStateSet& set, int path) {
    std::vector<std::string> parts;
    for (const auto& b : set.branches)
        if (b.path == path && !b.points.empty())
            parts.push_back(fmt::format("{} {:.1f}–{:.1f} ({:.2f}–{:.2f}°)", describeStability(b.stability),
                                        b.points.front().speedMph, b.points.back().speedMph,
                                        b.points.front().rollAmplitudeDeg, b.points.back().rollAmplitudeDeg));
    return fmt::format("{}", fmt::join(parts, "; "));
}
}  // namespace

SteadyByAmplitude traceSteady(const Settings& s) {
    const CarParameters car = makeCarParameters("70ton-loaded");
    const double L = 39 * units::foot;
    const std::vector<double> amps = s.quick ? std::vector<double>{0.75} : std::vector<double>{0.5, 0.75, 1.0};
    std::vector<SteadyStateSet> all(amps.size());
    std::vector<std::function<void()>> jobs;
    for (size_t i = 0; i < amps.size(); ++i)
        jobs.push_back([&, i] {
            const DescribingFunctionModel df(
                car, DescribingFunctionModel::calcFundamentalCrossLevel(amps[i] * units::inch, car.wheelbase, L), L);
            ContinuationSettings cs;
            cs.fromMph = kFromMph, cs.toMph = kToMph;
            cs.stability = s.quick ? StabilityMethod::None : StabilityMethod::FoldRule;
            if (s.quick) cs.sweepStepMph = 0, cs.twinPeriods = 0;
            all[i] = df.trace(cs);
        });
    runJobs(jobs, s.jobs);
    SteadyByAmplitude out;
    for (size_t i = 0; i < amps.size(); ++i) out[amps[i]] = all[i];
    return out;
}

std::string makeDescribingFunctionSection(const Settings& s, const SteadyByAmplitude& steady,
                                         const std::vector<SweepResult>& sweeps, nlohmann::ordered_json& meta) {
    const Mit1976& ref = Mit1976::get();
    const ContinuationSettings cs;
    std::string md = "## 5. Describing-function solution set over the simulated sweeps (report Figures 31 and 34)\n\n";
    md += fmt::format(
        "Made by `rockroll steady scenarios/70ton-loaded.toml --amplitude-in A --from-mph {:g} --to-mph {:g} "
        "--stability {}`{}; data `steady_70ton-loaded_<A>in.csv`, plot `steady_70ton-loaded_<A>in.png` with the "
        "sweeps' steady roll amplitudes. The input is the fundamental harmonic of the cross-level, "
        "8A/(3π)·cos(π·wheelbase/L_r) = 0.762·A. Paths start from rest at both ends of the range and, in the full "
        "run, from the time-domain twin's own sweeps down and up ({:g} mph steps, {} forcing periods a speed): each "
        "speed's last period projected on two harmonics and solved; a solution on no path traced so far starts a path "
        "of its own. Stability (full run): each stretch between folds is checked near both ends and in the middle, by "
        "Floquet multipliers of the twin's periodic orbit and a {}-period persistence run of the twin from the "
        "solution, and bisected where checks disagree; a check whose two pieces of evidence disagree labels nothing "
        "(docs/bespoke.md, \"Stability\").\n\n",
        kFromMph, kToMph, s.quick ? "none --twin-periods 0 --no-sweep-starts" : "fold", "", cs.sweepStepMph,
        cs.sweepPeriods, cs.persistencePeriods);
    md += "| A, in | paths | solutions traced | folds | speeds covered, mph | speed range with ≥ 3 solutions, mph | "
          "checks | checks whose Floquet and persistence disagree | stability changes without a fold |\n"
          "|---|---|---|---|---|---|---|---|---|\n";
    std::string pathsMd = "| A, in | path | started from | points | folds | stretches: stability, speeds mph (roll amplitude) |\n"
                          "|---|---|---|---|---|---|\n";
    for (const auto& [amp, set] : steady) {
        const std::string file = fmt::format("steady_70ton-loaded_{:.2f}in.csv", amp);
        int points = 0, folds = 0, checks = 0, disagree = 0;
        double lo = 1e9, hi = -1e9;
        writeAtomically(s.out / file, [&](std::ostream& o) {
            CsvWriter csv(o, {"branch", "path", "stable", "speed_mph", "roll_amplitude_deg", "roll_first_harmonic_deg",
                              "wheel_lift_fraction", "side_bearing_load_mean_lb", "side_bearing_load_first_harmonic_lb",
                              "twin_stayed", "twin_max_truck_side_wheel_load_lb", "twin_max_side_bearing_load_lb",
                              "checked", "stability_evidence", "folds_before"});
            for (size_t b = 0; b < set.branches.size(); ++b)
                for (const auto& p : set.branches[b].points) {
                    csv.writeRow({b, set.branches[b].path, toString(set.branches[b].stability),
                                  CsvCell::fixed(p.speedMph, 4), CsvCell::fixed(p.rollAmplitudeDeg, 4),
                                  CsvCell::fixed(p.rollFirstDeg, 4), CsvCell::fixed(p.wheelLiftFraction, 4),
                                  CsvCell::fixed(p.sideBearingLoad.meanLb, 0), CsvCell::fixed(p.sideBearingLoad.firstLb, 0),
                                  p.twin.computed ? (p.twin.stayed() ? "yes" : "no") : "not run",
                                  p.twin.computed ? CsvCell::fixed(p.twin.maxTruckSideWheelLoadLb, 0) : CsvCell(""),
                                  p.twin.computed ? CsvCell::fixed(p.twin.maxSideBearingLoadLb, 0) : CsvCell(""),
                                  p.checked ? 1 : 0, p.stabilityEvidence, p.foldsBefore});
                }
        });
        for (const auto& path : set.paths) {
            points += int(path.points.size());
            if (!path.points.empty()) folds += path.points.back().foldsBefore;
            for (const auto& p : path.points) {
                lo = std::min(lo, p.speedMph), hi = std::max(hi, p.speedMph);
                checks += p.checked ? 1 : 0;
                disagree += p.stabilityEvidence == "floquet, persistence disagree" ? 1 : 0;
            }
        }
        double lo3 = 1e9, hi3 = -1e9;
        for (double v = kFromMph; v <= kToMph + 1e-9; v += 0.05)
            if (findAllSteadyAt(set, v).size() >= 3) lo3 = std::min(lo3, v), hi3 = std::max(hi3, v);
        std::vector<std::string> changes;
        for (const auto& c : set.changes)
            changes.push_back(fmt::format("path {}, {:.2f}–{:.2f} mph: {}", c.path, c.fromMph, c.toMph, c.kind));
        md += fmt::format("| {:.2f} | {} | {} | {} | {} | {} | {} | {} | {} |\n", amp, set.paths.size(), points, folds,
                          lo <= hi ? fmt::format("{:.1f}–{:.1f}", std::max(lo, kFromMph), std::min(hi, kToMph)) : "none",
                          lo3 <= hi3 ? fmt::format("{:.1f}–{:.1f}", lo3, hi3) : "none", checks, disagree,
                          changes.empty() ? (s.quick ? "not checked" : "none") : fmt::format("{}", fmt::join(changes, "; ")));
        for (size_t k = 0; k < set.paths.size(); ++k)
            pathsMd += fmt::format("| {:.2f} | {} | {}{} | {} | {} | {} |\n", amp, k, set.paths[k].start,
                                   set.paths[k].closed ? " (closed: an isola)" : "", set.paths[k].points.size(),
                                   set.paths[k].points.empty() ? 0 : set.paths[k].points.back().foldsBefore,
                                   describeStretches(set, int(k)));
        meta["steady"].push_back({{"amplitude_in", amp}, {"file", file}, {"sweep_key", fmt::format("70ton-loaded_{:.2f}in", amp)}});
    }
    md += "\nEach path, and its stretches of one stability (a stretch of unstable or not-computed points between folds "
          "is the describing function's own statement, checked on its time-domain twin):\n\n" + pathsMd + "\n";

    // Every steady sweep point beside the describing function's solutions at its speed.
    if (!s.quick) {
        md += fmt::format("**The sweeps' steady responses and the describing function.** A sweep point counts as near a "
                          "solution when their roll amplitudes (the sweep's steady amplitude over its last 3 forcing "
                          "periods; the solution's two-harmonic amplitude) differ by at most {:g} %. The twin's own "
                          "sweeps are the describing function's model in the time domain; eom and the Simbody half car "
                          "drop the §4.1 simplifications.\n\n| A, in | model | direction | steady points | near a "
                          "solution | not near one: speed mph (sweep roll → nearest solution, deg) |\n|---|---|---|---|---|---|\n",
                          100 * kNearFraction);
        auto nearest = [](const SteadyStateSet& set, double mph, double roll) {
            double best = NAN;
            for (const SteadyAt& v : findAllSteadyAt(set, mph))
                if (!(std::abs(v.rollAmplitudeDeg - roll) >= std::abs(best - roll))) best = v.rollAmplitudeDeg;
            return best;
        };
        for (const auto& [amp, set] : steady) {
            // Whether the twin's own sweep, at the nearest speed it visited in the same
            // direction, was near a solution: the measured reason for a miss.
            auto twinNearAt = [&](const std::string& dir, double mph) -> std::optional<bool> {
                const TwinSweepStart* best = nullptr;
                for (const auto& t : set.sweepStarts)
                    if (t.direction == dir && std::abs(t.speedMph - mph) <= 0.5 &&
                        (!best || std::abs(t.speedMph - mph) < std::abs(best->speedMph - mph)))
                        best = &t;
                if (!best) return std::nullopt;
                const double n = nearest(set, best->speedMph, best->twinRollAmplitudeDeg);
                return std::abs(n - best->twinRollAmplitudeDeg) <= kNearFraction * best->twinRollAmplitudeDeg;
            };
            auto row = [&](const std::string& model, const std::string& dir, const std::vector<std::pair<double, double>>& pts,
                           bool isTwin) {
                int near = 0;
                std::vector<std::string> misses;
                for (const auto& [v, roll] : pts) {
                    const double n = nearest(set, v, roll);
                    if (std::abs(n - roll) <= kNearFraction * roll) {
                        ++near;
                        continue;
                    }
                    std::string why;
                    if (!isTwin) {
                        const auto twin = twinNearAt(dir, v);
                        why = !twin ? "" : *twin ? ": the twin there is near one, so the §4.1 simplifications"
                                                 : ": the twin there is not near one either";
                    }
                    misses.push_back(std::isfinite(n) ? fmt::format("{:g} ({:.2f} → {:.2f}{})", v, roll, n, why)
                                                      : fmt::format("{:g} ({:.2f} → none{})", v, roll, why));
                }
                md += fmt::format("| {:.2f} | {} | {} | {} | {} | {} |\n", amp, model, dir, pts.size(), near,
                                  misses.empty() ? "—" : fmt::format("{}", fmt::join(misses, ", ")));
            };
            for (const std::string dir : {"down", "up"}) {
                std::vector<std::pair<double, double>> pts;
                for (const auto& t : set.sweepStarts)
                    if (t.direction == dir) pts.push_back({t.speedMph, t.twinRollAmplitudeDeg});
                row("describing function's twin", dir, pts, true);
            }
            for (const auto& sw : sweeps) {
                if (sw.c.car != "70ton-loaded" || std::abs(sw.c.amplitudeIn - amp) > 1e-9) continue;
                for (const auto* dir : {&sw.down, &sw.up}) {
                    std::vector<std::pair<double, double>> pts;
                    for (const auto& p : *dir)
                        if (!p.failed && p.speedMph >= kFromMph - 1e-9 && p.speedMph <= kToMph + 1e-9)
                            pts.push_back({p.speedMph, p.summary.steadyRollAmplitudeDeg});
                    if (!pts.empty()) row(sw.model, dir == &sw.down ? "down" : "up", pts, false);
                }
            }
        }
        md += "\nWhy a point is not near a solution, measured: the twin's rows are the describing function's own "
              "model in the time domain, so a twin point not near a solution is a steady response the two-harmonic "
              "ansatz does not hold (its last period, projected on two harmonics, did not solve, or solved onto "
              "another solution). A miss of another model is marked by what the twin did at the nearest speed of its "
              "own sweep in the same direction (its 1 mph steps; unmarked when it visited none within 0.5 mph): near "
              "a solution there, the difference is the §4.1 simplifications' (docs/bespoke.md), not the ansatz's.\n\n";
    }

    // The report's highest branch, and what our labels say at its lowest speed.
    const double lowest = ref("describing_function.high_branch_lowest_speed", "mph");
    md += fmt::format("The report's describing function (§4.3, Figure 31), speed increasing from {} mph, leaves its lowest "
                      "curve at {}, {} and {} mph for 0.5, 0.75 and 1.0 in. Speed decreasing from {} mph, its highest set "
                      "of curves extends to {} mph (±{}° there); its digital simulation could not obtain that curve below "
                      "{} mph (§4.3, Figure 34).",
                      formatPublished(ref("describing_function.sweep_from", "mph")),
                      formatPublished(ref("describing_function.jump_up_0_50in", "mph")),
                      formatPublished(ref("describing_function.jump_up_0_75in", "mph")),
                      formatPublished(ref("describing_function.jump_up_1_00in", "mph")),
                      formatPublished(ref("describing_function.high_branch_from", "mph")),
                      formatPublished(ref("describing_function.high_branch_lowest_speed", "mph")),
                      formatPublished(ref("describing_function.high_branch_roll", "deg")),
                      formatPublished(ref("describing_function.simulation_high_branch_not_below", "mph")));
    for (const auto& [amp, set] : steady) {
        // The largest solution at the report's lowest speed, and the label of the nearer
        // traced point.
        const std::vector<SteadyAt> at = findAllSteadyAt(set, lowest);
        if (at.empty()) {
            md += fmt::format(" At {:.2f} in we traced no solution at {:g} mph.", amp, lowest);
            continue;
        }
        md += fmt::format(" At {:.2f} in our largest solution at {:g} mph has a roll amplitude of {:.2f}° and is labelled "
                          "{}.",
                          amp, lowest, at.back().rollAmplitudeDeg, describeStability(at.back().stability));
    }
    md += "\n\n";
    for (const auto& [a, set] : steady) md += fmt::format("![describing function, {:.2f} in](steady_70ton-loaded_{:.2f}in.png)\n", a, a);
    return md + "\n";
}

}  // namespace rockroll::app
