#pragma once
// Describing function (harmonic balance) steady state of the half car, report §4.
//
// Model: the equation-of-motion half car with every §4.1 simplification
// (EomSimplifications::describingFunctionTwin(): linear springs, bolster locked
// laterally to the side frames, elastic contacts, equal lateral shares, small
// angles), so its time-domain twin is EomHalfCarModel with the same flags.
// Input: a sinusoidal cross-level c(τ) = C·sin τ, τ = ωt, ω = 2πV/L_r, rails at
// ∓c/2; C is the fundamental harmonic of the actual cross-level,
//     C = (8A/3π)·cos(π·wheelbase/L_r)      (report §2.2 eqs 1–2 and 6–7: the rectified
// sine's fundamental, averaged over the wheelbase; the equivalent sinusoid of report §4).
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
#include <complex>
#include <limits>
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
/// "stable" | "unstable" | "not computed" (JSON and prose).
const char* describeStability(Stability s);

/// A force's mean and the amplitudes of its first two harmonics [lb]: what harmonic
/// balance determines (report eq. 23), exact for the two-harmonic motion
/// (HarmonicForce.h). Never a peak.
struct ForceHarmonics {
    double meanLb = 0;
    double firstLb = 0;   ///< |H₁| = √(a₁² + b₁²)
    double secondLb = 0;  ///< |H₂|
};

/// The time-domain twin started on a harmonic solution and run `periods` forcing
/// periods: the 20 Hz filtered maxima over its last period (summarizeRun's steady
/// part with one cycle), the way the other models' steady maxima are taken. These,
/// not the two-harmonic series, are the describing function's peak forces.
struct TwinMaxima {
    bool computed = false;          ///< false: not run (periods 0) or the twin's integration failed
    int periods = 0;
    double rollAmplitudeDeg = 0;    ///< half peak-to-peak over the last period
    double persistence = 0;         ///< rollAmplitudeDeg / the harmonic solution's
    double maxRollDeg = 0;
    double maxTruckSideWheelLoadLb = 0;
    double maxSideBearingLoadLb = 0;
    double maxCenterPlateLoadLb = 0;
    /// Its last period solved back onto the solution set (checkTwinPersistence over the
    /// same periods): "this solution" | "another solution" | "no solution" | "twin failed".
    std::string landedOn;
    /// The twin stayed on the solution: its last period solves back onto it, or, when it
    /// solves onto none, |persistence − 1| ≤ kPersistenceTolerance.
    bool stayed() const;
};

/// Relative roll-amplitude change within which the twin counts as staying on a
/// harmonic solution (the describing function itself is ~10 % off the twin's orbit
/// near resonance: docs/bespoke.md, "Stability").
inline constexpr double kPersistenceTolerance = 0.15;

/// What the twin did when started on a solution (DescribingFunctionModel::checkTwinPersistence).
struct TwinPersistence {
    double ratio = std::numeric_limits<double>::quiet_NaN();  ///< its last period's two-harmonic roll amplitude / the solution's
    std::string landedOn;  ///< "this solution" | "another solution" | "no solution"
    double landedRollDeg = std::numeric_limits<double>::quiet_NaN();  ///< the solution it solved onto
    bool stayed = false;
};

struct SteadyStatePoint {
    double speedMph = 0;
    double rollAmplitudeDeg = 0;      ///< half peak-to-peak of car-body roll (two-harmonic series)
    double rollMeanDeg = 0, rollFirstDeg = 0, rollSecondDeg = 0;  ///< roll's mean, |1st|, |2nd| harmonic
    /// Fraction of the period in which a wheel's two-harmonic displacement is off its
    /// rail (a property of the motion, not of a force peak).
    double wheelLiftFraction = 0;
    ForceHarmonics wheelLoad;         ///< one truck side's two wheels; the side with the larger |1st|
    ForceHarmonics sideBearingLoad;   ///< the side with the larger |1st|
    ForceHarmonics centerPlateLoad;   ///< both rim contacts together
    TwinMaxima twin;                  ///< peak values, from the twin's time history
    std::complex<double> dominantMultiplier{std::numeric_limits<double>::quiet_NaN(), 0.0};
    double maxFloquetMultiplier = 0;  ///< |μ|max on the twin's orbit; < 1 is stable (NaN when not computed)
    bool floquetConverged = false;    ///< the shooting found the twin's periodic orbit
    double twinPersistence = 0;       ///< twin's roll amplitude after the persistence run / this point's (NaN if not run)
    std::string twinLandedOn;         ///< where the persistence run's last period solved onto (TwinPersistence)
    /// floquet+persistence | persistence | floquet (persistence inconclusive) |
    /// floquet, persistence disagree | none | interpolated
    std::string stabilityEvidence = "none";
    bool checked = false;             ///< this point's own stability was checked (not taken from a neighbour)
    int foldsBefore = 0;              ///< folds passed along the path before this point
    int path = 0;                     ///< the continuation path (SteadyStatePath) it lies on
    Stability stability = Stability::NotComputed;
    Eigen::VectorXd harmonics;        ///< scaled unknowns (mm, mrad)
};

