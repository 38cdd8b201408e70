#include "bespoke/HarmonicForce.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <optional>
#include <stdexcept>

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

/// s's own harmonics up to `harmonics` (its integral over the whole period).
TrigSeries truncateTo(const TrigSeries& s, int harmonics) {
    TrigSeries out(harmonics);
    out.updMean() = s.getMean();
    for (int k = 1; k <= harmonics; ++k) out.updCos(k) = s.getCos(k), out.updSin(k) = s.getSin(k);
    return out;
}

/// The coefficients up to `harmonics` of f·w_j for each weight w_j, where f = constant_p +
/// slope_p·d(τ) on each piece p (together one period) plus `viscous`(τ) throughout.
/// Each piece adds its ∫ cos nτ, ∫ sin nτ (from the angles at its ends, computed once per
/// cut) to two sets of moments, weighted by its constant and by its slope; then
///   ∫ f·w_j·h = ∫ w_j·h dM_constant + ∫ (d·w_j)·h dM_slope + (γḋ·w_j's own coefficient),
/// h ∈ {1, cos kτ, sin kτ}: a few dot products per weight, however many pieces.
std::vector<TrigSeries> integratePieces(const std::vector<ForcePiece>& pieces, const TrigSeries& d,
                                        const TrigSeries* viscous, const std::vector<TrigSeries>& weights,
                                        int harmonics) {
    const int degree = std::min(TrigSeries::kMaxDegree, d.getDegree() + getMaxDegree(weights) + harmonics);
    TrigSeries::Moments constant(degree), slope(degree);
    std::optional<TrigSeries::Angles> a0;
    for (const ForcePiece& p : pieces) {
        if (p.t1 - p.t0 <= 0 || (p.constant == 0 && p.slope == 0)) continue;
        if (p.t1 - p.t0 == 2 * std::numbers::pi) {  // the whole period: exact moments
            constant.addPeriod(p.constant);
            slope.addPeriod(p.slope);
            continue;
        }
        if (!a0 || a0->tau != p.t0) a0.emplace(p.t0, degree);
        const TrigSeries::Angles a1(p.t1, degree);
        constant.add(*a0, a1, p.constant);
        slope.add(*a0, a1, p.slope);
        a0 = a1;
    }
    std::vector<TrigSeries> out(weights.size(), TrigSeries(harmonics));
    for (size_t j = 0; j < weights.size(); ++j) {
        const TrigSeries& w = weights[j];
        const TrigSeries dw = d * w;
        out[j].updMean() = (w.integrate(constant) + dw.integrate(slope)) / (2 * std::numbers::pi);
        for (int k = 1; k <= harmonics; ++k)
            for (bool sine : {false, true})
                (sine ? out[j].updSin(k) : out[j].updCos(k)) =
                    (w.integrateTimesHarmonic(constant, k, sine) + dw.integrateTimesHarmonic(slope, k, sine)) /
                    std::numbers::pi;
        if (viscous) out[j] += truncateTo(*viscous * w, harmonics);  // over the whole period
    }
    return out;
}

/// The pieces between consecutive cuts over [0, 2π), each with the law at its midpoint.
template <class LawAt>
std::vector<ForcePiece> makePieces(std::vector<double> cuts, const LawAt& lawAt) {
    cuts.push_back(0);
    cuts.push_back(2 * std::numbers::pi);
    std::sort(cuts.begin(), cuts.end());
    std::vector<ForcePiece> pieces;
    for (size_t i = 0; i + 1 < cuts.size(); ++i) {
        if (cuts[i + 1] - cuts[i] <= 0) continue;
        ForcePiece p{cuts[i], cuts[i + 1]};
        lawAt(0.5 * (cuts[i] + cuts[i + 1]), p);
        pieces.push_back(p);
    }
    return pieces;
}

/// The law's segments over one period of d: cut where d crosses a breakpoint.
std::vector<ForcePiece> makeLawPieces(const PiecewiseLinearLaw& law, const TrigSeries& d) {
    std::vector<double> cuts;
    for (double b : law.breakpoints)
        for (double r : d.findRoots(b)) cuts.push_back(r);
    return makePieces(cuts, [&](double mid, ForcePiece& p) {
        const int i = findSegment(law.breakpoints, d.evaluate(mid));
        p.constant = law.alpha[i], p.slope = law.beta[i];
    });
}

