// SPDX-License-Identifier: GPL-3.0-or-later
// Curvature of point sets: the fits of the mesh estimators over nearest neighbors.
#ifndef CGAL_CURVATURE_ESTIMATION_POINT_SET_CURVATURES_H
#define CGAL_CURVATURE_ESTIMATION_POINT_SET_CURVATURES_H

#include <CGAL/Curvature_estimation/Principal_curvatures_and_directions.h>
#include <CGAL/Curvature_estimation/internal/fit_settings.h>
#include <CGAL/Curvature_estimation/internal/for_each_vertex.h>
#include <CGAL/Curvature_estimation/internal/point_set_estimator.h>
#include <CGAL/Curvature_estimation/internal/point_set_search.h>
#include <CGAL/Curvature_estimation/internal/surface_estimate.h>
#include <CGAL/Curvature_estimation/parameters.h>

#include <CGAL/Point_set_3.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/tags.h>

#include <boost/iterator/counting_iterator.hpp>
#include <boost/range/iterator_range.hpp>

#include <Eigen/Core>

#include <cmath>
#include <cstddef>
#include <iterator>
#include <stdexcept>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Curvature_estimation {
namespace internal {

template <typename T>
struct Is_point_set_3 : std::false_type
{};
template <typename P, typename V>
struct Is_point_set_3<CGAL::Point_set_3<P, V>> : std::true_type
{};

// The fit settings and the neighborhood of `np`: `neighbors` nearest (0 over a radius, the
// settings' ball_radius). Throws std::invalid_argument where one is out of its range.
struct Point_set_parameters
{
  Fit_parameters fit;
  std::size_t neighbors;
};

template <typename NamedParameters>
Point_set_parameters point_set_parameters(const NamedParameters& np, const char* caller)
{
  Fit_parameters fit = curvature_fit_parameters(np, caller, 4, Neighborhoods::rings_or_selected);
  Fit_settings& settings = fit.settings;
  settings.ring_intercept = true;
  settings.ball_radius = static_cast<double>(parameter_or(np, ::CGAL::internal_np::neighbor_radius, 0.0));
  const bool by_radius = has_parameter<NamedParameters, ::CGAL::internal_np::neighbor_radius_t>();
  const std::size_t k =
    parameter_or(np, internal_np::number_of_neighbors, default_point_set_neighbors(settings.degree));
  const std::string where = std::string(caller) + ": ";
  if (by_radius && has_parameter<NamedParameters, internal_np::number_of_neighbors_t>())
    throw std::invalid_argument(where + "give number_of_neighbors or neighbor_radius, not both");
  if (by_radius && settings.selects_radius())
    throw std::invalid_argument(where + "neighbor_radius and ball_radius_range exclude each other");
  if (by_radius && !(settings.ball_radius > 0 && std::isfinite(settings.ball_radius)))
    throw std::invalid_argument(where + "neighbor_radius must be positive and finite");
  if (!by_radius && k < 3)
    throw std::invalid_argument(where + "number_of_neighbors must be at least 3");
  return {fit, by_radius ? 0 : k};
}

} // namespace internal