/// Where stability changes along a path between two checked points without a fold
/// between them, and what the multipliers say it is.
struct StabilityChange {
    int path = 0;
    double fromMph = 0, toMph = 0;  ///< the two checked points it lies between
    std::string kind;               ///< "real multiplier through +1" | "period doubling (-1)" | "complex pair" | "not classified"
};

/// One continuation: a connected piece of the solution set, with how it was found.
struct SteadyStatePath {
    std::string start;              ///< e.g. "rest at 10 mph", "twin down sweep at 18 mph"
    double startMph = 0;
    bool closed = false;            ///< the path came back to its start (an isola)
    std::vector<SteadyStatePoint> points;
};

struct SteadyStateBranch {
    Stability stability = Stability::NotComputed;
    int path = 0;                   ///< the path it is a stretch of
    std::vector<SteadyStatePoint> points;
};

/// How each point's stability is decided (docs/bespoke.md, "Stability"):
///   FoldRule: each stretch of a path between folds is checked near both ends and in
///             the middle (Floquet on the twin's orbit and a persistence run of the twin);
///             where checks disagree the stretch is bisected, and each point takes the
///             label of its nearest check;
///   Floquet:  every point checked (slow);
///   None:     not decided (every point Stability::NotComputed, multipliers NaN).
/// A check whose Floquet and persistence evidence disagree labels nothing
/// (Stability::NotComputed): a label always agrees with its persistence run.
enum class StabilityMethod { FoldRule, Floquet, None };

struct TwinFloquet {
    bool converged = false;    ///< shooting reached a periodic orbit of the twin
    double mismatch = 0;       ///< |φ_T(y) − y| in units of the perturbation steps
    double maxMultiplier = 0;  ///< |μ|max of the monodromy matrix there
    std::complex<double> dominant{0, 0};  ///< the multiplier of largest modulus
    double rollAmplitudeDeg = 0;
};

struct ContinuationSettings {
    double fromMph = 10, toMph = 22;
    double initialStep = 0.2;  ///< arclength in (mph, mm, mrad) units
    double minStep = 1e-3, maxStep = 1.0;
    int maxPoints = 600;       ///< per path
    StabilityMethod stability = StabilityMethod::FoldRule;
    int persistencePeriods = 20;  ///< the persistence run of a stability check
    int maxChecksPerStretch = 7;  ///< the fold rule's checks, bisection included
    /// Starts besides the two ends of the range: the twin swept down and up in
    /// speed (each speed `sweepPeriods` forcing periods, the state carried over),
    /// its last period projected onto two harmonics and solved; 0 = no sweep starts.
    double sweepStepMph = 1.0;
    int sweepPeriods = 12;
    int twinPeriods = 5;          ///< the twin maxima's run; 0 = not computed
    /// The twin maxima are run at each path's ends, at each checked point and wherever
    /// the speed has moved this far (or the roll amplitude 5 %) from the last one run.
    double twinSpacingMph = 0.25;
};

/// One speed of the twin's own sweeps (ContinuationSettings::sweepStepMph) and what
/// harmonic balance made of it.
struct TwinSweepStart {
    double speedMph = 0;
    std::string direction;            ///< "down" | "up"
    double twinRollAmplitudeDeg = 0;  ///< the twin's last period, its first two harmonics
    bool solved = false;              ///< Powell converged from it
    double solvedRollAmplitudeDeg = 0;
    bool newPath = false;             ///< it started a path of its own
};

