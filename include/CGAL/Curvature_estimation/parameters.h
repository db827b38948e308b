// SPDX-License-Identifier: GPL-3.0-or-later
// Named parameters of the curvature estimation package: a class deriving from
// CGAL::Named_function_parameters whose chaining members also cover this
// package's parameters, so that CGAL's lookup accepts it and both kinds chain in
// any order (the manual's "CGAL 5.5 and CGAL 6" says why).
#ifndef CGAL_CURVATURE_ESTIMATION_PARAMETERS_H
#define CGAL_CURVATURE_ESTIMATION_PARAMETERS_H

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/version.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <type_traits>

// X-macro lists: X(tag type, name); the tag's single value and the chaining
// function share the name, as in CGAL.
// The parameters that CGAL 6 defines too, with the same meaning (CGAL 6's
// interpolated corrected curvatures): on CGAL 6 they are CGAL's own tags, so that
// one chain serves CGAL's estimator and ours; on CGAL 5 this package declares them.
#define CGAL_CE_PARAMETERS_SHARED_WITH_CGAL_6(X)                                                                       \
  X(vertex_mean_curvature_map_t, vertex_mean_curvature_map)                                                            \
  X(vertex_Gaussian_curvature_map_t, vertex_Gaussian_curvature_map)                                                    \
  X(vertex_principal_curvatures_and_directions_map_t, vertex_principal_curvatures_and_directions_map)                  \
  X(ball_radius_t, ball_radius)
// The parameters of this package alone:
#define CGAL_CE_OWN_PARAMETERS(X)                                                                                      \
  X(vertex_estimation_status_map_t, vertex_estimation_status_map)                                                      \
  X(vertex_normal_method_t, vertex_normal_method)                                                                      \
  X(neighborhood_rings_t, neighborhood_rings)                                                                          \
  X(boundary_neighborhood_rings_t, boundary_neighborhood_rings)                                                        \
  X(max_neighborhood_rings_t, max_neighborhood_rings)                                                                  \
  X(max_condition_number_t, max_condition_number)                                                                      \
  X(neighbor_weighting_t, neighbor_weighting)                                                                          \
  X(curve_model_t, curve_model)                                                                                        \
  X(extrapolation_order_t, extrapolation_order)                                                                        \
  X(max_curve_irregularity_t, max_curve_irregularity)                                                                  \
  X(fit_degree_t, fit_degree)                                                                                          \
  X(jet_degree_t, jet_degree)                                                                                          \
  X(monge_degree_t, monge_degree)                                                                                      \
  X(use_fallbacks_t, use_fallbacks)                                                                                    \
  X(number_of_neighbors_t, number_of_neighbors)                                                                        \
  X(estimated_normal_map_t, estimated_normal_map)                                                                      \
  X(orientation_component_map_t, orientation_component_map)                                                            \
  X(orientation_confidence_map_t, orientation_confidence_map)                                                          \
  X(unsigned_curvatures_t, unsigned_curvatures)                                                                        \
  X(ball_radius_range_t, ball_radius_range)                                                                            \
  X(vertex_ball_radius_map_t, vertex_ball_radius_map)                                                                  \
  X(vertex_noise_map_t, vertex_noise_map)                                                                              \
  X(vertex_reach_map_t, vertex_reach_map)
#define CGAL_CE_PACKAGE_PARAMETERS(X)                                                                                  \
  CGAL_CE_PARAMETERS_SHARED_WITH_CGAL_6(X)                                                                             \
  CGAL_CE_OWN_PARAMETERS(X)

// CGAL's parameters that a chain of this package may carry, re-declared as members
// so that chaining them never falls back to CGAL's own class. The estimators read
// the first six; the index maps are only carried, so that one chain can also
// serve CGAL's functions that need them.
#define CGAL_CE_CGAL_PARAMETERS(X)                                                                                     \
  X(vertex_point_t, vertex_point_map)                                                                                  \
  X(vertex_normal_map_t, vertex_normal_map)                                                                            \
  X(geom_traits_t, geom_traits)                                                                                        \
  X(point_t, point_map)                                                                                                \
  X(normal_t, normal_map)                                                                                              \
  X(neighbor_radius_t, neighbor_radius)                                                                                \
  X(vertex_index_t, vertex_index_map)                                                                                  \
  X(face_index_t, face_index_map)

