// SPDX-License-Identifier: GPL-3.0-or-later
// The local coordinates of every estimator: points of the mesh in double, taken
// relative to the vertex and divided by a local length (a mean distance to the
// neighbors), which makes the estimates scale invariant.
#ifndef CGAL_CURVATURE_ESTIMATION_INTERNAL_LOCAL_COORDINATES_H
#define CGAL_CURVATURE_ESTIMATION_INTERNAL_LOCAL_COORDINATES_H

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/number_utils.h>

#include <boost/graph/graph_traits.hpp>

#include <Eigen/Core>

#include <cmath>

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

// The mean distance from `center` (the point of v) to the neighbors joined to v
// by an edge, ignoring coincident and non-finite ones; 0 when there is none.
template <typename FaceGraph, typename VertexPointMap>
double neighbor_length_scale(typename boost::graph_traits<FaceGraph>::vertex_descriptor v, const FaceGraph& g,
                             const VertexPointMap& vpm, const Eigen::Vector3d& center)
{
  if (halfedge(v, g) == boost::graph_traits<FaceGraph>::null_halfedge())
    return 0;
  double length_sum = 0;
  int count = 0;
  for (auto h : halfedges_around_target(v, g)) {
    const double length = safe_norm(Eigen::Vector3d(point_in_double(vpm, source(h, g)) - center));
    if (std::isfinite(length) && length > 0) {
      length_sum += length;
      ++count;
    }
  }
  return count == 0 ? 0 : length_sum / count;
}

// The points around one vertex of a FaceGraph in local coordinates: relative to
// the vertex's point, divided by neighbor_length_scale.
template <typename FaceGraph, typename VertexPointMap>
class Vertex_local_coordinates
{
public:
  using vertex_descriptor = typename boost::graph_traits<FaceGraph>::vertex_descriptor;

  Vertex_local_coordinates(const FaceGraph& g, VertexPointMap vpm)
      : g_(&g)
      , vpm_(vpm)
  {}

  // Centers the coordinates on `v`; false where its point is not finite or it has
  // no usable neighbor.
  bool center_on(vertex_descriptor v)
  {
    center_ = point_in_double(vpm_, v);
    if (!center_.allFinite())
      return false;
    scale_ = neighbor_length_scale(v, *g_, vpm_, center_);
    return scale_ > 0;
  }

  // The local coordinates of the point of `u`.
  Eigen::Vector3d operator()(vertex_descriptor u) const { return (point_in_double(vpm_, u) - center_) / scale_; }

  double scale() const { return scale_; }
  const FaceGraph& graph() const { return *g_; }

private:
  const FaceGraph* g_;
  VertexPointMap vpm_;
  Eigen::Vector3d center_ = Eigen::Vector3d::Zero();
  double scale_ = 1;
};

} // namespace internal
} // namespace Curvature_estimation
} // namespace CGAL

#endif // CGAL_CURVATURE_ESTIMATION_INTERNAL_LOCAL_COORDINATES_H
