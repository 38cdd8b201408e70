#include "bespoke/FullPivotLu.h"
#include "bespoke/TruckEquilibrium.h"
#include "scenarios/ScenarioRun.h"

#include <gtest/gtest.h>
#include <Eigen/LU>
#include <cmath>
#include <cstring>
#include <limits>
#include <string>
#include <random>

using namespace rockroll;

namespace {

/// FullPivotLu against Eigen's FullPivLU: the factors bit for bit, the permutations,
/// the rank and invertibility.
template <int n>
void expectEqualsEigen(const Eigen::Matrix<double, n, n>& a, const std::string& what) {
    const FullPivotLu<n> mine(a);
    const Eigen::FullPivLU<Eigen::Matrix<double, n, n>> eigen(a);
    const Eigen::Matrix<double, n, n> lu = eigen.matrixLU();
    ASSERT_EQ(std::memcmp(mine.getMatrixLU().data(), lu.data(), sizeof(double) * n * n), 0) << what;
    for (int i = 0; i < n; ++i) {
        ASSERT_EQ(mine.getRowPermutation()[size_t(i)], int(eigen.permutationP().indices()[i])) << what;
        ASSERT_EQ(mine.getColumnPermutation()[size_t(i)], int(eigen.permutationQ().indices()[i])) << what;
    }
    ASSERT_EQ(mine.getRank(), int(eigen.rank())) << what;
    ASSERT_EQ(mine.isInvertible(), eigen.isInvertible()) << what;
}

template <int n>
void checkRandomMatrices(std::mt19937& rng, int count) {
    using M = Eigen::Matrix<double, n, n>;
    std::normal_distribution<double> normal;
    std::uniform_int_distribution<int> small(-2, 2), pick(0, n - 1);
    std::uniform_real_distribution<double> unit(0, 1);
    for (int c = 0; c < count; ++c) {
        M a;
        const int kind = c % 5;
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                switch (kind) {
                case 0: a(i, j) = normal(rng); break;                                // general
                case 1: a(i, j) = small(rng); break;                                 // ties, often singular
                case 2: a(i, j) = unit(rng) < 0.7 ? 0.0 : normal(rng) * 1e4; break;  // sparse, scaled
                case 3: a(i, j) = unit(rng) < 0.5 ? 0.0 : double(small(rng)); break; // sparse ties
                default: a(i, j) = normal(rng) * std::pow(10.0, double(small(rng)) * 4); break;
                }
            }
        if (c % 7 == 0) a.row(pick(rng)) = a.row(pick(rng));  // a repeated row: rank deficient
        if (c % 11 == 0) a.col(pick(rng)).setZero();
        if (c % 13 == 0) a.row(pick(rng)) = -0.0 * a.row(pick(rng));  // signed zeros
        expectEqualsEigen<n>(a, "random matrix " + std::to_string(c));
        if (::testing::Test::HasFatalFailure()) return;
    }
}

}  // namespace

TEST(FullPivotLu, FactorsEqualEigensBitForBit) {
    std::mt19937 rng(20261207);
    checkRandomMatrices<15>(rng, 4000);
    checkRandomMatrices<4>(rng, 2000);
    checkRandomMatrices<1>(rng, 50);
    expectEqualsEigen<15>(Eigen::Matrix<double, 15, 15>::Zero(), "zero matrix");
    expectEqualsEigen<15>(Eigen::Matrix<double, 15, 15>::Identity(), "identity");
    expectEqualsEigen<15>(Eigen::Matrix<double, 15, 15>::Ones(), "ones");
}

TEST(FullPivotLu, MatrixWithANaNIsFactoredByEigen) {
    Eigen::Matrix<double, 4, 4> a = Eigen::Matrix<double, 4, 4>::Identity();
    a(2, 1) = std::numeric_limits<double>::quiet_NaN();
    a(0, 3) = std::numeric_limits<double>::infinity();
    expectEqualsEigen<4>(a, "NaN and infinity");
}

// Every truck mode's matrix, as the reduced model factors it (TruckEquilibrium.cpp).
TEST(FullPivotLu, EveryTruckModeMatrixFactorsAsEigens) {
    const TruckGeometry g(makeCarParameters("70ton-loaded"));
    TruckGeometry heavy = g;
    heavy.bolsterWeight = 5000, heavy.wheelsetWeight = 30000;
    int singular = 0;
    for (const TruckGeometry& geometry : {g, heavy})
        for (const TruckMode& mode : enumerateTruckModes()) {
            if (!(TruckModeCache::getMatrixClass(mode) == mode)) continue;
            const Eigen::Matrix<double, 15, 15> a = calcScaledModeMatrix(geometry, mode);
            expectEqualsEigen<15>(a, mode.describe());
            singular += !FullPivotLu<15>(a).isInvertible();
            if (HasFatalFailure()) return;
        }
    EXPECT_GT(singular, 0);  // the singular classes are among those compared
}