namespace CGAL {
namespace Curvature_estimation {
namespace internal_np {

#define CGAL_CE_DECLARE_TAG(TAG, NAME)                                                                                 \
  enum TAG                                                                                                             \
  {                                                                                                                    \
    NAME                                                                                                               \
  };
#if CGAL_VERSION_MAJOR >= 6
#define CGAL_CE_USE_CGAL_TAG(TAG, NAME)                                                                                \
  using ::CGAL::internal_np::TAG;                                                                                      \
  using ::CGAL::internal_np::NAME;
CGAL_CE_PARAMETERS_SHARED_WITH_CGAL_6(CGAL_CE_USE_CGAL_TAG)
#undef CGAL_CE_USE_CGAL_TAG
#else
CGAL_CE_PARAMETERS_SHARED_WITH_CGAL_6(CGAL_CE_DECLARE_TAG)
#endif
CGAL_CE_OWN_PARAMETERS(CGAL_CE_DECLARE_TAG)
#undef CGAL_CE_DECLARE_TAG

} // namespace internal_np

/// \ingroup PkgCurvatureEstimationRef
/// A named-parameter pack: a `CGAL::Named_function_parameters` whose chaining
/// members also cover the parameters of this package. Users never name this
/// type; they start a chain with a function of `CGAL::Curvature_estimation::parameters`.
template <typename T = bool, typename Tag = ::CGAL::internal_np::all_default_t,
          typename Base = ::CGAL::internal_np::No_property>
struct Named_function_parameters : ::CGAL::Named_function_parameters<T, Tag, Base>
{
  // Not called `base`: CGAL's lookup walks the chain through the inherited
  // typedef `base`, which must stay CGAL's Named_params_impl.
  using CGAL_pack = ::CGAL::Named_function_parameters<T, Tag, Base>;
  using self = Named_function_parameters<T, Tag, Base>;

