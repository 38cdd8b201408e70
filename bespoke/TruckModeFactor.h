#pragma once
// One truck mode's factorization and its substitutions (TruckEquilibrium.cpp): the
// matrix's full-pivoting LU factors, kept as rows and as their nonzero entries, and the
// screen's rows. Test: bespoke/test/test_TruckModeFactor.cpp.
#include <Eigen/Core>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#ifdef __SSE2__
#include <emmintrin.h>
#endif

namespace rockroll {
// Named, not anonymous: TruckModeCache::Factor (declared in TruckEquilibrium.h) derives from it.
namespace truck_equilibrium_detail {
/// The truck system's unknowns (TruckEquilibrium.cpp, enum Unknown) and the quantities
/// its consistency checks read (enum CheckedQuantity).
inline constexpr int kUnknownCount = 15;
inline constexpr int kCheckedQuantityCount = 18;

/// The scaled, row-equilibrated matrix's factorization: a function of the mode and
/// the geometry only (the inputs enter b alone), so TruckModeCache keeps one per mode.
///
/// Laid out for the search's memory traffic: what a screen reads first (invertible, then
/// checkRows), then what a solve reads. The values of the factors' nonzero entries follow
/// the object itself, as many as the factors hold (getEntryCount; TruckModeCache's arena
/// gives each factorization that much room, ModeFactorWithRoom room for all). L and U
/// themselves are not kept: getLu rebuilds them, bit for bit (the zeros' signs from a
/// mask), for the rare paths that need every entry. A run meets about a thousand of these,
/// in fresh memory (bench/README.md, "The search's memory").
struct alignas(64) ModeFactor {
    static constexpr int N = kUnknownCount;
    /// The most nonzero entries off the diagonal: every one of L's and U's.
    static constexpr int kMaxEntries = N * (N - 1);
    using Lu = Eigen::Matrix<double, N, N, Eigen::RowMajor>;
    ModeFactor() = default;
    /// Not copyable: the entries' values live after the object (getValues).
    ModeFactor(const ModeFactor&) = delete;
    ModeFactor& operator=(const ModeFactor&) = delete;

    bool invertible = false;
    /// The nonzero off-diagonal entries of L, then of U, row by row (about 40 of L's 105
    /// and 46 of U's 120 on the default car): row i's are [start[i], start[i + 1]) of
    /// column and getValues().
    std::array<std::uint8_t, N + 1> lowerStart, upperStart;
    std::array<std::uint8_t, N> p, q;  ///< FullPivLU's row and column permutations
    /// One row of the screen's, h, in single precision (rounded to nearest; the screen's
    /// error bound covers the rounding: kScreenRowRounding in TruckEquilibrium.h), on one
    /// 64-byte line: N entries and a 0.
    static_assert(N < 16, "a screen row holds N entries and a 0 in 16 floats");
    struct alignas(64) ScreenRow {
        std::array<float, 16> h;
        /// h·b, b padded to 16 entries with a 0 (in four partial sums: any order's
        /// rounding is within the screen's kScreenRelativeError).
        double dot(const double* b16) const { return sum<false>(b16); }
        /// |h|·|b|, as dot.
        double dotAbs(const double* b16) const { return sum<true>(b16); }

    private:
        template <bool Abs>
        double sum(const double* b16) const {
#ifdef __SSE2__
            __m128d a0 = _mm_setzero_pd(), a1 = _mm_setzero_pd();
            const __m128d noSign = _mm_castsi128_pd(_mm_set1_epi64x(0x7fffffffffffffffLL));
            for (int j = 0; j < 16; j += 4) {
                const __m128 h4 = _mm_load_ps(h.data() + j);
                __m128d p0 = _mm_mul_pd(_mm_cvtps_pd(h4), _mm_loadu_pd(b16 + j));
                __m128d p1 = _mm_mul_pd(_mm_cvtps_pd(_mm_movehl_ps(h4, h4)), _mm_loadu_pd(b16 + j + 2));
                if constexpr (Abs) p0 = _mm_and_pd(p0, noSign), p1 = _mm_and_pd(p1, noSign);
                a0 = _mm_add_pd(a0, p0), a1 = _mm_add_pd(a1, p1);
            }
            const __m128d a = _mm_add_pd(a0, a1);
            return _mm_cvtsd_f64(_mm_add_sd(a, _mm_unpackhi_pd(a, a)));
#else
            double s[4] = {};
            for (int j = 0; j < 16; ++j) {
                const double p = double(h[size_t(j)]) * b16[j];
                s[j % 4] += Abs ? std::abs(p) : p;
            }
            return (s[0] + s[2]) + (s[1] + s[3]);
#endif
        }
    };
    /// The screen's rows: each checked quantity (CheckedQuantity) is h·b plus its
    /// Kinematics constant, h its row of G·A⁻¹ with G the quantities' rows in the unknowns.
    /// Only for invertible matrices. In single precision: half the memory a screen reads.
    std::array<ScreenRow, kCheckedQuantityCount> checkRows;
    /// Keeps the rows of `rows` (G·A⁻¹ in double precision) as checkRows.
    void setCheckRows(const Eigen::Matrix<double, kCheckedQuantityCount, N, Eigen::RowMajor>& rows) {
        for (int q = 0; q < kCheckedQuantityCount; ++q) {
            for (int j = 0; j < N; ++j) checkRows[size_t(q)].h[size_t(j)] = float(rows(q, j));
            checkRows[size_t(q)].h[N] = 0;
        }
    }
    Eigen::Matrix<double, N, 1> rowScale;  ///< each scaled row's largest |coefficient| (0: row left as is)
    std::array<double, N> diagonal;        ///< U's diagonal
    std::array<std::uint64_t, (N * N + 63) / 64> negativeZero;  ///< bit i·N + j: L or U's entry (i, j) is −0
    std::array<std::uint8_t, kMaxEntries> column;

