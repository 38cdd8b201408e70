// Trig polynomials and the exact Fourier coefficients of piecewise-linear and
// Coulomb forces, checked against numerical quadrature.
#include "bespoke/HarmonicForce.h"

#include <Eigen/Eigenvalues>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

namespace { constexpr double kPi = 3.14159265358979323846; }

using namespace rockroll;

namespace {
TrigSeries makeSeries(double c0, double a1, double b1, double a2, double b2) {
    TrigSeries s(2);
    s.updMean() = c0;
    s.updCos(1) = a1;
    s.updSin(1) = b1;
    s.updCos(2) = a2;
    s.updSin(2) = b2;
    return s;
}
void expectSameCoefficients(const TrigSeries& a, const TrigSeries& b, double tol) {
    EXPECT_NEAR(a.getMean(), b.getMean(), tol);
    for (int k = 1; k <= 2; ++k) {
        EXPECT_NEAR(a.getCos(k), b.getCos(k), tol) << "cos " << k;
        EXPECT_NEAR(a.getSin(k), b.getSin(k), tol) << "sin " << k;
    }
}
}  // namespace

TEST(TrigSeries, ProductDerivativeAndIntegralAreExact) {
    const TrigSeries a = makeSeries(0.3, 1.1, -0.4, 0.25, 0.6), b = makeSeries(-0.2, 0.5, 0.9, -0.7, 0.1);
    const TrigSeries p = a * b;
    const TrigSeries d = a.derivative();
    for (double t : {0.0, 0.7, 2.1, 4.4, 6.0}) {
        EXPECT_NEAR(p.evaluate(t), a.evaluate(t) * b.evaluate(t), 1e-13);
        const double h = 1e-6;
        EXPECT_NEAR(d.evaluate(t), (a.evaluate(t + h) - a.evaluate(t - h)) / (2 * h), 1e-8);
    }
    double sum = 0;
    const int n = 200000;
    for (int i = 0; i < n; ++i) sum += p.evaluate(0.5 + (i + 0.5) * 2.0 / n) * 2.0 / n;
    EXPECT_NEAR(p.integrate(0.5, 2.5), sum, 1e-9);
}

TEST(TrigSeries, FindsEveryCrossing) {
    const auto r = TrigSeries::cosine(1).findRoots(0.5);
    ASSERT_EQ(r.size(), 2u);
    EXPECT_NEAR(r[0], kPi / 3, 1e-12);
    EXPECT_NEAR(r[1], 5 * kPi / 3, 1e-12);
    // Second harmonic dominant: four crossings.
    const TrigSeries s = makeSeries(0.1, 0.2, 0.0, 1.0, 0.3);
    const auto r2 = s.findRoots(0);
    ASSERT_EQ(r2.size(), 4u);
    for (double t : r2) EXPECT_NEAR(s.evaluate(t), 0.0, 1e-12);
    EXPECT_TRUE(TrigSeries::constant(2).findRoots(0).empty());
    EXPECT_TRUE(TrigSeries::cosine(1).findRoots(1.5).empty());
}

// findRoots answers {} without a search when the level is beyond the series' reach
// |c0 - level| > sum |(a_k, b_k)|: levels just inside the reach must still cross.
TEST(TrigSeries, LevelsJustInsideTheReachStillCross) {
    const TrigSeries s = makeSeries(0.1, 0.2, 0.3, 0.05, -0.4);  // reach hypot(.2,.3) + hypot(.05,.4)
    const double reach = std::hypot(0.2, 0.3) + std::hypot(0.05, 0.4);
    double top = -1e9, bottom = 1e9;  // the series' true extremes, sampled finely
    for (int i = 0; i < 200000; ++i) {
        const double v = s.evaluate(2 * kPi * i / 200000);
        top = std::max(top, v), bottom = std::min(bottom, v);
    }
    ASSERT_LE(top - 0.1, reach);
    EXPECT_FALSE(s.findRoots(top - 1e-4).empty());
    EXPECT_FALSE(s.findRoots(bottom + 1e-4).empty());
    EXPECT_TRUE(s.findRoots(0.1 + reach * 1.001).empty());
    EXPECT_TRUE(s.findRoots(0.1 - reach * 1.001).empty());
}