/// \ingroup PkgCurvatureEstimationRef
///
/// estimates principal curvatures and directions, mean and Gaussian curvature at every point of
/// `points` (a scan, a lidar or photogrammetry point cloud) by the Taylor fits of the mesh
/// estimators, over the nearest neighbors of each point instead of its rings.
///
/// The neighborhood is the `number_of_neighbors` nearest points (exactly), or all points within
/// `neighbor_radius`. At each point the polynomial of `fit_degree` with a constant term (the point
/// itself is a sample, its own noise averaged) is fitted by least squares to the heights of the
/// neighborhood over the least-squares plane of the neighbors, or over the plane of the given
/// normal; the fitted gradient corrects that normal, and the curvatures are those of the fitted
/// graph. Where the fit is ill-conditioned the neighborhood doubles, twice (status `widened`); at
/// degrees 3 and 4 the fit of degree 2 is the fallback (status `fallback`).
///
/// Orientation: a given `normal_map` (or the normals of a `Point_set_3`) orients the result. Without,
/// the normals are oriented consistently over the set by a maximum spanning tree of the neighbors'
/// normals' agreement, each connected part outward on the whole (see the User Manual, "Point sets",
/// for where this can flip); `orientation_component_map` and `orientation_confidence_map` show it per
/// point. With `unsigned_curvatures(true)` each point takes the side where H >= 0.
///
/// Conventions as on meshes: with outward normals a sphere of radius r has `max_curvature ==
/// min_curvature == 1/r`. A point that cannot be estimated (non-finite, fewer neighbors than the fit
/// has unknowns, neighbors on a line) gets NaN in every output. Only the outputs passed are written.
///
/// With `ball_radius_range(min, max)` the neighborhood is chosen per point instead: the ball of the radius in that
/// range of least estimated error of the mean curvature, or the nearest neighbors where the data are clean (the
/// selection of the mesh estimators, the balls nested and searched once).
///
/// Statuses: `widened` over 2k or 4k neighbors (or a grown ball); `fallback` at degrees 3 and 4, the
/// fit of degree 2 where no neighborhood conditions that of `fit_degree`; `not_estimable`, NaN.
///
/// \ceConcurrencyTag
/// \tparam PointRange a model of `Range` (`CGAL::Point_set_3` or any range with a `point_map`); the
///         property maps are keyed by its value type (`Point_set_3`'s index for a `Point_set_3`).
/// \tparam NamedParameters a sequence of named parameters, built with the functions of
///         `CGAL::Curvature_estimation::parameters`
/// \param points the points
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{point_map}
///     \cgalParamDescription{the points of the range's elements}
///     \cgalParamType{a `ReadablePropertyMap` from the range's value type to `GT::Point_3`}
///     \cgalParamDefault{`CGAL::Identity_property_map`, or the point map of a `Point_set_3`}
///   \cgalParamNEnd
///   \cgalParamNBegin{normal_map}
///     \cgalParamDescription{given normals (read, not written; they need not be unit), which set the fit's plane
///       and orient the result}
///     \cgalParamType{a `ReadablePropertyMap` from the range's value type to `GT::Vector_3`}
///     \cgalParamDefault{none: normals fitted and oriented by the propagation; for a `Point_set_3`, its normal map
///       if it has one}
///   \cgalParamNEnd
///   \cgalParamNBegin{geom_traits}
///     \cgalParamDescription{an instance of a geometric traits class}
///     \cgalParamType{a class model of `Kernel`}
///     \cgalParamDefault{a \cgal Kernel deduced from the point type, using `CGAL::Kernel_traits`}
///   \cgalParamNEnd
///   \cgalParamNBegin{number_of_neighbors}
///     \cgalParamDescription{the neighbors of a point's fit: the k nearest points (exactly those; ties by position)}
///     \cgalParamType{`std::size_t`, at least 3}
///     \cgalParamDefault{16, 32 and 64 at fit_degree 2, 3 and 4 (the error against k, with and without noise:
///       see the User Manual, Point sets)}
///   \cgalParamNEnd
///   \cgalParamNBegin{neighbor_radius}
///     \cgalParamDescription{instead of `number_of_neighbors`: the points within this distance, the ball grown by
///       25% steps up to twice the radius where too few or ill-conditioned; not with `number_of_neighbors`}
///     \cgalParamType{`double`, positive and finite, in the units of the points}
///     \cgalParamDefault{none: `number_of_neighbors`}
///   \cgalParamNEnd
///   \cgalParamNBegin{fit_degree}
///     \cgalParamDescription{the degree of the fitted polynomial}
///     \cgalParamType{`int`, 2, 3 or 4}
///     \cgalParamDefault{`2`}
///   \cgalParamNEnd
///   \cgalParamNBegin{neighborhood_rings}
///     \cgalParamDescription{the neighborhood a fit starts with: ring r is the k 2^(r-1) nearest neighbors}
///     \cgalParamType{`int`, at least 1}
///     \cgalParamDefault{`1`}
///   \cgalParamNEnd
///   \cgalParamNBegin{max_neighborhood_rings}
///     \cgalParamDescription{the widest neighborhood an ill-conditioned fit is widened to (status `widened`)}
///     \cgalParamType{`int`, at least `neighborhood_rings`}
///     \cgalParamDefault{`3`: up to 4k nearest neighbors}
///   \cgalParamNEnd
///   \cgalParamNBegin{max_condition_number}
///     \cgalParamDescription{the largest condition number of a fit's normal equations that is accepted (see the User
///       Manual, Conditioning)}
///     \cgalParamType{`double`, greater than 1}
///     \cgalParamDefault{`1e3`}
///   \cgalParamNEnd
///   \cePointSetScaleSelectionParameters
///   \ceUseFallbacksParameter
///   \cgalParamNBegin{unsigned_curvatures}
///     \cgalParamDescription{without given normals: whether each point takes the side where H >= 0 instead of the
///       propagated orientation}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`false`}
///   \cgalParamNEnd
///   \cgalParamNBegin{estimated_normal_map}
///     \cgalParamDescription{output: the unit normal of the fitted graph, oriented as the result}
///     \cgalParamType{a `WritablePropertyMap` from the range's value type to `GT::Vector_3`}
///     \cgalParamDefault{not computed}
///   \cgalParamNEnd
///   \cgalParamNBegin{orientation_component_map}
///     \cgalParamDescription{output: the connected part of the neighbor graph a point was oriented with, numbered
///       from 0; `std::size_t(-1)` where not oriented (given normals, unsigned curvatures, no normal)}
///     \cgalParamType{a `WritablePropertyMap` from the range's value type to `std::size_t`}
///     \cgalParamDefault{not computed}
///   \cgalParamNEnd
///   \cgalParamNBegin{orientation_confidence_map}
///     \cgalParamDescription{output: how surely the orientation holds, in [0, 1] (the weakest agreement of normals
///       on the point's path of the propagation, and how one-sided its part is); 0 where not oriented}
///     \cgalParamType{a `WritablePropertyMap` from the range's value type to `double`}
///     \cgalParamDefault{not computed}
///   \cgalParamNEnd
///   \ceSurfaceOutputParameters{K = k1 k2, `ok`\, `widened`\, `fallback` or `not_estimable`}
/// \cgalNamedParamsEnd
///
/// \throws std::invalid_argument if a parameter is out of its range or the range has 2^32 points or more.
template <typename ConcurrencyTag = CGAL::Sequential_tag, typename PointRange,
          typename NamedParameters = parameters::Default_named_parameters>
