// SPDX-License-Identifier: GPL-3.0-or-later
// Chen, Wu and Chi's estimator: the differential of the Gauss map, on any FaceGraph.
#ifndef CGAL_CURVATURE_ESTIMATION_GAUSS_MAP_H
#define CGAL_CURVATURE_ESTIMATION_GAUSS_MAP_H

#include <CGAL/Curvature_estimation/Neighbor_weighting.h>
#include <CGAL/Curvature_estimation/Principal_curvatures_and_directions.h>
#include <CGAL/Curvature_estimation/internal/estimate_at_vertices.h>
#include <CGAL/Curvature_estimation/internal/face_graph_neighborhood.h>
#include <CGAL/Curvature_estimation/internal/gauss_map_differential.h>
#include <CGAL/Curvature_estimation/internal/shape_matrix_estimate.h>
#include <CGAL/Curvature_estimation/parameters.h>
#include <CGAL/Curvature_estimation/vertex_normals.h>

#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/tags.h>

#include <boost/graph/graph_traits.hpp>

#include <Eigen/Core>

#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>
#include <type_traits>

namespace CGAL {
namespace Curvature_estimation {

namespace internal {

// The differential that `np` asks for: without neighbor_weighting the least-squares
// fit over the 2-ring, with it Chen, Wu and Chi's per-face Jacobians so weighted.
template <typename NamedParameters>
Gauss_map_differential_method gauss_map_differential_method(const NamedParameters& np)
{
  if constexpr (!has_parameter<NamedParameters, internal_np::neighbor_weighting_t>()) {
    (void)np;
    return Gauss_map_differential_method::least_squares_2_ring;
  } else {
    const Neighbor_weighting weighting = ::CGAL::parameters::get_parameter(np, internal_np::neighbor_weighting);
    if (weighting == Neighbor_weighting::centroid)
      return Gauss_map_differential_method::face_centroid_weighted;
    if (weighting == Neighbor_weighting::area)
      return Gauss_map_differential_method::face_area_weighted;
    throw std::invalid_argument("gauss_map_curvatures: neighbor_weighting must be area or centroid");
  }
}

// Every vertex's unit normal, NaN where there is none: the given ones of `np`,
// normalised, else estimated by `fit`'s method, with the reach of its fits. Computed
// before the differential, which reads each vertex's normal at all its neighbors.
template <typename ConcurrencyTag, typename FaceGraph, typename VertexPointMap, typename NamedParameters>
std::shared_ptr<const Vertex_normal_table<FaceGraph>>
gauss_map_normals(const FaceGraph& g, const VertexPointMap& vpm, const NamedParameters& np, const Fit_parameters& fit)
{
  using vertex_descriptor = typename boost::graph_traits<FaceGraph>::vertex_descriptor;
  using Entry = typename Vertex_normal_table<FaceGraph>::Entry;
  auto normals = std::make_shared<Vertex_normal_table<FaceGraph>>(g);
  if constexpr (has_parameter<NamedParameters, ::CGAL::internal_np::vertex_normal_map_t>()) {
    const auto normal_map = ::CGAL::parameters::get_parameter(np, ::CGAL::internal_np::vertex_normal_map);
    for (vertex_descriptor v : vertices(g)) {
      const Eigen::Vector3d n = load_given_normal<true>(normal_map, v);
      const double length = n.norm();
      Entry e;
      if (length > 0 && std::isfinite(length))
        e.normal = n / length;
      normals->set(v, e);
    }
  } else {
    (void)np;
    struct Estimator
    {
      Vertex_normal_estimator<FaceGraph, VertexPointMap> normals;
      Entry estimate(vertex_descriptor v, const Eigen::Vector3d*)
      {
        Entry e;
        const Eigen::Vector3d n = normals.estimate(v, nullptr);
        if (n.squaredNorm() > 0)
          e.normal = n;
        e.reach = normals.reach(v);
        return e;
      }
    };
    const Estimator estimator{
      {Surface_fitter<FaceGraph, VertexPointMap>(g, vpm, fit.settings), fit.normal_method, true}};
    estimate_at_vertices<ConcurrencyTag, false>(vertices(g), estimator,
                                                [&](vertex_descriptor v, const Entry& e) { normals->set(v, e); });
  }
  return normals;
}

} // namespace internal

/// \ingroup PkgCurvatureEstimationRef
///
/// estimates principal curvatures and directions, mean and Gaussian curvature at every vertex of `g` by
/// the differential of the Gauss map (Chen, Wu and Chi 2005), projected on a tangent frame T of the vertex
/// normal: the 2x2 matrix A, a_ij = <e_i, dN(e_j)>. H = tr(A)/2, K = det A, and the principal curvatures and
/// directions are the eigenvalues and eigenvectors of A's symmetric part (so k1 k2 may differ from K by the
/// square of A's antisymmetric part). By default A is the least-squares solution of
/// T^T (N(q) - N(p)) = A T^T (q - p) over the vertices q of the 2-ring of p; with `neighbor_weighting` it is
/// the paper's average of per-face Jacobians (`centroid`: Chen, Wu and Chi's weights; `area`), which
/// reproduces the paper's tables but does not converge on meshes with slivers. With `ball_radius(r)` the
/// least squares are over the ball of `paraboloid_fitting_curvatures()` (status `widened` where it grew),
/// and the fitted normals are those of the fit over the ball. The estimate divides differences of
/// normals by edge lengths: its accuracy is that of the normals, hence the fitted normals by default.
/// Boundary vertices use the neighbors they have, and faces may be any polygons. The User Manual
/// ("Gauss map") gives the measurements behind these choices.
///
/// Conventions: as `paraboloid_fitting_curvatures()`. A vertex without a normal, with a non-finite point or
/// whose neighbors' normals do not determine A is `not_estimable` (NaN). Only the outputs whose maps are
/// passed are written.
///
/// \ceSurfaceEstimatorParameters
///
/// \cgalNamedParamsBegin
///   \ceSurfaceInputParameters
///   \ceGivenNormalParameter
///   \ceQuadricFitNormalParameters
///   \cgalParamNBegin{neighbor_weighting}
///     \cgalParamDescription{`centroid` or `area` (`uniform` is refused): the paper's average of per-face
///                           Jacobians so weighted}
///     \cgalParamDefault{none: the least-squares fit}
///   \cgalParamNEnd
///   \ceBallRadiusParameter
///   \ceSurfaceOutputParameters{K = det A (see above), `ok`; `widened` where a ball grew; or `not_estimable`}
///   \ceReachOutputParameter
/// \cgalNamedParamsEnd
///
/// \throws std::invalid_argument if a parameter is out of its range, or if `ball_radius`
///         is given with `neighbor_weighting`.
template <typename ConcurrencyTag = CGAL::Sequential_tag, typename FaceGraph,
          typename NamedParameters = parameters::Default_named_parameters>
void gauss_map_curvatures(const FaceGraph& g, const NamedParameters& np = parameters::default_values())
{
  const internal::Fit_parameters fit =
    internal::fit_parameters(np, "gauss_map_curvatures", internal::Neighborhoods::rings_or_ball);
  const internal::Gauss_map_differential_method method = internal::gauss_map_differential_method(np);
  if (fit.settings.ball_radius > 0 && method != internal::Gauss_map_differential_method::least_squares_2_ring)
    throw std::invalid_argument("gauss_map_curvatures: ball_radius is for the least-squares differential, "
                                "not with neighbor_weighting");
  internal::estimate_surface_curvatures<ConcurrencyTag>(g, np, [&](const auto& vpm) {
    return internal::Gauss_map_estimator<FaceGraph, std::decay_t<decltype(vpm)>>(
      g, vpm, internal::Shared_vertex_normals<FaceGraph>{internal::gauss_map_normals<ConcurrencyTag>(g, vpm, np, fit)},
      method, fit.settings.ball_radius);
  });
}

} // namespace Curvature_estimation
} // namespace CGAL

#endif // CGAL_CURVATURE_ESTIMATION_GAUSS_MAP_H