// evaluate(Angles) is the same number as evaluate(τ), bit for bit (describe() relies on it).
TEST(TrigSeries, EvaluateFromAnglesIsBitIdentical) {
    const TrigSeries s = makeSeries(0.1, 0.2, 0.3, 0.05, -0.4);
    for (int i = 0; i < 1000; ++i) {
        const double tau = 2 * kPi * i / 1000 - 1.0;
        EXPECT_EQ(s.evaluate(TrigSeries::Angles(tau, 2)), s.evaluate(tau)) << tau;
    }
    EXPECT_THROW(s.evaluate(TrigSeries::Angles(0.3, 1)), std::logic_error);
}

namespace {
/// The roots findRoots used to give: the unit-circle eigenvalues of the companion matrix
/// of z^N·(s(τ) − level), z = e^{iτ}, polished by Newton on the real line. Kept here as
/// the reference the subdivision search is checked against.
std::vector<double> findRootsByEigenvalues(const TrigSeries& s, double level) {
    using C = std::complex<double>;
    const int N = s.getDegree(), deg = 2 * N;
    std::vector<C> p(deg + 1);
    p[N] = s.getMean() - level;
    for (int k = 1; k <= N; ++k) {
        p[N + k] = C(s.getCos(k), -s.getSin(k)) / 2.0;
        p[N - k] = C(s.getCos(k), s.getSin(k)) / 2.0;
    }
    Eigen::MatrixXcd companion = Eigen::MatrixXcd::Zero(deg, deg);
    for (int i = 1; i < deg; ++i) companion(i, i - 1) = 1;
    for (int i = 0; i < deg; ++i) companion(i, deg - 1) = -p[i] / p[deg];
    const Eigen::VectorXcd z = Eigen::ComplexEigenSolver<Eigen::MatrixXcd>(companion, false).eigenvalues();
    const TrigSeries ds = s.derivative();
    std::vector<double> roots;
    for (int i = 0; i < deg; ++i) {
        if (std::abs(std::abs(z[i]) - 1) > 1e-3) continue;
        double tau = std::arg(z[i]);
        for (int it = 0; it < 6; ++it) tau -= (s.evaluate(tau) - level) / ds.evaluate(tau);
        if (std::abs(s.evaluate(tau) - level) > 1e-10) continue;
        tau = std::fmod(tau, 2 * kPi);
        roots.push_back(tau < 0 ? tau + 2 * kPi : tau);
    }
    std::sort(roots.begin(), roots.end());
    return roots;
}

TrigSeries makeRandomSeries(std::mt19937& rng, int degree) {
    std::uniform_real_distribution<double> u(-1, 1);
    TrigSeries s(degree);
    s.updMean() = u(rng);
    for (int k = 1; k <= degree; ++k) s.updCos(k) = u(rng), s.updSin(k) = u(rng);
    return s;
}
}  // namespace

// Angles come from one sin τ, cos τ by the angle-addition recurrence: within a few units
// of rounding per multiple of the library's sin kτ, cos kτ.
TEST(TrigSeries, AnglesMatchTheLibrarySineAndCosine) {
    for (int i = 0; i <= 2000; ++i) {
        const double tau = -4 * kPi + 8 * kPi * i / 2000;
        const TrigSeries::Angles a(tau);
        for (int k = 0; k <= TrigSeries::kMaxDegree; ++k) {
            EXPECT_NEAR(a.sin[k], std::sin(k * tau), 4e-15 * (k + 1)) << tau << " k " << k;
            EXPECT_NEAR(a.cos[k], std::cos(k * tau), 4e-15 * (k + 1)) << tau << " k " << k;
        }
    }
}

