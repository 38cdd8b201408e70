#include "bespoke/HarmonicForce.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <optional>

namespace rockroll {

namespace {

int findSegment(const std::vector<double>& breakpoints, double d) {
    return int(std::upper_bound(breakpoints.begin(), breakpoints.end(), d) - breakpoints.begin());
}

int getMaxDegree(const std::vector<TrigSeries>& weights) {
    int n = 0;
    for (const TrigSeries& w : weights) n = std::max(n, w.getDegree());
    return n;
}

/// Adds ∫ Q·{1, cos kτ, sin kτ} over [a0.tau, a1.tau] (normalized) to `out`,
/// Q = g·w_j for each weight (the angles at both ends computed once).
void addPiece(const TrigSeries& g, const TrigSeries::Angles& a0, const TrigSeries::Angles& a1, int harmonics,
              const std::vector<TrigSeries>& weights, std::vector<TrigSeries>& out) {
    for (size_t j = 0; j < weights.size(); ++j) {
        const TrigSeries Q = g * weights[j];
        out[j].updMean() += Q.integrate(a0, a1) / (2 * std::numbers::pi);
        for (int k = 1; k <= harmonics; ++k) {
            out[j].updCos(k) += Q.timesHarmonic(k, false).integrate(a0, a1) / std::numbers::pi;
            out[j].updSin(k) += Q.timesHarmonic(k, true).integrate(a0, a1) / std::numbers::pi;
        }
    }
}

/// Integrates Q_j(τ)·{1, cos kτ, sin kτ} over [0, 2π) split at `cuts`, with
/// Q_j = g(midpoint)·w_j on each piece; `forceDegree` bounds the degree of g.
template <class LawOn>
std::vector<TrigSeries> integratePiecewise(std::vector<double> cuts, int harmonics, const std::vector<TrigSeries>& weights,
                                           int forceDegree, const LawOn& lawOn) {
    cuts.push_back(0);
    cuts.push_back(2 * std::numbers::pi);
    std::sort(cuts.begin(), cuts.end());
    const int degree = std::min(TrigSeries::kMaxDegree, forceDegree + getMaxDegree(weights) + harmonics);
    std::vector<TrigSeries> out(weights.size(), TrigSeries(harmonics));
    TrigSeries::Angles a0(cuts[0], degree);
    for (size_t i = 0; i + 1 < cuts.size(); ++i) {
        const double t0 = cuts[i], t1 = cuts[i + 1];
        if (t1 - t0 <= 0) continue;
        if (a0.tau != t0) a0 = TrigSeries::Angles(t0, degree);
        const TrigSeries::Angles a1(t1, degree);
        addPiece(lawOn(0.5 * (t0 + t1)), a0, a1, harmonics, weights, out);
        a0 = a1;
    }
    return out;
}

std::vector<TrigSeries> integratePieces(const std::vector<ForcePiece>& pieces, int harmonics,
                                        const std::vector<TrigSeries>& weights) {
    std::vector<TrigSeries> out(weights.size(), TrigSeries(harmonics));
    int forceDegree = 0;
    for (const ForcePiece& p : pieces) forceDegree = std::max(forceDegree, p.force.getDegree());
    const int degree = std::min(TrigSeries::kMaxDegree, forceDegree + getMaxDegree(weights) + harmonics);
    std::optional<TrigSeries::Angles> a0;
    for (const ForcePiece& p : pieces) {
        if (p.t1 - p.t0 <= 0) continue;
        if (!a0 || a0->tau != p.t0) a0.emplace(p.t0, degree);
        const TrigSeries::Angles a1(p.t1, degree);
        addPiece(p.force, *a0, a1, harmonics, weights, out);
        a0 = a1;
    }
    return out;
}

TrigSeries integrateNumerically(int harmonics, int n, const std::function<double(double)>& f) {
    TrigSeries out(harmonics);
    const double h = 2 * std::numbers::pi / n;
    for (int i = 0; i < n; ++i) {
        const double tau = (i + 0.5) * h, v = f(tau) * h;
        out.updMean() += v / (2 * std::numbers::pi);
        for (int k = 1; k <= harmonics; ++k) {
            out.updCos(k) += v * std::cos(k * tau) / std::numbers::pi;
            out.updSin(k) += v * std::sin(k * tau) / std::numbers::pi;
        }
    }
    return out;
}
}  // namespace

double PiecewiseLinearLaw::evaluate(double d, double dDot) const {
    const int i = findSegment(breakpoints, d);
    return alpha[i] + beta[i] * d + viscous * dDot;
}

std::vector<TrigSeries> calcForceHarmonics(const PiecewiseLinearLaw& law, const TrigSeries& d, double omega,
                                           const std::vector<TrigSeries>& weights, int harmonics) {
    std::vector<double> cuts;
    for (double b : law.breakpoints)
        for (double r : d.findRoots(b)) cuts.push_back(r);
    const TrigSeries rate = d.derivative() * omega;
    return integratePiecewise(cuts, harmonics, weights, d.getDegree(), [&](double mid) {
        const int i = findSegment(law.breakpoints, d.evaluate(mid));
        return TrigSeries::constant(law.alpha[i]) + d * law.beta[i] + rate * law.viscous;
    });
}

std::vector<TrigSeries> calcForceHarmonics(const CoulombLaw& law, const TrigSeries& d, double omega,
                                           const std::vector<TrigSeries>& weights, int harmonics) {
    const TrigSeries rate = d.derivative() * omega;
    return integratePiecewise(rate.findRoots(0), harmonics, weights, 0,
                              [&](double mid) { return TrigSeries::constant(law.evaluate(rate.evaluate(mid))); });
}

TrigSeries calcForceHarmonics(const PiecewiseLinearLaw& law, const TrigSeries& d, double omega, const TrigSeries& w,
                              int harmonics) {
    return calcForceHarmonics(law, d, omega, std::vector<TrigSeries>{w}, harmonics)[0];
}

TrigSeries calcForceHarmonics(const CoulombLaw& law, const TrigSeries& d, double omega, const TrigSeries& w,
                              int harmonics) {
    return calcForceHarmonics(law, d, omega, std::vector<TrigSeries>{w}, harmonics)[0];
}

TrigSeries calcForceHarmonicsNumerically(const PiecewiseLinearLaw& law, const TrigSeries& d, double omega,
                                         const TrigSeries& w, int harmonics, int n) {
    const TrigSeries rate = d.derivative() * omega;
    return integrateNumerically(harmonics, n, [&](double tau) {
        return law.evaluate(d.evaluate(tau), rate.evaluate(tau)) * w.evaluate(tau);
    });
}

TrigSeries calcForceHarmonicsNumerically(const CoulombLaw& law, const TrigSeries& d, double omega,
                                         const TrigSeries& w, int harmonics, int n) {
    const TrigSeries rate = d.derivative() * omega;
    return integrateNumerically(harmonics, n,
                                [&](double tau) { return law.evaluate(rate.evaluate(tau)) * w.evaluate(tau); });
}

std::vector<ForcePiece> calcElastoPlasticHistory(const ElastoPlasticLaw& law, const TrigSeries& d) {
    const double k = law.stiffness, Fc = law.limit;
    const std::vector<double> turning = d.derivative().findRoots(0);
    if (turning.size() < 2) return {{0, 2 * std::numbers::pi, TrigSeries::constant(0)}};
    size_t iMax = 0, iMin = 0;
    for (size_t i = 0; i < turning.size(); ++i) {
        if (d.evaluate(turning[i]) > d.evaluate(turning[iMax])) iMax = i;
        if (d.evaluate(turning[i]) < d.evaluate(turning[iMin])) iMin = i;
    }
    const double dMax = d.evaluate(turning[iMax]), dMin = d.evaluate(turning[iMin]);
    if (dMax - dMin <= 2 * Fc / k)  // sticks all period, about mid-range
        return {{0, 2 * std::numbers::pi, TrigSeries::constant(k * 0.5 * (dMax + dMin)) + d * -k}};

    std::vector<double> t;  // turning points from the global maximum, unwrapped
    for (size_t i = 0; i < turning.size(); ++i) {
        const double ti = turning[(iMax + i) % turning.size()];
        t.push_back(ti < turning[iMax] ? ti + 2 * std::numbers::pi : ti);
    }
    t.push_back(turning[iMax] + 2 * std::numbers::pi);
    std::vector<ForcePiece> pieces;
    double fr = -Fc, dr = dMax;
    for (size_t i = 0; i + 1 < t.size(); ++i) {
        const double ta = t[i], tb = t[i + 1];
        const bool down = d.evaluate(0.5 * (ta + tb)) < dr;
        const double fLimit = down ? Fc : -Fc;
        const double dSlip = dr + (fr - fLimit) / k;  // where f_r − k(d − d_r) = f_limit
        const TrigSeries stick = TrigSeries::constant(fr + k * dr) + d * -k;
        // d is monotone between turning points, so the slip point (if any) is
        // the single crossing of d = dSlip in (ta, tb): bisection finds it exactly.
        double tSlip = tb;
        const double side0 = d.evaluate(ta) - dSlip, side1 = d.evaluate(tb) - dSlip;
        if (side0 * side1 < 0) {
            double lo = ta, hi = tb;
            for (int it = 0; it < 60; ++it) {
                const double mid = 0.5 * (lo + hi);
                // Once mid is lo or hi (adjacent doubles), every further step reassigns
                // the same value: stopping changes nothing.
                if (mid == lo || mid == hi) break;
                ((d.evaluate(mid) - dSlip) * side0 > 0 ? lo : hi) = mid;
            }
            tSlip = 0.5 * (lo + hi);
        }
        pieces.push_back({ta, tSlip, stick});
        if (tSlip < tb) {
            pieces.push_back({tSlip, tb, TrigSeries::constant(fLimit)});
            fr = fLimit;
        } else {
            fr = std::clamp(fr - k * (d.evaluate(tb) - dr), -Fc, Fc);
        }
        dr = d.evaluate(tb);
    }
    return pieces;
}

double evaluateHistory(const std::vector<ForcePiece>& pieces, double tau) {
    const double start = pieces.front().t0;
    double t = std::fmod(tau - start, 2 * std::numbers::pi);
    if (t < 0) t += 2 * std::numbers::pi;
    t += start;
    for (const ForcePiece& p : pieces)
        if (t >= p.t0 && t <= p.t1) return p.force.evaluate(t);
    return pieces.back().force.evaluate(t);
}

std::vector<TrigSeries> calcForceHarmonics(const ElastoPlasticLaw& law, const TrigSeries& d, double,
                                           const std::vector<TrigSeries>& weights, int harmonics) {
    return integratePieces(calcElastoPlasticHistory(law, d), harmonics, weights);
}

TrigSeries calcForceHarmonicsNumerically(const ElastoPlasticLaw& law, const TrigSeries& d, const TrigSeries& w,
                                         int harmonics, int n) {
    const double h = 2 * std::numbers::pi / n;
    double f = 0, dPrev = d.evaluate(0);
    TrigSeries out(harmonics);
    for (int i = 0; i < 2 * n; ++i) {
        const double tau = (i + 0.5) * h, dNow = d.evaluate(tau);
        f = std::clamp(f - law.stiffness * (dNow - dPrev), -law.limit, law.limit);
        dPrev = dNow;
        if (i < n) continue;
        const double v = f * w.evaluate(tau) * h;
        out.updMean() += v / (2 * std::numbers::pi);
        for (int k = 1; k <= harmonics; ++k) {
            out.updCos(k) += v * std::cos(k * tau) / std::numbers::pi;
            out.updSin(k) += v * std::sin(k * tau) / std::numbers::pi;
        }
    }
    return out;
}

}  // namespace rockroll
