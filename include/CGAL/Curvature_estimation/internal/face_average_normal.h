// SPDX-License-Identifier: GPL-3.0-or-later
// The face-averaged normal at one vertex: the first-order normal that every
// estimator can start from.
#ifndef CGAL_CURVATURE_ESTIMATION_INTERNAL_FACE_AVERAGE_NORMAL_H
#define CGAL_CURVATURE_ESTIMATION_INTERNAL_FACE_AVERAGE_NORMAL_H

#include <CGAL/Curvature_estimation/Vertex_normal_method.h>
#include <CGAL/Curvature_estimation/internal/local_coordinates.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/number_utils.h>

#include <boost/graph/graph_traits.hpp>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace CGAL {
namespace Curvature_estimation {
namespace internal {

// One walk around a polygonal face, in the local coordinates q = local(u) of its
// vertices u, starting at the target of halfedge h: Newell's vector
// sum_i q_i x q_{i+1} (twice the vector area), the sum of the vertices, their number,
// and the vertices after and before the target of h.
struct Face_walk
{
  Eigen::Vector3d newell = Eigen::Vector3d::Zero();
  Eigen::Vector3d vertex_sum = Eigen::Vector3d::Zero();
  Eigen::Vector3d next = Eigen::Vector3d::Zero();
  Eigen::Vector3d previous = Eigen::Vector3d::Zero();
  int size = 0;
};

template <typename FaceGraph, typename Local>
Face_walk walk_face(typename boost::graph_traits<FaceGraph>::halfedge_descriptor h, const FaceGraph& g,
                    const Local& local)
{
  Face_walk walk;
  Eigen::Vector3d first = Eigen::Vector3d::Zero();
  for (auto k : halfedges_around_face(h, g)) {
    const Eigen::Vector3d q = local(target(k, g));
    if (walk.size == 0)
      first = q;
    else
      walk.newell += walk.previous.cross(q);
    if (walk.size == 1)
      walk.next = q;
    walk.vertex_sum += q;
    walk.previous = q;
    ++walk.size;
  }
  walk.newell += walk.previous.cross(first);
  return walk;
}

// The unit average at vertex `v` of the unit normals of its faces, weighted by
// `method` (`area_weighted`, `angle_weighted` or `centroid_weighted`; quadric_fit
// throws std::invalid_argument), in double, in coordinates relative to `v` scaled
// by the largest difference to its neighbors. Faces may be any polygons (Newell's
// normal; a reflex angle exceeds pi); a degenerate face or one with a non-finite
// point contributes nothing; faces whose centroid is `v` have an infinite centroid
// weight (their average alone). The zero vector where `v` has no usable face or the
// normals cancel; NaNs where its point is not finite or the sum overflows.
template <typename FaceGraph, typename VPM>
Eigen::Vector3d face_average_normal(typename boost::graph_traits<FaceGraph>::vertex_descriptor v, const FaceGraph& g,
                                    const VPM& vpm, Vertex_normal_method method)
{
  using Graph_traits = boost::graph_traits<FaceGraph>;
  using vertex_descriptor = typename Graph_traits::vertex_descriptor;
  using halfedge_descriptor = typename Graph_traits::halfedge_descriptor;

  if (method == Vertex_normal_method::quadric_fit)
    throw std::invalid_argument("CGAL::Curvature_estimation::internal::face_average_normal(): quadric_fit is not an "
                                "average of face normals; use area_weighted, angle_weighted or centroid_weighted");

  const Eigen::Vector3d zero = Eigen::Vector3d::Zero();
  const Eigen::Vector3d nan = Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
  constexpr double two_pi = 6.283185307179586476925286766559;

  // Isolated vertex: no halfedge to circulate around.
  if (halfedge(v, g) == Graph_traits::null_halfedge())
    return zero;

  auto point = [&vpm](vertex_descriptor u) { return point_in_double(vpm, u); };

  const Eigen::Vector3d pv = point(v);
  if (!pv.allFinite())
    return nan;

  // Local length scale: the largest coordinate difference between v and a neighbor.
  double scale = 0.;
  for (halfedge_descriptor h : halfedges_around_target(v, g)) {
    const double d = (point(source(h, g)) - pv).template lpNorm<Eigen::Infinity>();
    if (!(d <= (std::numeric_limits<double>::max)())) // NaN or infinite: its faces are skipped below
      continue;
    if (d > scale)
      scale = d;
  }
  if (!(scale > 0.)) // all neighbors coincide with v: every face is degenerate
    return zero;

  // Position of u relative to v, in units of `scale` (division, not multiplication by
  // 1/scale, which overflows when scale is subnormal).
  auto local = [&](vertex_descriptor u) -> Eigen::Vector3d { return (point(u) - pv) / scale; };

  Eigen::Vector3d sum = zero;
  Eigen::Vector3d sum_infinite_weights = zero; // centroid_weighted only
  for (halfedge_descriptor h : halfedges_around_target(v, g)) {
    if (is_border(h, g))
      continue;

    // The face from h, whose target v is at the local origin.
    const Face_walk walk = walk_face(h, g, local);
    const Eigen::Vector3d& newell = walk.newell;
    const Eigen::Vector3d& vertex_sum = walk.vertex_sum;
    const Eigen::Vector3d& next_of_v = walk.next;
    const Eigen::Vector3d& previous_of_v = walk.previous;
    const int n_vertices = walk.size;

    if (!newell.allFinite() || !vertex_sum.allFinite()) // a non-finite point: no normal, no weight
      continue;
    const double twice_area = newell.norm();
    if (!(twice_area > 0.)) // degenerate face: no normal, no weight
      continue;

    switch (method) {
      case Vertex_normal_method::area_weighted:
        // area * unit normal = newell / 2; the common factor does not matter
        sum += newell;
        break;

      case Vertex_normal_method::angle_weighted: {
        const Eigen::Vector3d nf = newell / twice_area;
        if (next_of_v == zero || previous_of_v == zero) // zero-length edge at v
          break;
        // Angle from the edge to the next vertex to the edge to the previous one,
        // counter-clockwise around nf: in [0, 2 pi), larger than pi at a reflex vertex.
        double angle = std::atan2(next_of_v.cross(previous_of_v).dot(nf), next_of_v.dot(previous_of_v));
        if (angle < 0.)
          angle += two_pi;
        sum += angle * nf;
        break;
      }

      case Vertex_normal_method::centroid_weighted: {
        const double d2 = (vertex_sum / double(n_vertices)).squaredNorm(); // |G_f - v|^2 / scale^2
        const double w = 1. / d2;
        if (std::isfinite(w))
          sum += (w / twice_area) * newell;
        else // centroid at v (possible for non-convex polygons): infinite weight
          sum_infinite_weights += newell / twice_area;
        break;
      }

      default: // quadric_fit was refused above
        break;
    }
  }

  // Faces of infinite weight (centroid at v) dominate all others: this is the limit
  // of the weighted average as a centroid tends to v.
  if (sum_infinite_weights != zero)
    sum = sum_infinite_weights;

  // Normalise without overflow: first by the largest component.
  const double largest = sum.cwiseAbs().maxCoeff();
  if (!std::isfinite(largest))
    return nan;
  if (!(largest > 0.))
    return zero;
  const Eigen::Vector3d s = sum / largest;
  return s / s.norm();
}

} // namespace internal

} // namespace Curvature_estimation
} // namespace CGAL

#endif // CGAL_CURVATURE_ESTIMATION_INTERNAL_FACE_AVERAGE_NORMAL_H