// The subdivision search against the companion-matrix eigenvalues it replaced: on random
// series of degree 1 to 4 and levels across their range, the same roots to 1e-12 (cases
// with two roots closer than 1e-6, where either method's tangency handling decides, are
// left out; there are none in practice at these seeds, and the test counts them).
TEST(TrigSeries, RootsMatchTheCompanionMatrixEigenvalues) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-1, 1);
    int compared = 0, rootsCompared = 0, closePairs = 0;
    for (int degree = 1; degree <= 4; ++degree)
        for (int trial = 0; trial < 500; ++trial) {
            const TrigSeries s = makeRandomSeries(rng, degree);
            const double level = s.getMean() + 1.5 * u(rng);
            const std::vector<double> reference = findRootsByEigenvalues(s, level);
            bool close = false;
            for (size_t i = 0; i < reference.size(); ++i) {
                const double next = i + 1 < reference.size() ? reference[i + 1] : reference[0] + 2 * kPi;
                close = close || next - reference[i] < 1e-6;
            }
            if (close) {
                ++closePairs;
                continue;
            }
            const std::vector<double> roots = s.findRoots(level);
            ASSERT_EQ(roots.size(), reference.size()) << "degree " << degree << " trial " << trial;
            for (size_t i = 0; i < roots.size(); ++i) EXPECT_NEAR(roots[i], reference[i], 1e-12);
            ++compared;
            rootsCompared += int(roots.size());
        }
    EXPECT_GT(rootsCompared, 3000);
    EXPECT_LT(closePairs, 5);
    EXPECT_EQ(compared + closePairs, 2000);
}

// A pair of roots 1e-4 apart about a maximum that sits on the search's first grid point
// (τ = 0, where the bound on s'' is reached exactly): both found.
// A coefficient or level that is not finite has no roots (a NaN makes every pruning
// comparison false; the search must not subdivide without end).
TEST(TrigSeries, NonFiniteCoefficientsHaveNoRoots) {
    const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
    for (int c = 0; c < 5; ++c)
        for (double bad : {nan, inf, -inf}) {
            TrigSeries s = makeSeries(0.1, 1.0, -0.5, 0.3, 0.2);
            (c == 0 ? s.updMean() : c % 2 ? s.updCos((c + 1) / 2) : s.updSin(c / 2)) = bad;
            EXPECT_TRUE(s.findRoots(0.2).empty()) << "coefficient " << c << " = " << bad;
        }
    EXPECT_TRUE(makeSeries(0.1, 1.0, -0.5, 0.3, 0.2).findRoots(nan).empty());
    EXPECT_EQ(makeSeries(0.1, 1.0, -0.5, 0.3, 0.2).findRoots(0.2).size() % 2, 0u);  // finite: crossings in pairs
    EXPECT_FALSE(makeSeries(0.1, 1.0, -0.5, 0.3, 0.2).findRoots(0.2).empty());
}

TEST(TrigSeries, FindsCloseRootPairs) {
    const TrigSeries s = TrigSeries::cosine(1) + TrigSeries::cosine(2, 0.2);  // max 1.2 at τ = 0
    const double top = s.evaluate(0.0), curvature = 1 + 4 * 0.2;              // s ≈ top − curvature·τ²/2
    const double gap = 1e-4, level = top - curvature * gap * gap / 8;         // roots at ±gap/2
    const std::vector<double> roots = s.findRoots(level);
    ASSERT_EQ(roots.size(), 2u);  // one just above 0, one just below 2π
    EXPECT_NEAR(roots.front(), gap / 2, 1e-10);
    EXPECT_NEAR(roots.back(), 2 * kPi - gap / 2, 1e-10);
}

// The moments give the same integrals as the products they stand for.
TEST(TrigSeries, MomentsIntegrateLikeTheProducts) {
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(-1, 7);
    for (int trial = 0; trial < 200; ++trial) {
        const TrigSeries s = makeRandomSeries(rng, 1 + trial % 4);
        double t0 = u(rng), t1 = u(rng), t2 = u(rng);
        TrigSeries::Moments m;
        m.add(TrigSeries::Angles(t0), TrigSeries::Angles(t1), 0.7);
        m.add(TrigSeries::Angles(t1), TrigSeries::Angles(t2), -1.3);
        m.addPeriod(0.4);
        auto byProduct = [&](const TrigSeries& p) {
            return 0.7 * p.integrate(t0, t1) - 1.3 * p.integrate(t1, t2) + 0.4 * 2 * kPi * p.getMean();
        };
        EXPECT_NEAR(s.integrate(m), byProduct(s), 1e-13);
        for (int k = 1; k <= 4; ++k) {
            EXPECT_NEAR(s.integrateTimesHarmonic(m, k, false), byProduct(s * TrigSeries::cosine(k)), 1e-13);
            EXPECT_NEAR(s.integrateTimesHarmonic(m, k, true), byProduct(s * TrigSeries::sine(k)), 1e-13);
        }
    }
}

