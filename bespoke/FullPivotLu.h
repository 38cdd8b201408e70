#pragma once
// LU factorization with complete pivoting of a small fixed-size matrix, P·A·Q = L·U,
// with the arithmetic of Eigen 3.4's FullPivLU::computeInPlace, operation for
// operation, so that the factors, the permutations and the rank decision equal
// Eigen's bit for bit (test FullPivotLu.FactorsEqualEigensBitForBit). The reduced
// model factors one 15 × 15 matrix per truck-mode class (TruckEquilibrium.cpp).
//
// Step k: the pivot is the first largest |a_ij| of the corner i, j ≥ k in
// column-major order (Eigen's maxCoeff visitor keeps the first of equal values); rows
// k and i and columns k and j are swapped; the column below the pivot is divided by
// it, and the corner updated a_ij −= a_kj·a_ik. A corner of zeros ends the
// elimination. The rank counts the pivots above ε·n·max|pivot| (Eigen's default
// threshold).
//
// The search finds each column's largest magnitude, then the first column holding the
// largest of those, then its first row holding it: the first largest value in
// column-major order, as Eigen's sequential scan, because max is exact. A column's
// largest magnitude is found again only after the column changed. A matrix
// with a NaN or an infinity is factored by Eigen itself (the scans differ there).
#include <Eigen/Core>
#include <Eigen/LU>
#include <array>
#include <cmath>
#include <limits>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace rockroll {

template <int n>
class FullPivotLu {
public:
    using Matrix = Eigen::Matrix<double, n, n>;  // column-major, as Eigen's FullPivLU keeps it

    explicit FullPivotLu(const Matrix& a) : lu_(a) {
        if (a.allFinite()) compute();
        else computeByEigen();
    }

    /// L (unit lower, below the diagonal) and U (on and above it), as Eigen's matrixLU().
    const Matrix& getMatrixLU() const { return lu_; }
    /// Eigen's permutationP().indices() and permutationQ().indices().
    const std::array<int, n>& getRowPermutation() const { return p_; }
    const std::array<int, n>& getColumnPermutation() const { return q_; }
    int getRank() const {
        const double threshold = std::abs(maxPivot_) * (std::numeric_limits<double>::epsilon() * double(n));
        int rank = 0;
        for (int i = 0; i < nonzeroPivots_; ++i) rank += std::abs(lu_(i, i)) > threshold;
        return rank;
    }
    bool isInvertible() const { return getRank() == n; }

private:
    /// max |x_i| over m values (max is exact: any order gives the same value).
    static double calcMaxMagnitude(const double* x, int m) {
        int i = 0;
        double best = 0;
#if defined(__SSE2__)
        const __m128d sign = _mm_set1_pd(-0.0);
        __m128d v = _mm_setzero_pd();
        for (; i + 1 < m; i += 2) v = _mm_max_pd(v, _mm_andnot_pd(sign, _mm_loadu_pd(x + i)));
        best = std::max(_mm_cvtsd_f64(v), _mm_cvtsd_f64(_mm_unpackhi_pd(v, v)));
#endif
        for (; i < m; ++i) best = std::max(best, std::abs(x[i]));
        return best;
    }
    /// Whether one of m values is −0.
    static bool hasNegativeZero(const double* x, int m) {
        int i = 0;
        bool found = false;
#if defined(__SSE2__)
        const __m128d sign = _mm_set1_pd(-0.0), zero = _mm_setzero_pd();
        __m128d v = _mm_setzero_pd();  // sign bits of the entries equal to zero
        for (; i + 1 < m; i += 2) {
            const __m128d x2 = _mm_loadu_pd(x + i);
            v = _mm_or_pd(v, _mm_and_pd(_mm_cmpeq_pd(x2, zero), _mm_and_pd(x2, sign)));
        }
        found = _mm_movemask_pd(v) != 0;
#endif
        for (; i < m; ++i) found = found || (x[i] == 0 && std::signbit(x[i]));
        return found;
    }
    /// y_i −= r·x_i: a product, then a difference, per element (no fused multiply-add).
    static void subtractMultiple(double* y, double r, const double* x, int m) {
        int i = 0;
#if defined(__SSE2__)
        const __m128d vr = _mm_set1_pd(r);
        for (; i + 1 < m; i += 2)
            _mm_storeu_pd(y + i, _mm_sub_pd(_mm_loadu_pd(y + i), _mm_mul_pd(vr, _mm_loadu_pd(x + i))));
#endif
        for (; i < m; ++i) y[i] -= r * x[i];
    }

