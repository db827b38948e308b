// SPDX-License-Identifier: GPL-3.0-or-later
// Vertex normals of a surface mesh as weighted averages of face normals.
//
// The per-vertex kernel `internal::face_average_normal()` is a pure function of
// one vertex's star, allocation-free, meant to be called from the vertex loop of
// an estimator; `estimate_vertex_normals()` is the public function that fills a
// property map for every vertex of a `FaceGraph`.
#ifndef CGAL_CURVATURE_ESTIMATION_VERTEX_NORMALS_H
#define CGAL_CURVATURE_ESTIMATION_VERTEX_NORMALS_H

#include <CGAL/Curvature_estimation/Principal_curvatures_and_directions.h>
#include <CGAL/Curvature_estimation/internal/estimate_at_vertices.h>
#include <CGAL/Curvature_estimation/internal/face_average_normal.h>
#include <CGAL/Curvature_estimation/internal/face_graph_platelet.h>
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

  Platelet_fitter<FaceGraph, VertexPointMap> fitter;
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
};

} // namespace internal

/**
 * \ingroup PkgCurvatureEstimationRef
 *
 * estimates a unit normal at every vertex of `g` and writes it into `normals`: by default
 * from a local Taylor fit (second order, also at boundary vertices), or as a weighted
 * average of the normals of its incident faces (first order in general).
 *
 * Faces may be any (simple) polygons. Face normals are oriented by the orientation of the
 * faces, so a closed, consistently oriented mesh gets outward normals when its faces are
 * oriented counter-clockwise seen from outside. The computation is done in `double`
 * (see `internal::face_average_normal()`), independently of the scale of the mesh.
 *
 * A vertex gets no normal when it is isolated, when all its incident faces are degenerate
 * (zero area) or have a non-finite point, or their weighted normals cancel, or when its own
 * point is not finite.
 * Its normal is then a vector of three quiet NaNs (the null vector if `FT` has no NaN, as
 * for exact number types), and its status `Estimation_status::not_estimable`.
 * An empty mesh is not an error: nothing is written.
 *
 * @tparam FaceGraph a model of `FaceListGraph` (faces may be any polygons)
 * @tparam VertexNormalMap a model of `WritablePropertyMap` with
 *         `boost::graph_traits<FaceGraph>::%vertex_descriptor` as key type and
 *         `GT::Vector_3` as value type, where `GT` is the type of the geometric traits
 * @tparam NamedParameters a sequence of named parameters, built with the functions of
 *         `CGAL::Curvature_estimation::parameters`
 *
 * @param g the surface mesh
 * @param normals the property map in which the unit normals are written
 * @param np an optional sequence of named parameters among the ones listed below
 *
 * \cgalNamedParamsBegin
 *   \cgalParamNBegin{vertex_point_map}
 *     \cgalParamDescription{a property map associating points to the vertices of `g`}
 *     \cgalParamType{a class model of `ReadablePropertyMap` with `boost::graph_traits<FaceGraph>::%vertex_descriptor`
 *                    as key type and `GT::Point_3` as value type}
 *     \cgalParamDefault{`boost::get(CGAL::vertex_point, g)`}
 *     \cgalParamExtra{If this parameter is omitted, an internal property map for `CGAL::vertex_point_t`
 *                     must be available in `FaceGraph`.}
 *   \cgalParamNEnd
 *
 *   \cgalParamNBegin{geom_traits}
 *     \cgalParamDescription{an instance of a geometric traits class, which gives `FT` and `Vector_3`
 *                           and constructs the vectors written}
 *     \cgalParamType{a class model of `Kernel`}
 *     \cgalParamDefault{a \cgal Kernel deduced from the point type, using `CGAL::Kernel_traits`}
 *     \cgalParamExtra{The geometric traits class must be compatible with the vertex point type.}
 *   \cgalParamNEnd
 *
 *   \cgalParamNBegin{vertex_normal_method}
 *     \cgalParamDescription{the weights of the face normals:
 *                           `Vertex_normal_method::area_weighted` (face areas),
 *                           `Vertex_normal_method::angle_weighted` (interior angles at the vertex) or
 *                           `Vertex_normal_method::centroid_weighted` (inverse squared distances from the
 *                           vertex to the face centroids, Chen, Wu and Chi 2005), or
 *                           `Vertex_normal_method::quadric_fit`: the area-weighted normal corrected by the
 *                           gradient of a local Taylor fit (degree 2 over the 1-ring in the interior, a
 *                           cubic over at least 3 rings at boundary vertices), second order everywhere,
 *                           where face averages are only first order at boundaries and irregular stars.}
 *     \cgalParamType{`CGAL::Curvature_estimation::Vertex_normal_method`}
 *     \cgalParamDefault{`Vertex_normal_method::quadric_fit`}
 *   \cgalParamNEnd
 *
 *   \cgalParamNBegin{neighborhood_rings}
 *     \cgalParamDescription{`quadric_fit` only: rings an interior vertex's fit starts with}
 *     \cgalParamType{`int`, at least 1}
 *     \cgalParamDefault{`1`}
 *   \cgalParamNEnd
 *
 *   \cgalParamNBegin{boundary_neighborhood_rings}
 *     \cgalParamDescription{`quadric_fit` only: rings a boundary vertex's fit starts with}
 *     \cgalParamType{`int`, at least 1}
 *     \cgalParamDefault{the value of `neighborhood_rings`}
 *   \cgalParamNEnd
 *
 *   \cgalParamNBegin{max_neighborhood_rings}
 *     \cgalParamDescription{`quadric_fit` only: the widest neighborhood an ill-conditioned fit is widened to}
 *     \cgalParamType{`int`}
 *     \cgalParamDefault{`3`}
 *   \cgalParamNEnd
 *
 *   \cgalParamNBegin{max_condition_number}
 *     \cgalParamDescription{`quadric_fit` only: fits whose normal equations have a larger condition number are
 *                           widened (see `paraboloid_fitting_curvatures()`)}
 *     \cgalParamType{`double`}
 *     \cgalParamDefault{`1e3`}
 *   \cgalParamNEnd
 *
 *   \cgalParamNBegin{fit_degree}
 *     \cgalParamDescription{`quadric_fit` only: the degree of the Taylor fit whose gradient corrects the
 *                           area-weighted normal, in the interior and at the boundary: `2` as described above,
 *                           `3` or `4` the fits of `paraboloid_fitting_curvatures()` with the same `fit_degree`
 *                           (over 2 and 3 rings), whose normals are of third and fourth order where the degree-2
 *                           normal is of second order; where such a fit is not determined up to the widest
 *                           neighborhood, the degree-2 normal. These are the normals that those fits read their
 *                           curvatures in; pass them as `vertex_normal_map` to another estimator to give it
 *                           normals of that order.}
 *     \cgalParamType{`int`, 2 to 4}
 *     \cgalParamDefault{`2`}
 *   \cgalParamNEnd
 *
 *   \cgalParamNBegin{ball_radius}
 *     \cgalParamDescription{`quadric_fit` only: the area-weighted normal corrected by the gradient of the fit
 *                           over the ball of this radius of `paraboloid_fitting_curvatures()` (see Curvature at
 *                           a scale there), instead of the rings: normals at that scale, for noisy meshes}
 *     \cgalParamType{`double`, positive, in the units of the mesh (see `mean_edge_length()`)}
 *     \cgalParamDefault{none: the rings}
 *   \cgalParamNEnd
 *
 *   \cgalParamNBegin{vertex_estimation_status_map}
 *     \cgalParamDescription{an optional output property map receiving for each vertex
 *                           `Estimation_status::ok` when a normal was estimated and
 *                           `Estimation_status::not_estimable` when not (its normal is then NaN)}
 *     \cgalParamType{a class model of `WritablePropertyMap` with `boost::graph_traits<FaceGraph>::%vertex_descriptor`
 *                    as key type and `CGAL::Curvature_estimation::Estimation_status` as value type}
 *     \cgalParamDefault{none: no status is written}
 *   \cgalParamNEnd
 * \cgalNamedParamsEnd
 *
 * @tparam ConcurrencyTag `CGAL::Sequential_tag` (default), `CGAL::Parallel_tag` or `CGAL::Parallel_if_available_tag`
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
  const internal::Fit_parameters fit = internal::curvature_fit_parameters(np, "estimate_vertex_normals", 4, true);

  constexpr bool write_status = internal::has_parameter<NamedParameters, internal_np::vertex_estimation_status_map_t>();

  const auto construct_vector = traits.construct_vector_3_object();
  const FT no_value = std::numeric_limits<FT>::has_quiet_NaN ? std::numeric_limits<FT>::quiet_NaN() : FT(0);
  const Vector_3 no_normal = construct_vector(no_value, no_value, no_value);

  const internal::Vertex_normal_estimator<FaceGraph, VPM> estimator{
    internal::Platelet_fitter<FaceGraph, VPM>(g, vpm, fit.settings), fit.normal_method, false};
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