  Named_function_parameters()
      : CGAL_pack()
  {}
  Named_function_parameters(const T& v)
      : CGAL_pack(v)
  {}
  Named_function_parameters(const T& v, const Base& b)
      : CGAL_pack(v, b)
  {}

#define CGAL_CE_MEMBER(NS, TAG, NAME)                                                                                  \
  template <typename K>                                                                                                \
  Named_function_parameters<K, NS::TAG, self> NAME(const K& k) const                                                   \
  {                                                                                                                    \
    return Named_function_parameters<K, NS::TAG, self>(k, *this);                                                      \
  }
#define CGAL_CE_PACKAGE_MEMBER(TAG, NAME) CGAL_CE_MEMBER(::CGAL::Curvature_estimation::internal_np, TAG, NAME)
#define CGAL_CE_CGAL_MEMBER(TAG, NAME) CGAL_CE_MEMBER(::CGAL::internal_np, TAG, NAME)
  CGAL_CE_PACKAGE_PARAMETERS(CGAL_CE_PACKAGE_MEMBER)
  CGAL_CE_CGAL_PARAMETERS(CGAL_CE_CGAL_MEMBER)
#undef CGAL_CE_PACKAGE_MEMBER
#undef CGAL_CE_CGAL_MEMBER
#undef CGAL_CE_MEMBER
};

namespace parameters {

using Default_named_parameters = Named_function_parameters<>;

/// An empty pack: every parameter takes its default value.
inline Default_named_parameters default_values() { return Default_named_parameters(); }

#define CGAL_CE_FREE_FUNCTION(NS, TAG, NAME)                                                                           \
  template <typename K>                                                                                                \
  Named_function_parameters<K, NS::TAG> NAME(const K& k)                                                               \
  {                                                                                                                    \
    return Named_function_parameters<K, NS::TAG>(k);                                                                   \
  }
#define CGAL_CE_PACKAGE_FREE(TAG, NAME) CGAL_CE_FREE_FUNCTION(::CGAL::Curvature_estimation::internal_np, TAG, NAME)
#define CGAL_CE_CGAL_FREE(TAG, NAME) CGAL_CE_FREE_FUNCTION(::CGAL::internal_np, TAG, NAME)
CGAL_CE_PACKAGE_PARAMETERS(CGAL_CE_PACKAGE_FREE)
CGAL_CE_CGAL_PARAMETERS(CGAL_CE_CGAL_FREE)
#undef CGAL_CE_PACKAGE_FREE
#undef CGAL_CE_CGAL_FREE
#undef CGAL_CE_FREE_FUNCTION

} // namespace parameters

namespace internal {

// True when `np` holds a parameter with tag `Tag`.
template <typename NamedParameters, typename Tag>
constexpr bool has_parameter()
{
  return !::CGAL::parameters::is_default_parameter<NamedParameters, Tag>::value;
}

// The value of the parameter of `np` with tag `tag`, or `default_value` where `np`
// has none (CGAL's choose_parameter(get_parameter(np, tag), default_value)).
template <typename NamedParameters, typename Tag, typename T>
auto parameter_or(const NamedParameters& np, Tag tag, const T& default_value)
{
  return ::CGAL::parameters::choose_parameter(::CGAL::parameters::get_parameter(np, tag), default_value);
}

// The radii between which the scale selection chooses, in the mesh's units;
// max == 0 where `np` asks for none.
struct Radius_range
{
  double min = 0;
  double max = 0;
  bool given() const { return max > 0; }
};

// The `ball_radius_range` of `np` (a pair min, max). Throws std::invalid_argument
// where it is given with `ball_radius`, or not with 0 < min <= max, both finite, or
// where an output of the selection is asked for without it.
template <typename NamedParameters>
Radius_range ball_radius_range_or_none(const NamedParameters& np, const char* caller)
{
  const std::string where = std::string(caller) + ": ";
  Radius_range range;
  if constexpr (has_parameter<NamedParameters, internal_np::ball_radius_range_t>()) {
    const auto given = ::CGAL::parameters::get_parameter(np, internal_np::ball_radius_range);
    range.min = static_cast<double>(given.first);
    range.max = static_cast<double>(given.second);
    if (!(range.min > 0 && range.min <= range.max && std::isfinite(range.max)))
      throw std::invalid_argument(where + "ball_radius_range needs 0 < min <= max, finite");
    if (has_parameter<NamedParameters, internal_np::ball_radius_t>())
      throw std::invalid_argument(where + "ball_radius and ball_radius_range exclude each other");
  } else if (has_parameter<NamedParameters, internal_np::vertex_ball_radius_map_t>() ||
             has_parameter<NamedParameters, internal_np::vertex_noise_map_t>())
    throw std::invalid_argument(where + "vertex_ball_radius_map and vertex_noise_map need ball_radius_range");
  return range;
}

// The estimators without scale selection refuse its parameters rather than ignore them.
template <typename NamedParameters>
void reject_scale_selection(const char* caller)
{
  if (has_parameter<NamedParameters, internal_np::ball_radius_range_t>() ||
      has_parameter<NamedParameters, internal_np::vertex_ball_radius_map_t>() ||
      has_parameter<NamedParameters, internal_np::vertex_noise_map_t>())
    throw std::invalid_argument(std::string(caller) + ": the scale selection (ball_radius_range) is not supported");
}

// Radius neighborhoods (CGAL 6's `ball_radius`) are implemented by the paraboloid
// fits and jet fitting only: the other estimators refuse a pack that
// sets it rather than ignore it, so that a chain written for CGAL's interpolated
// corrected curvatures does not silently give 1-ring estimates there.
template <typename NamedParameters>
void reject_ball_radius_alone(const char* caller)
{
  if (has_parameter<NamedParameters, internal_np::ball_radius_t>())
    throw std::invalid_argument(std::string(caller) + ": ball_radius is not supported; neighborhoods are set in rings "
                                                      "(neighborhood_rings)");
}
template <typename NamedParameters>
void reject_ball_radius(const char* caller)
{
  reject_ball_radius_alone<NamedParameters>(caller);
  reject_scale_selection<NamedParameters>(caller);
}

// The `ball_radius` of `np`, or 0 where it has none. Throws std::invalid_argument
// where it is given but not positive and finite.
template <typename NamedParameters>
double ball_radius_or_zero(const NamedParameters& np, const char* caller)
{
  const double radius = static_cast<double>(parameter_or(np, internal_np::ball_radius, 0.0));
  if (has_parameter<NamedParameters, internal_np::ball_radius_t>() && !(radius > 0 && std::isfinite(radius)))
    throw std::invalid_argument(std::string(caller) + ": ball_radius must be positive and finite");
  return radius;
}

} // namespace internal
} // namespace Curvature_estimation
} // namespace CGAL

#endif // CGAL_CURVATURE_ESTIMATION_PARAMETERS_H
