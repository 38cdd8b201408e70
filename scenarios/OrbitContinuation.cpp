#include "scenarios/OrbitContinuation.h"

#include <cmath>
#include <fmt/format.h>

namespace rockroll {

OrbitContinuation::OrbitContinuation(const PeriodicOrbitSolver& solver, OrbitContinuationSettings settings)
    : solver_(solver), settings_(settings) {
    if (!(settings_.stepMph > 0)) throw std::invalid_argument("orbit continuation: the speed step must be positive");
}

namespace {
/// The largest modulus of a complex (non-real) multiplier; 0 when there is none.
double calcComplexModulus(const PeriodicOrbit& o) {
    double m = 0;
    for (const auto& mu : o.multipliers)
        if (mu.imag() != 0) m = std::max(m, std::abs(mu));
    return m;
}
}  // namespace

OrbitBranch OrbitContinuation::trace(const std::vector<double>& start,
                                     const std::function<void(const PeriodicOrbit&)>& progress) const {
    OrbitBranch b;
    const double margin = solver_.getSettings().stabilityMargin;
    const double dir = settings_.toMph < settings_.fromMph ? -1.0 : 1.0;
    auto report = [&](const PeriodicOrbit& o) {
        if (progress) progress(o);
    };
    const std::vector<double> settled =
        settings_.settlePeriods > 0 ? solver_.runPeriods(settings_.fromMph, start, settings_.settlePeriods).restart.y
                                    : start;
    PeriodicOrbit cur = solver_.solve(settings_.fromMph, settled);
    b.points.push_back(cur);
    report(cur);
    if (!cur.converged) {
        b.stopReason = "no orbit at the start speed";
        return b;
    }
    std::optional<PeriodicOrbit> prev;
    double step = settings_.stepMph;
    int halvings = 0;
    bool crossedPlusOne = false;  ///< a real multiplier crossed +1 between the last two orbits
    const double eps = 1e-9;
    for (;;) {
        if (dir * (settings_.toMph - cur.speedMph) <= eps) {
            b.stopReason = "minimum speed reached";
            if (dir > 0) b.stopReason = "maximum speed reached";
            break;
        }
        double next = cur.speedMph + dir * step;
        if (dir * (next - settings_.toMph) > 0) next = settings_.toMph;
        next = std::round(next * 1e9) / 1e9;
        // Secant predictor in the flat state (the accumulating entries are ignored by the shooting).
        std::vector<double> guess = cur.y;
        if (prev && prev->period == cur.period) {
            const double f = (next - cur.speedMph) / (cur.speedMph - prev->speedMph);
            for (size_t i = 0; i < guess.size(); ++i) guess[i] = cur.y[i] + f * (cur.y[i] - prev->y[i]);
            for (int i : solver_.getDiscreteIndices()) guess[size_t(i)] = cur.y[size_t(i)];
        }
        const bool reuse = settings_.reuseMonodromy && cur.period == 1;
        PeriodicOrbit o =
            solver_.solve(next, guess, reuse ? cur.monodromy : Eigen::MatrixXd(), settings_.branchNewtonSteps);
        bool accepted = o.converged;
        if (accepted) {
            const double jump = std::abs(o.rollAmplitudeDeg - cur.rollAmplitudeDeg);
            if (jump > settings_.jumpFraction * std::max(cur.rollAmplitudeDeg, 0.1)) {
                accepted = false;
                o.failure = fmt::format("converged onto another branch's orbit (roll amplitude {:.3f} deg against "
                                        "{:.3f} deg at {:g} mph)",
                                        o.rollAmplitudeDeg, cur.rollAmplitudeDeg, cur.speedMph);
                o.converged = false;  // reported as a failed point: never as this branch's orbit
            }
        }
        b.points.push_back(o);
        report(o);
        if (!accepted) {
            if (halvings < settings_.refinements) {
                step /= 2;
                ++halvings;
                continue;
            }
            b.endBracketMph = std::make_pair(cur.speedMph, o.speedMph);
            // A fold: the last orbit's largest real multiplier is near +1, or a real multiplier
            // crossed +1 between the last two orbits (the continuation slid from the stable onto
            // the unstable side of a saddle-node, so both sides exist at the last orbit's speed
            // and the fold lies between it and the failed speed).
            const bool nearOne = cur.largestRealMultiplier > settings_.foldMultiplier &&
                                 cur.largestRealMultiplier < 2 - settings_.foldMultiplier;
            const bool iterated = cur.method == OrbitMethod::Iteration;
            const bool fold = !iterated && (nearOne || crossedPlusOne);
            OrbitEvent e;
            e.kind = fold ? "fold" : "branch end";
            e.fromMph = cur.speedMph;
            e.toMph = o.speedMph;
            e.detail = fmt::format("last orbit at {:g} mph: largest real multiplier {:.4f}, |mu|max {:.4f}; at {:g} "
                                   "mph: {}",
                                   cur.speedMph, cur.largestRealMultiplier, cur.maxMultiplier, o.speedMph, o.failure);
            b.events.push_back(e);
            b.stopReason = fold ? std::string(nearOne ? "fold" : "fold (a real multiplier crossed +1 just before it)")
                           : iterated ? std::string("branch end (iteration: no attracting orbit on this branch past it; "
                                                    "a fold is not told from a loss of stability)")
                                      : fmt::format("branch end (shooting failed; the last orbit's largest real "
                                                       "multiplier {:.4f} is not near +1)",
                                                       cur.largestRealMultiplier);
            break;
        }
        // Multiplier crossings between cur and o (same period only).
        if (o.period == cur.period) {
            auto add = [&](const char* kind, std::string detail) {
                b.events.push_back(OrbitEvent{kind, cur.speedMph, o.speedMph, std::move(detail)});
            };
            if (cur.smallestRealMultiplier > -1 && o.smallestRealMultiplier <= -1)
                add("period doubling", fmt::format("smallest real multiplier {:.4f} -> {:.4f}",
                                                   cur.smallestRealMultiplier, o.smallestRealMultiplier));
            const double c0 = calcComplexModulus(cur), c1 = calcComplexModulus(o);
            if (c0 <= margin && c1 > margin)
                add("complex pair leaves the unit circle", fmt::format("|mu| {:.4f} -> {:.4f}", c0, c1));
            crossedPlusOne = cur.largestRealMultiplier <= margin && o.largestRealMultiplier > margin;
            if (crossedPlusOne)
                add("real multiplier crosses +1", fmt::format("largest real multiplier {:.4f} -> {:.4f}",
                                                              cur.largestRealMultiplier, o.largestRealMultiplier));
        } else {
            crossedPlusOne = false;
            b.events.push_back(OrbitEvent{"period changes", cur.speedMph, o.speedMph,
                                          fmt::format("period {} -> {}", cur.period, o.period)});
        }
        prev = std::move(cur);
        cur = std::move(o);
    }
    return b;
}

}  // namespace rockroll
