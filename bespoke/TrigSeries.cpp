#include "bespoke/TrigSeries.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

namespace rockroll {

namespace {
constexpr double kTwoPi = 2 * std::numbers::pi;
}

TrigSeries TrigSeries::cosine(int k, double amplitude) {
    TrigSeries s(k);
    if (k == 0) s.c_[0] = amplitude;
    else s.c_[2 * k - 1] = amplitude;
    return s;
}

TrigSeries TrigSeries::sine(int k, double amplitude) {
    TrigSeries s(k);
    if (k > 0) s.c_[2 * k] = amplitude;
    return s;
}

TrigSeries TrigSeries::basis(int index) {
    return index == 0 ? constant(1) : index % 2 == 1 ? cosine((index + 1) / 2) : sine(index / 2);
}

int TrigSeries::checkedSize(int degree) {
    if (degree < 0 || degree > kMaxDegree)
        throw std::length_error("TrigSeries: degree " + std::to_string(degree) + " above the maximum " +
                                std::to_string(kMaxDegree));
    return 2 * degree + 1;
}

void TrigSeries::grow(int degree) {
    if (degree > getDegree()) size_ = checkedSize(degree);  // coefficients past size_ are zero
}

TrigSeries::Angles::Angles(double t, int n) : tau(t), degree(std::min(n, kMaxDegree)) {
    sin[0] = 0, cos[0] = 1;
    if (degree == 0) return;
    sin[1] = std::sin(t), cos[1] = std::cos(t);
    for (int k = 2; k <= degree; ++k) {  // sin(a + t), cos(a + t) with a = (k − 1)τ
        sin[k] = sin[k - 1] * cos[1] + cos[k - 1] * sin[1];
        cos[k] = cos[k - 1] * cos[1] - sin[k - 1] * sin[1];
    }
}

void TrigSeries::Moments::add(const Angles& a0, const Angles& a1, double weight) {
    if (std::min(a0.degree, a1.degree) < degree) throw std::logic_error("TrigSeries::Moments: angles of too low a degree");
    cos[0] += weight * (a1.tau - a0.tau);
    for (int n = 1; n <= degree; ++n) {
        cos[n] += weight * (a1.sin[n] - a0.sin[n]) / n;   // ∫ cos nτ = sin nτ / n
        sin[n] -= weight * (a1.cos[n] - a0.cos[n]) / n;   // ∫ sin nτ = −cos nτ / n
    }
}

double& TrigSeries::updCos(int k) {
    grow(k);
    return c_[2 * k - 1];
}

double& TrigSeries::updSin(int k) {
    grow(k);
    return c_[2 * k];
}

double TrigSeries::evaluate(const Angles& a) const {
    if (getDegree() > a.degree) throw std::logic_error("TrigSeries::evaluate: angles of too low a degree");
    double v = c_[0];
    for (int k = 1; k <= getDegree(); ++k) v += c_[2 * k - 1] * a.cos[k] + c_[2 * k] * a.sin[k];
    return v;
}

TrigSeries TrigSeries::derivative() const {
    TrigSeries d(getDegree());
    for (int k = 1; k <= getDegree(); ++k) {
        d.c_[2 * k - 1] = k * c_[2 * k];   // d/dτ (b sin kτ) = k b cos kτ
        d.c_[2 * k] = -k * c_[2 * k - 1];  // d/dτ (a cos kτ) = −k a sin kτ
    }
    return d;
}

double TrigSeries::integrate(const Angles& a0, const Angles& a1) const {
    if (getDegree() > std::min(a0.degree, a1.degree)) throw std::logic_error("TrigSeries::integrate: angles of too low a degree");
    Moments m(getDegree());
    m.add(a0, a1, 1);
    return integrate(m);
}

double TrigSeries::integrate(const Moments& m) const {
    if (getDegree() > m.degree) throw std::logic_error("TrigSeries::integrate: moments of too low a degree");
    double v = c_[0] * m.cos[0];
    for (int k = 1; k <= getDegree(); ++k) v += c_[2 * k - 1] * m.cos[k] + c_[2 * k] * m.sin[k];
    return v;
}

double TrigSeries::integrateTimesHarmonic(const Moments& m, int k, bool sine) const {
    if (k < 1 || getDegree() + k > m.degree)
        throw std::logic_error("TrigSeries::integrateTimesHarmonic: moments of too low a degree");
    // ∫ cos nτ·cos kτ = ½[C(n−k) + C(n+k)],  ∫ sin nτ·cos kτ = ½[S(n+k) + S(n−k)],
    // ∫ cos nτ·sin kτ = ½[S(n+k) − S(n−k)],  ∫ sin nτ·sin kτ = ½[C(n−k) − C(n+k)],
    // with C(−j) = C(j), S(−j) = −S(j) the moments (operator*'s identities).
    auto C = [&m](int j) { return m.cos[std::abs(j)]; };
    auto S = [&m](int j) { return j < 0 ? -m.sin[-j] : m.sin[j]; };
    double v = c_[0] * (sine ? S(k) : C(k));
    for (int n = 1; n <= getDegree(); ++n) {
        const double a = c_[2 * n - 1], b = c_[2 * n];
        if (!sine) v += 0.5 * (a * (C(n - k) + C(n + k)) + b * (S(n + k) + S(n - k)));
        else v += 0.5 * (a * (S(n + k) - S(n - k)) + b * (C(n - k) - C(n + k)));
    }
    return v;
}

TrigSeries& TrigSeries::operator+=(const TrigSeries& o) {
    grow(o.getDegree());
    for (int i = 0; i < o.size_; ++i) c_[i] += o.c_[i];
    return *this;
}

TrigSeries& TrigSeries::operator*=(double x) {
    for (int i = 0; i < size_; ++i) c_[i] *= x;
    return *this;
}

TrigSeries operator*(const TrigSeries& a, const TrigSeries& b) {
    // Products of harmonics m and n (m, n ≥ 0, cos 0 = 1, sin 0 = 0):
    //   cos m·cos n = ½[cos(m−n) + cos(m+n)],  sin m·sin n = ½[cos(m−n) − cos(m+n)],
    //   sin m·cos n = ½[sin(m+n) + sin(m−n)],  with sin(−k) = −sin k.
    TrigSeries p(a.getDegree() + b.getDegree());
    auto addCos = [&p](int k, double v) { (k == 0 ? p.c_[0] : p.c_[2 * std::abs(k) - 1]) += v; };
    auto addSin = [&p](int k, double v) {
        if (k != 0) p.c_[2 * std::abs(k)] += (k > 0 ? v : -v);
    };
    for (int m = 0; m <= a.getDegree(); ++m)
        for (int n = 0; n <= b.getDegree(); ++n) {
            const double ac = m == 0 ? a.c_[0] : a.c_[2 * m - 1], as = m == 0 ? 0.0 : a.c_[2 * m];
            const double bc = n == 0 ? b.c_[0] : b.c_[2 * n - 1], bs = n == 0 ? 0.0 : b.c_[2 * n];
            addCos(m - n, 0.5 * (ac * bc + as * bs));
            addCos(m + n, 0.5 * (ac * bc - as * bs));
            addSin(m + n, 0.5 * (as * bc + ac * bs));
            addSin(m - n, 0.5 * (as * bc - ac * bs));
        }
    return p;
}

std::vector<double> TrigSeries::findRoots(double level) const {
    // Not finite: no comparison below could prune an interval (and nothing crosses).
    if (!std::isfinite(level)) return {};
    for (int i = 0; i < size_; ++i)
        if (!std::isfinite(c_[i])) return {};
    double scale = std::abs(c_[0] - level);
    for (int i = 1; i < size_; ++i) scale = std::max(scale, std::abs(c_[i]));
    if (scale == 0) return {};
    // Out of reach: |s(τ) − c₀| ≤ Σ|(a_k, b_k)| for every τ, so when |c₀ − level| exceeds
    // that by more than the rounding of an evaluation (bounded by 1e-12 of the
    // coefficients' sum) nothing crosses: the answer is {} without a search.
    double reach = 0, sum = std::abs(c_[0]) + std::abs(level);
    for (int k = 1; k <= getDegree(); ++k)
        reach += std::hypot(c_[2 * k - 1], c_[2 * k]), sum += std::abs(c_[2 * k - 1]) + std::abs(c_[2 * k]);
    if (std::abs(c_[0] - level) - reach > 1e-12 * sum) return {};
    int N = getDegree();
    while (N > 0 && std::hypot(c_[2 * N - 1], c_[2 * N]) < 1e-14 * scale) --N;
    if (N == 0) return {};  // a constant within rounding
    // On [c − r, c + r], Taylor's theorem with |s''| ≤ M2 = Σ k²·|(a_k, b_k)|:
    //   |s(τ) − s(c) − s'(c)(τ − c)| ≤ M2 r²/2  and  |s'(τ) − s'(c)| ≤ M2 r.
    // So no crossing when |s(c) − level| > |s'(c)| r + M2 r²/2, and s is monotone (one
    // crossing at most, there when the ends differ in sign) when |s'(c)| > M2 r. Otherwise
    // the interval is halved, down to a half-width of 1e-10 (a tangency within rounding).
    // Both tests carry a margin for the rounding of an evaluation, as the reach test does.
    double m2 = 0, slopeSum = 0;
    for (int k = 1; k <= getDegree(); ++k)
        m2 += k * k * std::hypot(c_[2 * k - 1], c_[2 * k]), slopeSum += k * (std::abs(c_[2 * k - 1]) + std::abs(c_[2 * k]));
    const double valueMargin = 1e-12 * sum, slopeMargin = 1e-12 * slopeSum;
    constexpr double kMinHalfWidth = 1e-10;
    const TrigSeries ds = derivative();
    struct Interval {
        double a, b, va, vb;
    };
    std::array<Interval, 128> stack;  // depth ≤ log2(π / kMinHalfWidth) ≈ 35 below the first grid
    int top = 0;
    const int grid = 4 * N;
    std::array<double, 4 * kMaxDegree + 1> gridValues;
    // The grid's angles depend on N alone: computed once (the same bits as Angles(τ_i)).
    static const auto gridAngles = [] {
        std::array<std::vector<Angles>, kMaxDegree + 1> table;
        for (int n = 1; n <= kMaxDegree; ++n)
            for (int i = 0; i < 4 * n; ++i) table[n].emplace_back(kTwoPi * i / (4 * n), kMaxDegree);
        return table;
    }();
    for (int i = 0; i < grid; ++i) gridValues[i] = evaluate(gridAngles[N][i]) - level;
    gridValues[grid] = gridValues[0];  // s(2π) = s(0): one period
    for (int i = grid - 1; i >= 0; --i)  // the first interval on top
        stack[top++] = {kTwoPi * i / grid, kTwoPi * (i + 1) / grid, gridValues[i], gridValues[i + 1]};
    std::vector<double> roots;
    while (top > 0) {
        const Interval iv = stack[--top];
        const double c = 0.5 * (iv.a + iv.b), r = 0.5 * (iv.b - iv.a);
        const Angles angles(c, getDegree());
        const double v = evaluate(angles) - level, slope = ds.evaluate(angles);
        if (std::abs(v) > std::abs(slope) * r + 0.5 * m2 * r * r + valueMargin) continue;
        const bool monotone = std::abs(slope) > m2 * r + slopeMargin;
        if (monotone || r < kMinHalfWidth || top + 2 > int(stack.size())) {
            if (iv.va == 0) roots.push_back(iv.a);  // a crossing at b is the next interval's a
            else if ((iv.va < 0) != (iv.vb < 0) && iv.vb != 0) roots.push_back(findCrossing(level, iv.a, iv.b, iv.va, ds));
            continue;
        }
        stack[top++] = {c, iv.b, v, iv.vb};
        stack[top++] = {iv.a, c, iv.va, v};
    }
    for (double& tau : roots) {
        tau = std::fmod(tau, kTwoPi);
        if (tau < 0) tau += kTwoPi;
    }
    std::sort(roots.begin(), roots.end());
    std::vector<double> unique;
    for (double r : roots)
        if (unique.empty() || r - unique.back() > 1e-10) unique.push_back(r);
    if (unique.size() > 1 && unique.front() + kTwoPi - unique.back() < 1e-10) unique.pop_back();
    return unique;
}

double TrigSeries::findCrossing(double level, double lo, double hi) const {
    return findCrossing(level, lo, hi, evaluate(lo) - level, derivative());
}

double TrigSeries::findCrossing(double level, double lo, double hi, double vLo, const TrigSeries& ds) const {
    // Newton from the middle; a step that leaves the bracket is replaced by bisection.
    // It ends when a step moves τ by less than the rounding of τ itself.
    const bool negativeAtLo = vLo < 0;
    double t = 0.5 * (lo + hi);
    for (int it = 0; it < 100; ++it) {
        const Angles a(t, getDegree());
        const double v = evaluate(a) - level, slope = ds.evaluate(a);
        if (v == 0) return t;
        ((v < 0) == negativeAtLo ? lo : hi) = t;
        double next = slope != 0 ? t - v / slope : 0.5 * (lo + hi);
        if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
        if (std::abs(next - t) <= 4 * std::numeric_limits<double>::epsilon() * std::max(1.0, std::abs(t))) return next;
        t = next;
    }
    return t;
}

}  // namespace rockroll
