// SPDX-License-Identifier: GPL-3.0-or-later
// The symmetric eigen-solvers of the package, in one place. The policy:
//  - a shape operator (2 x 2 for surfaces, 3 x 3 for hypersurfaces), whose eigenvalues
//    are the curvatures: symmetric_eigen, in closed form for 2 x 2 (Eigen's direct 2 x 2
//    solver costs more than the whole fit) and by Eigen's direct solver for 3 x 3;
//  - a normal matrix or scatter matrix whose SMALLEST eigenvalue decides (a condition
//    number, the normal of a plane of points or directions): symmetric_eigen_accurate,
//    Eigen's iterative QL solver, which keeps the small eigenvalues' relative accuracy
//    that the direct solver loses.
#ifndef CGAL_CURVATURE_ESTIMATION_INTERNAL_SYMMETRIC_EIGEN_H
#define CGAL_CURVATURE_ESTIMATION_INTERNAL_SYMMETRIC_EIGEN_H

#include <Eigen/Core>
#include <Eigen/Eigenvalues>

#include <cmath>

namespace CGAL {
namespace Curvature_estimation {
namespace internal {

// The eigenvalues (ascending) and unit eigenvectors (columns) of a symmetric D x D
// matrix where only its curvatures are wanted: the shape operators of the fits
// (D = 2 in closed form, D = 3 by Eigen's direct solver).
template <int D>
void symmetric_eigen(const Eigen::Matrix<double, D, D>& m, Eigen::Matrix<double, D, 1>& values,
                     Eigen::Matrix<double, D, D>& vectors)
{
  if constexpr (D == 2) {
    // Closed form: Eigen's direct 2x2 solver costs more than the whole fit.
    const double a = m(0, 0), b = m(0, 1), c = m(1, 1);
    const double mean = 0.5 * (a + c);
    const double half_difference = 0.5 * (a - c);
    const double radius = std::sqrt(half_difference * half_difference + b * b);  // scaled curvatures: no overflow
    values << mean - radius, mean + radius;
    // An eigenvector of the larger eigenvalue: (b, l - a) or (l - c, b), whichever
    // is the better conditioned; the other is orthogonal.
    const double l = values[1];
    Eigen::Vector2d larger = std::abs(l - a) > std::abs(l - c) ? Eigen::Vector2d(b, l - a) : Eigen::Vector2d(l - c, b);
    const double length = larger.norm();
    larger = length > 0 ? Eigen::Vector2d(larger / length) : Eigen::Vector2d(1, 0);  // umbilic: any frame
    vectors.col(1) = larger;
    vectors.col(0) = Eigen::Vector2d(-larger.y(), larger.x());
  } else {
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, D, D>> eigen;
    eigen.computeDirect(m);
    values = eigen.eigenvalues();
    vectors = eigen.eigenvectors();
  }
}

// The eigenvalues (ascending) and unit eigenvectors (columns) of a symmetric D x D
// matrix whose small eigenvalues matter; false if the solver did not converge.
template <int D>
bool symmetric_eigen_accurate(const Eigen::Matrix<double, D, D>& m, Eigen::Matrix<double, D, 1>& values,
                              Eigen::Matrix<double, D, D>& vectors)
{
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, D, D>> eigen(m);
  if (eigen.info() != Eigen::Success)
    return false;
  values = eigen.eigenvalues();
  vectors = eigen.eigenvectors();
  return true;
}

} // namespace internal
} // namespace Curvature_estimation
} // namespace CGAL

#endif // CGAL_CURVATURE_ESTIMATION_INTERNAL_SYMMETRIC_EIGEN_H
