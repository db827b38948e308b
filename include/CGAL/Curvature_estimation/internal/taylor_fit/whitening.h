// SPDX-License-Identifier: GPL-3.0-or-later
// The whitening of tangent coordinates by the samples' second moments, under
// which the whitened condition test does not depend on a linear change of the
// tangent coordinates (see the manual, "Conditioning").
#ifndef CGAL_CURVATURE_ESTIMATION_INTERNAL_TAYLOR_FIT_WHITENING_H
#define CGAL_CURVATURE_ESTIMATION_INTERNAL_TAYLOR_FIT_WHITENING_H

#include <Eigen/Core>

#include <cmath>

namespace CGAL {
namespace Curvature_estimation {
namespace internal {

// The whitening is not trusted where the second moments' condition number
// (estimated as tr(M) tr(M^-1)) is above this: whitening amplifies the rounding
// of the coordinates by its square root (at most 1e4), and samples on a line
// through the vertex show about 1e16.
constexpr double max_whitening_condition = 1e8;

// W = L^-1 for M = L L^T, lower triangular; false where M is not positive
// definite or tr(M) tr(M^-1) exceeds max_whitening_condition.
template <int D>
bool whitening(const Eigen::Matrix<double, D, D>& M, Eigen::Matrix<double, D, D>& W)
{
  Eigen::Matrix<double, D, D> L = Eigen::Matrix<double, D, D>::Zero();
  for (int j = 0; j < D; ++j) {
    double diagonal = M(j, j);
    for (int k = 0; k < j; ++k)
      diagonal -= L(j, k) * L(j, k);
    if (!(diagonal > 0))
      return false;
    L(j, j) = std::sqrt(diagonal);
    for (int i = j + 1; i < D; ++i) {
      double value = M(i, j);
      for (int k = 0; k < j; ++k)
        value -= L(i, k) * L(j, k);
      L(i, j) = value / L(j, j);
    }
  }
  W.setZero();
  for (int j = 0; j < D; ++j) {
    W(j, j) = 1 / L(j, j);
    for (int i = j + 1; i < D; ++i) {
      double value = 0;
      for (int k = j; k < i; ++k)
        value -= L(i, k) * W(k, j);
      W(i, j) = value / L(i, i);
    }
  }
  return M.trace() * W.squaredNorm() <= max_whitening_condition; // tr(M^-1) = |W|_F^2
}

} // namespace internal
} // namespace Curvature_estimation
} // namespace CGAL

#endif // CGAL_CURVATURE_ESTIMATION_INTERNAL_TAYLOR_FIT_WHITENING_H
