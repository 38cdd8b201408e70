#pragma once
// Shooting for a fixed point of a map (no model, no Simbody): the scheme of the
// describing function's twin Floquet check (bespoke/DescribingFunction.cpp,
// calcTwinFloquet) for any map P over the shooting coordinates x.
//
// Newton on F(x) = P(x) − x = 0, with the monodromy matrix by forward differences
//
//     M = ∂P/∂x,   M_·i ≈ (P(x + h_i·e_i) − P(x)) / h_i,
//
// its columns independent maps evaluated on the program's pool (mbmodel/Parallel.h:
// each column writes its own slot, so the bits do not depend on the thread count).
// The Newton step solves (M − I)·δ = −F in least squares (complete orthogonal
// decomposition): a friction wedge that sticks all period long is neutral (μ = 1,
// M − I singular up to finite-difference noise), so orbits come in a family along
// that direction and the step leaves it where it is. Mismatch: max_i |F_i| / s_i,
// s_i the perturbation steps unless other scales are given; converged below `tolerance`. A step is
// capped at `maxStep` perturbation steps and halved up to `lineSearchHalvings` times
// while the mismatch does not fall (far from the orbit the map is strongly nonlinear:
// contacts open and close); when no try lowers it, the best try is taken unless it
// grew past 10× the current mismatch, which ends the search, as does a map that fails
// on every try, or two Newton steps running that lower nothing. The Floquet multipliers
// are the eigenvalues of M at the last iterate (a sticking wedge contributes one
// μ = 1 with finite-difference noise).
//
// A given monodromy (a neighbouring orbit's, in a continuation) starts a chord
// Newton: its steps reuse that M, one map each instead of n + 1, for as long as each
// full step cuts the mismatch to at most `chordContraction` of what it was. A chord
// step that does not is replaced by a fresh M at the current iterate, and the
// search goes on as above. An orbit found with a reused M gets a fresh M at it, so
// its multipliers are always the orbit's own (PeriodicShooting.ChordNewton*).
#include <Eigen/Dense>
#include <functional>
#include <string>

namespace rockroll {

struct ShootingSettings {
    int maxIterations = 8;   ///< Newton steps with a fresh M (chord steps come on top: each halves the mismatch)
    double tolerance = 5;    ///< converged when max_i |F_i| / h_i is below this
    double maxStep = 1e5;    ///< largest Newton step, in perturbation steps
    int lineSearchHalvings = 4;  ///< halvings of a Newton step whose mismatch does not fall
    int threads = 0;         ///< parallelFor's limit for the monodromy's columns (0: the pool's)
    /// A chord step (reused M) is kept when it cuts the mismatch to at most this fraction.
    double chordContraction = 0.5;
};

struct ShootingResult {
    bool converged = false;
    Eigen::VectorXd x;          ///< the last iterate
    Eigen::VectorXd mapped;     ///< P(x)
    double mismatch = 0;        ///< max_i |P(x)_i − x_i| / h_i
    int iterations = 0;         ///< Newton steps taken (chord steps included)
    int mapEvaluations = 0;
    int chordSteps = 0;         ///< Newton steps taken with a reused M
    Eigen::MatrixXd monodromy;  ///< M at x
    Eigen::VectorXcd multipliers;  ///< eigenvalues of M, by decreasing modulus
    std::string failure;        ///< why it did not converge (empty when it did)
};

class PeriodicShooting {
public:
    /// The map P; it may throw (a failed integration), which ends the search.
    using Map = std::function<Eigen::VectorXd(const Eigen::VectorXd&)>;

    /// steps: h_i > 0, one per coordinate; scales: s_i > 0 the mismatch is measured in,
    /// max_i |F_i| / s_i (empty: the steps).
    PeriodicShooting(Map map, Eigen::VectorXd steps, ShootingSettings settings = {}, Eigen::VectorXd scales = {});

    /// initialMonodromy: M to start a chord Newton with (n × n; empty: a fresh M at the guess).
    ShootingResult solve(const Eigen::VectorXd& guess, const Eigen::MatrixXd& initialMonodromy = {}) const;
    /// M at x, given P(x).
    Eigen::MatrixXd calcMonodromy(const Eigen::VectorXd& x, const Eigen::VectorXd& mapped) const;
    double calcMismatch(const Eigen::VectorXd& x, const Eigen::VectorXd& mapped) const;
    /// Eigenvalues of M, sorted by decreasing modulus (ties: by real part, then imaginary).
    static Eigen::VectorXcd calcMultipliers(const Eigen::MatrixXd& monodromy);
    const Eigen::VectorXd& getSteps() const { return steps_; }

private:
    Map map_;
    Eigen::VectorXd steps_, scales_;
    ShootingSettings settings_;
};

}  // namespace rockroll