TEST(HarmonicForce, UnilateralContactMatchesQuadrature) {
    // Contact f = k·max(0, −d − c) (side bearing with clearance c), d with two harmonics.
    const double k = 1e7, c = 0.004;
    PiecewiseLinearLaw law{{-c}, {-k * c, 0.0}, {-k, 0.0}, 0.0};
    const TrigSeries d = makeSeries(-0.001, 0.006, 0.002, 0.0015, -0.001);
    const TrigSeries exact = calcForceHarmonics(law, d, 3.0, TrigSeries::constant(1), 2);
    const TrigSeries quad = calcForceHarmonicsNumerically(law, d, 3.0, TrigSeries::constant(1), 2, 400000);
    ASSERT_GT(std::abs(exact.getCos(1)), 1e3);
    expectSameCoefficients(exact, quad, 1e-6 * k * c);
    // Open all the time: zero force.
    const TrigSeries open = calcForceHarmonics(law, makeSeries(0.01, 0.001, 0, 0, 0), 3.0, TrigSeries::constant(1), 2);
    expectSameCoefficients(open, TrigSeries(2), 0.0);
}

TEST(HarmonicForce, WeightedAndViscousLawsMatchQuadrature) {
    // Bilinear spring with viscous term, times a roll-angle weight (moment arm).
    PiecewiseLinearLaw law{{0.0}, {0.0, 0.0}, {1e5, 4e6}, 2e3};
    const TrigSeries d = makeSeries(0.0005, 0.002, -0.001, 0.0007, 0.0003);
    const TrigSeries w = makeSeries(0.01, 0.05, 0.02, -0.01, 0.004);
    const TrigSeries exact = calcForceHarmonics(law, d, 4.0, w, 2);
    const TrigSeries quad = calcForceHarmonicsNumerically(law, d, 4.0, w, 2, 400000);
    expectSameCoefficients(exact, quad, 1e-5);
}

TEST(HarmonicForce, CoulombMatchesQuadratureAndTheClassicalDescribingFunction) {
    CoulombLaw law{4000};
    const TrigSeries d = makeSeries(0.2, 0.01, 0.004, 0.003, -0.002);
    const TrigSeries exact = calcForceHarmonics(law, d, 2.0, TrigSeries::constant(1), 2);
    const TrigSeries quad = calcForceHarmonicsNumerically(law, d, 2.0, TrigSeries::constant(1), 2, 400000);
    // The midpoint rule on a step is only first order: error ~ F_c·h/π ≈ 0.06 N here.
    expectSameCoefficients(exact, quad, 0.1);
    // Pure sine displacement d = X sin τ: the Coulomb force's fundamental is −(4F_c/π)·cos τ.
    const TrigSeries pure = calcForceHarmonics(law, TrigSeries::sine(1, 0.01), 2.0, TrigSeries::constant(1), 2);
    EXPECT_NEAR(pure.getCos(1), -4 * 4000 / kPi, 1e-9);
    EXPECT_NEAR(pure.getSin(1), 0.0, 1e-9);
    EXPECT_NEAR(pure.getMean(), 0.0, 1e-9);
}

namespace {
/// A wedge displacement with a minor loop (turning points at d ≈ 15.21, 7.196, 7.207 and
/// 7.050 mm).
const TrigSeries kMinorLoop = makeSeries(0.01, 0.004, 0.0003, 0.0012, 0.0001);
}  // namespace

