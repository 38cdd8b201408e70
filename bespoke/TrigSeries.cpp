#include "bespoke/TrigSeries.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <complex>
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
    for (int k = 1; k <= degree; ++k) sin[k] = std::sin(k * t), cos[k] = std::cos(k * t);
}

double& TrigSeries::updCos(int k) {
    grow(k);
    return c_[2 * k - 1];
}

double& TrigSeries::updSin(int k) {
    grow(k);
    return c_[2 * k];
}

double TrigSeries::evaluate(double tau) const {
    double v = c_[0];
    for (int k = 1; k <= getDegree(); ++k) v += c_[2 * k - 1] * std::cos(k * tau) + c_[2 * k] * std::sin(k * tau);
    return v;
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

double TrigSeries::integrate(double t0, double t1) const {
    double v = c_[0] * (t1 - t0);
    for (int k = 1; k <= getDegree(); ++k)
        v += (c_[2 * k - 1] * (std::sin(k * t1) - std::sin(k * t0)) -
              c_[2 * k] * (std::cos(k * t1) - std::cos(k * t0))) / k;
    return v;
}

double TrigSeries::integrate(const Angles& a0, const Angles& a1) const {
    if (getDegree() > std::min(a0.degree, a1.degree)) throw std::logic_error("TrigSeries::integrate: angles of too low a degree");
    double v = c_[0] * (a1.tau - a0.tau);
    for (int k = 1; k <= getDegree(); ++k)
        v += (c_[2 * k - 1] * (a1.sin[k] - a0.sin[k]) - c_[2 * k] * (a1.cos[k] - a0.cos[k])) / k;
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

TrigSeries TrigSeries::timesHarmonic(int k, bool sine) const {
    // operator*(*this, cosine(k)) has b_c = 1, b_s = 0 at n = k and zeros elsewhere
    // (sine(k): b_c = 0, b_s = 1); the terms of the other n add only zeros.
    TrigSeries p(getDegree() + k);
    auto addCos = [&p](int j, double v) { (j == 0 ? p.c_[0] : p.c_[2 * std::abs(j) - 1]) += v; };
    auto addSin = [&p](int j, double v) {
        if (j != 0) p.c_[2 * std::abs(j)] += (j > 0 ? v : -v);
    };
    for (int m = 0; m <= getDegree(); ++m) {
        const double ac = m == 0 ? c_[0] : c_[2 * m - 1], as = m == 0 ? 0.0 : c_[2 * m];
        if (!sine) {
            addCos(m - k, 0.5 * ac);
            addCos(m + k, 0.5 * ac);
            addSin(m + k, 0.5 * as);
            addSin(m - k, 0.5 * as);
        } else {
            addCos(m - k, 0.5 * as);
            addCos(m + k, 0.5 * -as);
            addSin(m + k, 0.5 * ac);
            addSin(m - k, 0.5 * -ac);
        }
    }
    return p;
}

std::vector<double> TrigSeries::findRoots(double level) const {
    // s(τ) − level = Σ_{k=−N..N} γ_k e^{ikτ}, γ₀ = c₀ − level, γ_{±k} = (a_k ∓ i b_k)/2.
    // With z = e^{iτ}, z^N·(s − level) is a polynomial of degree 2N whose roots
    // on the unit circle are the crossings; its companion matrix gives them all.
    double scale = std::abs(c_[0] - level);
    for (int i = 1; i < size_; ++i) scale = std::max(scale, std::abs(c_[i]));
    if (scale == 0) return {};
    // Out of reach: |s(τ) − c₀| ≤ Σ|(a_k, b_k)| for every τ, so when c₀ − level exceeds
    // that by more than the acceptance test below (1e-8·scale) plus the rounding of an
    // evaluation (bounded by 1e-12 of the coefficients' sum), every candidate the
    // eigenvalues could give is rejected there: the answer is {} without solving.
    double reach = 0, sum = std::abs(c_[0]) + std::abs(level);
    for (int k = 1; k <= getDegree(); ++k)
        reach += std::hypot(c_[2 * k - 1], c_[2 * k]), sum += std::abs(c_[2 * k - 1]) + std::abs(c_[2 * k]);
    if (std::abs(c_[0] - level) - reach > 1e-8 * scale + 1e-12 * sum) return {};
    int N = getDegree();
    while (N > 0 && std::hypot(c_[2 * N - 1], c_[2 * N]) < 1e-14 * scale) --N;
    if (N == 0) return {};
    using C = std::complex<double>;
    std::array<C, 2 * kMaxDegree + 1> p{};  // p[j] multiplies z^j
    p[N] = c_[0] - level;
    for (int k = 1; k <= N; ++k) {
        p[N + k] = C(c_[2 * k - 1], -c_[2 * k]) / 2.0;
        p[N - k] = C(c_[2 * k - 1], c_[2 * k]) / 2.0;
    }
    const int deg = 2 * N;
    // Fixed maximum size: the eigen-solve allocates nothing.
    using Companion = Eigen::Matrix<C, Eigen::Dynamic, Eigen::Dynamic, 0, 2 * kMaxDegree, 2 * kMaxDegree>;
    Companion companion = Companion::Zero(deg, deg);
    for (int i = 1; i < deg; ++i) companion(i, i - 1) = 1;
    for (int i = 0; i < deg; ++i) companion(i, deg - 1) = -p[i] / p[deg];
    const auto z = Eigen::ComplexEigenSolver<Companion>(companion, false).eigenvalues();

    const TrigSeries ds = derivative();
    std::vector<double> roots;
    for (int i = 0; i < deg; ++i) {
        if (std::abs(std::abs(z[i]) - 1) > 1e-3) continue;
        double tau = std::arg(z[i]);
        for (int it = 0; it < 4; ++it) {  // polish on the real line (one set of angles per τ)
            const Angles a(tau, getDegree());
            const double slope = ds.evaluate(a);
            if (slope == 0) break;
            tau -= (evaluate(a) - level) / slope;
        }
        if (std::abs(evaluate(tau) - level) > 1e-8 * scale) continue;
        tau = std::fmod(tau, kTwoPi);
        if (tau < 0) tau += kTwoPi;
        roots.push_back(tau);
    }
    std::sort(roots.begin(), roots.end());
    std::vector<double> unique;
    for (double r : roots)
        if (unique.empty() || r - unique.back() > 1e-10) unique.push_back(r);
    if (unique.size() > 1 && unique.front() + kTwoPi - unique.back() < 1e-10) unique.pop_back();
    return unique;
}

}  // namespace rockroll
