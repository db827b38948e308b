// SPDX-License-Identifier: GPL-3.0-or-later
// Vertex normals of a surface mesh: fitted, or weighted averages of face normals.
#ifndef CGAL_CURVATURE_ESTIMATION_VERTEX_NORMALS_H
#define CGAL_CURVATURE_ESTIMATION_VERTEX_NORMALS_H

#include <CGAL/Curvature_estimation/Principal_curvatures_and_directions.h>
#include <CGAL/Curvature_estimation/internal/estimate_at_vertices.h>
#include <CGAL/Curvature_estimation/internal/face_average_normal.h>
#include <CGAL/Curvature_estimation/internal/face_graph_neighborhood.h>
#include <CGAL/Curvature_estimation/parameters.h>

#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/tags.h>

#include <boost/graph/graph_traits.hpp>

#include <Eigen/Core>

#include <limits>

namespace CGAL {
namespace Curvature_estimation {
namespace internal {

// The unit normal at one vertex by `method`, or zero where there is none. With
// `fall_back`, a vertex where quadric_fit fails (a tiny component: too few or
// ill-conditioned neighbors up to the widest ring) gets its uncorrected starting
// normal, the area-weighted one.
template <typename FaceGraph, typename VertexPointMap>
struct Vertex_normal_estimator
{
  static constexpr bool uses_given_normals = false;

  Surface_fitter<FaceGraph, VertexPointMap> fitter;
  Vertex_normal_method method;
  bool fall_back;

  Eigen::Vector3d estimate(typename boost::graph_traits<FaceGraph>::vertex_descriptor v, const Eigen::Vector3d*)
  {
    Eigen::Vector3d n;
    return find(v, n) ? n : Eigen::Vector3d::Zero();
  }

  // The same as Gauss_map_estimator's normals, computed on demand; false where `v` has none.
  bool find(typename boost::graph_traits<FaceGraph>::vertex_descriptor v, Eigen::Vector3d& n)
  {
    return fitter.normal(v, method, n) || (fall_back && method == Vertex_normal_method::quadric_fit &&
                                           fitter.normal(v, Vertex_normal_method::area_weighted, n));
  }

  // After find(v): the radius of the widest ball its fits gathered (0: none).
  double reach(typename boost::graph_traits<FaceGraph>::vertex_descriptor v) { return fitter.widest_ball(v); }
};

} // namespace internal

/**
 * \ingroup PkgCurvatureEstimationRef
 *
 * estimates a unit normal at every vertex of `g` and writes it into `normals`: by default the fitted normal
 * (the area-weighted normal corrected by the gradient of a local Taylor fit, second order also at boundary
 * vertices; of third and fourth order with `fit_degree(3)` and `fit_degree(4)`: the normals that
 * `paraboloid_fitting_curvatures()` with the same `fit_degree` reads its curvatures in), or a weighted
 * average of the normals of the incident faces (first order in general). Faces may be any polygons;
 * normals are oriented as the faces. A vertex that is isolated, whose faces are all degenerate or whose
 * point is not finite gets no normal: three NaNs (the null vector if `FT` has no NaN) and the status
 * `not_estimable`. See the User Manual, "Vertex normals".
 *
 * @tparam ConcurrencyTag `CGAL::Sequential_tag` (default), `CGAL::Parallel_tag` or `CGAL::Parallel_if_available_tag`
 * @tparam FaceGraph a model of `FaceListGraph`
 * @tparam VertexNormalMap a model of `WritablePropertyMap` with `boost::graph_traits<FaceGraph>::%vertex_descriptor`
 *         as key type and `GT::Vector_3` as value type
 * @tparam NamedParameters a sequence of named parameters, built with the functions of
 *         `CGAL::Curvature_estimation::parameters`
 *
 * @param g the surface mesh
 * @param normals the property map in which the unit normals are written
 * @param np an optional sequence of named parameters among the ones listed below
 *
 * \cgalNamedParamsBegin
 *   \ceSurfaceInputParameters
 *   \cgalParamNBegin{vertex_normal_method}
 *     \cgalParamDescription{`quadric_fit`, or the face normals averaged with weights (`area_weighted`,
 *                           `angle_weighted` or `centroid_weighted`)}
 *     \cgalParamDefault{`Vertex_normal_method::quadric_fit`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{fit_degree}
 *     \cgalParamDescription{`quadric_fit` only: the degree of the fit whose gradient corrects the normal, 2 to 4}
 *     \cgalParamDefault{`2`}
 *   \cgalParamNEnd
 *   \ceBallRadiusParameter
 *   \ceRingParameters
 *   \cgalParamNBegin{vertex_estimation_status_map}
 *     \cgalParamDescription{output: `ok` where a normal was estimated, `not_estimable` where not}
 *     \cgalParamDefault{not written}
 *   \cgalParamNEnd
 * \cgalNamedParamsEnd
 *
 * \throws std::invalid_argument if a ring, condition, `fit_degree` or `ball_radius` parameter is out of its range.
 */
template <typename ConcurrencyTag = CGAL::Sequential_tag, typename FaceGraph, typename VertexNormalMap,
          typename NamedParameters = parameters::Default_named_parameters>
void estimate_vertex_normals(const FaceGraph& g, VertexNormalMap normals,
                             const NamedParameters& np = parameters::default_values())
{
  using ::CGAL::parameters::choose_parameter;
  using ::CGAL::parameters::get_parameter;

  using GT = typename CGAL::GetGeomTraits<FaceGraph, NamedParameters>::type;
  using VPM = typename CGAL::GetVertexPointMap<FaceGraph, NamedParameters>::const_type;
  using FT = typename GT::FT;
  using Vector_3 = typename GT::Vector_3;
  using vertex_descriptor = typename boost::graph_traits<FaceGraph>::vertex_descriptor;

  const GT traits = choose_parameter<GT>(get_parameter(np, ::CGAL::internal_np::geom_traits));
  const VPM vpm =
    internal::parameter_or(np, ::CGAL::internal_np::vertex_point, get_const_property_map(CGAL::vertex_point, g));
  const internal::Fit_parameters fit =
    internal::curvature_fit_parameters(np, "estimate_vertex_normals", 4, internal::Neighborhoods::rings_or_ball);

  constexpr bool write_status = internal::has_parameter<NamedParameters, internal_np::vertex_estimation_status_map_t>();

  const auto construct_vector = traits.construct_vector_3_object();
  const FT no_value = std::numeric_limits<FT>::has_quiet_NaN ? std::numeric_limits<FT>::quiet_NaN() : FT(0);
  const Vector_3 no_normal = construct_vector(no_value, no_value, no_value);

  const internal::Vertex_normal_estimator<FaceGraph, VPM> estimator{
    internal::Surface_fitter<FaceGraph, VPM>(g, vpm, fit.settings), fit.normal_method, false};
  internal::estimate_at_vertices<ConcurrencyTag, false>(
    vertices(g), estimator, [&](vertex_descriptor v, const Eigen::Vector3d& n) {
      const bool estimated = n.squaredNorm() > 0;
      put(normals, v, estimated ? construct_vector(FT(n.x()), FT(n.y()), FT(n.z())) : no_normal);
      if constexpr (write_status)
        put(get_parameter(np, internal_np::vertex_estimation_status_map), v,
            estimated ? Estimation_status::ok : Estimation_status::not_estimable);
    });
}

} // namespace Curvature_estimation
} // namespace CGAL

#endif // CGAL_CURVATURE_ESTIMATION_VERTEX_NORMALS_H
