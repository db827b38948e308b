// SPDX-License-Identifier: GPL-3.0-or-later
// The local coordinates of every estimator: points of the mesh in double, taken
// relative to the vertex and divided by a local length (a mean distance to the
// neighbors), which makes the estimates scale invariant.
#ifndef CGAL_CURVATURE_ESTIMATION_INTERNAL_LOCAL_COORDINATES_H
#define CGAL_CURVATURE_ESTIMATION_INTERNAL_LOCAL_COORDINATES_H

#include <CGAL/number_utils.h>

#include <Eigen/Core>

namespace CGAL {
namespace Curvature_estimation {
namespace internal {

// The Euclidean norm of `d`, without overflow or underflow on huge or tiny meshes:
// the plain norm where its square is representable, Eigen's scaled norm elsewhere.
template <typename Vector>
double safe_norm(const Vector& d)
{
  const double length = d.norm();
  return length > 1e-150 && length < 1e150 ? length : d.stableNorm();
}

// The point of `u` in double.
template <typename VertexPointMap, typename VertexDescriptor>
Eigen::Vector3d point_in_double(const VertexPointMap& vpm, VertexDescriptor u)
{
  const auto& p = get(vpm, u);
  return Eigen::Vector3d(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
}

} // namespace internal
} // namespace Curvature_estimation
} // namespace CGAL

#endif // CGAL_CURVATURE_ESTIMATION_INTERNAL_LOCAL_COORDINATES_H
