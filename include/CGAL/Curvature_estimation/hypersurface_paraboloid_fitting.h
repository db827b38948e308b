// SPDX-License-Identifier: GPL-3.0-or-later
// Hamann's paraboloid fitting over the tetrahedral platelet of a 3-dimensional
// hypersurface of R^4 (Hamann's thesis §4.3), on any TetrahedralComplex.
//
// Naming: the surface estimator is `paraboloid_fitting_curvatures` in
// paraboloid_fitting.h; its tetrahedral twin prefixes both with `hypersurface_`:
// `hypersurface_paraboloid_fitting_curvatures` in hypersurface_paraboloid_fitting.h.
#ifndef CGAL_CURVATURE_ESTIMATION_HYPERSURFACE_PARABOLOID_FITTING_H
#define CGAL_CURVATURE_ESTIMATION_HYPERSURFACE_PARABOLOID_FITTING_H

#include <CGAL/Curvature_estimation/Principal_curvatures_and_directions.h>
#include <CGAL/Curvature_estimation/Tetrahedral_complex_traits.h>
#include <CGAL/Curvature_estimation/internal/estimate_at_vertices.h>
#include <CGAL/Curvature_estimation/internal/fit_parameters.h>
#include <CGAL/Curvature_estimation/internal/tetrahedral_platelet_fit.h>
#include <CGAL/Curvature_estimation/parameters.h>

#include <CGAL/tags.h>

#include <boost/property_map/property_map.hpp>
#include <boost/range/irange.hpp>

#include <cstddef>
#include <stdexcept>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Curvature_estimation {
namespace internal {

// Hamann's fit at one vertex of a tetrahedral complex (an index into its stars),
// with the given normal or one estimated by `method`.
template <typename Fitter>
struct Hypersurface_paraboloid_estimator
{
  Fitter fitter;
  Vertex_normal_method method;

  Hypersurface_estimate estimate(std::size_t i, const Eigen::Vector4d* given)
  {
    return given != nullptr ? fitter.fit(i, *given) : fitter.fit(i, method);
  }
};

// Writes the outputs that `np` asks for at vertex `v`, and only those.
template <typename NamedParameters, typename Vertex>
void put_hypersurface_estimate(const NamedParameters& np, const Vertex& v, const Hypersurface_estimate& e)
{
  using ::CGAL::parameters::get_parameter;
  if constexpr (has_parameter<NamedParameters, internal_np::vertex_principal_curvatures_and_directions_map_t>()) {
    auto map = get_parameter(np, internal_np::vertex_principal_curvatures_and_directions_map);
    using Value = typename boost::property_traits<std::remove_cv_t<std::remove_reference_t<decltype(map)>>>::value_type;
    using V4 = std::remove_cv_t<std::remove_reference_t<decltype(Value().max_direction)>>;
    using FT = typename Value::FT;
    Value value;
    value.max_curvature = FT(e.curvatures[0]);
    value.mid_curvature = FT(e.curvatures[1]);
    value.min_curvature = FT(e.curvatures[2]);
    value.max_direction = from_vector_4<V4>(e.directions.col(0));
    value.mid_direction = from_vector_4<V4>(e.directions.col(1));
    value.min_direction = from_vector_4<V4>(e.directions.col(2));
    put(map, v, value);
  }
  if constexpr (has_parameter<NamedParameters, internal_np::vertex_mean_curvature_map_t>()) {
    auto map = get_parameter(np, internal_np::vertex_mean_curvature_map);
    using FT = typename boost::property_traits<std::remove_cv_t<std::remove_reference_t<decltype(map)>>>::value_type;
    put(map, v, FT(e.curvatures.sum() / 3));
  }
  if constexpr (has_parameter<NamedParameters, internal_np::vertex_Gaussian_curvature_map_t>()) {
    auto map = get_parameter(np, internal_np::vertex_Gaussian_curvature_map);
    using FT = typename boost::property_traits<std::remove_cv_t<std::remove_reference_t<decltype(map)>>>::value_type;
    put(map, v, FT(e.curvatures.prod()));
  }
  if constexpr (has_parameter<NamedParameters, internal_np::vertex_estimation_status_map_t>())
    put(get_parameter(np, internal_np::vertex_estimation_status_map), v, e.status);
  (void)np;
  (void)v;
  (void)e;
}

} // namespace internal