/// Everything trace() finds.
struct SteadyStateSet {
    std::vector<SteadyStatePath> paths;
    std::vector<SteadyStateBranch> branches;  ///< the paths cut where stability changes
    std::vector<StabilityChange> changes;
    std::vector<TwinSweepStart> sweepStarts;  ///< every speed tried; newPath marks those that started a path
};

class DescribingFunctionModel {
public:
    static constexpr int kHarmonics = 2;
    static constexpr int kCoefficients = 2 * kHarmonics + 1;
    static constexpr int kNumUnknowns = EomHalfCarModel::kNumDofs * kCoefficients;

    /// crossLevelAmplitude: C [m]; railLength: L_r [m].
    DescribingFunctionModel(const CarParameters& car, double crossLevelAmplitude, double railLength);
    static double calcFundamentalCrossLevel(double amplitude, double wheelbase, double railLength);

    double calcOmega(double speedMph) const;
    /// Scaled harmonic-balance residual (forces in 10 kN, moments in 10 kN·m).
    Eigen::VectorXd calcResidual(const Eigen::VectorXd& x, double speedMph) const;
    /// ∂R/∂x (45 columns) and, with speedColumn, ∂R/∂V [per mph], exact: each element's
    /// harmonics differentiated in closed form (calcForceHarmonicsDerivatives), chained
    /// through its displacement and weights to the unknowns (test
    /// DescribingFunction.ExactJacobianMatchesCentralDifferences).
    Eigen::MatrixXd calcResidualJacobian(const Eigen::VectorXd& x, double speedMph, bool speedColumn) const;
    /// Static equilibrium, no harmonics.
    Eigen::VectorXd makeStaticGuess() const;
    /// Powell's hybrid method at fixed speed; nullopt when it does not converge.
    std::optional<Eigen::VectorXd> solve(double speedMph, const Eigen::VectorXd& guess) const;
    /// solve() from the static state, through a homotopy in wedge friction.
    std::optional<Eigen::VectorXd> solveFromRest(double speedMph) const;
    /// The solution set over [fromMph, toMph]: pseudo-arclength continuation from the
    /// solutions at both ends of the range and from the twin's swept steady states,
    /// each new one a path of its own; then stability and the twin maxima.
    SteadyStateSet trace(const ContinuationSettings& settings) const;

    /// The harmonics, force harmonics and the two-harmonic roll amplitude of a solution.
    SteadyStatePoint describe(const Eigen::VectorXd& x, double speedMph) const;
    /// The twin run `periods` periods from the solution (TwinMaxima).
    TwinMaxima calcTwinMaxima(const Eigen::VectorXd& x, double speedMph, int periods) const;
    /// The twin's state over its last period projected on the ansatz (a guess for solve()).
    Eigen::VectorXd projectTwinState(const EomHalfCarModel::State& y, double speedMph, int periods,
                                     EomHalfCarModel::State* end = nullptr) const;
    /// Floquet multipliers of the time-domain twin: shooting (Newton on the
    /// one-period flow map, finite-difference monodromy) from the harmonic
    /// solution's state to the twin's periodic orbit, then |μ|max there.
    TwinFloquet calcTwinFloquet(const Eigen::VectorXd& x, double speedMph) const;
    /// The twin started on the harmonic solution: its roll amplitude over the
    /// last of `periods` periods divided by the harmonic solution's.
    double calcTwinPersistence(const Eigen::VectorXd& x, double speedMph, int periods) const;
    /// The persistence check: the twin run `periods` periods from the solution, its last
    /// period projected on two harmonics and solved. It stayed when that solves back onto
    /// the solution it started from (so the describing function's truncation error, the
    /// gap between the solution and the twin's own orbit, is not read as leaving); it left
    /// when it solves onto another solution; when it solves onto none, the check says
    /// neither (landedOn "no solution", stayed false).
    TwinPersistence checkTwinPersistence(const Eigen::VectorXd& x, double speedMph, int periods) const;
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
    Eigen::VectorXd assembleResidual(const std::vector<TrigSeries>& q,
                                     const std::vector<std::vector<TrigSeries>>& harmonics, double omega) const;

    CarParameters car_;
    double inputAmplitude_ = 0, railLength_ = 0;
    EomHalfCarModel reference_;  // geometry, laws, masses and static state of the twin
    std::vector<Element> elements_;
};

}  // namespace rockroll
