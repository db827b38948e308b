// SPDX-License-Identifier: GPL-3.0-or-later
// Euler's theorem fitted to normal curvatures: the one least-squares core of the
// estimators that measure normal curvatures along tangent directions (Chen and
// Schmitt 1992; Wollmann 2000).
#ifndef CGAL_CURVATURE_ESTIMATION_INTERNAL_EULER_FIT_H
#define CGAL_CURVATURE_ESTIMATION_INTERNAL_EULER_FIT_H

#include <CGAL/Curvature_estimation/internal/symmetric_eigen.h>

#include <Eigen/Core>

#include <cmath>

namespace CGAL {
namespace Curvature_estimation {
namespace internal {

// Euler's theorem written linearly in the second fundamental form S: the normal
// curvature along the unit tangent (x, y) is S11 x^2 + 2 S12 x y + S22 y^2. Three
// directions determine S exactly, more by (weighted) least squares.
class Euler_fit
{
public:
  void add(const Eigen::Vector2d& unit_direction, double normal_curvature, double weight = 1)
  {
    const double x = unit_direction.x(), y = unit_direction.y();
    const Eigen::Vector3d row(x * x, 2 * x * y, y * y);
    normal_matrix_ += weight * row * row.transpose();
    right_hand_side_ += (weight * normal_curvature) * row;
  }

  // S, or false where the 2-norm condition number of the (weighted) sample rows
  // exceeds `max_condition` (about 2 for three directions 60 degrees apart).
  bool solve(double max_condition, Eigen::Matrix2d& shape) const
  {
    Eigen::Vector3d values;
    Eigen::Matrix3d vectors;
    if (!symmetric_eigen_accurate<3>(normal_matrix_, values, vectors) || !(values[0] > 0) ||
        !(std::sqrt(values[2] / values[0]) <= max_condition))
      return false;
    const Eigen::Vector3d s = vectors * (vectors.transpose() * right_hand_side_).cwiseQuotient(values);
    shape << s[0], s[1], s[1], s[2];
    return shape.allFinite();
  }

private:
  Eigen::Matrix3d normal_matrix_ = Eigen::Matrix3d::Zero();
  Eigen::Vector3d right_hand_side_ = Eigen::Vector3d::Zero();
};

} // namespace internal
} // namespace Curvature_estimation
} // namespace CGAL

#endif // CGAL_CURVATURE_ESTIMATION_INTERNAL_EULER_FIT_H
