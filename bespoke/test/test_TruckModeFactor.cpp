#include "bespoke/TruckModeFactor.h"
#include "bespoke/TruckEquilibrium.h"

#include <gtest/gtest.h>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <random>

using namespace rockroll;
using truck_equilibrium_detail::ModeFactor;
using truck_equilibrium_detail::ModeFactorWithRoom;

namespace {
using Vector = Eigen::Matrix<double, ModeFactor::N, 1>;

/// A hand-made factorization: unit L and U with a few nonzero entries off the diagonal,
/// permutations that reverse and rotate, and row scales of 1, 0 and 4.
void makeFactor(ModeFactorWithRoom& room) {
    constexpr int n = ModeFactor::N;
    ModeFactor& f = room.factor;
    ModeFactor::Lu lu = ModeFactor::Lu::Identity();
    lu(2, 0) = 0.5, lu(3, 2) = -0.25, lu(7, 1) = 2, lu(14, 9) = -3, lu(6, 5) = -0.0;  // L
    lu(0, 4) = 0.3, lu(5, 11) = -1.5, lu(9, 10) = 0.125, lu(1, 13) = -0.0;            // U
    lu(4, 4) = -2, lu(10, 10) = 8;
    for (int i = 0; i < n; ++i) f.p[size_t(i)] = n - 1 - i, f.q[size_t(i)] = (i + 3) % n;
    f.rowScale.setOnes();
    f.rowScale[6] = 0, f.rowScale[8] = 4;
    f.invertible = true;
    f.compress(lu);
}

void expectSameBits(const Vector& a, const Vector& b, const char* what) {
    for (int i = 0; i < ModeFactor::N; ++i) {
        std::uint64_t x, y;
        std::memcpy(&x, &a[i], 8), std::memcpy(&y, &b[i], 8);
        EXPECT_EQ(x, y) << what << ": unknown " << i << ", " << a[i] << " / " << b[i];
    }
}
}  // namespace

// The factors are kept as their nonzero entries and the places of their −0s: getLu
// gives back what compress was given, bit for bit.
TEST(TruckModeFactor, KeepsTheFactorsBitForBit) {
    ModeFactor::Lu lu;
    std::mt19937 rng(3);
    std::uniform_int_distribution<int> kind(0, 3);
    std::normal_distribution<double> normal;
    for (int i = 0; i < ModeFactor::N; ++i)
        for (int j = 0; j < ModeFactor::N; ++j) {
            const int k = kind(rng);
            lu(i, j) = k == 0 ? 0.0 : k == 1 ? -0.0 : normal(rng);
        }
    ModeFactorWithRoom room;
    ModeFactor& f = room.factor;
    f.compress(lu);
    const ModeFactor::Lu back = f.getLu();
    EXPECT_EQ(std::memcmp(back.data(), lu.data(), sizeof(double) * ModeFactor::N * ModeFactor::N), 0);
    int kept = 0;
    for (int i = 0; i < ModeFactor::N; ++i)
        for (int j = 0; j < ModeFactor::N; ++j) kept += i != j && lu(i, j) != 0 ? 1 : 0;
    EXPECT_EQ(int(f.upperStart[ModeFactor::N]), kept);
    EXPECT_EQ(ModeFactor::getEntryCount(lu), kept);
    EXPECT_EQ(ModeFactor::getBytes(lu), sizeof(ModeFactor) + sizeof(double) * size_t(kept));
}

// A factorization needs room for its nonzero entries alone: compress writes no value
// beyond getEntryCount's (the room after them keeps a marker), and the solve reads none.
TEST(TruckModeFactor, KeepsOnlyTheEntriesItCounts) {
    ModeFactorWithRoom room;
    makeFactor(room);
    ModeFactor::Lu lu = room.factor.getLu();
    const int n = ModeFactor::getEntryCount(lu);
    ASSERT_EQ(n, 7);  // makeFactor's nonzero entries off the diagonal
    ModeFactorWithRoom again;
    const double marker = 12345.0;
    again.values.fill(marker);
    again.factor.compress(lu);
    for (int k = n; k < ModeFactor::kMaxEntries; ++k) ASSERT_EQ(again.values[size_t(k)], marker) << k;
    EXPECT_EQ(std::memcmp(again.factor.getLu().data(), lu.data(), sizeof lu), 0);
}

// The sparse substitution equals the dense one, bit for bit, on finite right-hand sides.
TEST(TruckModeFactor, SparseSolveEqualsTheDenseOne) {
    ModeFactorWithRoom room;
    makeFactor(room);
    const ModeFactor& f = room.factor;
    const Vector colScale = Vector::LinSpaced(1e-3, 1e4);
    std::mt19937 rng(7);
    std::normal_distribution<double> normal;
    for (int c = 0; c < 200; ++c) {
        Vector b;
        for (int i = 0; i < ModeFactor::N; ++i) b[i] = c % 3 == 0 && i % 2 ? 0.0 : normal(rng);
        expectSameBits(f.solve(b, colScale), f.solveDense(b, colScale), "random b");
    }
}

