// SPDX-License-Identifier: GPL-3.0-or-later
// The quartic part of a height function that its own Hessian implies: all of
// the quartic part on a sphere or a cylinder, which a fit of degree 2 or 3 takes
// into its Hessian as an O(h^2) error and a second solve without it removes
// (see the manual, "The curvature's own quartic term").
#ifndef CGAL_CURVATURE_ESTIMATION_INTERNAL_TAYLOR_FIT_CURVATURE_QUARTIC_H
#define CGAL_CURVATURE_ESTIMATION_INTERNAL_TAYLOR_FIT_CURVATURE_QUARTIC_H

#include <Eigen/Core>

namespace CGAL {
namespace Curvature_estimation {
namespace internal {

// (x^T C x) |C x|^2 / 8 for the Hessian C of the height.
template <int D>
double curvature_quartic(const Eigen::Matrix<double, D, D>& C, const Eigen::Matrix<double, D, 1>& x)
{
  const Eigen::Matrix<double, D, 1> Cx = C * x;
  return x.dot(Cx) * Cx.squaredNorm() / 8;
}

// The coefficients of (x^T A x)(x^T B x) / 8 in the monomials x0^(4 - j) x1^j:
// curvature_quartic for A = C, B = C^2, in any coordinates.
inline void quartic_product_coefficients(const Eigen::Matrix2d& A, const Eigen::Matrix2d& B, double (&quartic)[5])
{
  quartic[0] = A(0, 0) * B(0, 0) / 8;
  quartic[1] = (A(0, 0) * B(0, 1) + A(0, 1) * B(0, 0)) / 4;
  quartic[2] = (A(0, 0) * B(1, 1) + A(1, 1) * B(0, 0) + 4 * A(0, 1) * B(0, 1)) / 8;
  quartic[3] = (A(0, 1) * B(1, 1) + A(1, 1) * B(0, 1)) / 4;
  quartic[4] = A(1, 1) * B(1, 1) / 8;
}

} // namespace internal
} // namespace Curvature_estimation
} // namespace CGAL

#endif // CGAL_CURVATURE_ESTIMATION_INTERNAL_TAYLOR_FIT_CURVATURE_QUARTIC_H