    /// The values of the nonzero entries, right after the object.
    const double* getValues() const { return reinterpret_cast<const double*>(this + 1); }
    double* updValues() { return reinterpret_cast<double*>(this + 1); }
    /// The nonzero entries lu (L and U, N × N, either storage order) holds off its
    /// diagonal: the values compress keeps.
    template <class Matrix>
    static int getEntryCount(const Matrix& lu) {
        return int((lu.array() != 0).count() - (lu.diagonal().array() != 0).count());
    }
    /// The room a ModeFactor needs for lu's factors: the object and its values.
    template <class Matrix>
    static std::size_t getBytes(const Matrix& lu) {
        return sizeof(ModeFactor) + sizeof(double) * getEntryCount(lu);
    }

    /// Keeps lu's diagonal, its nonzero entries and the places of its −0s; the object must
    /// have room after it for getEntryCount(lu) values.
    template <class Matrix>
    void compress(const Matrix& lu) {
        int n = 0;
        double* value = updValues();
        negativeZero.fill(0);
        auto keep = [&](int i, int j) {
            const double v = lu(i, j);
            if (v != 0) column[size_t(n)] = std::uint8_t(j), value[n++] = v;
            else if (std::signbit(v)) negativeZero[size_t((i * N + j) / 64)] |= std::uint64_t(1) << ((i * N + j) % 64);
        };
        for (int i = 0; i < N; ++i) {
            lowerStart[i] = std::uint8_t(n);
            for (int j = 0; j < i; ++j) keep(i, j);
        }
        lowerStart[N] = std::uint8_t(n);
        for (int i = 0; i < N; ++i) {
            diagonal[i] = lu(i, i);
            upperStart[i] = std::uint8_t(n);
            for (int j = i + 1; j < N; ++j) keep(i, j);
        }
        upperStart[N] = std::uint8_t(n);
    }

    /// L (below the diagonal) and U, as compress was given them, bit for bit.
    Lu getLu() const {
        const double* value = getValues();
        Lu lu;
        for (int i = 0; i < N; ++i)
            for (int j = 0; j < N; ++j)
                lu(i, j) = (negativeZero[size_t((i * N + j) / 64)] >> ((i * N + j) % 64)) & 1 ? -0.0 : 0.0;
        for (int i = 0; i < N; ++i) {
            lu(i, i) = diagonal[i];
            for (int k = lowerStart[i]; k < lowerStart[i + 1]; ++k) lu(i, column[k]) = value[k];
            for (int k = upperStart[i]; k < upperStart[i + 1]; ++k) lu(i, column[k]) = value[k];
        }
        return lu;
    }

    /// c = P·b with each row divided by its rowScale: what the substitutions start from.
    void loadRightHandSide(const Eigen::Matrix<double, N, 1>& b, double* c) const {
        for (int i = 0; i < N; ++i) c[p[i]] = rowScale[i] > 0 ? b[i] / rowScale[i] : b[i];
    }
    /// x = Q·c with each unknown multiplied by its column scale.
    Eigen::Matrix<double, N, 1> unloadSolution(const double* c, const Eigen::Matrix<double, N, 1>& colScale) const {
        Eigen::Matrix<double, N, 1> x;
        for (int i = 0; i < N; ++i) x[q[i]] = colScale[q[i]] * c[i];
        return x;
    }