/// N·∫ s·h over the moments' intervals, h = 1, cos kτ, sin kτ (k ≤ harmonics), N = 1/2π
/// for the mean and 1/π for a harmonic: the harmonics of s restricted to those intervals.
TrigSeries projectOnMoments(const TrigSeries& s, const TrigSeries::Moments& m, int harmonics) {
    TrigSeries out(harmonics);
    out.updMean() = s.integrate(m) / (2 * std::numbers::pi);
    for (int k = 1; k <= harmonics; ++k) {
        out.updCos(k) = s.integrateTimesHarmonic(m, k, false) / std::numbers::pi;
        out.updSin(k) = s.integrateTimesHarmonic(m, k, true) / std::numbers::pi;
    }
    return out;
}

/// Where f jumps: at τ, by f(τ⁻) − f(τ⁺), τ a root of d'.
struct ForceJump {
    double tau = 0, size = 0;
};

/// ForceHarmonicsDerivatives for f = constant_p + slope_p·d on the pieces (one period),
/// plus γω·d' throughout, with each piece's ∂constant/∂d_m (null: constants fixed) and
/// the jumps of f at roots of d'.
ForceHarmonicsDerivatives differentiatePieces(const std::vector<ForcePiece>& pieces,
                                              const std::vector<ConstantGradient>* constantGradients,
                                              const std::vector<ForceJump>& jumps, const TrigSeries& d,
                                              double viscous, double omega, const std::vector<TrigSeries>& weights,
                                              int harmonics) {
    const int nd = d.getNumCoefficients(), nw = 2 * getMaxDegree(weights) + 1;
    const int degree = std::min(TrigSeries::kMaxDegree, d.getDegree() + getMaxDegree(weights) + harmonics);
    TrigSeries::Moments constant(degree), slope(degree);
    std::vector<TrigSeries::Moments> constantBy(constantGradients ? nd : 0, TrigSeries::Moments(degree));
    std::optional<TrigSeries::Angles> a0;
    for (size_t p = 0; p < pieces.size(); ++p) {
        const ForcePiece& piece = pieces[p];
        if (piece.t1 - piece.t0 <= 0) continue;
        if (piece.t1 - piece.t0 == 2 * std::numbers::pi) {
            constant.addPeriod(piece.constant);
            slope.addPeriod(piece.slope);
            for (size_t m = 0; m < constantBy.size(); ++m) constantBy[m].addPeriod((*constantGradients)[p][m]);
            continue;
        }
        if (!a0 || a0->tau != piece.t0) a0.emplace(piece.t0, degree);
        const TrigSeries::Angles a1(piece.t1, degree);
        constant.add(*a0, a1, piece.constant);
        slope.add(*a0, a1, piece.slope);
        for (size_t m = 0; m < constantBy.size(); ++m) constantBy[m].add(*a0, a1, (*constantGradients)[p][m]);
        a0 = a1;
    }
    const TrigSeries rate = d.derivative(), curvature = rate.derivative();
    ForceHarmonicsDerivatives out;
    for (int m = 0; m < nw; ++m) {
        const TrigSeries phi = TrigSeries::basis(m);
        TrigSeries h = projectOnMoments(phi, constant, harmonics) + projectOnMoments(d * phi, slope, harmonics);
        if (viscous != 0) h += truncateTo(rate * phi, harmonics) * (viscous * omega);
        out.byWeight.push_back(h);
    }
    for (const TrigSeries& w : weights) {
        out.byOmega.push_back(viscous != 0 ? truncateTo(rate * w, harmonics) * viscous : TrigSeries(harmonics));
        std::vector<TrigSeries> byD;
        for (int m = 0; m < nd; ++m) {
            const TrigSeries phi = TrigSeries::basis(m);
            TrigSeries h = projectOnMoments(phi * w, slope, harmonics);
            if (constantGradients) h += projectOnMoments(w, constantBy[m], harmonics);
            if (viscous != 0) h += truncateTo(phi.derivative() * w, harmonics) * (viscous * omega);
            for (const ForceJump& jump : jumps) {
                const TrigSeries::Angles a(jump.tau, degree);
                const double moves = -phi.derivative().evaluate(a) / curvature.evaluate(a);  // ∂r/∂d_m
                const double c = jump.size * w.evaluate(a) * moves / std::numbers::pi;
                h.updMean() += 0.5 * c;
                for (int k = 1; k <= harmonics; ++k) h.updCos(k) += c * a.cos[k], h.updSin(k) += c * a.sin[k];
            }
            byD.push_back(h);
        }
        out.byDisplacement.push_back(std::move(byD));
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
    const std::vector<ForcePiece> pieces = makeLawPieces(law, d);
    const TrigSeries viscous = d.derivative() * (omega * law.viscous);
    return integratePieces(pieces, d, law.viscous != 0 ? &viscous : nullptr, weights, harmonics);
}

std::vector<TrigSeries> calcForceHarmonics(const CoulombLaw& law, const TrigSeries& d, double omega,
                                           const std::vector<TrigSeries>& weights, int harmonics) {
    const TrigSeries rate = d.derivative() * omega;
    const std::vector<ForcePiece> pieces = makePieces(
        rate.findRoots(0), [&](double mid, ForcePiece& p) { p.constant = law.evaluate(rate.evaluate(mid)); });
    return integratePieces(pieces, d, nullptr, weights, harmonics);
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

std::vector<ForcePiece> calcElastoPlasticHistory(const ElastoPlasticLaw& law, const TrigSeries& d,
                                                 std::vector<ConstantGradient>* constantGradients) {
    const double k = law.stiffness, Fc = law.limit;
    const int nd = d.getNumCoefficients();
    // φ_m at τ, m < nd: d_r = d(t_r) at a turning point moves by φ_m(t_r) (d'(t_r) = 0).
    auto basisAt = [nd, &d](double tau) {
        const TrigSeries::Angles a(tau, d.getDegree());
        ConstantGradient g{};
        g[0] = 1;
        for (int m = 1; m < nd; ++m) g[m] = m % 2 == 1 ? a.cos[(m + 1) / 2] : a.sin[m / 2];
        return g;
    };
    if (constantGradients) constantGradients->clear();
    const std::vector<double> turning = d.derivative().findRoots(0);
    if (turning.size() < 2) {  // d constant: no force
        if (!constantGradients) return {{0, 2 * std::numbers::pi, 0.0, 0.0}};
        // The same zero force written as the stick about the mean, f = k_b·(d̄ − d), so the
        // derivatives are those of the smallest motion (it sticks about mid-range).
        ConstantGradient g{};
        g[0] = k;
        constantGradients->push_back(g);
        return {{0, 2 * std::numbers::pi, k * d.getMean(), -k}};
    }
    std::vector<double> dTurning;  // d at each turning point
    for (double t : turning) dTurning.push_back(d.evaluate(t));
    size_t iMax = 0, iMin = 0;
    for (size_t i = 0; i < turning.size(); ++i) {
        if (dTurning[i] > dTurning[iMax]) iMax = i;
        if (dTurning[i] < dTurning[iMin]) iMin = i;
    }
    const double dMax = dTurning[iMax], dMin = dTurning[iMin];
    if (dMax - dMin <= 2 * Fc / k) {  // sticks all period, about mid-range
        if (constantGradients) {
            const ConstantGradient gMax = basisAt(turning[iMax]), gMin = basisAt(turning[iMin]);
            ConstantGradient g{};
            for (int m = 0; m < nd; ++m) g[m] = k * 0.5 * (gMax[m] + gMin[m]);
            constantGradients->push_back(g);
        }
        return {{0, 2 * std::numbers::pi, k * 0.5 * (dMax + dMin), -k}};
    }

    std::vector<double> t, dt;  // turning points from the global maximum, unwrapped, and d there
    for (size_t i = 0; i <= turning.size(); ++i) {
        const size_t m = (iMax + i) % turning.size();
        t.push_back(turning[m] < turning[iMax] || i == turning.size() ? turning[m] + 2 * std::numbers::pi : turning[m]);
        dt.push_back(dTurning[m]);
    }
    std::vector<ForcePiece> pieces;
    double fr = -Fc, dr = dMax;
    // ∂f_r/∂d_m and ∂d_r/∂d_m, carried along the loop when asked for.
    ConstantGradient gfr{}, gdr = constantGradients ? basisAt(t[0]) : ConstantGradient{};
    for (size_t i = 0; i + 1 < t.size(); ++i) {
        const double ta = t[i], tb = t[i + 1];
        const bool down = dt[i + 1] < dr;  // d is monotone from ta to tb
        const double fLimit = down ? Fc : -Fc;
        const double dSlip = dr + (fr - fLimit) / k;  // where f_r − k(d − d_r) = f_limit
        // d is monotone between turning points, so the slip point (if any) is the
        // single crossing of d = dSlip in (ta, tb).
        double tSlip = tb;
        if ((dt[i] - dSlip) * (dt[i + 1] - dSlip) < 0) tSlip = d.findCrossing(dSlip, ta, tb);
        pieces.push_back({ta, tSlip, fr + k * dr, -k});  // sticks: f_r − k(d − d_r)
        const ConstantGradient gb = constantGradients ? basisAt(tb) : ConstantGradient{};
        if (constantGradients) {
            ConstantGradient g{};
            for (int m = 0; m < nd; ++m) g[m] = gfr[m] + k * gdr[m];
            constantGradients->push_back(g);
        }
        if (tSlip < tb) {
            pieces.push_back({tSlip, tb, fLimit, 0.0});
            if (constantGradients) constantGradients->push_back(ConstantGradient{});
            fr = fLimit;
            gfr = ConstantGradient{};
        } else {
            const double unclamped = fr - k * (dt[i + 1] - dr);
            fr = std::clamp(unclamped, -Fc, Fc);
            for (int m = 0; m < nd; ++m) gfr[m] = fr == unclamped ? gfr[m] - k * (gb[m] - gdr[m]) : 0.0;
        }
        dr = dt[i + 1];
        gdr = gb;
    }
    return pieces;
}

double evaluateHistory(const std::vector<ForcePiece>& pieces, const TrigSeries& d, double tau) {
    const double start = pieces.front().t0;
    double t = std::fmod(tau - start, 2 * std::numbers::pi);
    if (t < 0) t += 2 * std::numbers::pi;
    t += start;
    const ForcePiece* at = &pieces.back();
    for (const ForcePiece& p : pieces)
        if (t >= p.t0 && t <= p.t1) {
            at = &p;
            break;
        }
    return at->constant + at->slope * d.evaluate(t);
}

std::vector<TrigSeries> calcForceHarmonics(const ElastoPlasticLaw& law, const TrigSeries& d, double,
                                           const std::vector<TrigSeries>& weights, int harmonics) {
    return integratePieces(calcElastoPlasticHistory(law, d), d, nullptr, weights, harmonics);
}

ForceHarmonicsDerivatives calcForceHarmonicsDerivatives(const PiecewiseLinearLaw& law, const TrigSeries& d,
                                                        double omega, const std::vector<TrigSeries>& weights,
                                                        int harmonics) {
    // The derivative leaves out the moving ends of the segments: f must not jump there.
    for (size_t i = 0; i < law.breakpoints.size(); ++i) {
        const double b = law.breakpoints[i], below = law.alpha[i] + law.beta[i] * b,
                     above = law.alpha[i + 1] + law.beta[i + 1] * b;
        if (std::abs(below - above) > 1e-9 * std::max({1.0, std::abs(below), std::abs(above)}))
            throw std::logic_error("calcForceHarmonicsDerivatives: a piecewise-linear law that jumps at a breakpoint");
    }
    const std::vector<ForcePiece> pieces = makeLawPieces(law, d);
    return differentiatePieces(pieces, nullptr, {}, d, law.viscous, omega, weights, harmonics);
}

ForceHarmonicsDerivatives calcForceHarmonicsDerivatives(const CoulombLaw& law, const TrigSeries& d, double omega,
                                                        const std::vector<TrigSeries>& weights, int harmonics) {
    const TrigSeries rate = d.derivative() * omega, curvature = d.derivative().derivative();
    const std::vector<double> roots = rate.findRoots(0);
    const std::vector<ForcePiece> pieces =
        makePieces(roots, [&](double mid, ForcePiece& p) { p.constant = law.evaluate(rate.evaluate(mid)); });
    std::vector<ForceJump> jumps;
    for (double r : roots) {  // d' from + to − (d'' < 0): f from −F_c to +F_c, a jump f(r⁻) − f(r⁺) = −2F_c
        const double c = curvature.evaluate(r);
        if (c != 0) jumps.push_back({r, c < 0 ? -2 * law.limit : 2 * law.limit});
    }
    return differentiatePieces(pieces, nullptr, jumps, d, 0.0, omega, weights, harmonics);
}

ForceHarmonicsDerivatives calcForceHarmonicsDerivatives(const ElastoPlasticLaw& law, const TrigSeries& d, double omega,
                                                        const std::vector<TrigSeries>& weights, int harmonics) {
    std::vector<ConstantGradient> gradients;
    const std::vector<ForcePiece> pieces = calcElastoPlasticHistory(law, d, &gradients);
    return differentiatePieces(pieces, &gradients, {}, d, 0.0, omega, weights, harmonics);
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
