// SPDX-License-Identifier: GPL-3.0-or-later
// Mesh lines, the curves of the curve network: which pairs of neighbors make a
// curve through a vertex, how far a curve is from a mesh line, and the next
// vertex along a straight line of a grid triangulation.
#ifndef CGAL_CURVATURE_ESTIMATION_INTERNAL_MESH_LINES_H
#define CGAL_CURVATURE_ESTIMATION_INTERNAL_MESH_LINES_H

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <boost/graph/graph_traits.hpp>

#include <Eigen/Core>

#include <array>
#include <cstddef>

namespace CGAL {
namespace Curvature_estimation {
namespace internal {

// Neighbors whose tangent-plane directions make an angle of at least 150 degrees
// may form a curve through the vertex (sharper kinks mix two directions).
constexpr double curve_pair_max_cosine = -0.866;

// The irregularity s^2 + tan^2(delta / 2) of a curve a - p - b, the size of its
// estimate's leading relative error (see the manual's "Curve network"): s the
// asymmetry (h_a - h_b) / (h_a + h_b) of its two edges, delta its kink; `a` and
// `b` are the offsets from p, `cosine` the cosine of their angle in the tangent
// plane (at most curve_pair_max_cosine, so the division is safe).
inline double curve_irregularity(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double cosine)
{
  const double length_a = a.norm(), length_b = b.norm();
  const double s = (length_a - length_b) / (length_a + length_b);
  return s * s + (1 + cosine) / (1 - cosine);
}

// The default of `max_curve_irregularity` (its measurement: see the manual).
constexpr double default_max_curve_irregularity = 0.04;

// The neighbor of `at` straight across from `from`: the third of its six
// neighbors counted around it from `from`, if `at` is an interior vertex of
// valence 6 (of a grid triangulation, the next vertex on the grid line).
template <typename FaceGraph, typename Vertex>
bool next_on_mesh_line(Vertex from, Vertex at, const FaceGraph& g, Vertex& next)
{
  const auto h = halfedge(at, g);
  if (h == boost::graph_traits<FaceGraph>::null_halfedge())
    return false;
  std::array<Vertex, 6> around;
  std::size_t count = 0;
  for (auto incoming : halfedges_around_target(h, g)) {
    if (count == 6 || is_border(incoming, g) || is_border(opposite(incoming, g), g))
      return false;
    around[count++] = source(incoming, g);
  }
  if (count != 6)
    return false;
  for (std::size_t k = 0; k < 6; ++k)
    if (around[k] == from) {
      next = around[(k + 3) % 6];
      return true;
    }
  return false;
}

} // namespace internal
} // namespace Curvature_estimation
} // namespace CGAL

#endif // CGAL_CURVATURE_ESTIMATION_INTERNAL_MESH_LINES_H
