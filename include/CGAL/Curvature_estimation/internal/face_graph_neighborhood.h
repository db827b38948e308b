// SPDX-License-Identifier: GPL-3.0-or-later
// The neighborhood policy that runs the fits of vertex_fitter.h at the vertices
// of a FaceGraph, and the fitter it makes.
#ifndef CGAL_CURVATURE_ESTIMATION_INTERNAL_FACE_GRAPH_NEIGHBORHOOD_H
#define CGAL_CURVATURE_ESTIMATION_INTERNAL_FACE_GRAPH_NEIGHBORHOOD_H

#include <CGAL/Curvature_estimation/Principal_curvatures_and_directions.h>
#include <CGAL/Curvature_estimation/Vertex_normal_method.h>
#include <CGAL/Curvature_estimation/internal/face_average_normal.h>
#include <CGAL/Curvature_estimation/internal/fit_settings.h>
#include <CGAL/Curvature_estimation/internal/local_coordinates.h>
#include <CGAL/Curvature_estimation/internal/rings.h>
#include <CGAL/Curvature_estimation/internal/scale_selector.h>
#include <CGAL/Curvature_estimation/internal/shape_operator.h>
#include <CGAL/Curvature_estimation/internal/surface_estimate.h>
#include <CGAL/Curvature_estimation/internal/vertex_fitter.h>

#include <boost/graph/graph_traits.hpp>

#include <Eigen/Core>

#include <cmath>
#include <cstddef>
#include <memory>
#include <utility>
#include <vector>

namespace CGAL {
namespace Curvature_estimation {
namespace internal {

// The neighborhood policy of a FaceGraph: k-rings by halfedge circulation, the
// area-weighted normal (or another face average) as the first-order normal.
template <typename FaceGraph, typename VertexPointMap>
class Face_graph_neighborhood
{
public:
  static constexpr int ambient_dimension = 3;
  static constexpr bool restart_from_hyperplane = false;
  using Vertex = typename boost::graph_traits<FaceGraph>::vertex_descriptor;
  using Estimate = Surface_estimate;

  // `adjacency`: see Ring_collector::use_adjacency.
  Face_graph_neighborhood(const FaceGraph& g, VertexPointMap vpm,
                          std::shared_ptr<const Vertex_adjacency> adjacency = nullptr)
      : g_(&g)
      , vpm_(vpm)
  {
    rings_.use_adjacency(std::move(adjacency));
  }

  Eigen::Vector3d point(Vertex v) const { return point_in_double(vpm_, v); }
  void start(Vertex v) { rings_.start(v, *g_); }
  bool extend() { return rings_.extend(*g_); }
  int rings() const { return rings_.rings(); }
  const std::vector<Vertex>& vertices() const { return rings_.vertices(); }
  std::size_t ring_end(int r) const { return rings_.ring_end(r); }
  bool center_on_border(Vertex) const { return rings_.center_on_border(); }

  bool grow_ball(double radius, const Eigen::Vector3d& center)
  {
    return rings_.grow_ball(*g_, radius * radius, [&](Vertex w) { return (point(w) - center).squaredNorm(); });
  }
  bool inside_ball(std::size_t i) const { return rings_.inside_ball(i); }
  std::size_t ball_size() const { return rings_.ball_size(); }
  std::size_t ball_joined(std::size_t k) const { return rings_.ball_joined(k); }
  // The radius of the widest ball grown about v since the neighborhood moved to v (0: none).
  double widest_ball(Vertex v) const { return std::sqrt(rings_.widest_squared_ball(v)); }

  // Face averages need no neighborhood.
  static bool gathers_for_normal(Vertex_normal_method method) { return method == Vertex_normal_method::quadric_fit; }