    void compute() {
        double* a = lu_.data();  // a[j·n + i] = A(i, j)
        // Without a −0 in A the corner never holds one (y − r·x is −0 only for y = −0; the
        // divisions write L, outside the corner), so a column whose multiplier a_kj is ±0
        // is left as it is: y − (±0) = y for every y but −0. With one, every column is updated.
        const bool negativeZero = hasNegativeZero(a, n * n);
        std::array<int, n> rowSwap{}, colSwap{};
        nonzeroPivots_ = n;
        maxPivot_ = 0;
        // Each corner column's largest magnitude, kept between steps where the column did not
        // change: a column left as it is (its multiplier ±0) loses only that zero from the
        // corner, and the row swaps stay inside it.
        double columnMax[n];
        bool stale[n];
        for (int j = 0; j < n; ++j) stale[j] = true;
        for (int k = 0; k < n; ++k) {
            double best = 0;
            for (int j = k; j < n; ++j) {
                if (stale[j]) columnMax[j] = calcMaxMagnitude(a + j * n + k, n - k), stale[j] = false;
                best = std::max(best, columnMax[j]);
            }
            if (best == 0) {
                nonzeroPivots_ = k;
                for (int i = k; i < n; ++i) rowSwap[i] = colSwap[i] = i;
                break;
            }
            int bj = k;
            while (columnMax[bj] != best) ++bj;
            int bi = k;
            while (std::abs(a[bj * n + bi]) != best) ++bi;
            if (best > maxPivot_) maxPivot_ = best;
            rowSwap[k] = bi, colSwap[k] = bj;
            if (bi != k)
                for (int j = 0; j < n; ++j) std::swap(a[j * n + k], a[j * n + bi]);
            if (bj != k) {
                for (int i = 0; i < n; ++i) std::swap(a[k * n + i], a[bj * n + i]);
                std::swap(columnMax[k], columnMax[bj]);
                std::swap(stale[k], stale[bj]);
            }
            double* colK = a + k * n;
            const double pivot = colK[k];
            for (int i = k + 1; i < n; ++i) colK[i] /= pivot;
            for (int j = k + 1; j < n; ++j) {
                double* col = a + j * n;
                if (col[k] == 0 && !negativeZero) continue;
                subtractMultiple(col + k + 1, col[k], colK + k + 1, n - k - 1);
                stale[j] = true;
            }
        }
        for (int i = 0; i < n; ++i) p_[i] = q_[i] = i;
        for (int k = n - 1; k >= 0; --k) std::swap(p_[k], p_[rowSwap[k]]);
        for (int k = 0; k < n; ++k) std::swap(q_[k], q_[colSwap[k]]);
    }

    void computeByEigen() {
        const Eigen::FullPivLU<Matrix> lu(lu_);
        lu_ = lu.matrixLU();
        for (int i = 0; i < n; ++i) p_[i] = int(lu.permutationP().indices()[i]), q_[i] = int(lu.permutationQ().indices()[i]);
        nonzeroPivots_ = int(lu.nonzeroPivots());
        maxPivot_ = lu.maxPivot();
    }

    Matrix lu_;
    std::array<int, n> p_{}, q_{};
    int nonzeroPivots_ = n;
    double maxPivot_ = 0;
};

}  // namespace rockroll
