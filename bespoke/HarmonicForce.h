#pragma once
// Fourier coefficients of the describing function's nonlinear forces, exact.
//
// Every element force of the §4.1 model is a function of one relative
// displacement d(τ) and its rate ḋ = ω·d'(τ), where d is a trig polynomial
// (mean + two harmonics of the positions, plus the input):
//   piecewise linear:  f = α_i + β_i·d + γ·ḋ   on segment i between breakpoints;
//   Coulomb:           f = −F_c·sign(ḋ).
// Between the zero crossings of d − breakpoint (or of ḋ) the integrand f·w·cos kτ
// is a trig polynomial, so each Fourier integral (report eq. 22)
//   F₀ = 1/2π ∫ f·w dτ,   C_k = 1/π ∫ f·w·cos kτ dτ,   D_k = 1/π ∫ f·w·sin kτ dτ
// is a finite sum of closed-form integrals. The weight w(τ) (1, or a roll angle
// for the moment of a force whose arm turns with the body) is a trig polynomial too.
#include "bespoke/TrigSeries.h"

#include <array>
#include <vector>

namespace rockroll {

struct PiecewiseLinearLaw {
    std::vector<double> breakpoints;  ///< ascending; n breakpoints make n + 1 segments
    std::vector<double> alpha, beta;  ///< per segment: f = α + β·d
    double viscous = 0;               ///< γ, on every segment
    double evaluate(double d, double dDot) const;
};

struct CoulombLaw {
    double limit = 0;  ///< F_c: f = −F_c·sign(ḋ)
    double evaluate(double dDot) const { return dDot > 0 ? -limit : (dDot < 0 ? limit : 0.0); }
};

/// Coulomb friction with stick: an elasto-plastic element (stiffness k_b in
/// series with a slider of limit F_c), the steady periodic hysteresis for d(τ).
/// Between turning points of d it sticks (f = f_r − k_b·(d − d_r), linear in d)
/// until |f| reaches F_c, then slides (f = ∓F_c); starting at the global maximum
/// of d (arrived at sliding, f = −F_c) the loop closes after one period. If the
/// range of d is below 2F_c/k_b it sticks throughout, about the mid-range.
struct ElastoPlasticLaw {
    double limit = 0;      ///< F_c
    double stiffness = 0;  ///< k_b
};

/// One piece of a piecewise force history of the displacement d: f(τ) = constant +
/// slope·d(τ) on [t0, t1] (t may exceed 2π).
struct ForcePiece {
    double t0 = 0, t1 = 0;
    double constant = 0, slope = 0;
};
/// Each piece's constant as a function of d's coefficients: ∂constant/∂d_m, m in
/// TrigSeries::basis order (a stuck piece's constant f_r + k_b·d_r carries d at its
/// turning points; a sliding piece's is ±F_c).
using ConstantGradient = std::array<double, 2 * TrigSeries::kMaxDegree + 1>;
std::vector<ForcePiece> calcElastoPlasticHistory(const ElastoPlasticLaw& law, const TrigSeries& d,
                                                 std::vector<ConstantGradient>* constantGradients = nullptr);
/// f(τ) of a history of d (the pieces cover one period from pieces.front().t0).
double evaluateHistory(const std::vector<ForcePiece>& pieces, const TrigSeries& d, double tau);

/// Fourier coefficients up to `harmonics` of f(d(τ), ω·d'(τ))·w(τ), exact.
TrigSeries calcForceHarmonics(const PiecewiseLinearLaw& law, const TrigSeries& d, double omega, const TrigSeries& w,
                              int harmonics);
TrigSeries calcForceHarmonics(const CoulombLaw& law, const TrigSeries& d, double omega, const TrigSeries& w,
                              int harmonics);

/// The same for several weights at once (one root search): one series per weight.
std::vector<TrigSeries> calcForceHarmonics(const PiecewiseLinearLaw& law, const TrigSeries& d, double omega,
                                           const std::vector<TrigSeries>& weights, int harmonics);
std::vector<TrigSeries> calcForceHarmonics(const CoulombLaw& law, const TrigSeries& d, double omega,
                                           const std::vector<TrigSeries>& weights, int harmonics);

std::vector<TrigSeries> calcForceHarmonics(const ElastoPlasticLaw& law, const TrigSeries& d, double omega,
                                           const std::vector<TrigSeries>& weights, int harmonics);

/// The first derivatives of calcForceHarmonics(law, d, ω, weights) H_j (the harmonics of
/// f·w_j), exact. With d_m and w_m the coefficients of d and w_j in TrigSeries::basis
/// order, f = c_p + β_p·d + γ·ω·d' on piece p, N = 1/2π for the mean and 1/π for a
/// harmonic h = cos kτ, sin kτ:
///   ∂H_j/∂d_m = N·[Σ_p ∂c_p/∂d_m ∫_p w_j·h + ∫ β·φ_m·w_j·h + γω ∫ φ_m'·w_j·h]
///               + N·Σ_r (f(r⁻) − f(r⁺))·w_j(r)·h(r)·∂r/∂d_m,
///   ∂H_j/∂w_m = N·∫ f·φ_m·h,        ∂H_j/∂ω = N·γ ∫ d'·w_j·h,
/// φ_m = TrigSeries::basis(m). The moving ends of the pieces add nothing where f is
/// continuous in τ (the piecewise-linear laws, whose segments meet, and the
/// elasto-plastic loop); where it jumps (Coulomb, at the roots r of d', which move by
/// ∂r/∂d_m = −φ_m'(r)/d''(r)) they add the last sum.
struct ForceHarmonicsDerivatives {
    std::vector<std::vector<TrigSeries>> byDisplacement;  ///< [j][m]: ∂H_j/∂d_m
    std::vector<TrigSeries> byWeight;                     ///< [m]: ∂H_j/∂w_m, the same for every j
    std::vector<TrigSeries> byOmega;                      ///< [j]: ∂H_j/∂ω
};
ForceHarmonicsDerivatives calcForceHarmonicsDerivatives(const PiecewiseLinearLaw& law, const TrigSeries& d,
                                                        double omega, const std::vector<TrigSeries>& weights,
                                                        int harmonics);
ForceHarmonicsDerivatives calcForceHarmonicsDerivatives(const CoulombLaw& law, const TrigSeries& d, double omega,
                                                        const std::vector<TrigSeries>& weights, int harmonics);
ForceHarmonicsDerivatives calcForceHarmonicsDerivatives(const ElastoPlasticLaw& law, const TrigSeries& d,
                                                        double omega, const std::vector<TrigSeries>& weights,
                                                        int harmonics);
/// Steps the elasto-plastic law through two periods on n points and takes the
/// coefficients of the second by the midpoint rule (for checking).
TrigSeries calcForceHarmonicsNumerically(const ElastoPlasticLaw& law, const TrigSeries& d, const TrigSeries& w,
                                         int harmonics, int n);

/// The same coefficients by the midpoint rule on n points (for checking).
TrigSeries calcForceHarmonicsNumerically(const PiecewiseLinearLaw& law, const TrigSeries& d, double omega,
                                         const TrigSeries& w, int harmonics, int n);
TrigSeries calcForceHarmonicsNumerically(const CoulombLaw& law, const TrigSeries& d, double omega,
                                         const TrigSeries& w, int harmonics, int n);

}  // namespace rockroll