TEST(HarmonicForce, ElastoPlasticFrictionMatchesSteppedHysteresis) {
    const ElastoPlasticLaw law{4000, 4000 / 2.5e-4};
    // Slides both ways (range ≫ 2F_c/k_b, two turning points); and with a minor loop: four
    // turning points, the swing between the middle two (1e-5 m) far below 2F_c/k_b, so it
    // sticks through it and the loop's memory carries on.
    const TrigSeries w = makeSeries(0.01, 0.05, 0.02, -0.01, 0.004);
    for (const TrigSeries& d : {makeSeries(0.01, 0.004, 0.002, 0.0012, -0.0018), kMinorLoop}) {
        for (const TrigSeries& weight : {TrigSeries::constant(1), w}) {
            const TrigSeries exact = calcForceHarmonics(law, d, 2.0, std::vector<TrigSeries>{weight}, 2)[0];
            const TrigSeries stepped = calcForceHarmonicsNumerically(law, d, weight, 2, 400000);
            expectSameCoefficients(exact, stepped, 0.1);
        }
    }
    ASSERT_EQ(kMinorLoop.derivative().findRoots(0).size(), 4u);
    // Large amplitude: tends to the ideal Coulomb element.
    const TrigSeries big = TrigSeries::sine(1, 0.05);
    const TrigSeries ep = calcForceHarmonics(law, big, 2.0, std::vector<TrigSeries>{TrigSeries::constant(1)}, 2)[0];
    const TrigSeries coulomb = calcForceHarmonics(CoulombLaw{4000}, big, 2.0, TrigSeries::constant(1), 2);
    EXPECT_NEAR(std::hypot(ep.getCos(1), ep.getSin(1)), std::hypot(coulomb.getCos(1), coulomb.getSin(1)), 0.02 * 4000);
    // Small amplitude: sticks, a linear spring about mid-range (no creep, no mean force).
    const TrigSeries small = makeSeries(0.3, 1e-5, 0, 0, 0);
    const TrigSeries st = calcForceHarmonics(law, small, 2.0, std::vector<TrigSeries>{TrigSeries::constant(1)}, 2)[0];
    EXPECT_NEAR(st.getMean(), 0.0, 1e-9);
    EXPECT_NEAR(st.getCos(1), -law.stiffness * 1e-5, 1e-6);
}

namespace {
/// Every derivative of calcForceHarmonicsDerivatives against central differences of
/// calcForceHarmonics (step h in d's and the weights' coefficients and in ω), to `tol`
/// of the largest derivative of its kind.
template <class Law>
void expectDerivativesMatchCentralDifferences(const Law& law, const TrigSeries& d, double omega,
                                              const std::vector<TrigSeries>& weights, double h, double tol) {
    const ForceHarmonicsDerivatives D = calcForceHarmonicsDerivatives(law, d, omega, weights, 2);
    ASSERT_EQ(D.byDisplacement.size(), weights.size());
    auto harmonicsAt = [&](const TrigSeries& dd, double w, const std::vector<TrigSeries>& ws) {
        return calcForceHarmonics(law, dd, w, ws, 2);
    };
    auto compare = [&](const TrigSeries& exact, const TrigSeries& plus, const TrigSeries& minus, double step,
                       double scale, const std::string& what) {
        for (int c = 0; c < 5; ++c) {
            const double fd = (plus.getCoefficient(c) - minus.getCoefficient(c)) / (2 * step);
            EXPECT_NEAR(exact.getCoefficient(c), fd, tol * scale) << what << ", coefficient " << c;
        }
    };
    auto largest = [](const auto& seriesList) {
        double m = 0;
        for (const TrigSeries& s : seriesList)
            for (int c = 0; c < 5; ++c) m = std::max(m, std::abs(s.getCoefficient(c)));
        return m;
    };
    double scaleD = 0;
    for (const auto& byD : D.byDisplacement) scaleD = std::max(scaleD, largest(byD));
    ASSERT_GT(scaleD, 0);
    for (int m = 0; m < 5; ++m) {
        TrigSeries dp = d, dm = d;
        const double step = h * std::max(1e-3, std::abs(d.getCoefficient(m)));
        (m == 0 ? dp.updMean() : m % 2 ? dp.updCos((m + 1) / 2) : dp.updSin(m / 2)) += step;
        (m == 0 ? dm.updMean() : m % 2 ? dm.updCos((m + 1) / 2) : dm.updSin(m / 2)) -= step;
        const auto plus = harmonicsAt(dp, omega, weights), minus = harmonicsAt(dm, omega, weights);
        for (size_t j = 0; j < weights.size(); ++j)
            compare(D.byDisplacement[j][m], plus[j], minus[j], step, scaleD,
                    "d/dd_" + std::to_string(m) + ", weight " + std::to_string(j));
    }
    const double scaleW = largest(D.byWeight);
    for (int m = 0; m < 5; ++m) {  // a weight's derivative, through the last weight (the same for each)
        std::vector<TrigSeries> wp = weights, wm = weights;
        TrigSeries& p = wp.back();
        TrigSeries& q = wm.back();
        const double step = 1e-6;
        (m == 0 ? p.updMean() : m % 2 ? p.updCos((m + 1) / 2) : p.updSin(m / 2)) += step;
        (m == 0 ? q.updMean() : m % 2 ? q.updCos((m + 1) / 2) : q.updSin(m / 2)) -= step;
        compare(D.byWeight[m], harmonicsAt(d, omega, wp).back(), harmonicsAt(d, omega, wm).back(), step, scaleW,
                "d/dw_" + std::to_string(m));
    }
    const double stepOmega = 1e-6 * omega;
    const auto plus = harmonicsAt(d, omega + stepOmega, weights), minus = harmonicsAt(d, omega - stepOmega, weights);
    for (size_t j = 0; j < weights.size(); ++j)
        compare(D.byOmega[j], plus[j], minus[j], stepOmega, std::max(1.0, largest(D.byOmega)), "d/domega");
}
}  // namespace

