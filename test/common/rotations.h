// SPDX-License-Identifier: GPL-3.0-or-later
// Rotations of R^3 for the tests of invariance under rigid motions.
//
// Header-only, no GoogleTest dependency; everything lives in namespace `ce_test`.
#ifndef CE_TEST_COMMON_ROTATIONS_H
#define CE_TEST_COMMON_ROTATIONS_H

#include <Eigen/Geometry>

namespace ce_test {

/// The rotation R_z(a) R_y(b) R_x(c) (Euler angles in radians, z-y-x).
inline Eigen::Matrix3d rotation(double a, double b, double c)
{
  return (Eigen::AngleAxisd(a, Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(b, Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(c, Eigen::Vector3d::UnitX()))
    .toRotationMatrix();
}

} // namespace ce_test

#endif // CE_TEST_COMMON_ROTATIONS_H
