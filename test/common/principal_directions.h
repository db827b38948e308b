// SPDX-License-Identifier: GPL-3.0-or-later
// The GoogleTest checks of the principal directions an estimator gives, against
// exact curvature: shared by the surface estimators' tests.
#ifndef CE_TEST_COMMON_PRINCIPAL_DIRECTIONS_H
#define CE_TEST_COMMON_PRINCIPAL_DIRECTIONS_H

#include <Eigen/Dense>

#include <gtest/gtest.h>

#include "estimator_runs.h"
#include "test_surfaces.h"

#include <cmath>
#include <cstddef>
#include <vector>

namespace ce_test {

// A CGAL Vector_3 as an Eigen vector.
template <typename Vector>
Eigen::Vector3d to_eigen(const Vector& v)
{
  return Eigen::Vector3d(v.x(), v.y(), v.z());
}

// Checks that at every vertex the two directions are unit and orthogonal and the
// maximum one is tangent (orthogonal to the exact normal within `tangent_tolerance`);
// returns the largest 1 - |cos| between the estimated and the exact maximum
// directions (principal directions are defined up to sign).
template <typename Kernel>
double max_direction_error(const Estimates<Kernel>& e, const std::vector<Exact_curvature>& exact,
                           double tangent_tolerance)
{
  Error_accumulator direction;
  for (std::size_t i = 0; i < exact.size(); ++i) {
    const Eigen::Vector3d d_max = to_eigen(e.principal[i].max_direction);
    const Eigen::Vector3d d_min = to_eigen(e.principal[i].min_direction);
    EXPECT_NEAR(d_max.norm(), 1, 1e-12);
    EXPECT_NEAR(d_min.norm(), 1, 1e-12);
    EXPECT_NEAR(d_max.dot(d_min), 0, 1e-12);
    EXPECT_NEAR(d_max.dot(exact[i].normal), 0, tangent_tolerance);
    direction.add(1 - std::abs(d_max.dot(exact[i].d_max)));
  }
  return direction.stats().max;
}

} // namespace ce_test

#endif // CE_TEST_COMMON_PRINCIPAL_DIRECTIONS_H
