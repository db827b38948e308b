// SPDX-License-Identifier: GPL-3.0-or-later
// The symmetric eigen-solvers of the package, in one place: shape operators
// (symmetric_eigen: closed form in 2 x 2, Eigen's direct solver in 3 x 3); matrices
// whose smallest eigenvalue decides (symmetric_eigen_accurate: Eigen's iterative
// solver, which keeps its relative accuracy); the normal of a least-squares
// hyperplane (smallest_eigenvector in R^3, cyclic Jacobi rotations in R^4, where
// Eigen's iterative solver warns under GCC 12's -Wmaybe-uninitialized).
#ifndef CGAL_CURVATURE_ESTIMATION_INTERNAL_SYMMETRIC_EIGEN_H
#define CGAL_CURVATURE_ESTIMATION_INTERNAL_SYMMETRIC_EIGEN_H

#include <Eigen/Core>
#include <Eigen/Eigenvalues>

#include <cmath>
#include <cstddef>

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
    const double radius = std::sqrt(half_difference * half_difference + b * b); // scaled curvatures: no overflow
    values << mean - radius, mean + radius;
    // An eigenvector of the larger eigenvalue: (b, l - a) or (l - c, b), whichever
    // is the better conditioned; the other is orthogonal.
    const double l = values[1];
    Eigen::Vector2d larger = std::abs(l - a) > std::abs(l - c) ? Eigen::Vector2d(b, l - a) : Eigen::Vector2d(l - c, b);
    const double length = larger.norm();
    larger = length > 0 ? Eigen::Vector2d(larger / length) : Eigen::Vector2d(1, 0); // umbilic: any frame
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

// The index of the longest of three vectors (the first of equals).
inline int longest_of_three(const Eigen::Vector3d (&vectors)[3])
{
  int longest = 0;
  for (int i = 1; i < 3; ++i)
    if (vectors[i].squaredNorm() > vectors[longest].squaredNorm())
      longest = i;
  return longest;
}

// The unit eigenvector of the smallest eigenvalue l1 of a symmetric positive
// semi-definite 3 x 3 matrix A (NaN where A is zero): l1 by Newton's method on
// det(A - l I) from 0 (the iterates rise to l1 without passing it), the vector as
// the longest cross product of two rows of A - l1 I. Near a double root only to
// about sqrt(rounding): the points are then near a line, and the fits refuse the frame.
inline Eigen::Vector3d smallest_eigenvector(const Eigen::Matrix3d& a)
{
  const double c2 = a.trace();
  const double c1 = a(0, 0) * a(1, 1) - a(0, 1) * a(0, 1) + a(0, 0) * a(2, 2) - a(0, 2) * a(0, 2) + a(1, 1) * a(2, 2) -
                    a(1, 2) * a(1, 2);
  const double c0 = a.determinant();
  double l = 0;
  // c1 >= l2 l3 >= l2 c2 / 3: where it is below 1e-12 c2^2, A is of rank 1 or 0
  // to that precision, its p and slope rounding errors, and l1 = 0.
  if (c1 > 1e-12 * c2 * c2)
    for (int iteration = 0; iteration < 100; ++iteration) {
      const double p = c0 - l * (c1 - l * (c2 - l));
      const double slope = c1 - l * (2 * c2 - 3 * l); // -p'(l), positive below l1
      const double step = p / slope;
      if (!(step > 1e-17 * c2)) // converged, or past l1 by rounding
        break;
      l += step;
    }
  Eigen::Matrix3d shifted = a;
  shifted.diagonal().array() -= l;
  const Eigen::Vector3d rows[3] = {shifted.row(0), shifted.row(1), shifted.row(2)};
  const Eigen::Vector3d candidates[3] = {rows[0].cross(rows[1]), rows[0].cross(rows[2]), rows[1].cross(rows[2])};
  const Eigen::Vector3d& longest = candidates[longest_of_three(candidates)];
  // Rows that are parallel to rounding (A - l1 I of rank 1: l1 a double root,
  // points on a line) have cross products of rounding errors: then any unit
  // vector orthogonal to the longest row is an eigenvector of l1.
  if (!(longest.norm() > 1e-12 * c2 * c2))
    return rows[longest_of_three(rows)].unitOrthogonal();
  return longest / longest.norm();
}

// The unit normal of the least-squares hyperplane through `count` points: the
// eigenvector of the smallest eigenvalue of their scatter matrix, in R^3 by
// smallest_eigenvector, in R^4 by cyclic Jacobi rotations (see above).
template <int N>
Eigen::Matrix<double, N, 1> least_squares_hyperplane_normal(const Eigen::Matrix<double, N, 1>* points,
                                                            std::size_t count)
{
  using Vector = Eigen::Matrix<double, N, 1>;
  using Square = Eigen::Matrix<double, N, N>;
  Vector mean = Vector::Zero();
  for (std::size_t i = 0; i < count; ++i)
    mean += points[i];
  mean /= double(count);
  Square scatter = Square::Zero();
  for (std::size_t i = 0; i < count; ++i) {
    const Vector offset = points[i] - mean;
    scatter.noalias() += offset * offset.transpose();
  }
  if constexpr (N == 3)
    return smallest_eigenvector(scatter);
  Square vectors = Square::Identity();
  for (int sweep = 0; sweep < 50; ++sweep) {
    double off = 0;
    for (int p = 0; p < N; ++p)
      for (int q = p + 1; q < N; ++q)
        off += scatter(p, q) * scatter(p, q);
    if (!(off > 1e-30 * scatter.squaredNorm()))
      break;
    for (int p = 0; p < N; ++p)
      for (int q = p + 1; q < N; ++q) {
        if (scatter(p, q) == 0)
          continue;
        const double theta = 0.5 * (scatter(q, q) - scatter(p, p)) / scatter(p, q);
        const double t = (theta >= 0 ? 1.0 : -1.0) / (std::abs(theta) + std::sqrt(theta * theta + 1));
        const double c = 1 / std::sqrt(t * t + 1), s = t * c;
        for (int k = 0; k < N; ++k) { // scatter <- J^T scatter J, vectors <- vectors J
          const double a = scatter(k, p), b = scatter(k, q);
          scatter(k, p) = c * a - s * b;
          scatter(k, q) = s * a + c * b;
        }
        for (int k = 0; k < N; ++k) {
          const double a = scatter(p, k), b = scatter(q, k);
          scatter(p, k) = c * a - s * b;
          scatter(q, k) = s * a + c * b;
        }
        for (int k = 0; k < N; ++k) {
          const double a = vectors(k, p), b = vectors(k, q);
          vectors(k, p) = c * a - s * b;
          vectors(k, q) = s * a + c * b;
        }
      }
  }
  int smallest = 0;
  scatter.diagonal().minCoeff(&smallest);
  return vectors.col(smallest);
}

} // namespace internal
} // namespace Curvature_estimation
} // namespace CGAL

#endif // CGAL_CURVATURE_ESTIMATION_INTERNAL_SYMMETRIC_EIGEN_H