  // The area-weighted normal from the gathered 1-ring for quadric_fit, and for
  // area_weighted where the 1-ring is gathered and its faces are triangles (the same
  // normal, without walking the faces again); else the face average by `method`.
  Eigen::Vector3d initial_normal(Vertex v, Vertex_normal_method method, bool gathered,
                                 const std::vector<Eigen::Vector3d>& offsets, const std::vector<char>& finite,
                                 double) const
  {
    const bool from_ring = method == Vertex_normal_method::quadric_fit ||
                           (gathered && method == Vertex_normal_method::area_weighted && rings_.faces_are_triangles());
    return from_ring ? corner_normal_sum(v, offsets, finite) : face_average_normal(v, *g_, vpm_, method);
  }

  static void set_estimate(Surface_estimate& e, Estimation_status status, const Graph_curvature<3>& curvature,
                           double scale)
  {
    set_surface_estimate(e, status, curvature, scale);
  }

private:
  // The sum of the faces' corner normals at the center, from the gathered 1-ring:
  // the area-weighted normal on a triangle mesh, without walking the faces again.
  Eigen::Vector3d corner_normal_sum(Vertex v, const std::vector<Eigen::Vector3d>& offsets,
                                    const std::vector<char>& finite) const
  {
    if (!rings_.one_ring_in_fan_order())
      return face_average_normal(v, *g_, vpm_, Vertex_normal_method::area_weighted);
    const std::size_t valence = rings_.ring_end(1) - 1;
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (std::size_t k = 0; k < valence; ++k) {
      const std::size_t next = k + 1 < valence ? k + 2 : 1;
      if (rings_.has_face(k) && finite[1 + k] && finite[next])
        sum += offsets[next].cross(offsets[1 + k]);
    }
    return sum;
  }

  const FaceGraph* g_;
  VertexPointMap vpm_;
  Ring_collector<FaceGraph> rings_;
};

// The fits of vertex_fitter.h at the vertices of a FaceGraph. Fits that gather
// more than the 1-ring at most vertices (fit_degree 3 and 4, balls, wider
// starting rings) read the rings from the graph's Vertex_adjacency, built here
// once; the default, on the 1-ring but where it widens, would not win it back.
template <typename FaceGraph, typename VertexPointMap>
class Surface_fitter : public Vertex_fitter<Face_graph_neighborhood<FaceGraph, VertexPointMap>>
{
public:
  Surface_fitter(const FaceGraph& g, VertexPointMap vpm, const Fit_settings& settings)
      : Surface_fitter(g, vpm, settings, adjacency_for(g, settings))
  {}

  // With the rings from `adjacency` (null: by halfedge circulation), for a fitter
  // that runs at few vertices.
  Surface_fitter(const FaceGraph& g, VertexPointMap vpm, const Fit_settings& settings,
                 std::shared_ptr<const Vertex_adjacency> adjacency)
      : Vertex_fitter<Face_graph_neighborhood<FaceGraph, VertexPointMap>>(
          Face_graph_neighborhood<FaceGraph, VertexPointMap>(g, vpm, std::move(adjacency)), settings)
  {}

  // The adjacency that a fitter with `settings` reads its rings from (null: none).
  static std::shared_ptr<const Vertex_adjacency> adjacency_for(const FaceGraph& g, const Fit_settings& settings)
  {
    const bool beyond_one_ring = settings.degree > 2 || settings.ball_radius > 0 || settings.selects_radius() ||
                                 settings.rings > 1 || settings.boundary_rings > 1;
    return beyond_one_ring ? vertex_adjacency(g) : nullptr;
  }
};

// The scale selection at the vertices of a FaceGraph.
template <typename FaceGraph, typename VertexPointMap>
using Surface_scale_selector = Scale_selector<Face_graph_neighborhood<FaceGraph, VertexPointMap>>;

} // namespace internal
} // namespace Curvature_estimation
} // namespace CGAL

#endif // CGAL_CURVATURE_ESTIMATION_INTERNAL_FACE_GRAPH_NEIGHBORHOOD_H