    /// FullPivLU::solve's steps (x = Q·U⁻¹·L⁻¹·P·b) by plain substitution: Eigen's
    /// blocked triangular solves cost ~1 µs at this size, the loops ~0.1 µs. Same
    /// factors; only the rounding of the sums differs.
    ///
    /// Each row's sum runs over the nonzero entries alone, in the dense loop's order.
    /// Leaving out a term l·c with l = 0 (c finite, so l·c = ±0) cannot change a
    /// nonzero running sum, nor a +0 one (+0 − ±0 = +0); it changes only a −0 sum that
    /// the dense loop would turn into +0 (−0 − (−0) = +0). A sum becomes −0 only by
    /// starting as −0 (an exact cancellation gives +0). So the two sums are equal at
    /// every step, or both zero and the sparse one −0 where the row started at −0: a row
    /// that starts at −0 and sums to zero (or to something not finite) is summed again
    /// by the dense loop, over rows before it that are the dense loop's by induction
    /// (solveChecked; tests ReducedModel.CachedSolveOfEveryModeIsBitIdenticalToTheDirectSolve,
    /// TruckModeFactor.NegativeZeroInTheRightHandSideGivesTheDenseLoopsZero). Where a sum
    /// is not finite, the dense loop's 0·∞ of a left-out term is NaN: the solution is not
    /// finite either way, but its values may differ from the dense loop's.
    ///
    /// Those per-row tests are needed only when a row can start at −0 or a sum is not
    /// finite. The rows start at the scaled b (the first pass) and at the first pass's
    /// results (the second), and the first pass's results hold no −0 when b holds none
    /// (a sum that does not start at −0 never becomes −0). A sum that is not finite
    /// leaves its unknown not finite (it is divided by a finite nonzero pivot, and every
    /// later step on an unknown that is not finite keeps it so). So the loops run
    /// without the tests, and solveChecked runs instead when the scaled b holds a −0 or
    /// a result is not finite: the same values either way (test
    /// TruckModeFactor.NonFiniteRightHandSideTakesThePerRowPath).
    ///
    /// b is the unscaled right-hand side: each row divided by its rowScale on the way in,
    /// each unknown multiplied by its column scale on the way out (as solveScaled's steps).
    Eigen::Matrix<double, N, 1> solve(const Eigen::Matrix<double, N, 1>& b,
                                      const Eigen::Matrix<double, N, 1>& colScale) const {
        double c[N];
        loadRightHandSide(b, c);
        bool negativeZero = false;
        for (int i = 0; i < N; ++i) negativeZero |= c[i] == 0 && std::signbit(c[i]);
        if (negativeZero) return solveChecked(b, colScale);
        const double* value = getValues();
        for (int i = 1; i < N; ++i) {
            double v = c[i];
            for (int k = lowerStart[i]; k < lowerStart[i + 1]; ++k) v -= value[k] * c[column[k]];
            c[i] = v;
        }
        bool finite = true;
        for (int i = N - 1; i >= 0; --i) {
            double v = c[i];
            for (int k = upperStart[i]; k < upperStart[i + 1]; ++k) v -= value[k] * c[column[k]];
            c[i] = v / diagonal[i];
            finite &= std::isfinite(c[i]);
        }
        if (!finite) return solveChecked(b, colScale);
        return unloadSolution(c, colScale);
    }

    /// solve with each row's test, for a b holding a −0 or a solution that is not finite.
    Eigen::Matrix<double, N, 1> solveChecked(const Eigen::Matrix<double, N, 1>& b,
                                             const Eigen::Matrix<double, N, 1>& colScale) const {
        return substituteRowByRow(b, colScale, false);
    }

    /// The dense loops: what solve must equal, bit for bit.
    Eigen::Matrix<double, N, 1> solveDense(const Eigen::Matrix<double, N, 1>& b,
                                           const Eigen::Matrix<double, N, 1>& colScale) const {
        return substituteRowByRow(b, colScale, true);
    }

private:
    /// Each row's sum over its nonzero entries, summed again over every entry of the row
    /// where it started at −0 and came to zero or is not finite; with dense, every row over
    /// every entry.
    Eigen::Matrix<double, N, 1> substituteRowByRow(const Eigen::Matrix<double, N, 1>& b,
                                                   const Eigen::Matrix<double, N, 1>& colScale, bool dense) const {
        const Lu lu = getLu();
        const double* value = getValues();
        double c[N];
        loadRightHandSide(b, c);
        auto sum = [&](int i, int firstColumn, int endColumn, int firstEntry, int endEntry) {
            double v = c[i];
            if (!dense)
                for (int k = firstEntry; k < endEntry; ++k) v -= value[k] * c[column[k]];
            if (dense || (v == 0 && std::signbit(c[i])) || !std::isfinite(v)) {
                v = c[i];
                for (int j = firstColumn; j < endColumn; ++j) v -= lu(i, j) * c[j];
            }
            return v;
        };
        for (int i = 1; i < N; ++i) c[i] = sum(i, 0, i, lowerStart[i], lowerStart[i + 1]);
        for (int i = N - 1; i >= 0; --i) c[i] = sum(i, i + 1, N, upperStart[i], upperStart[i + 1]) / diagonal[i];
        return unloadSolution(c, colScale);
    }
};

/// A ModeFactor with room after it for every entry's value: a factorization kept outside
/// TruckModeCache's arena.
struct ModeFactorWithRoom {
    ModeFactor factor;
    std::array<double, ModeFactor::kMaxEntries> values;
};
static_assert(offsetof(ModeFactorWithRoom, values) == sizeof(ModeFactor), "the values right after the factor");
}  // namespace truck_equilibrium_detail
}  // namespace rockroll
