#include "bespoke/HarmonicForce.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>

namespace rockroll {

namespace {
constexpr double kPi = std::numbers::pi;

int findSegment(const std::vector<double>& breakpoints, double d) {
    return int(std::upper_bound(breakpoints.begin(), breakpoints.end(), d) - breakpoints.begin());
}

/// Integrates Q(τ)·{1, cos kτ, sin kτ} over [0, 2π) split at `cuts`, with Q on
/// each piece given by integrandOn(midpoint).
TrigSeries integratePiecewise(std::vector<double> cuts, int harmonics,
                              const std::function<TrigSeries(double mid)>& integrandOn) {
    cuts.push_back(0);
    cuts.push_back(2 * kPi);
    std::sort(cuts.begin(), cuts.end());
    TrigSeries out(harmonics);
    for (size_t i = 0; i + 1 < cuts.size(); ++i) {
        const double t0 = cuts[i], t1 = cuts[i + 1];
        if (t1 - t0 <= 0) continue;
        const TrigSeries Q = integrandOn(0.5 * (t0 + t1));
        out.updMean() += Q.integrate(t0, t1) / (2 * kPi);
        for (int k = 1; k <= harmonics; ++k) {
            out.updCos(k) += (Q * TrigSeries::cosine(k)).integrate(t0, t1) / kPi;
            out.updSin(k) += (Q * TrigSeries::sine(k)).integrate(t0, t1) / kPi;
        }
    }
    return out;
}

TrigSeries integrateNumerically(int harmonics, int n, const std::function<double(double)>& f) {
    TrigSeries out(harmonics);
    const double h = 2 * kPi / n;
    for (int i = 0; i < n; ++i) {
        const double tau = (i + 0.5) * h, v = f(tau) * h;
        out.updMean() += v / (2 * kPi);
        for (int k = 1; k <= harmonics; ++k) {
            out.updCos(k) += v * std::cos(k * tau) / kPi;
            out.updSin(k) += v * std::sin(k * tau) / kPi;
        }
    }
    return out;
}
}  // namespace

double PiecewiseLinearLaw::evaluate(double d, double dDot) const {
    const int i = findSegment(breakpoints, d);
    return alpha[i] + beta[i] * d + viscous * dDot;
}

TrigSeries calcForceHarmonics(const PiecewiseLinearLaw& law, const TrigSeries& d, double omega, const TrigSeries& w,
                              int harmonics) {
    std::vector<double> cuts;
    for (double b : law.breakpoints)
        for (double r : d.findRoots(b)) cuts.push_back(r);
    const TrigSeries rate = d.derivative() * omega;
    return integratePiecewise(cuts, harmonics, [&](double mid) {
        const int i = findSegment(law.breakpoints, d.evaluate(mid));
        return (TrigSeries::constant(law.alpha[i]) + d * law.beta[i] + rate * law.viscous) * w;
    });
}

TrigSeries calcForceHarmonics(const CoulombLaw& law, const TrigSeries& d, double omega, const TrigSeries& w,
                              int harmonics) {
    const TrigSeries rate = d.derivative() * omega;
    return integratePiecewise(rate.findRoots(0), harmonics,
                              [&](double mid) { return w * law.evaluate(rate.evaluate(mid)); });
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

}  // namespace rockroll
