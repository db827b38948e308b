// SPDX-License-Identifier: GPL-3.0-or-later
// Chen, Wu and Chi's estimator: the differential of the Gauss map, on any FaceGraph.
#ifndef CGAL_CURVATURE_ESTIMATION_GAUSS_MAP_H
#define CGAL_CURVATURE_ESTIMATION_GAUSS_MAP_H

#include <CGAL/Curvature_estimation/Neighbor_weighting.h>
#include <CGAL/Curvature_estimation/Principal_curvatures_and_directions.h>
#include <CGAL/Curvature_estimation/internal/estimate_at_vertices.h>
#include <CGAL/Curvature_estimation/internal/face_graph_platelet.h>
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
// normalised, else estimated by `fit`'s method. Computed before the differential,
// which reads each vertex's normal at all its neighbors.
template <typename ConcurrencyTag, typename FaceGraph, typename VertexPointMap, typename NamedParameters>
std::shared_ptr<const Vertex_normal_table<FaceGraph>>
gauss_map_normals(const FaceGraph& g, const VertexPointMap& vpm, const NamedParameters& np, const Fit_parameters& fit)
{
  using vertex_descriptor = typename boost::graph_traits<FaceGraph>::vertex_descriptor;
  const Eigen::Vector3d no_normal = Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
  auto normals = std::make_shared<Vertex_normal_table<FaceGraph>>(g);
  if constexpr (has_parameter<NamedParameters, ::CGAL::internal_np::vertex_normal_map_t>()) {
    const auto normal_map = ::CGAL::parameters::get_parameter(np, ::CGAL::internal_np::vertex_normal_map);
    for (vertex_descriptor v : vertices(g)) {
      const Eigen::Vector3d n = load_given_normal<true>(normal_map, v);
      const double length = n.norm();
      normals->set(v, length > 0 && std::isfinite(length) ? Eigen::Vector3d(n / length) : no_normal);
    }
  } else {
    (void)np;
    const Vertex_normal_estimator<FaceGraph, VertexPointMap> estimator{
      Platelet_fitter<FaceGraph, VertexPointMap>(g, vpm, fit.settings), fit.normal_method, true};
    estimate_at_vertices<ConcurrencyTag, false>(
      vertices(g), estimator,
      [&](vertex_descriptor v, const Eigen::Vector3d& n) { normals->set(v, n.squaredNorm() > 0 ? n : no_normal); });
  }
  return normals;
}

} // namespace internal