/// \ingroup PkgCurvatureEstimationRef
///
/// Estimates the three principal curvatures and directions, the mean and the Gaussian
/// curvature at every vertex of a tetrahedral complex whose vertices are points of R^4
/// (a 3-dimensional hypersurface, for instance the graph W = f(x, y, z) of a trivariate
/// function) by Hamann's method (Hamann's thesis, §4.3): the vertex's platelet (the
/// vertices of its incident tetrahedra) is expressed in an orthonormal frame of the
/// 3-dimensional tangent space of the vertex normal, the osculating paraboloid
/// d = 1/2 (c200 u^2 + 2 c110 uv + 2 c101 uw + c020 v^2 + 2 c011 vw + c002 w^2) is fitted
/// to it by least squares (6 coefficients), and the curvatures are those of the
/// paraboloid at the vertex: the eigenvalues of its coefficient matrix.
///
/// **Normals.** With a `vertex_normal_map` the given normals (vectors of R^4) are
/// trusted, as in the thesis. Without one, the default `Vertex_normal_method::quadric_fit`
/// starts from the 3-volume-weighted mean of the normals of the incident tetrahedra (the
/// generalized cross product of each tetrahedron's edge vectors, oriented by the order of
/// its vertices) and corrects it by the gradient of a Taylor fit with linear terms, exactly
/// as `paraboloid_fitting_curvatures()` does on surfaces: a degree-2 fit at interior vertices,
/// and at boundary vertices a Gaussian-weighted fit with cubic terms over at least 3 rings
/// (falling back to degree 2 where it is ill-conditioned), so that the normal is second
/// order also at the boundary, where the cells' mean is only first order and gives an O(1)
/// curvature error. With that normal, at interior vertices, the curvature fit keeps the
/// linear terms where they are determined, as on surfaces (see
/// `paraboloid_fitting_curvatures()`). `Vertex_normal_method::area_weighted` uses the
/// cells' mean as is, in Hamann's fit.
/// Normals are oriented as the cells: for positively oriented tetrahedra of R^3 (as in
/// `CGAL::Triangulation_3`) lifted to a graph, the normal points to increasing W.
///
/// **Widening.** A vertex whose normal equations are ill-conditioned (condition number
/// above `max_condition_number`, in coordinates scaled by the mean 1-ring edge length) is
/// fitted again over one more ring, up to `max_neighborhood_rings` rings; beyond that it is
/// not estimable. A vertex is a boundary vertex when it lies on a triangle of only one cell.
///
/// **Conventions.** Curvatures are positive where the hypersurface bends away from the
/// normal, `max_curvature >= mid_curvature >= min_curvature`, H = (k1 + k2 + k3) / 3 (the
/// thesis' mean curvature), K = k1 k2 k3. Directions are unit vectors of R^4, tangent and
/// mutually orthogonal. Scaling the points by s scales the curvatures by 1/s, to rounding.
/// A vertex that cannot be estimated (isolated, non-finite coordinates, ill-conditioned up
/// to the widest ring) gets NaN in every output and the status `not_estimable`.
///
/// Only the outputs whose maps are passed are written; passing none does nothing.
///
/// \tparam ConcurrencyTag `CGAL::Sequential_tag` (default), `CGAL::Parallel_tag` or
///         `CGAL::Parallel_if_available_tag`. Sequential and parallel runs give identical
///         results. All property maps are read and written by the calling thread only.
/// \tparam TetrahedralComplex a model of `TetrahedralComplex`: `Indexed_tetrahedral_mesh`, or a
///         `CGAL::Triangulation_3` (any 3D triangulation of CGAL; finite cells only).
/// \tparam NamedParameters a sequence of named parameters, built with the functions of
///         `CGAL::Curvature_estimation::parameters`
///
/// \param complex the tetrahedral complex
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{a property map associating points of R^4 to the vertices}
///     \cgalParamType{a model of `ReadablePropertyMap` with the complex's vertex descriptor as key type and
///                    as value type `Eigen::Vector4d`, `std::array<double, 4>` or a CGAL
///                    `Epick_d<Dimension_tag<4>>::Point_d`; `make_graph_point_map()` builds one from a 3D point map and
///                    a scalar map}
///     \cgalParamDefault{the complex's points (`points[i]` of an `Indexed_tetrahedral_mesh`; for a
///                       `Triangulation_3`, whose points are in R^3, the map must be given)}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_normal_map}
///     \cgalParamDescription{normals of R^4 at the vertices, trusted as given (they need not be unit)}
///     \cgalParamType{a model of `ReadablePropertyMap` with the vertex descriptor as key type and a vector
///                    type of R^4 as value type (as for the points)}
///     \cgalParamDefault{normals estimated by `vertex_normal_method`}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_normal_method}
///     \cgalParamDescription{how normals are estimated when no `vertex_normal_map` is given}
///     \cgalParamType{`Vertex_normal_method::quadric_fit` or `Vertex_normal_method::area_weighted`
///                    (the 3-volume-weighted mean of the cells' normals)}
///     \cgalParamDefault{`Vertex_normal_method::quadric_fit`}
///   \cgalParamNEnd
///   \cgalParamNBegin{fit_degree}
///     \cgalParamDescription{the degree of the fitted polynomial in the three tangent variables: 2 is Hamann's
///                           paraboloid, 3 the cubic Taylor fit with linear terms over 2 rings, in the frame of the
///                           first-order normal, as for `paraboloid_fitting_curvatures()` (degree 4, whose fit would
///                           have 34 unknowns, is for surfaces only)}
///     \cgalParamType{`int`, 2 or 3}
///     \cgalParamDefault{`2`}
///   \cgalParamNEnd
///   \cgalParamNBegin{ball_radius}
///     \cgalParamDescription{the radius of the ball of R^4 that is the neighborhood instead of the rings: the
///                           fit of `fit_degree` with a constant term over the part of the complex in the ball
///                           joined to the vertex inside it, as `paraboloid_fitting_curvatures()` does on surfaces
///                           (see Curvature at a scale there), for noisy fields}
///     \cgalParamType{`double`, positive, in the units of the points}
///     \cgalParamDefault{none: the rings}
///   \cgalParamNEnd
///   \cgalParamNBegin{neighbor_weighting}
///     \cgalParamDescription{with a `ball_radius` only: `uniform` or `smooth` weights, as for
///                           `paraboloid_fitting_curvatures()`}
///     \cgalParamType{`CGAL::Curvature_estimation::Neighbor_weighting`}
///     \cgalParamDefault{`Neighbor_weighting::uniform`}
///   \cgalParamNEnd
///   \cgalParamNBegin{neighborhood_rings}
///     \cgalParamDescription{number of rings an interior vertex's fit starts with (1: Hamann's platelet)}
///     \cgalParamType{`int`, at least 1}
///     \cgalParamDefault{`1`}
///   \cgalParamNEnd
///   \cgalParamNBegin{boundary_neighborhood_rings}
///     \cgalParamDescription{number of rings a boundary vertex's fit starts with}
///     \cgalParamType{`int`, at least 1}
///     \cgalParamDefault{the value of `neighborhood_rings`}
///   \cgalParamNEnd
///   \cgalParamNBegin{max_neighborhood_rings}
///     \cgalParamDescription{the widest neighborhood an ill-conditioned fit is widened to}
///     \cgalParamType{`int`, at least the two values above}
///     \cgalParamDefault{`3`}
///   \cgalParamNEnd
///   \cgalParamNBegin{max_condition_number}
///     \cgalParamDescription{normal equations whose 1-norm condition number (in coordinates scaled by
///                           the mean 1-ring edge length) exceeds this value are widened}
///     \cgalParamType{`double`, greater than 1}
///     \cgalParamDefault{`1e3`}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_principal_curvatures_and_directions_map}
///     \cgalParamDescription{output: the three principal curvatures and directions}
///     \cgalParamType{a model of `WritablePropertyMap` with the vertex descriptor as key type and
///                    `Hypersurface_principal_curvatures_and_directions<Vector_4, FT>` as value type}
///     \cgalParamDefault{not computed}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_mean_curvature_map}
///     \cgalParamDescription{output: mean curvature H = (k1 + k2 + k3) / 3}
///     \cgalParamType{a model of `WritablePropertyMap` with the vertex descriptor as key type and a
///                    floating-point value type}
///     \cgalParamDefault{not computed}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_Gaussian_curvature_map}
///     \cgalParamDescription{output: Gaussian curvature K = k1 k2 k3}
///     \cgalParamType{a model of `WritablePropertyMap` with the vertex descriptor as key type and a
///                    floating-point value type}
///     \cgalParamDefault{not computed}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_estimation_status_map}
///     \cgalParamDescription{output: the outcome at each vertex}
///     \cgalParamType{a model of `WritablePropertyMap` with the vertex descriptor as key type and
///                    `CGAL::Curvature_estimation::Estimation_status` as value type}
///     \cgalParamDefault{not computed}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \throws std::invalid_argument if a parameter is out of its range, a cell index is out of
///         range, or the points do not have 4 coordinates.
template <typename ConcurrencyTag = CGAL::Sequential_tag, typename TetrahedralComplex,
          typename NamedParameters = parameters::Default_named_parameters>
