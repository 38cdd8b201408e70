#pragma once
// A real trigonometric polynomial in τ = ω t,
//
//     s(τ) = c₀ + Σ_{k=1..N} (a_k cos kτ + b_k sin kτ),
//
// with the exact operations the describing function needs: sums, products
// (degree adds), the τ-derivative, the integral over any interval, and every
// root of s(τ) = level in [0, 2π).
#include <array>
#include <vector>

namespace rockroll {

class TrigSeries {
public:
    /// Highest degree a series can have (the describing function needs 6: a force of
    /// degree 2 times a weight of degree 2 times cos 2τ). The coefficients live inline,
    /// so series arithmetic never allocates; a larger degree throws std::length_error.
    static constexpr int kMaxDegree = 8;

    /// sin kτ and cos kτ for k = 0 … kMaxDegree at one τ (std::sin(k·τ), std::cos(k·τ)),
    /// so that the integrals over many pieces sharing an endpoint evaluate them once.
    struct Angles {
        explicit Angles(double tau, int degree = kMaxDegree);
        double tau = 0;
        int degree = 0;
        std::array<double, kMaxDegree + 1> sin{}, cos{};
    };

    TrigSeries() : size_(1) {}
    explicit TrigSeries(int degree) : size_(checkedSize(degree)) {}
    static TrigSeries constant(double c0) {
        TrigSeries s;
        s.c_[0] = c0;
        return s;
    }
    static TrigSeries cosine(int k, double amplitude = 1);
    static TrigSeries sine(int k, double amplitude = 1);

    int getDegree() const { return (size_ - 1) / 2; }
    double getMean() const { return c_[0]; }
    double getCos(int k) const { return k <= getDegree() ? c_[2 * k - 1] : 0.0; }
    double getSin(int k) const { return k <= getDegree() ? c_[2 * k] : 0.0; }
    double& updMean() { return c_[0]; }
    double& updCos(int k);
    double& updSin(int k);

    double evaluate(double tau) const;
    /// The same from precomputed angles (bit-identical to evaluate(a.tau)).
    double evaluate(const Angles& a) const;
    TrigSeries derivative() const;  ///< ds/dτ
    /// ∫ s(τ) dτ over [t0, t1], exactly.
    double integrate(double t0, double t1) const;
    /// The same from precomputed angles (bit-identical to integrate(a0.tau, a1.tau)).
    double integrate(const Angles& a0, const Angles& a1) const;
    /// Every τ in [0, 2π) with s(τ) = level, ascending (tangencies may be missed).
    std::vector<double> findRoots(double level = 0) const;

    TrigSeries& operator+=(const TrigSeries& o);
    TrigSeries& operator*=(double x);
    friend TrigSeries operator+(TrigSeries a, const TrigSeries& b) { return a += b; }
    friend TrigSeries operator*(TrigSeries a, double x) { return a *= x; }
    friend TrigSeries operator*(double x, TrigSeries a) { return a *= x; }
    friend TrigSeries operator*(const TrigSeries& a, const TrigSeries& b);
    /// *this · cos kτ or *this · sin kτ (k ≥ 1): operator* with cosine(k) / sine(k),
    /// the same sums in the same order without the products by zero.
    TrigSeries timesHarmonic(int k, bool sine) const;

private:
    static int checkedSize(int degree);
    void grow(int degree);
    int size_ = 1;                                  ///< 2·degree + 1 coefficients in use
    std::array<double, 2 * kMaxDegree + 1> c_{};    ///< c₀, a₁, b₁, a₂, b₂, …; zero past size_
};

}  // namespace rockroll
