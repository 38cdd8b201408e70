#pragma once
// Describing function (harmonic balance) steady state of the half car, report §4.
//
// Model: the equation-of-motion half car with every §4.1 simplification
// (EomSimplifications::describingFunctionTwin(): linear springs, bolster locked
// laterally to the side frames, elastic contacts, equal lateral shares, small
// angles), so its time-domain twin is EomHalfCarModel with the same flags.
// Input: a sinusoidal cross-level c(τ) = C·sin τ, τ = ωt, ω = 2πV/L_r, rails at
// ∓c/2; C is the fundamental harmonic of the actual cross-level,
//     C = (8A/3π)·cos(π·wheelbase/L_r)      (brief §5).
// Ansatz: every position q_j(τ) = q_j0 + a_j1 cos τ + b_j1 sin τ + a_j2 cos 2τ + b_j2 sin 2τ.
// Balance, per degree of freedom j and harmonic (report eq. 23):
//     mean:  0 = Q_j0,     k = 1, 2:  −(kω)²·M_j·(a_jk, b_jk) = (Q_j,cos k, Q_j,sin k),
// where Q_j are the Fourier coefficients of the generalized forces, exact from
// the zero crossings (HarmonicForce.h). 9 positions × 5 coefficients = 45
// equations, solved by Powell's hybrid method (Eigen's HybridNonLinearSolver)
// and continued in speed by pseudo-arclength continuation. Stability: Floquet
// multipliers of the time-domain twin on its periodic orbit near the harmonic
// solution, at the first point or at every point (docs/bespoke.md).
#include "bespoke/EomHalfCarModel.h"
#include "bespoke/HarmonicForce.h"

#include <Eigen/Dense>
#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace rockroll {

/// A steady-state solution's stability. NotComputed when nothing decided it
/// (`--stability none`, or no evidence from the time-domain twin): never read
/// it as stable.
enum class Stability { Stable, Unstable, NotComputed };
/// "yes" | "no" | "not computed" (CSV cells and text tables).
const char* toString(Stability s);

struct SteadyStatePoint {
    double speedMph = 0;
    double rollAmplitudeDeg = 0;      ///< half peak-to-peak of car-body roll
    double wheelLiftFraction = 0;     ///< fraction of the period with a wheel off its rail
    double maxWheelLoadLb = 0;        ///< equivalent wheelset wheel = two wheels, one truck side
    double maxSideBearingLoadLb = 0;
    double minCenterPlateLoadLb = 0;
    double maxFloquetMultiplier = 0;  ///< |μ|max on the twin's orbit; < 1 is stable (NaN when not computed)
    bool floquetConverged = false;    ///< the shooting found the twin's periodic orbit
    double twinPersistence = 0;       ///< twin's roll amplitude after 10 periods / this point's (NaN if not run)
    std::string stabilityEvidence = "none";  ///< floquet | persistence | none (fold rule)
    int foldsBefore = 0;              ///< folds passed along the path before this point
    Stability stability = Stability::NotComputed;
    Eigen::VectorXd harmonics;        ///< scaled unknowns (mm, mrad)
};

struct SteadyStateBranch {
    Stability stability = Stability::NotComputed;
    std::vector<SteadyStatePoint> points;
};

/// How each point's stability is decided (docs/bespoke.md):
///   FoldRule: the path is cut at its folds; each stretch is marked by Floquet on the twin
///             at its middle point (flipping from the stretch before where shooting fails);
///   Floquet:  every point by Floquet on the twin (slow: a shooting per point);
///   None:     not decided (every point Stability::NotComputed, multipliers NaN).
/// A point whose evidence fails (no twin orbit, twin integration fails) is
/// NotComputed too, and so is a FoldRule stretch without evidence that has no
/// decided stretch before it to flip from.
enum class StabilityMethod { FoldRule, Floquet, None };

struct TwinFloquet {
    bool converged = false;    ///< shooting reached a periodic orbit of the twin
    double mismatch = 0;       ///< |φ_T(y) − y| in units of the perturbation steps
    double maxMultiplier = 0;  ///< |μ|max of the monodromy matrix there
    double rollAmplitudeDeg = 0;
};

struct ContinuationSettings {
    double fromMph = 10, toMph = 22;
    double initialStep = 0.2;  ///< arclength in (mph, mm, mrad) units
    double minStep = 1e-3, maxStep = 1.0;
    int maxPoints = 600;
    StabilityMethod stability = StabilityMethod::FoldRule;
};

