#pragma once
// Periodic orbits of any time-domain model (scenarios/TimeDomainModel.h) at constant
// speed, by shooting on its stroboscopic map. No Simbody in the interface.
//
// The track repeats every L (the rectified sine: every rail length L_r, report
// §2.1 eqs 1–2; a measured table with `repeat`: its length), so at speed V the
// forcing period is T = L / V. From track distance s₀ with the flat state y, at V
// from t = 0 (no ramp), the model's own run over T gives
//
//     P(y) = φ_T(y; s₀),
//
// and a periodic orbit is a fixed point P(y*) = y*. The shooting coordinates x are
// y without the entries that grow without bound (StateKind::Accumulating: the
// energy audit's integrals) and without discrete modes (StateKind::Discrete: the
// reduced model's truck mode, held during Newton; an orbit must return to the mode
// it started in); the friction bristles are included. Steps h_i:
// positions 10 µm (or 10 µrad), rates 0.1 mm/s, bristles 0.1 µm, as the
// describing function's twin check, times OrbitSettings::stepScale. The mismatch is measured in the same units
// except for the bristles, in 1 µm (0.4 % of the wedges' bristle limit): a wedge
// that sticks creeps by a few µm a period, the neutral direction Newton leaves
// alone. Newton (mbmodel/PeriodicShooting.h) runs on
// P(x) − x; when it fails it runs on P∘P, and an orbit fixed by P∘P but not by P
// is a period-2 response. Floquet multipliers: the eigenvalues of ∂(P^k)/∂x at the
// orbit (k = 1 or 2).
//
// Integration: the scenario's integrator at `accuracy` (default 1e-7): the finite
// differences need the integration error well below the perturbation steps (at the
// scenarios' 1e-4 it is of the order of the steps themselves). The output rate is
// the scenario's, rounded up to a whole number of samples per period.
#include "mbmodel/PeriodicShooting.h"
#include "scenarios/ScenarioRun.h"

#include <Eigen/Dense>
#include <chrono>
#include <string>
#include <vector>

namespace rockroll {

/// How an orbit is found. Newton finds stable and unstable orbits and their
/// multipliers, and needs a map smooth at the finite-difference steps. Iteration
/// (y ← P(y) until P(y) − y is within the tolerance) finds only attracting orbits:
/// for the reduced model, whose fixed 5 ms steps make the map jump where a truck-mode
/// switch moves by a step (docs/orbits.md).
enum class OrbitMethod { Newton, Iteration };

struct OrbitSettings {
    OrbitMethod method = OrbitMethod::Newton;
    int iterationPeriods = 300; ///< Iteration: the most map evaluations per orbit
    double accuracy = 1e-7;     ///< integrator accuracy of the map (≤ 0: the scenario's)
    ShootingSettings shooting;
    bool tryPeriodTwo = true;   ///< when P's Newton fails, shoot P∘P
    /// Scales the finite-difference steps h_i; the mismatch stays measured in the unscaled
    /// steps, so the tolerance does not move with it (the step-halving check, docs/orbits.md).
    double stepScale = 1;
    /// A multiplier modulus up to this counts as not unstable: a wedge sticking all
    /// period long contributes μ = 1 with finite-difference noise.
    double stabilityMargin = 1.01;
};

struct PeriodicOrbit {
    double speedMph = 0;
    bool converged = false;
    int period = 0;                   ///< forcing periods of the orbit: 1 or 2 (0 when not converged)
    std::vector<double> y;            ///< the model's flat state at s₀ (the last iterate when not converged)
    double mismatch = 0;              ///< max_i |P^k(x)_i − x_i| / h_i
    double periodOneMismatch = 0;     ///< the same for P alone (period 2: large)
    int iterations = 0, mapEvaluations = 0;
    OrbitMethod method = OrbitMethod::Newton;
    /// Of P^period at the orbit, by decreasing modulus. Iteration: empty; maxMultiplier is
    /// then the contraction per period of the last iterates' mismatch (the dominant |μ|) and
    /// the real multipliers are NaN.
    Eigen::VectorXcd multipliers;
    Eigen::MatrixXd monodromy;        ///< ∂(P^period)/∂x at the orbit (converged only)
    double maxMultiplier = 0;         ///< |μ|max
    double largestRealMultiplier = 0; ///< the largest real part of a real multiplier (fold: → +1)
    double smallestRealMultiplier = 0;///< the smallest real multiplier (period doubling: → −1)
    bool stable = false;              ///< |μ|max ≤ OrbitSettings::stabilityMargin
    std::string failure;              ///< why it did not converge
    // Over one orbit period (period × T) from y, the model's own run:
    ScenarioRun run;                  ///< its history and summary (20 Hz filtered maxima)
    double rollAmplitudeDeg = 0;      ///< (max − min) / 2 of car-body roll
    double wheelLiftFraction = 0;     ///< share of the samples with any wheel lifted
    double wallTimeS = 0;             ///< the shooting's wall time
};

class PeriodicOrbitSolver {
public:
    /// base: the scenario (its model, car, track; its speed is replaced by solve's);
    /// startDistance: s₀ [m], on the periodic track. ScenarioError when the track
    /// does not repeat (a measured table without `repeat`, a rectified sine of
    /// limited rails) or the model's state cannot be shot.
    PeriodicOrbitSolver(Scenario base, double startDistance, OrbitSettings settings = {});

    /// The length after which the track repeats [m]; ScenarioError when it does not.
    static double calcTrackPeriod(const Scenario& sc);
    double getForcingPeriod(double speedMph) const;  ///< T = L / V [s]
    double getStartDistance() const { return startDistance_; }
    const Scenario& getScenario() const { return base_; }
    const OrbitSettings& getSettings() const { return settings_; }

    /// Shoots from the model's flat state `guess` at speedMph. startMonodromy: a neighbouring
    /// period-1 orbit's ∂P/∂x, to start a chord Newton on P with (PeriodicShooting.h; empty: none).
    /// maxNewtonSteps > 0 replaces settings.shooting.maxIterations for this orbit.
    PeriodicOrbit solve(double speedMph, const std::vector<double>& guess, const Eigen::MatrixXd& startMonodromy = {},
                        int maxNewtonSteps = 0) const;
    /// The model's run over `periods` forcing periods from y at s₀ (NumericalFailure
    /// when it fails, or a run limit stops it).
    ScenarioRun runPeriods(double speedMph, const std::vector<double>& y, int periods) const;

    std::vector<double> toFull(const Eigen::VectorXd& x, const std::vector<double>& like) const;
    Eigen::VectorXd toShooting(const std::vector<double>& y) const;
    const Eigen::VectorXd& getSteps() const { return steps_; }
    /// Indices of the flat state's discrete modes (StateKind::Discrete): never interpolated.
    const std::vector<int>& getDiscreteIndices() const { return discrete_; }

private:
    Scenario makeScenario(double speedMph, int periods) const;
    PeriodicOrbit iterate(double speedMph, const std::vector<double>& guess,
                          std::chrono::steady_clock::time_point wall0) const;
    /// The converged orbit's run over its period: summary, roll amplitude, wheel-lift fraction.
    void describe(PeriodicOrbit& o) const;
    Scenario base_;
    double startDistance_ = 0, trackPeriod_ = 0;
    OrbitSettings settings_;
    std::vector<int> shot_;            ///< indices of y in x
    std::vector<int> discrete_;        ///< indices of y's discrete modes (StateKind::Discrete)
    size_t stateSize_ = 0;
    Eigen::VectorXd steps_, scales_;
    std::vector<double> staticReference_;  ///< the static state's history row (static loads of the summary)
};

}  // namespace rockroll