/// \ingroup PkgCurvatureEstimationRef
///
/// Estimates principal curvatures and directions, mean and Gaussian curvature at
/// every vertex of a surface mesh by the differential of the Gauss map (Chen, Wu
/// and Chi 2005), projected on a tangent frame of the vertex normal (the paper's
/// eq. 28): a 2x2 matrix `A`, `a_ij = <e_i, dN(e_j)>`.
/// `H = tr(A)/2` (the paper's `-tr(A)/2` is for
/// the normal pointing toward the centre of curvature), `K = det A`, and
/// the principal curvatures and directions are the eigenvalues and eigenvectors of
/// the symmetric part of `A` (so `max_curvature * min_curvature` may
/// differ from K by the square of A's antisymmetric part).
/// Boundary vertices use the neighbors they have, and faces may be any polygons.
///
/// **The differential.** By default `A` is the least-squares solution of
/// `T^T (N(q_i) - N(p)) = A T^T (q_i - p)` over the vertices `q_i` of the 2-ring of
/// p, all at once (T the tangent frame, unweighted), which no single face's height
/// divides. With `neighbor_weighting` it is the paper's: the three components of the
/// vertex normals are interpolated linearly over each corner (the vertex and its
/// two neighbors in an incident face); their gradients (eqs. 19-21) form the 3x3
/// Jacobian of the normal on that face, and the Jacobians are averaged with the
/// centroid weights `1/|G_f - v|^2` of eq. 23 (`Neighbor_weighting::centroid`: the
/// paper's estimator, which reproduces its tables) or with the corners' areas
/// (`Neighbor_weighting::area`). A per-face gradient divides the normals' errors by
/// the face's height, and on meshes with slivers and clusters of nearly coincident
/// vertices (marching tetrahedra of smooth surfaces, vertices on the surface,
/// `quadric_fit` normals; test `MarchingTetrahedraConvergence`) the paper's weights
/// do not converge: at 20, 40, 80 cells the RMS error of H was 1.4, 2.8, 0.52 on an
/// ellipsoid, 12.9, 3.4, 9.0 on a torus and 2.0, 0.55, 1.1 on blobs, with maxima up
/// to 1,579. Area weights give slivers no weight but still fail (RMS 0.14, 0.62, 0.24
/// at 80 cells), and so does the least-squares fit over the 1-ring (0.052, 0.57,
/// 0.28): near a grid corner all the 1-ring of a vertex lies within 1e-3 of the mean
/// edge length h, and its normals differ by their O(h^2) errors. The 2-ring reaches
/// the vertices at distance about h, and the unweighted fit is dominated by them:
/// 4.4e-2, 2.1e-2, 1.0e-2 (ellipsoid), 5.5e-2, 2.1e-2, 1.1e-2 (torus), 7.0e-2, 3.2e-2,
/// 1.6e-2 (blobs), maxima at most 0.10 at 80 cells, order 1.0 on all three. It costs
/// accuracy where the per-face weights do well: on the jittered torus of the next
/// paragraph 5.5e-3 instead of 3.0e-3, on Delaunay triangulations of random points (graphs of Hamann's functions,
/// 16,000 points, interior vertices) 2 to 3.5 times the RMS error of the paper's weights,
/// at the same order 1. With exact normals on a sphere it is exact.
///
/// **Normals.** The estimate divides differences of neighboring normals by edge
/// lengths, so its accuracy is that of the normals divided by h: with exact
/// normals the estimate converges, with first-order normals (any average of face
/// normals on an irregular mesh or at a boundary) its error is O(1). Normals come
/// from `vertex_normal_map` when given (at the vertex and at its neighbors).
/// Otherwise they are estimated once per vertex by `vertex_normal_method`, whose
/// default here is `Vertex_normal_method::quadric_fit` (second order, also at
/// boundary vertices). Measured on a torus (R = 3, r = 1, 48x24 and 96x48 vertices; the test
/// `Gauss_map.ErrorWithEachNormalChoiceOnRegularAndJitteredTorus` prints the table),
/// RMS error of H at 96x48: on the regular mesh every choice gives the error of the
/// exact normals (2.2e-3 with the paper's weights, 2.9e-3 to 3.4e-3 by least squares:
/// the symmetric stencils cancel the first-order normal errors); on the jittered mesh
/// (offsets up to 0.2 of the spacing), with the paper's weights, the exact normals give
/// 2.7e-3, `quadric_fit` 3.0e-3, and the face averages 3.1e-2 (`angle_weighted`),
/// 6.6e-2 (`centroid_weighted`, the paper's) and 7.6e-2 (`area_weighted`), the same at
/// both resolutions: they do not converge; by least squares over the wider 2-ring,
/// 5.2e-3, 5.5e-3, and 8.9e-3, 9.8e-3, 1.8e-2. Hence `quadric_fit`. A vertex where the fit is
/// impossible even over the widest ring (a tiny component, such as the rim of a
/// lone fan) falls back to the area-weighted normal the fit starts from, so that it
/// does not deprive its neighbors of an estimate; first order there.
///
/// **Curvature at a scale.** With `ball_radius(r)` the least squares are over the
/// ball of `paraboloid_fitting_curvatures()` (the part of the mesh inside the ball of
/// radius r about the vertex, joined to it by edges inside the ball) instead of the
/// 2-ring, grown by steps of 25% until it holds 6 vertices (twice the 3 that determine
/// `A`) and then while `A` is not determined, up to twice that radius (status `widened`
/// where it grew); the `quadric_fit` normals are then those of the fit over the ball of
/// the same radius about each vertex. Its data thus reach twice the radius, and on a
/// noisy mesh its error at r is about that of the paraboloid fit at 2r: on an
/// ellipsoid of 10,242 vertices with Gaussian noise of 7% of the mean edge length h
/// per coordinate, H RMS 0.24, 0.065, 0.034, 0.039, 0.063 at 2, 3, 4, 6, 8 h
/// (the paraboloid fit of degree 2: 1.02, 0.29, 0.12, 0.040, 0.035). Without noise,
/// at a fixed number of edges, it converges at order 1 on Delaunay meshes (test
/// `test_ball_radius`).
///
/// **Conventions.** Curvatures are positive where the surface bends away from the
/// normal (a sphere with outward normals has `max_curvature == min_curvature == 1/r`),
/// `max_curvature >= min_curvature`, directions are unit, tangent and orthogonal.
/// Scaling the mesh by s scales the curvatures by 1/s, to rounding. A vertex
/// that cannot be estimated (isolated, without a normal, non-finite point; by
/// least squares, 2-ring neighbors with normals all on one line through the vertex
/// in the tangent plane; per face, no incident face with a non-degenerate corner
/// and normals at its corner) gets NaN
/// in every output and the status `Estimation_status::not_estimable`.
///
/// Only the outputs whose maps are passed are written; passing none does nothing.
///
/// \ceConcurrencyTag
/// \tparam FaceGraph a model of `FaceGraph` (faces may be any polygons).
/// \tparam NamedParameters a sequence of named parameters, built with the functions of
/// `CGAL::Curvature_estimation::parameters`
///
/// \param g the mesh
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \ceSurfaceInputParameters
///   \ceGivenNormalParameter
///   \ceQuadricFitNormalParameters
///   \cgalParamNBegin{neighbor_weighting}
///     \cgalParamDescription{when given, the differential is the paper's average of per-face Jacobians with these
///                           weights (`Neighbor_weighting::centroid`: Chen, Wu and Chi's; `Neighbor_weighting::area`:
///                           the corners' areas) instead of the least-squares fit over the 2-ring;
///                           `Neighbor_weighting::uniform` is refused}
///     \cgalParamType{`CGAL::Curvature_estimation::Neighbor_weighting`}
///     \cgalParamDefault{none: the least-squares fit}
///   \cgalParamNEnd
///   \cgalParamNBegin{ball_radius}
///     \cgalParamDescription{the radius of the ball that is the neighborhood of the least-squares differential
///                           and of the `quadric_fit` normals instead of the rings (see Curvature at a scale
///                           above); not with `neighbor_weighting`}
///     \cgalParamType{`double`, positive, in the units of the mesh (see `mean_edge_length()`)}
///     \cgalParamDefault{none: the rings}
///   \cgalParamNEnd
///   \ceSurfaceOutputParameters{K = det A (see above), `ok`; `widened` where a ball grew; or `not_estimable`}
/// \cgalNamedParamsEnd
///
/// \throws std::invalid_argument if a parameter is out of its range, or if `ball_radius`
///         is given with `neighbor_weighting`.
template <typename ConcurrencyTag = CGAL::Sequential_tag, typename FaceGraph,
          typename NamedParameters = parameters::Default_named_parameters>
void gauss_map_curvatures(const FaceGraph& g, const NamedParameters& np = parameters::default_values())
{
  const internal::Fit_parameters fit = internal::fit_parameters(np, "gauss_map_curvatures", true);
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
