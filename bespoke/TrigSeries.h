#pragma once
// A real trigonometric polynomial in τ = ω t,
//
//     s(τ) = c₀ + Σ_{k=1..N} (a_k cos kτ + b_k sin kτ),
//
// with the exact operations the describing function needs: sums, products
// (degree adds), the τ-derivative, the integral over any interval, and every
// root of s(τ) = level in [0, 2π).
#include <array>
#include <numbers>
#include <vector>

namespace rockroll {

class TrigSeries {
public:
    /// Highest degree a series can have (the describing function needs 6: a force of
    /// degree 2 times a weight of degree 2 times cos 2τ). The coefficients live inline,
    /// so series arithmetic never allocates; a larger degree throws std::length_error.
    static constexpr int kMaxDegree = 8;

    /// sin kτ and cos kτ for k = 0 … degree at one τ, from one sin τ, cos τ by the
    /// angle-addition recurrence (rounding grows by about one unit per k: k·1e-16 for
    /// k ≤ kMaxDegree; test TrigSeries.AnglesMatchTheLibrarySineAndCosine). Every evaluation
    /// and integral of a series goes through them, so the integrals over many pieces
    /// sharing an endpoint evaluate them once.
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
    /// The index-th basis function in the coefficients' order: 1, cos τ, sin τ, cos 2τ, sin 2τ, …
    static TrigSeries basis(int index);

    int getDegree() const { return (size_ - 1) / 2; }
    double getMean() const { return c_[0]; }
    double getCos(int k) const { return k <= getDegree() ? c_[2 * k - 1] : 0.0; }
    double getSin(int k) const { return k <= getDegree() ? c_[2 * k] : 0.0; }
    /// 2·degree + 1: the mean, then cos kτ and sin kτ for k = 1 … degree.
    int getNumCoefficients() const { return size_; }
    /// The coefficient of basis(index) (zero past the degree).
    double getCoefficient(int index) const { return index < size_ ? c_[index] : 0.0; }
    double& updMean() { return c_[0]; }
    double& updCos(int k);
    double& updSin(int k);

    /// The same from precomputed angles (bit-identical to evaluate(a.tau)).
    double evaluate(const Angles& a) const;
    double evaluate(double tau) const { return evaluate(Angles(tau, getDegree())); }
    TrigSeries derivative() const;  ///< ds/dτ
    /// ∫ cos nτ dτ and ∫ sin nτ dτ (n = 0 … degree) over intervals, each interval's
    /// integrals times a weight, summed: the weighted integral of any series of at most
    /// that degree over those intervals is then a dot product with its coefficients.
    struct Moments {
        explicit Moments(int degree = kMaxDegree) : degree(degree) {}
        /// weight·∫ over [a0.tau, a1.tau] (angles of at least this degree).
        void add(const Angles& a0, const Angles& a1, double weight);
        /// weight·∫ over a whole period: 2π·weight for n = 0, exactly zero otherwise.
        void addPeriod(double weight) { cos[0] += 2 * std::numbers::pi * weight; }
        int degree = 0;
        std::array<double, kMaxDegree + 1> cos{}, sin{};  ///< sin[0] stays 0
    };
    /// ∫ s(τ) dτ over the moments' intervals, weighted (s of at most the moments' degree).
    double integrate(const Moments& m) const;
    /// ∫ s(τ)·cos kτ dτ (sine: sin kτ) over them: (*this * cosine(k)).integrate(m) by the
    /// product-to-sum identities, without forming the product (degree + k ≤ m.degree).
    double integrateTimesHarmonic(const Moments& m, int k, bool sine) const;
    /// ∫ s(τ) dτ over [t0, t1], exactly.
    double integrate(double t0, double t1) const { return integrate(Angles(t0, getDegree()), Angles(t1, getDegree())); }
    /// The same from precomputed angles (bit-identical to integrate(a0.tau, a1.tau)).
    double integrate(const Angles& a0, const Angles& a1) const;
    /// Every τ in [0, 2π) with s(τ) = level, ascending (tangencies, and pairs of roots
    /// closer than about 1e-9, may be missed; none when a coefficient or the level is not
    /// finite). Interval subdivision with a bound on s''
    /// that cannot skip a crossing (docs/bespoke.md, "Exact Fourier coefficients").
    std::vector<double> findRoots(double level = 0) const;
    /// The τ in [lo, hi] with s(τ) = level, when s − level changes sign there and s is
    /// monotone on it: Newton's method kept inside the shrinking bracket.
    double findCrossing(double level, double lo, double hi) const;

    TrigSeries& operator+=(const TrigSeries& o);
    TrigSeries& operator*=(double x);
    friend TrigSeries operator+(TrigSeries a, const TrigSeries& b) { return a += b; }
    friend TrigSeries operator*(TrigSeries a, double x) { return a *= x; }
    friend TrigSeries operator*(double x, TrigSeries a) { return a *= x; }
    friend TrigSeries operator*(const TrigSeries& a, const TrigSeries& b);

private:
    static int checkedSize(int degree);
    double findCrossing(double level, double lo, double hi, double vLo, const TrigSeries& ds) const;
    void grow(int degree);
    int size_ = 1;                                  ///< 2·degree + 1 coefficients in use
    std::array<double, 2 * kMaxDegree + 1> c_{};    ///< c₀, a₁, b₁, a₂, b₂, …; zero past size_
};

}  // namespace rockroll
