#include "bespoke/TrigSeries.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>

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

void TrigSeries::grow(int degree) {
    if (degree > getDegree()) c_.resize(2 * degree + 1, 0.0);
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

TrigSeries& TrigSeries::operator+=(const TrigSeries& o) {
    grow(o.getDegree());
    for (size_t i = 0; i < o.c_.size(); ++i) c_[i] += o.c_[i];
    return *this;
}

TrigSeries& TrigSeries::operator*=(double x) {
    for (double& c : c_) c *= x;
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
    // s(τ) − level = Σ_{k=−N..N} γ_k e^{ikτ}, γ₀ = c₀ − level, γ_{±k} = (a_k ∓ i b_k)/2.
    // With z = e^{iτ}, z^N·(s − level) is a polynomial of degree 2N whose roots
    // on the unit circle are the crossings; its companion matrix gives them all.
    double scale = std::abs(c_[0] - level);
    for (size_t i = 1; i < c_.size(); ++i) scale = std::max(scale, std::abs(c_[i]));
    if (scale == 0) return {};
    int N = getDegree();
    while (N > 0 && std::hypot(c_[2 * N - 1], c_[2 * N]) < 1e-14 * scale) --N;
    if (N == 0) return {};
    using C = std::complex<double>;
    std::vector<C> p(2 * N + 1);  // p[j] multiplies z^j
    p[N] = c_[0] - level;
    for (int k = 1; k <= N; ++k) {
        p[N + k] = C(c_[2 * k - 1], -c_[2 * k]) / 2.0;
        p[N - k] = C(c_[2 * k - 1], c_[2 * k]) / 2.0;
    }
    const int deg = 2 * N;
    Eigen::MatrixXcd companion = Eigen::MatrixXcd::Zero(deg, deg);
    for (int i = 1; i < deg; ++i) companion(i, i - 1) = 1;
    for (int i = 0; i < deg; ++i) companion(i, deg - 1) = -p[i] / p[deg];
    const Eigen::VectorXcd z = Eigen::ComplexEigenSolver<Eigen::MatrixXcd>(companion, false).eigenvalues();

    const TrigSeries ds = derivative();
    std::vector<double> roots;
    for (int i = 0; i < deg; ++i) {
        if (std::abs(std::abs(z[i]) - 1) > 1e-3) continue;
        double tau = std::arg(z[i]);
        for (int it = 0; it < 4; ++it) {  // polish on the real line
            const double slope = ds.evaluate(tau);
            if (slope == 0) break;
            tau -= (evaluate(tau) - level) / slope;
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
