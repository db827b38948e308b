// SPDX-License-Identifier: GPL-3.0-or-later
// The Cholesky factor of a small symmetric matrix, its inverse and its
// substitutions, in fixed-size loops over a packed layout whose aligned pairs
// of entries are computed in one SSE2 register.
#ifndef CGAL_CURVATURE_ESTIMATION_INTERNAL_TAYLOR_FIT_PACKED_CHOLESKY_H
#define CGAL_CURVATURE_ESTIMATION_INTERNAL_TAYLOR_FIT_PACKED_CHOLESKY_H

#include <CGAL/Curvature_estimation/internal/taylor_fit/pairs.h>

#include <cmath>

namespace CGAL {
namespace Curvature_estimation {
namespace internal {

// Triangular matrices of at most Size rows in lines of an even length (stride),
// so that the leading n x n block of any n <= Size is stored in place and every
// pair at an even index is aligned. The factor L is stored by columns (L_ij at
// index(j, i)), its inverse F by rows (F_ij at index(i, j)). Each lane of a pair
// computes the chain of operations of the textbook loop, in the same order.
template <int Size>
struct Packed_cholesky
{
  static constexpr int stride = (Size + 1) / 2 * 2;
  static constexpr int size = stride * Size;
  static constexpr int index(int i, int j) { return stride * i + j; }
  using Triangle = double[size];
  using Diagonal = double[Size];

  // The factor L of the leading n x n block of the symmetric N (N = L L^T), whose
  // entries N.normal_entry(i, j) are computed where needed (a matrix written
  // entry by entry and read in pairs stalls the reads), and the inverses of its
  // diagonal; above the diagonal, in a column's first pair, any finite number.
  // False if the block is not positive definite.
  template <int n, typename Matrix>
  CGAL_CURVATURE_ESTIMATION_INLINE static bool factor(const Matrix& N, Triangle& L, Diagonal& inverse_diagonal)
  {
    static_assert(n <= Size, "array too small");
    constexpr int pairs = (n + 1) / 2;
    CGAL_CURVATURE_ESTIMATION_UNROLL
    for (int j = 0; j < n; ++j) {
      double* column = L + stride * j;
      CGAL_CURVATURE_ESTIMATION_UNROLL
      for (int p = j / 2; p < pairs; ++p) {
        const int i = 2 * p; // rows i and i + 1 (row j - 1 or n: unused, any finite number)
        Pair value(N.normal_entry(i, j), N.normal_entry(i + 1 < n ? i + 1 : i, j));
        CGAL_CURVATURE_ESTIMATION_UNROLL
        for (int k = 0; k < j; ++k)
          value -= pair_at(L + stride * k + i) * L[index(k, j)];
        pair_at(column + i) = value;
      }
      const double diagonal = column[j];
      if (!(diagonal > 0))
        return false;
      inverse_diagonal[j] = 1 / std::sqrt(diagonal);
      CGAL_CURVATURE_ESTIMATION_UNROLL
      for (int p = j / 2; p < pairs; ++p)
        pair_at(column + 2 * p) *= inverse_diagonal[j];
    }
    return true;
  }

  // F = L^-1 (so that N^-1 = F^T F), zero above the diagonal up to a row's last
  // pair: row i of F is e_i minus the rows above it times row i of L, over L_ii.
  template <int n>
  static void invert(const Triangle& L, const Diagonal& inverse_diagonal, Triangle& F)
  {
    constexpr int pairs = (n + 1) / 2;
    CGAL_CURVATURE_ESTIMATION_UNROLL
    for (int i = 0; i < n; ++i) {
      Pair row[pairs];
      CGAL_CURVATURE_ESTIMATION_UNROLL
      for (int p = 0; p <= i / 2; ++p)
        row[p] = Pair(2 * p == i ? 1.0 : 0.0, 2 * p + 1 == i ? 1.0 : 0.0);
      CGAL_CURVATURE_ESTIMATION_UNROLL
      for (int k = 0; k < i; ++k) {
        const double entry = L[index(k, i)];
        CGAL_CURVATURE_ESTIMATION_UNROLL
        for (int p = 0; p <= k / 2; ++p)
          row[p] -= pair_at(F + stride * k + 2 * p) * entry;
      }
      CGAL_CURVATURE_ESTIMATION_UNROLL
      for (int p = 0; p <= i / 2; ++p)
        pair_at(F + stride * i + 2 * p) = row[p] * inverse_diagonal[i];
    }
  }

  // Solutions of T y = b for T = L (forward) and T = L^T (backward), with the
  // entries of T off its diagonal read through `entry` (as they are to solve;
  // as -|L_ij| for the comparison matrix of condition_bounds.h).
  template <int n, typename Entry>
  CGAL_CURVATURE_ESTIMATION_INLINE static void forward_substitution(const Triangle& L, const Diagonal& inverse_diagonal,
                                                                    const double (&b)[n], Entry entry, double (&y)[n])
  {
    CGAL_CURVATURE_ESTIMATION_UNROLL
    for (int i = 0; i < n; ++i) {
      double value = b[i];
      CGAL_CURVATURE_ESTIMATION_UNROLL
      for (int k = 0; k < i; ++k)
        value -= entry(L[index(k, i)]) * y[k];
      y[i] = value * inverse_diagonal[i];
    }
  }
  template <int n, typename Entry>
  CGAL_CURVATURE_ESTIMATION_INLINE static void backward_substitution(const Triangle& L,
                                                                     const Diagonal& inverse_diagonal,
                                                                     const double (&b)[n], Entry entry, double (&y)[n])
  {
    CGAL_CURVATURE_ESTIMATION_UNROLL
    for (int i = n - 1; i >= 0; --i) {
      double value = b[i];
      CGAL_CURVATURE_ESTIMATION_UNROLL
      for (int k = i + 1; k < n; ++k)
        value -= entry(L[index(i, k)]) * y[k];
      y[i] = value * inverse_diagonal[i];
    }
  }

  // x with N x = b: L y = b, then L^T x = y.
  template <int n>
  CGAL_CURVATURE_ESTIMATION_INLINE static void solve(const Triangle& L, const Diagonal& inverse_diagonal,
                                                     const double (&b)[n], double (&x)[n])
  {
    const auto entry = [](double value) { return value; };
    double y[n];
    forward_substitution<n>(L, inverse_diagonal, b, entry, y);
    backward_substitution<n>(L, inverse_diagonal, y, entry, x);
  }
};

} // namespace internal
} // namespace Curvature_estimation
} // namespace CGAL

#endif // CGAL_CURVATURE_ESTIMATION_INTERNAL_TAYLOR_FIT_PACKED_CHOLESKY_H
