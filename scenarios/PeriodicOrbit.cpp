#include "scenarios/PeriodicOrbit.h"

#include "mbmodel/TrackInput.h"
#include "mbmodel/Units.h"
#include "scenarios/ModelRegistry.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fmt/format.h>
#include <limits>

namespace rockroll {

double PeriodicOrbitSolver::calcTrackPeriod(const Scenario& sc) {
    const TrackSpec& t = sc.track;
    if (!t.measured.empty()) {
        if (!t.repeat)
            throw ScenarioError(fmt::format("{}: the measured track does not repeat (no 'repeat = true' in [track]): a "
                                            "periodic orbit needs a periodic track",
                                            sc.source));
        return t.measured.back().distance - t.measured.front().distance;
    }
    if (t.rails != 0)
        throw ScenarioError(fmt::format("{}: key 'track.rails' = {}: the perturbation ends after {} rail lengths; a "
                                        "periodic orbit needs rails = 0 (no end)",
                                        sc.source, t.rails, t.rails));
    if (!(t.amplitude > 0))
        throw ScenarioError(fmt::format("{}: key 'track.amplitude' = 0: level track has no forcing period", sc.source));
    return t.railLength;
}

PeriodicOrbitSolver::PeriodicOrbitSolver(Scenario base, double startDistance, OrbitSettings settings)
    : base_(std::move(base)), startDistance_(startDistance), settings_(settings) {
    trackPeriod_ = calcTrackPeriod(base_);
    checkSwitchesApply(base_);
    if (!(settings_.stepScale > 0))
        throw std::invalid_argument("periodic orbit: the finite-difference step scale must be positive");
    const ModelDescriptor& d = ModelRegistry::get().getModel(base_.model);
    const std::vector<StateKind> kinds = d.make(base_, makeTrackMotion(base_))->getStateKinds();
    if (kinds.empty())
        throw ScenarioError(fmt::format("model \"{}\": its state cannot be shot for a periodic orbit (it holds a "
                                        "discrete truck mode); expected a model with a continuous state",
                                        base_.model));
    stateSize_ = kinds.size();
    std::vector<double> steps, scales;
    for (size_t i = 0; i < kinds.size(); ++i) {
        if (kinds[i] == StateKind::Discrete) discrete_.push_back(int(i));
        if (kinds[i] == StateKind::Accumulating || kinds[i] == StateKind::Discrete) continue;
        shot_.push_back(int(i));
        const double h = kinds[i] == StateKind::Position ? 1e-5 : kinds[i] == StateKind::Rate ? 1e-4 : 1e-7;
        steps.push_back(settings_.stepScale * h);
        scales.push_back(kinds[i] == StateKind::Internal ? 1e-6 : h);
    }
    steps_ = Eigen::Map<const Eigen::VectorXd>(steps.data(), Eigen::Index(steps.size()));
    scales_ = Eigen::Map<const Eigen::VectorXd>(scales.data(), Eigen::Index(scales.size()));
    // The static state's history row, for the summaries' static loads (the orbit's first row is not static).
    Scenario rest = base_;
    rest.run.duration = 0.05;
    if (settings_.accuracy > 0) rest.run.integrator.accuracy = settings_.accuracy;
    staticReference_ = runScenario(rest).staticReference;
}

double PeriodicOrbitSolver::getForcingPeriod(double speedMph) const { return trackPeriod_ / (speedMph * units::mph); }

Scenario PeriodicOrbitSolver::makeScenario(double speedMph, int periods) const {
    Scenario sc = base_;
    sc.speed = speedMph * units::mph;
    const double T = getForcingPeriod(speedMph);
    sc.run.duration = periods * T;
    // A whole number of output samples per period, so the run ends at exactly k·T.
    const double perPeriod = std::max(4.0, std::ceil(T * base_.run.outputRate - 1e-9));
    sc.run.outputRate = perPeriod / T;
    if (settings_.accuracy > 0) sc.run.integrator.accuracy = settings_.accuracy;
    return sc;
}

ScenarioRun PeriodicOrbitSolver::runPeriods(double speedMph, const std::vector<double>& y, int periods) const {
    const Scenario sc = makeScenario(speedMph, periods);
    RunStart start;
    start.from = RestartState{sc.model, y, startDistance_, sc.speed};  // startSpeed = speed: no ramp
    start.staticReference = staticReference_;
    ScenarioRun r = runScenario(sc, start);
    if (r.result.stop)
        throw NumericalFailure(fmt::format("the car {} at t = {:.3f} s: {}", r.result.stop->regime,
                                           r.result.stop->time, r.result.stop->reason),
                               r.result.stop->time);
    if (std::abs(r.result.simTime - sc.run.duration) > 1e-9 * sc.run.duration)
        throw NumericalFailure(fmt::format("the run ended at t = {:.9f} s, not at {:.9f} s", r.result.simTime,
                                           sc.run.duration),
                               r.result.simTime);
    return r;
}

std::vector<double> PeriodicOrbitSolver::toFull(const Eigen::VectorXd& x, const std::vector<double>& like) const {
    std::vector<double> y = like;
    y.resize(stateSize_, 0.0);
    for (size_t k = 0; k < shot_.size(); ++k) y[size_t(shot_[k])] = x[Eigen::Index(k)];
    return y;
}

Eigen::VectorXd PeriodicOrbitSolver::toShooting(const std::vector<double>& y) const {
    if (y.size() != stateSize_)
        throw std::invalid_argument(fmt::format("model \"{}\": a state of {} entries; expected {}", base_.model,
                                                y.size(), stateSize_));
    Eigen::VectorXd x(Eigen::Index(shot_.size()));
    for (size_t k = 0; k < shot_.size(); ++k) x[Eigen::Index(k)] = y[size_t(shot_[k])];
    return x;
}

PeriodicOrbit PeriodicOrbitSolver::solve(double speedMph, const std::vector<double>& guess,
                                         const Eigen::MatrixXd& startMonodromy, int maxNewtonSteps) const {
    ShootingSettings shooting = settings_.shooting;
    if (maxNewtonSteps > 0) shooting.maxIterations = maxNewtonSteps;
    const auto wall0 = std::chrono::steady_clock::now();
    PeriodicOrbit o;
    o.speedMph = speedMph;
    // The entries not shot (discrete modes, accumulating integrals) come from `like`.
    std::vector<double> like = guess;
    auto mapOf = [&](int periods) {
        return [this, speedMph, periods, &like](const Eigen::VectorXd& x) {
            return toShooting(runPeriods(speedMph, toFull(x, like), periods).restart.y);
        };
    };
    const Eigen::VectorXd x0 = toShooting(guess);
    if (settings_.method == OrbitMethod::Iteration) return iterate(speedMph, guess, wall0);
    ShootingResult r = PeriodicShooting(mapOf(1), steps_, shooting, scales_).solve(x0, startMonodromy);
    o.mapEvaluations = r.mapEvaluations;
    int period = 1;
    if (!r.converged && settings_.tryPeriodTwo) {
        ShootingResult r2 = PeriodicShooting(mapOf(2), steps_, shooting, scales_).solve(x0);
        o.mapEvaluations += r2.mapEvaluations;
        if (r2.converged) {
            r = std::move(r2);
            period = 2;
        } else {
            r.failure += fmt::format("; shooting on two periods: {}", r2.failure);
        }
    }
    // A discrete mode is held at the guess's during Newton. An orbit must come back to
    // the mode it started from: when it does not, Newton runs again (chord, from the
    // monodromy just found) with the mode the map reached.
    for (int pass = 0; r.converged && !discrete_.empty(); ++pass) {
        const std::vector<double> end = runPeriods(speedMph, toFull(r.x, like), period).restart.y;
        ++o.mapEvaluations;
        bool same = true;
        for (int i : discrete_) same = same && end[size_t(i)] == like[size_t(i)];
        if (same) break;
        if (pass == 2) {
            r.converged = false;
            r.failure = "the discrete mode a period after the orbit's start differs from the one it started in";
            break;
        }
        for (int i : discrete_) like[size_t(i)] = end[size_t(i)];
        const int evaluations = o.mapEvaluations;
        r = PeriodicShooting(mapOf(period), steps_, shooting, scales_).solve(r.x, r.monodromy);
        o.mapEvaluations = evaluations + r.mapEvaluations;
    }
    o.y = toFull(r.x, like);
    o.mismatch = r.mismatch;
    o.iterations = r.iterations;
    o.multipliers = r.multipliers;
    if (r.converged) o.monodromy = r.monodromy;
    o.failure = r.failure;
    o.converged = r.converged;
    if (o.converged) {
        // P alone: an orbit of P∘P that P also fixes is of period 1.
        if (period == 2) {
            const Eigen::VectorXd once = toShooting(runPeriods(speedMph, o.y, 1).restart.y);
            ++o.mapEvaluations;
            o.periodOneMismatch = (once - r.x).cwiseQuotient(scales_).cwiseAbs().maxCoeff();
            if (o.periodOneMismatch < settings_.shooting.tolerance) period = 1;
        } else {
            o.periodOneMismatch = o.mismatch;
        }
        o.period = period;
        o.maxMultiplier = o.multipliers.size() ? std::abs(o.multipliers[0]) : 0.0;
        o.largestRealMultiplier = -std::numeric_limits<double>::infinity();
        o.smallestRealMultiplier = std::numeric_limits<double>::infinity();
        for (const auto& mu : o.multipliers)
            if (mu.imag() == 0) {
                o.largestRealMultiplier = std::max(o.largestRealMultiplier, mu.real());
                o.smallestRealMultiplier = std::min(o.smallestRealMultiplier, mu.real());
            }
        o.stable = o.maxMultiplier <= settings_.stabilityMargin;
        describe(o);
    }
    o.wallTimeS = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
    return o;
}

PeriodicOrbit PeriodicOrbitSolver::iterate(double speedMph, const std::vector<double>& guess,
                                           std::chrono::steady_clock::time_point wall0) const {
    PeriodicOrbit o;
    o.speedMph = speedMph;
    o.method = OrbitMethod::Iteration;
    const double tol = settings_.shooting.tolerance;
    auto distance = [&](const std::vector<double>& a, const std::vector<double>& b) {
        return (toShooting(a) - toShooting(b)).cwiseQuotient(scales_).cwiseAbs().maxCoeff();
    };
    // ys[k] = P^k(guess); d1[k] = |ys[k+1] − ys[k]|, d2[k] = |ys[k+2] − ys[k]| (in the mismatch scales).
    std::vector<std::vector<double>> ys{guess};
    std::vector<double> d1, d2;
    auto contraction = [](const std::vector<double>& d) {
        const size_t m = std::min<size_t>(5, d.size() - 1);
        if (m == 0 || !(d[d.size() - 1 - m] > 0)) return std::numeric_limits<double>::quiet_NaN();
        return std::pow(d.back() / d[d.size() - 1 - m], 1.0 / double(m));
    };
    std::vector<double> found;
    try {
        for (int k = 0; k < settings_.iterationPeriods && o.period == 0; ++k) {
            ys.push_back(runPeriods(speedMph, ys.back(), 1).restart.y);
            ++o.mapEvaluations;
            const size_t n = ys.size();
            d1.push_back(distance(ys[n - 1], ys[n - 2]));
            // At least three periods, for the contraction estimate.
            if (d1.back() < tol && d1.size() >= 3) {
                o.period = 1, found = ys[n - 2], o.mismatch = o.periodOneMismatch = d1.back();
                o.maxMultiplier = contraction(d1);
            } else if (n >= 3) {
                d2.push_back(distance(ys[n - 1], ys[n - 3]));
                if (d2.back() < tol && d2.size() >= 2) {
                    o.period = 2, found = ys[n - 3], o.mismatch = d2.back();
                    o.periodOneMismatch = d1[d1.size() - 2];
                    o.maxMultiplier = contraction(d2);
                }
            }
            if (ys.size() > 3) ys.erase(ys.begin());
        }
    } catch (const NumericalFailure& e) {
        o.failure = fmt::format("the map failed after {} periods: {}", o.mapEvaluations, e.what());
    }
    o.iterations = o.mapEvaluations;
    if (o.period == 0) {
        o.y = ys.back();
        o.mismatch = d1.empty() ? 0.0 : d1.back();
        if (o.failure.empty())
            o.failure = fmt::format("iteration: P(y) − y still {:.3g} perturbation steps after {} periods "
                                    "(P∘P(y) − y: {:.3g})",
                                    o.mismatch, o.mapEvaluations, d2.empty() ? 0.0 : d2.back());
    } else {
        o.converged = true;
        o.y = found;
        o.largestRealMultiplier = o.smallestRealMultiplier = std::numeric_limits<double>::quiet_NaN();
        o.stable = true;  // iteration only reaches attracting orbits
        describe(o);
    }
    o.wallTimeS = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
    return o;
}

void PeriodicOrbitSolver::describe(PeriodicOrbit& o) const {
    const double speedMph = o.speedMph;
    const int period = o.period;
    {
        // One orbit period from y: the summary's filtered maxima over it (the criteria over all of it).
        o.run = runPeriods(speedMph, o.y, period);
        const Scenario sc = makeScenario(speedMph, period);
        SummaryOptions opt;
        opt.forcingPeriod = getForcingPeriod(speedMph);
        opt.steadyCycles = period;
        opt.filterCutoffHz = sc.filterCutoffHz;
        opt.staticReference = staticReference_;
        opt.severeSeparationTime = sc.severeSeparationTime;
        opt.criteria = resolveCriteriaLimits(sc);
        opt.criteriaFromS = 0;
        RunSummary s = summarizeRun(o.run.result, o.run.channels, opt);
        s.model = o.run.summary.model;
        s.car = o.run.summary.car;
        s.speedMph = o.run.summary.speedMph;
        s.amplitudeIn = o.run.summary.amplitudeIn;
        s.durationS = o.run.summary.durationS;
        o.run.summary = std::move(s);
        const TimeHistory& h = o.run.result.history;
        const ChannelLayout& c = o.run.channels;
        double lo = 1e300, hi = -1e300;
        long lifted = 0;
        for (const auto& row : h.samples) {
            lo = std::min(lo, row[size_t(c.roll + 1)]);
            hi = std::max(hi, row[size_t(c.roll + 1)]);
            bool any = false;
            for (int w : c.wheelLift) any = any || row[size_t(w + 1)] > 0;
            lifted += any ? 1 : 0;
        }
        o.rollAmplitudeDeg = 0.5 * (hi - lo);
        // The first and last samples are the same instant of the orbit: count it once.
        const long n = std::max<long>(1, long(h.samples.size()) - 1);
        if (!h.samples.empty()) {
            bool lastLifted = false;
            for (int w : c.wheelLift) lastLifted = lastLifted || h.samples.back()[size_t(w + 1)] > 0;
            lifted -= lastLifted ? 1 : 0;
        }
        o.wheelLiftFraction = double(lifted) / double(n);
    }
}

}  // namespace rockroll
