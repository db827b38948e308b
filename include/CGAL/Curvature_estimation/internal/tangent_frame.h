// SPDX-License-Identifier: GPL-3.0-or-later
// Orthonormal basis of the tangent space orthogonal to a unit normal, any dimension.
#ifndef CGAL_CURVATURE_ESTIMATION_INTERNAL_TANGENT_FRAME_H
#define CGAL_CURVATURE_ESTIMATION_INTERNAL_TANGENT_FRAME_H

#include <Eigen/Core>

namespace CGAL {
namespace Curvature_estimation {
namespace internal {

// The tangent frame of a surface in R^3: two orthonormal tangent vectors as columns.
using Tangent_frame = Eigen::Matrix<double, 3, 2>;

// The N-1 columns other than k of the Householder reflection that maps the axis
// e_k most aligned with the unit `n` onto -sign(n_k) n.
template <int N>
Eigen::Matrix<double, N, N - 1> tangent_basis(const Eigen::Matrix<double, N, 1>& n)
{
  int k = 0;
  n.cwiseAbs().maxCoeff(&k);
  Eigen::Matrix<double, N, 1> w = n;
  w[k] += (n[k] < 0 ? -1.0 : 1.0);
  const double scale = 2.0 / w.squaredNorm();

  Eigen::Matrix<double, N, N - 1> basis;
  for (int j = 0, column = 0; j < N; ++j) {
    if (j == k)
      continue;
    basis.col(column) = -scale * w[j] * w;
    basis(j, column) += 1.0;
    ++column;
  }
  return basis;
}

} // namespace internal
} // namespace Curvature_estimation
} // namespace CGAL

#endif // CGAL_CURVATURE_ESTIMATION_INTERNAL_TANGENT_FRAME_H