void hypersurface_paraboloid_fitting_curvatures(const TetrahedralComplex& complex,
                                                const NamedParameters& np = parameters::default_values())
{
  using ::CGAL::parameters::get_parameter;
  using Traits = Tetrahedral_complex_traits<TetrahedralComplex>;
  using Stars = Tetrahedral_complex_stars<TetrahedralComplex>;
  using Fitter = internal::Tetrahedral_platelet_fitter<Stars>;

  const internal::Fit_parameters fit =
    internal::curvature_fit_parameters(np, "hypersurface_paraboloid_fitting_curvatures", 3, true);
  if (fit.normal_method != Vertex_normal_method::quadric_fit &&
      fit.normal_method != Vertex_normal_method::area_weighted)
    throw std::invalid_argument("hypersurface_paraboloid_fitting_curvatures: vertex_normal_method must be "
                                "quadric_fit or area_weighted");
  if constexpr (!internal::wants_curvature_output<NamedParameters>())
    return;
  else {
    constexpr bool given_normals = internal::has_parameter<NamedParameters, ::CGAL::internal_np::vertex_normal_map_t>();
    const auto vpm = internal::parameter_or(np, CGAL::internal_np::vertex_point, Traits::default_point_map(complex));
    const auto normals = get_parameter(np, CGAL::internal_np::vertex_normal_map);

    const Stars stars(complex);
    std::vector<Eigen::Vector4d> points;
    points.reserve(stars.size());
    for (const auto& v : stars.vertices)
      points.push_back(to_vector_4(get(vpm, v)));

    // The hypersurface's maps are read and written on the calling thread.
    const internal::Hypersurface_paraboloid_estimator<Fitter> estimator{Fitter(stars, points, fit.settings),
                                                                        fit.normal_method};
    internal::estimate_at_vertices<ConcurrencyTag, false, given_normals>(
      boost::irange(std::size_t(0), stars.size()), estimator,
      [&](std::size_t i) -> Eigen::Vector4d {
        if constexpr (given_normals)
          return to_vector_4(get(normals, stars.vertices[i]));
        else {
          (void)i;
          return Eigen::Vector4d::Zero();
        }
      },
      [&](std::size_t i, const internal::Hypersurface_estimate& e) {
        internal::put_hypersurface_estimate(np, stars.vertices[i], e);
      });
  }
}

} // namespace Curvature_estimation
} // namespace CGAL

#endif // CGAL_CURVATURE_ESTIMATION_HYPERSURFACE_PARABOLOID_FITTING_H