class DescribingFunctionModel {
public:
    static constexpr int kHarmonics = 2;
    static constexpr int kCoefficients = 2 * kHarmonics + 1;
    static constexpr int kNumUnknowns = EomHalfCarModel::kNumDofs * kCoefficients;

    /// crossLevelAmplitude: C [m]; railLength: L_r [m].
    DescribingFunctionModel(const CarParameters& car, double crossLevelAmplitude, double railLength);
    static double calcFundamentalCrossLevel(double amplitude, double wheelbase, double railLength);

    double getInputAmplitude() const { return inputAmplitude_; }
    double calcOmega(double speedMph) const;
    /// Scaled harmonic-balance residual (forces in 10 kN, moments in 10 kN·m).
    Eigen::VectorXd calcResidual(const Eigen::VectorXd& x, double speedMph) const;
    /// ∂R/∂x (45 columns) and, with speedColumn, ∂R/∂V [per mph]: the forward differences
    /// of calcResidual with the step 1e-6·max(1, |u_i|), each column re-evaluating only
    /// the elements its unknown moves (bit-identical to differencing calcResidual).
    Eigen::MatrixXd calcResidualJacobian(const Eigen::VectorXd& x, double speedMph, bool speedColumn) const;
    /// Static equilibrium, no harmonics.
    Eigen::VectorXd makeStaticGuess() const;
    /// Powell's hybrid method at fixed speed; nullopt when it does not converge.
    std::optional<Eigen::VectorXd> solve(double speedMph, const Eigen::VectorXd& guess) const;
    /// solve() from the static state, through a homotopy in wedge friction.
    std::optional<Eigen::VectorXd> solveFromRest(double speedMph) const;
    /// Pseudo-arclength continuation from the solution at settings.fromMph.
    std::vector<SteadyStateBranch> trace(const ContinuationSettings& settings) const;

    SteadyStatePoint describe(const Eigen::VectorXd& x, double speedMph) const;
    /// Floquet multipliers of the time-domain twin: shooting (Newton on the
    /// one-period flow map, finite-difference monodromy) from the harmonic
    /// solution's state to the twin's periodic orbit, then |μ|max there.
    TwinFloquet calcTwinFloquet(const Eigen::VectorXd& x, double speedMph) const;
    /// The twin started on the harmonic solution: its roll amplitude over the
    /// last of `periods` periods divided by the harmonic solution's.
    double calcTwinPersistence(const Eigen::VectorXd& x, double speedMph, int periods) const;
    /// The twin's state at τ = 0 reconstructed from the harmonics.
    EomHalfCarModel::State makeTwinState(const Eigen::VectorXd& x, double speedMph) const;
    EomHalfCarModel makeTwin(double speedMph) const;
    /// q_j(τ) of every degree of freedom [m, rad].
    std::vector<TrigSeries> getPositions(const Eigen::VectorXd& x) const;

private:
    struct Element {
        int axis = 2;           ///< 1 = lateral (y), 2 = vertical (z)
        int bodyA = 0;          ///< force +f on A at pA
        Eigen::Vector2d pA;
        int bodyB = -1;         ///< −f on B at pB; −1 = the rail
        Eigen::Vector2d pB;
        int railSide = -1;      ///< when B is the rail: 0 left, 1 right
        std::variant<PiecewiseLinearLaw, CoulombLaw, ElastoPlasticLaw> law;
        std::string name;
    };
    void buildElements();
    TrigSeries calcStationSeries(const std::vector<TrigSeries>& q, int body, const Eigen::Vector2d& p, int axis) const;
    TrigSeries calcRailSeries(int side, int axis) const;
    TrigSeries calcRelative(const std::vector<TrigSeries>& q, const Element& e) const;
    /// Fourier coefficients of the element's force, weighted by 1, θ_A and θ_B.
    std::vector<TrigSeries> calcElementHarmonics(const std::vector<TrigSeries>& q, const Element& e, double omega) const;
    /// Whether unknown i (of the 45) enters the element's displacement or weights.
    static bool movesElement(int unknown, const Element& e);
    Eigen::VectorXd assembleResidual(const std::vector<TrigSeries>& q,
                                     const std::vector<std::vector<TrigSeries>>& harmonics, double omega) const;

    CarParameters car_;
    double inputAmplitude_ = 0, railLength_ = 0;
    EomHalfCarModel reference_;  // geometry, laws, masses and static state of the twin
    std::vector<Element> elements_;
};

}  // namespace rockroll
