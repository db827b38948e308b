// SPDX-License-Identifier: GPL-3.0-or-later
// The 1-norm of a symmetric matrix and three upper bounds of the 1-norm of its
// inverse from its Cholesky factor, from the cheapest to the exact number: a
// condition test takes the first bound that is below its threshold, so that its
// decisions are those of the exact number.
#ifndef CGAL_CURVATURE_ESTIMATION_INTERNAL_TAYLOR_FIT_CONDITION_BOUNDS_H
#define CGAL_CURVATURE_ESTIMATION_INTERNAL_TAYLOR_FIT_CONDITION_BOUNDS_H

#include <CGAL/Curvature_estimation/internal/taylor_fit/packed_cholesky.h>

#include <algorithm>
#include <cmath>

namespace CGAL {
namespace Curvature_estimation {
namespace internal {

// The largest column sum of absolute values of the leading n x n block of N.
template <int n, typename Matrix>
CGAL_CURVATURE_ESTIMATION_INLINE double one_norm(const Matrix& N)
{
  double largest = 0;
  CGAL_CURVATURE_ESTIMATION_UNROLL
  for (int j = 0; j < n; ++j) {
    double sum = 0;
    CGAL_CURVATURE_ESTIMATION_UNROLL
    for (int i = 0; i < n; ++i)
      sum += std::abs(N.normal_entry(i, j));
    largest = sum > largest ? sum : largest;
  }
  return largest;
}

// A bound of ||L^-1||_1 ||L^-1||_inf, hence of ||N^-1||_1, from the factor L
// alone, at the cost of two triangular solves: the comparison matrix M of L
// (|L_ij| on the diagonal, -|L_ij| below it) has M^-1 >= |L^-1| entrywise
// (Higham, Accuracy and Stability of Numerical Algorithms, section 8.3).
template <int Size, int n>
CGAL_CURVATURE_ESTIMATION_INLINE double
comparison_bound(const typename Packed_cholesky<Size>::Triangle& L,
                 const typename Packed_cholesky<Size>::Diagonal& inverse_diagonal)
{
  double ones[n];
  std::fill(ones, ones + n, 1.0);
  const auto entry = [](double value) { return -std::abs(value); };
  double forward[n];
  Packed_cholesky<Size>::template forward_substitution<n>(L, inverse_diagonal, ones, entry, forward);
  double backward[n];
  Packed_cholesky<Size>::template backward_substitution<n>(L, inverse_diagonal, ones, entry, backward);
  return *std::max_element(forward, forward + n) * *std::max_element(backward, backward + n);
}

// ||F||_1 ||F||_inf for the inverse F of the factor: a bound of ||F^T F||_1.
template <int Size, int n>
double triangular_norms_product(const typename Packed_cholesky<Size>::Triangle& F)
{
  constexpr auto index = Packed_cholesky<Size>::index;
  double column_sums[n] = {};
  double largest_row_sum = 0;
  CGAL_CURVATURE_ESTIMATION_UNROLL
  for (int i = 0; i < n; ++i) {
    double row_sum = 0;
    CGAL_CURVATURE_ESTIMATION_UNROLL
    for (int j = 0; j <= i; ++j) {
      row_sum += std::abs(F[index(i, j)]);
      column_sums[j] += std::abs(F[index(i, j)]);
    }
    largest_row_sum = row_sum > largest_row_sum ? row_sum : largest_row_sum;
  }
  return largest_row_sum * *std::max_element(column_sums, column_sums + n);
}

// ||F^T F||_1 = ||N^-1||_1 for the inverse F of the factor.
template <int Size, int n>
double inverse_one_norm(const typename Packed_cholesky<Size>::Triangle& F)
{
  constexpr auto index = Packed_cholesky<Size>::index;
  double column_sums[n] = {};
  CGAL_CURVATURE_ESTIMATION_UNROLL
  for (int i = 0; i < n; ++i) {
    CGAL_CURVATURE_ESTIMATION_UNROLL
    for (int j = 0; j <= i; ++j) {
      double value = 0;
      CGAL_CURVATURE_ESTIMATION_UNROLL
      for (int k = i; k < n; ++k)
        value += F[index(k, i)] * F[index(k, j)];
      column_sums[j] += std::abs(value);
      if (j != i)
        column_sums[i] += std::abs(value);
    }
  }
  return *std::max_element(column_sums, column_sums + n);
}

} // namespace internal
} // namespace Curvature_estimation
} // namespace CGAL

#endif // CGAL_CURVATURE_ESTIMATION_INTERNAL_TAYLOR_FIT_CONDITION_BOUNDS_H
