// SPDX-License-Identifier: GPL-3.0-or-later
// Hamann's paraboloid fitting over the tetrahedral 1-ring of a 3-dimensional
// hypersurface of R^4 (Hamann's thesis §4.3), on any TetrahedralComplex.
#ifndef CGAL_CURVATURE_ESTIMATION_HYPERSURFACE_PARABOLOID_FITTING_H
#define CGAL_CURVATURE_ESTIMATION_HYPERSURFACE_PARABOLOID_FITTING_H

#include <CGAL/Curvature_estimation/Principal_curvatures_and_directions.h>
#include <CGAL/Curvature_estimation/Tetrahedral_complex_traits.h>
#include <CGAL/Curvature_estimation/internal/estimate_at_vertices.h>
#include <CGAL/Curvature_estimation/internal/fallback_chain.h>
#include <CGAL/Curvature_estimation/internal/fit_settings.h>
#include <CGAL/Curvature_estimation/internal/tetrahedral_neighborhood.h>
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
  bool use_fallbacks;

  // The fallback chain: the fit of fit_degree; where it is refused, at
  // fit_degree 3 over rings, the fit of degree 2.
  Hypersurface_estimate estimate(std::size_t i, const Eigen::Vector4d* given)
  {
    Hypersurface_estimate estimate;
    estimate_with_fallbacks(
      estimate, use_fallbacks,
      [&](Hypersurface_estimate& out) {
        if (given != nullptr)
          fitter.fit(i, *given, out);
        else
          fitter.fit(i, method, out);
        return accepted_or_refused(out);
      },
      fallback(Tried_where::refused, [&](Hypersurface_estimate& out) {
        const Fit_settings& s = fitter.settings();
        if (s.degree == 2 || s.in_ball())
          return Verdict::refused;
        fitter.degree_two_fit(i, given, method, out);
        return accepted_or_refused(out);
      }));
    return estimate;
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
/// estimates the three principal curvatures and directions, the mean and the Gaussian curvature at every
/// vertex of a tetrahedral complex whose vertices are points of R^4 (a 3-dimensional hypersurface, such as
/// the graph W = f(x, y, z) of a trivariate function) by Hamann's method (Hamann's thesis, §4.3): the Taylor
/// polynomial of the height over the 3-dimensional tangent space is fitted to the vertex's neighborhood.
/// Normals, widening, fit degrees, balls and fallbacks are as for surfaces (`paraboloid_fitting_curvatures()`);
/// the first-order normal is the 3-volume-weighted mean of the cells' normals, oriented as the cells
/// (for positively oriented tetrahedra of R^3 lifted to a graph: towards increasing W). A boundary vertex
/// lies on a triangle of one cell only. See the User Manual, "Hypersurfaces of R^4".
///
/// Conventions: curvatures are positive where the hypersurface bends away from the normal,
/// k1 >= k2 >= k3, H = (k1 + k2 + k3) / 3, K = k1 k2 k3; directions are unit, tangent and orthogonal.
/// Scaling the points by s scales the curvatures by 1/s. A vertex that cannot be estimated gets NaN.
///
/// \tparam ConcurrencyTag `CGAL::Sequential_tag` (default), `CGAL::Parallel_tag` or
///         `CGAL::Parallel_if_available_tag`; the maps are read and written by the calling thread only
/// \tparam TetrahedralComplex a model of `TetrahedralComplex` (`Indexed_tetrahedral_mesh`, a `CGAL::Triangulation_3`)
/// \tparam NamedParameters a sequence of named parameters of `CGAL::Curvature_estimation::parameters`
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{points of R^4 (`Eigen::Vector4d`, `std::array<double, 4>`, `Epick_d` points) of the
///                           vertices; `make_graph_point_map()` makes one from a 3D point map and a scalar map}
///     \cgalParamDefault{`points[i]` of an `Indexed_tetrahedral_mesh`; none for a `Triangulation_3`}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_normal_map}
///     \cgalParamDescription{normals of R^4 at the vertices, trusted as given}
///     \cgalParamDefault{normals estimated by `vertex_normal_method`}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_normal_method}
///     \cgalParamDescription{`quadric_fit`, or `area_weighted` (the cells' normals' mean)}
///     \cgalParamDefault{`Vertex_normal_method::quadric_fit`}
///   \cgalParamNEnd
///   \cgalParamNBegin{fit_degree}
///     \cgalParamDescription{the degree of the fitted polynomial: 2 or 3}
///     \cgalParamDefault{`2`}
///   \cgalParamNEnd
///   \ceBallRadiusParameter
///   \ceBallWeightingParameter
///   \ceRingParameters
///   \ceUseFallbacksParameter
///   \cgalParamNBegin{vertex_principal_curvatures_and_directions_map}
///     \cgalParamDescription{output, of `Hypersurface_principal_curvatures_and_directions<Vector_4, FT>`}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_mean_curvature_map, vertex_Gaussian_curvature_map}
///     \cgalParamDescription{outputs: H and K, of a floating-point type}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_estimation_status_map}
///     \cgalParamDescription{output: `ok`, `widened`, `fallback` or `not_estimable`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \throws std::invalid_argument if a parameter is out of its range, a cell index is out of range, or the
///         points do not have 4 coordinates.
template <typename ConcurrencyTag = CGAL::Sequential_tag, typename TetrahedralComplex,
          typename NamedParameters = parameters::Default_named_parameters>
void hypersurface_paraboloid_fitting_curvatures(const TetrahedralComplex& complex,
                                                const NamedParameters& np = parameters::default_values())
{
  using ::CGAL::parameters::get_parameter;
  using Traits = Tetrahedral_complex_traits<TetrahedralComplex>;
  using Stars = Tetrahedral_complex_stars<TetrahedralComplex>;
  using Fitter = internal::Hypersurface_fitter<Stars>;

  const internal::Fit_parameters fit = internal::curvature_fit_parameters(
    np, "hypersurface_paraboloid_fitting_curvatures", 3, internal::Neighborhoods::rings_or_ball);
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
    const internal::Hypersurface_paraboloid_estimator<Fitter> estimator{
      Fitter(stars, points, fit.settings), fit.normal_method,
      internal::parameter_or(np, internal_np::use_fallbacks, true)};
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