// A row that starts at −0 and whose nonzero entries add nothing: the dense loop's
// −0 − 0·(−1) is +0, the sparse sum alone stays −0. solve takes the per-row path when the
// scaled b holds a −0 (ModeFactor::solve), and gives the dense loop's +0.
TEST(TruckModeFactor, NegativeZeroInTheRightHandSideGivesTheDenseLoopsZero) {
    ModeFactorWithRoom room;
    makeFactor(room);
    const ModeFactor& f = room.factor;
    const Vector colScale = Vector::Ones();
    Vector b = Vector::Zero();
    b[14] = -1;    // c[0] (p reverses the rows)
    b[13] = -0.0;  // c[1]: row 1's only term below the diagonal, lu(1, 0) = 0, the sparse sum leaves out
    const Vector dense = f.solveDense(b, colScale);
    expectSameBits(f.solve(b, colScale), dense, "b with −0");
    expectSameBits(f.solveChecked(b, colScale), dense, "b with −0, per-row tests");
    EXPECT_FALSE(std::signbit(dense[f.q[1]]));
}

// A right-hand side that is not finite: solve gives what the per-row tests give (the
// dense loop's sum for each row that is not finite), not the sparse sums' values.
TEST(TruckModeFactor, NonFiniteRightHandSideTakesThePerRowPath) {
    ModeFactorWithRoom room;
    makeFactor(room);
    const ModeFactor& f = room.factor;
    const Vector colScale = Vector::Ones();
    const double inf = std::numeric_limits<double>::infinity();
    for (double v : {inf, -inf, std::numeric_limits<double>::quiet_NaN()}) {
        Vector b = Vector::Ones();
        b[14] = v, b[13] = v;  // rows 0 and 1 after the permutation: row 1's dense sum is v − 0·v = NaN
        const Vector x = f.solve(b, colScale);
        expectSameBits(x, f.solveChecked(b, colScale), "b not finite");
        EXPECT_TRUE(std::isnan(x[f.q[1]])) << v;
    }
}

// The screen's single-precision rows: h·b and |h|·|b| equal long-double sums over the
// kept entries to within the double rounding the screen allows for (kScreenRelativeError
// of |h|·|b|), the padding entry is 0, and the rows' rounding from double precision is
// within kScreenRowRounding·|h̃|·|b| of the double rows' h·b: at scales from 1e-30 to 1e30,
// with zeros and both signs.
TEST(TruckModeFactor, ScreenRowsRoundWithinTheScreensBound) {
    std::mt19937 rng(11);
    std::normal_distribution<double> normal;
    std::uniform_int_distribution<int> exponent(-30, 30), zero(0, 4);
    ModeFactorWithRoom room;
    ModeFactor& f = room.factor;
    double worstRounding = 0, worstSum = 0;
    for (int c = 0; c < 2000; ++c) {
        Eigen::Matrix<double, truck_equilibrium_detail::kCheckedQuantityCount, ModeFactor::N, Eigen::RowMajor> rows;
        const double scale = std::pow(10.0, exponent(rng));
        for (int q = 0; q < rows.rows(); ++q)
            for (int j = 0; j < ModeFactor::N; ++j) rows(q, j) = zero(rng) == 0 ? 0.0 : scale * normal(rng);
        f.setCheckRows(rows);
        double b[16];
        for (int j = 0; j < ModeFactor::N; ++j) b[j] = zero(rng) == 0 ? 0.0 : std::pow(10.0, exponent(rng) / 6) * normal(rng);
        b[ModeFactor::N] = 0;
        for (int q = 0; q < rows.rows(); ++q) {
            const ModeFactor::ScreenRow& row = f.checkRows[size_t(q)];
            ASSERT_EQ(row.h[ModeFactor::N], 0.0f);
            long double kept = 0, keptAbs = 0, exact = 0;
            for (int j = 0; j < ModeFactor::N; ++j) {
                kept += (long double)row.h[size_t(j)] * b[j];
                keptAbs += std::abs((long double)row.h[size_t(j)] * b[j]);
                exact += (long double)rows(q, j) * b[j];
            }
            const double size = row.dotAbs(b);
            EXPECT_NEAR(double(keptAbs), size, kScreenRelativeError * size);
            if (size == 0) {
                EXPECT_EQ(row.dot(b), 0.0);
                continue;
            }
            worstSum = std::max(worstSum, double(std::abs(row.dot(b) - kept)) / (kScreenRelativeError * size));
            worstRounding = std::max(worstRounding, double(std::abs(kept - exact)) / (kScreenRowRounding * size));
        }
    }
    EXPECT_LE(worstSum, 1.0);
    EXPECT_LE(worstRounding, 1.0);
    EXPECT_GT(worstRounding, 0.3);  // the bound is near what rounding to nearest can reach
    std::printf("screen rows: the sums' rounding %.3g, the rows' rounding %.3g of their bounds\n", worstSum,
                worstRounding);
}
