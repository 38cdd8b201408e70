#include "mbmodel/PeriodicShooting.h"

#include "mbmodel/Parallel.h"

#include <algorithm>
#include <cstdlib>
#include <exception>
#include <fmt/format.h>
#include <limits>
#include <stdexcept>
#include <vector>

namespace rockroll {

PeriodicShooting::PeriodicShooting(Map map, Eigen::VectorXd steps, ShootingSettings settings, Eigen::VectorXd scales)
    : map_(std::move(map)), steps_(std::move(steps)), scales_(std::move(scales)), settings_(settings) {
    if (steps_.size() == 0 || (steps_.array() <= 0).any())
        throw std::invalid_argument("shooting: expected a positive perturbation step for every coordinate");
    if (scales_.size() == 0) scales_ = steps_;
    if (scales_.size() != steps_.size() || (scales_.array() <= 0).any())
        throw std::invalid_argument("shooting: expected a positive mismatch scale for every coordinate");
}

double PeriodicShooting::calcMismatch(const Eigen::VectorXd& x, const Eigen::VectorXd& mapped) const {
    return (mapped - x).cwiseQuotient(scales_).cwiseAbs().maxCoeff();
}

Eigen::MatrixXd PeriodicShooting::calcMonodromy(const Eigen::VectorXd& x, const Eigen::VectorXd& mapped) const {
    const Eigen::Index n = x.size();
    Eigen::MatrixXd M(n, n);
    parallelFor(size_t(n), settings_.threads, [&](size_t i) {
        Eigen::VectorXd xp = x;
        xp[Eigen::Index(i)] += steps_[Eigen::Index(i)];
        M.col(Eigen::Index(i)) = (map_(xp) - mapped) / steps_[Eigen::Index(i)];
    });
    return M;
}

Eigen::VectorXcd PeriodicShooting::calcMultipliers(const Eigen::MatrixXd& monodromy) {
    const Eigen::VectorXcd mu = monodromy.eigenvalues();
    std::vector<std::complex<double>> v(mu.data(), mu.data() + mu.size());
    std::sort(v.begin(), v.end(), [](const std::complex<double>& a, const std::complex<double>& b) {
        if (std::abs(a) != std::abs(b)) return std::abs(a) > std::abs(b);
        if (a.real() != b.real()) return a.real() > b.real();
        return a.imag() > b.imag();
    });
    return Eigen::Map<const Eigen::VectorXcd>(v.data(), Eigen::Index(v.size()));
}

ShootingResult PeriodicShooting::solve(const Eigen::VectorXd& guess, const Eigen::MatrixXd& initialMonodromy) const {
    const Eigen::Index n = guess.size();
    if (n != steps_.size())
        throw std::invalid_argument(fmt::format("shooting: guess has {} coordinates; expected {}", n, steps_.size()));
    const bool chord = initialMonodromy.size() != 0;
    if (chord && (initialMonodromy.rows() != n || initialMonodromy.cols() != n))
        throw std::invalid_argument(fmt::format("shooting: a {}x{} monodromy to start from; expected {}x{}",
                                                initialMonodromy.rows(), initialMonodromy.cols(), n, n));
    ShootingResult out;
    out.x = guess;
    try {
        out.mapped = map_(out.x);
        ++out.mapEvaluations;
        if (chord) {
            out.monodromy = initialMonodromy;
        } else {
            out.monodromy = calcMonodromy(out.x, out.mapped);
            out.mapEvaluations += int(n);
        }
    } catch (const std::exception& e) {
        out.failure = fmt::format("the map failed at the start: {}", e.what());
        out.mismatch = std::numeric_limits<double>::infinity();
        return out;
    }
    bool stale = chord;  ///< out.monodromy is not M at out.x
    auto refresh = [&]() {
        out.monodromy = calcMonodromy(out.x, out.mapped);
        out.mapEvaluations += int(n);
        stale = false;
    };
    const Eigen::MatrixXd I = Eigen::MatrixXd::Identity(n, n);
    int stalled = 0;
    for (;;) {
        out.mismatch = calcMismatch(out.x, out.mapped);
        if (std::getenv("ROCKROLL_SHOOTING_TRACE")) {
            Eigen::Index worst = 0;
            (out.mapped - out.x).cwiseQuotient(scales_).cwiseAbs().maxCoeff(&worst);
            fmt::print(stderr, "shooting: step {} mismatch {:.4g} (coordinate {}), |mu|max {:.4g}\n", out.iterations,
                       out.mismatch, worst, std::abs(calcMultipliers(out.monodromy)[0]));
        }
        if (out.mismatch < settings_.tolerance) {
            if (stale) {
                try {
                    refresh();  // the orbit's own multipliers
                } catch (const std::exception& e) {
                    out.failure = fmt::format("the map failed in the monodromy at the orbit: {}", e.what());
                    break;
                }
            }
            out.converged = true;
            break;
        }
        if (out.iterations - out.chordSteps >= settings_.maxIterations) {
            out.failure = fmt::format("no convergence in {} Newton steps (mismatch {:.3g} perturbation steps)",
                                      settings_.maxIterations, out.mismatch);
            break;
        }
        Eigen::VectorXd delta = (out.monodromy - I).completeOrthogonalDecomposition().solve(out.x - out.mapped);
        const double size = delta.cwiseQuotient(steps_).cwiseAbs().maxCoeff();
        if (size > settings_.maxStep) delta *= settings_.maxStep / size;
        if (stale) {
            // Chord step: the full step only. Kept while it contracts fast enough; otherwise a fresh M
            // at the better of the two iterates, and the search goes on with full Newton steps.
            const Eigen::VectorXd trial = out.x + delta;
            try {
                Eigen::VectorXd trialMapped = map_(trial);
                ++out.mapEvaluations;
                const double m = calcMismatch(trial, trialMapped);
                if (m < out.mismatch) {
                    out.x = trial;
                    out.mapped = std::move(trialMapped);
                    ++out.iterations;
                    ++out.chordSteps;
                    if (m <= settings_.chordContraction * out.mismatch) continue;
                }
            } catch (const std::exception&) {
                // the fresh M below decides
            }
            try {
                refresh();
            } catch (const std::exception& e) {
                out.failure = fmt::format("the map failed in the monodromy after Newton step {}: {}", out.iterations,
                                          e.what());
                break;
            }
            continue;
        }
        // Backtracking: the full step first, then halved while the mismatch does not fall; when no
        // try falls, the try with the smallest mismatch, unless it grew past 10× the current one.
        Eigen::VectorXd next, nextMapped;
        double nextMismatch = std::numeric_limits<double>::infinity();
        std::string mapFailure;
        double fraction = 1;
        for (int h = 0; h <= settings_.lineSearchHalvings; ++h, fraction *= 0.5) {
            const Eigen::VectorXd trial = out.x + fraction * delta;
            Eigen::VectorXd trialMapped;
            try {
                trialMapped = map_(trial);
                ++out.mapEvaluations;
            } catch (const std::exception& e) {
                mapFailure = e.what();
                continue;
            }
            const double m = calcMismatch(trial, trialMapped);
            if (m < nextMismatch) {
                next = trial;
                nextMapped = std::move(trialMapped);
                nextMismatch = m;
            }
            if (nextMismatch < out.mismatch) break;
        }
        if (next.size() == 0) {
            out.failure = fmt::format("the map failed after Newton step {}: {}", out.iterations + 1, mapFailure);
            break;
        }
        if (!(nextMismatch <= 10 * out.mismatch)) {
            out.failure = fmt::format("Newton step {} made the mismatch grow from {:.3g} to {:.3g} perturbation steps",
                                      out.iterations + 1, out.mismatch, nextMismatch);
            break;
        }
        // Stalled: no try lowered the mismatch twice running (a non-smooth map whose Newton
        // direction is no descent direction; more steps only cost monodromies).
        stalled = nextMismatch >= out.mismatch ? stalled + 1 : 0;
        if (stalled >= 2) {
            out.failure = fmt::format("Newton stalled at step {}: no step lowered the mismatch ({:.3g} perturbation "
                                      "steps) twice running",
                                      out.iterations + 1, out.mismatch);
            break;
        }
        out.x = next;
        out.mapped = nextMapped;
        ++out.iterations;
        try {
            out.monodromy = calcMonodromy(out.x, out.mapped);
            out.mapEvaluations += int(n);
        } catch (const std::exception& e) {
            out.failure = fmt::format("the map failed in the monodromy after Newton step {}: {}", out.iterations,
                                      e.what());
            break;
        }
    }
    out.multipliers = calcMultipliers(out.monodromy);
    return out;
}

}  // namespace rockroll
