#pragma once
// A branch of periodic orbits (scenarios/PeriodicOrbit.h) continued in speed:
// natural-parameter continuation with a secant predictor. From the orbit y_k at
// V_k (and y_{k−1} at V_{k−1}) the guess at V_{k+1} = V_k ∓ ΔV is
//
//     y_pred = y_k + (y_k − y_{k−1})·(V_{k+1} − V_k)/(V_k − V_{k−1}),
//
// then shooting corrects it. Where shooting fails, or converges onto an orbit whose
// roll amplitude differs from the last one's by more than `jumpFraction` (another
// branch: the predictor overshot the end of this one), ΔV is halved up to
// `refinements` times; then the branch ends there and the speeds bracket its end.
// A branch that ends so with the largest real multiplier of its last orbit near +1
// (within 1 ± (1 − `foldMultiplier`)), or with a real multiplier that crossed +1
// between its last two orbits (the continuation slid onto the unstable side of the
// saddle-node, which exists at the last speed too), ends at a fold (a saddle-node of
// periodic orbits: a real multiplier reaches +1 there). Between neighbouring orbits it records a real
// multiplier crossing −1 (period doubling), a complex pair leaving the unit circle
// (Neimark–Sacker), and a real multiplier crossing +1, each as the speed bracket
// where it happens (moduli compared with OrbitSettings::stabilityMargin).
//
// With `reuseMonodromy`, the shooting at V_{k+1} starts a chord Newton from the
// monodromy of the period-1 orbit at V_k (PeriodicShooting.h); each orbit's own
// multipliers are still computed at it.
#include "scenarios/PeriodicOrbit.h"

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace rockroll {

struct OrbitContinuationSettings {
    double fromMph = 16, toMph = 10, stepMph = 0.25;
    int refinements = 2;          ///< halvings of the step at a failure before the branch ends
    double jumpFraction = 0.3;    ///< |Δ roll amplitude| / roll amplitude above which an orbit is another branch's
    double foldMultiplier = 0.8;  ///< the end is a fold when the last orbit's largest real multiplier is in (this, 2 − this)
    bool reuseMonodromy = true;   ///< start each shooting from the last period-1 orbit's monodromy (chord Newton)
    /// Periods the map is iterated from `start` at fromMph before the first shooting: a
    /// stable orbit's basin pulls the start closer, for a map whose finite-difference
    /// monodromy is poor far from the orbit (the reduced model's piecewise truck, docs/orbits.md).
    int settlePeriods = 0;
    /// Fresh-monodromy Newton steps for each orbit after the first (0: the solver's own). From
    /// the predictor and the previous monodromy a converging orbit needs few; a failing one
    /// spends them all, on P and again on P∘P.
    int branchNewtonSteps = 0;
};

struct OrbitEvent {
    std::string kind;             ///< "period doubling" | "complex pair leaves the unit circle" | "real multiplier crosses +1" | "fold" | "branch end"
    double fromMph = 0, toMph = 0;  ///< the speed bracket
    std::string detail;
};

struct OrbitBranch {
    std::vector<PeriodicOrbit> points;  ///< in the order computed, failed attempts included (converged = false)
    std::vector<OrbitEvent> events;
    /// "minimum speed reached", "fold", or "branch end (...)": why the continuation stopped.
    std::string stopReason;
    std::optional<std::pair<double, double>> endBracketMph;  ///< {last converged, first failed} speed
};

class OrbitContinuation {
public:
    OrbitContinuation(const PeriodicOrbitSolver& solver, OrbitContinuationSettings settings);
    /// From the flat state `start` (a long run's end, advanced by settlePeriods): the orbit at fromMph, then on
    /// towards toMph. The first point not converging ends the branch at once
    /// (stopReason "no orbit at the start speed").
    OrbitBranch trace(const std::vector<double>& start,
                      const std::function<void(const PeriodicOrbit&)>& progress = {}) const;

private:
    const PeriodicOrbitSolver& solver_;
    OrbitContinuationSettings settings_;
};

}  // namespace rockroll