TEST(HarmonicForce, DerivativesOfEveryLawMatchCentralDifferences) {
    const TrigSeries d = makeSeries(-0.001, 0.006, 0.002, 0.0015, -0.001);
    const std::vector<TrigSeries> weights{TrigSeries::constant(1), makeSeries(0.01, 0.05, 0.02, -0.01, 0.004),
                                          makeSeries(-0.02, 0.01, -0.03, 0.006, 0.002)};
    // A unilateral contact with clearance (open part of the period), a viscous bilinear spring.
    const double k = 1e7, c = 0.004;
    expectDerivativesMatchCentralDifferences(PiecewiseLinearLaw{{-c}, {-k * c, 0.0}, {-k, 0.0}, 0.0}, d, 3.0, weights,
                                             1e-6, 1e-6);
    expectDerivativesMatchCentralDifferences(PiecewiseLinearLaw{{0.0}, {0.0, 0.0}, {1e5, 4e6}, 2e3}, d, 4.0, weights,
                                             1e-6, 1e-6);
    // Coulomb: the moving jumps.
    expectDerivativesMatchCentralDifferences(CoulombLaw{4000}, d, 2.0, weights, 1e-6, 1e-6);
    // Elasto-plastic: sliding both ways, sliding with a minor loop stuck through (the
    // loop's memory in the stuck pieces' constants), and sticking throughout.
    const ElastoPlasticLaw friction{4000, 4000 / 2.5e-4};
    expectDerivativesMatchCentralDifferences(friction, makeSeries(0.01, 0.004, 0.002, 0.0012, -0.0018), 2.0, weights,
                                             1e-6, 1e-6);
    expectDerivativesMatchCentralDifferences(friction, kMinorLoop, 2.0, weights, 1e-6, 1e-6);
    expectDerivativesMatchCentralDifferences(friction, makeSeries(0.3, 1e-5, 2e-6, 1e-6, 0), 2.0, weights, 1e-6, 1e-6);
    // d constant: no force, and the derivatives of the smallest motion (sticking).
    const ForceHarmonicsDerivatives still =
        calcForceHarmonicsDerivatives(friction, makeSeries(0.01, 0, 0, 0, 0), 2.0, weights, 2);
    ASSERT_EQ(still.byDisplacement[0].size(), 5u);
    EXPECT_NEAR(still.byDisplacement[0][1].getCos(1), -friction.stiffness, 1e-9 * friction.stiffness);
    EXPECT_NEAR(still.byDisplacement[0][0].getMean(), 0.0, 1e-9 * friction.stiffness);
}