void point_set_curvatures(PointRange& points, const NamedParameters& np = parameters::default_values())
{
  using ::CGAL::parameters::get_parameter;
  using NP_helper = CGAL::Point_set_processing_3_np_helper<PointRange, NamedParameters>;
  using GT = typename NP_helper::Geom_traits;
  using Iterator = decltype(std::begin(points));
  constexpr bool random_access =
    std::is_base_of<std::random_access_iterator_tag, typename std::iterator_traits<Iterator>::iterator_category>::value;
  const char* const caller = "point_set_curvatures";
  static_assert(!internal::has_parameter<NamedParameters, internal_np::vertex_reach_map_t>(),
                "point_set_curvatures: vertex_reach_map is an output of the mesh estimators");

  const internal::Point_set_parameters parameters = internal::point_set_parameters(np, caller);
  const internal::Fit_settings& settings = parameters.fit.settings;
  const std::size_t neighbors = parameters.neighbors; // 0 over a radius
  const bool use_fallbacks = internal::parameter_or(np, internal_np::use_fallbacks, true);
  const bool unsigned_curvatures = internal::parameter_or(np, internal_np::unsigned_curvatures, false);

  // The elements' keys, by position.
  std::vector<Iterator> iterators;
  if constexpr (!random_access)
    for (auto it = std::begin(points); it != std::end(points); ++it)
      iterators.push_back(it);
  const auto key = [&](std::size_t i) -> decltype(auto) {
    if constexpr (random_access)
      return *(std::begin(points) + i);
    else
      return *iterators[i];
  };
  const std::size_t n = static_cast<std::size_t>(std::distance(std::begin(points), std::end(points)));
  if (n >= std::size_t(internal::Point_set_rings::none))
    throw std::invalid_argument(std::string(caller) + ": at most 2^32 - 1 points");

  const auto point_map = NP_helper::get_const_point_map(points, np);
  std::vector<Eigen::Vector3d> coordinates(n);
  for (std::size_t i = 0; i < n; ++i) {
    const auto& p = get(point_map, key(i));
    coordinates[i] = Eigen::Vector3d(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
  }
  const internal::Point_set_search search(coordinates, ConcurrencyTag());
  std::vector<Eigen::Vector3d>().swap(coordinates);
  const auto key_of = [&](std::size_t i) -> decltype(auto) { return key(search.original(i)); }; // i: the search's

  const auto run = [&](auto with_normals, const auto& normal_map) {
    constexpr bool given = decltype(with_normals)::value;
    internal::Point_set_rings rings;
    internal::Normal_orientation orientation;
    if (!given && !unsigned_curvatures)
      orientation = internal::oriented_rings<ConcurrencyTag>(search, neighbors, settings.ball_radius,
                                                             neighbors > 0 ? neighbors : 16, rings);
    const bool oriented = !orientation.part.empty();
    const auto store = [&](std::size_t i, internal::Surface_estimate e) {
      if (unsigned_curvatures && !given && e.max_curvature + e.min_curvature < 0)
        e = internal::flipped(e);
      internal::put_surface_estimate<GT>(np, key_of(i), e);
      if constexpr (internal::has_parameter<NamedParameters, internal_np::estimated_normal_map_t>())
        put(get_parameter(np, internal_np::estimated_normal_map), key_of(i),
            typename GT::Vector_3(e.normal.x(), e.normal.y(), e.normal.z()));
      if constexpr (internal::has_parameter<NamedParameters, internal_np::orientation_component_map_t>())
        put(get_parameter(np, internal_np::orientation_component_map), key_of(i),
            oriented && orientation.part[i] != internal::Normal_orientation::no_part ? std::size_t(orientation.part[i])
                                                                                     : std::size_t(-1));
      if constexpr (internal::has_parameter<NamedParameters, internal_np::orientation_confidence_map_t>())
        put(get_parameter(np, internal_np::orientation_confidence_map), key_of(i),
            oriented ? double(orientation.confidence[i]) : 0.0);
    };
    const auto indices =
      boost::make_iterator_range(boost::counting_iterator<std::size_t>(0), boost::counting_iterator<std::size_t>(n));
    using Worker = internal::Point_set_worker<given, std::decay_t<decltype(normal_map)>, decltype(key_of)>;
    internal::for_each_vertex<ConcurrencyTag, false>(
      indices,
      Worker{internal::Point_set_estimator(search, settings, neighbors, oriented ? &rings : nullptr, use_fallbacks),
             normal_map, &key_of},
      store);
  };
  if constexpr (internal::has_parameter<NamedParameters, ::CGAL::internal_np::normal_t>())
    run(std::true_type(), get_parameter(np, ::CGAL::internal_np::normal_map));
  else if constexpr (internal::Is_point_set_3<std::remove_cv_t<PointRange>>::value) {
    if (points.has_normal_map())
      run(std::true_type(), points.normal_map());
    else
      run(std::false_type(), 0);
  } else
    run(std::false_type(), 0);
}

} // namespace Curvature_estimation
} // namespace CGAL

#endif // CGAL_CURVATURE_ESTIMATION_POINT_SET_CURVATURES_H
