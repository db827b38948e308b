// SPDX-License-Identifier: GPL-3.0-or-later
// What every surface estimator computes at a vertex, and its writing into the
// output maps the user passed: one place for the outputs of all estimators.
#ifndef CGAL_CURVATURE_ESTIMATION_INTERNAL_SURFACE_ESTIMATE_H
#define CGAL_CURVATURE_ESTIMATION_INTERNAL_SURFACE_ESTIMATE_H

#include <CGAL/Curvature_estimation/Principal_curvatures_and_directions.h>
#include <CGAL/Curvature_estimation/internal/for_each_vertex.h>
#include <CGAL/Curvature_estimation/internal/local_coordinates.h>
#include <CGAL/Curvature_estimation/internal/shape_operator.h>
#include <CGAL/Curvature_estimation/parameters.h>

#include <CGAL/number_utils.h>

#include <Eigen/Core>

#include <limits>
#include <utility>

namespace CGAL {
namespace Curvature_estimation {
namespace internal {

// The estimate at one vertex. A not-estimable vertex keeps the NaN defaults.
struct Surface_estimate
{
  Estimation_status status = Estimation_status::not_estimable;
  double max_curvature = std::numeric_limits<double>::quiet_NaN();
  double min_curvature = std::numeric_limits<double>::quiet_NaN();
  // K: the product of the principal curvatures, except where an estimator has
  // its own (the Gauss map's determinant of the differential).
  double gaussian_curvature = std::numeric_limits<double>::quiet_NaN();
  Eigen::Vector3d max_direction = Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
  Eigen::Vector3d min_direction = Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
  Eigen::Vector3d normal = Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
  // Under scale selection (scale_selection.h): the radius of the estimate's
  // neighborhood and the noise estimated there.
  double radius = std::numeric_limits<double>::quiet_NaN();
  double noise = std::numeric_limits<double>::quiet_NaN();
  // On meshes: how far from the vertex the balls it read reach (0: rings only).
  double reach = 0;

  double mean_curvature() const { return 0.5 * (max_curvature + min_curvature); }

  // Sets every member but the radius, the noise and the reach, with K = k1 k2.
  void set_principal(Estimation_status s, double max_k, double min_k, const Eigen::Vector3d& max_d,
                     const Eigen::Vector3d& min_d, const Eigen::Vector3d& n)
  {
    status = s;
    max_curvature = max_k;
    min_curvature = min_k;
    gaussian_curvature = max_k * min_k;
    max_direction = max_d;
    min_direction = min_d;
    normal = n;
  }

  static Surface_estimate from_principal(Estimation_status status, double max_curvature, double min_curvature,
                                         const Eigen::Vector3d& max_direction, const Eigen::Vector3d& min_direction,
                                         const Eigen::Vector3d& normal)
  {
    Surface_estimate e;
    e.set_principal(status, max_curvature, min_curvature, max_direction, min_direction, normal);
    return e;
  }
};

// Sets `e` to the curvature of a fit's graph in coordinates divided by `scale`.
inline void set_surface_estimate(Surface_estimate& e, Estimation_status status, const Graph_curvature<3>& curvature,
                                 double scale)
{
  e.set_principal(status, curvature.curvatures[0] / scale, curvature.curvatures[1] / scale, curvature.directions.col(0),
                  curvature.directions.col(1), curvature.normal);
}

// True when `np` asks for any output of a curvature estimator.
template <typename NamedParameters>
constexpr bool wants_curvature_output()
{
  return has_parameter<NamedParameters, internal_np::vertex_principal_curvatures_and_directions_map_t>() ||
         has_parameter<NamedParameters, internal_np::vertex_mean_curvature_map_t>() ||
         has_parameter<NamedParameters, internal_np::vertex_Gaussian_curvature_map_t>() ||
         has_parameter<NamedParameters, internal_np::vertex_estimation_status_map_t>() ||
         has_parameter<NamedParameters, internal_np::vertex_ball_radius_map_t>() ||
         has_parameter<NamedParameters, internal_np::vertex_noise_map_t>() ||
         has_parameter<NamedParameters, internal_np::vertex_reach_map_t>();
}

// Whether the map that `np` (of type NP) holds under `tag`, if it holds one, may
// be accessed from the worker threads (see for_each_vertex).
template <typename NP, typename Tag>
constexpr bool given_map_accessible_concurrently(Tag tag)
{
  if constexpr (has_parameter<NP, Tag>())
    return accessible_concurrently<decltype(::CGAL::parameters::get_parameter(std::declval<const NP&>(), tag))>();
  else
    return true;
}

// Whether the output maps of a surface estimator that `np` holds may all be
// accessed from the worker threads.
template <typename NP>
constexpr bool surface_outputs_accessible_concurrently()
{
  return given_map_accessible_concurrently<NP>(internal_np::vertex_principal_curvatures_and_directions_map) &&
         given_map_accessible_concurrently<NP>(internal_np::vertex_mean_curvature_map) &&
         given_map_accessible_concurrently<NP>(internal_np::vertex_Gaussian_curvature_map) &&
         given_map_accessible_concurrently<NP>(internal_np::vertex_estimation_status_map) &&
         given_map_accessible_concurrently<NP>(internal_np::vertex_ball_radius_map) &&
         given_map_accessible_concurrently<NP>(internal_np::vertex_noise_map) &&
         given_map_accessible_concurrently<NP>(internal_np::vertex_reach_map);
}

// Writes the outputs that `np` asks for, and only those; `v` by reference for the
// maps that write into the key (those of a point range's elements).
template <typename GT, typename NamedParameters, typename VertexDescriptor>
void put_surface_estimate(const NamedParameters& np, VertexDescriptor&& v, const Surface_estimate& e)
{
  using ::CGAL::parameters::get_parameter;
  using FT = typename GT::FT;
  using Vector_3 = typename GT::Vector_3;
  if constexpr (has_parameter<NamedParameters, internal_np::vertex_principal_curvatures_and_directions_map_t>())
    put(
      get_parameter(np, internal_np::vertex_principal_curvatures_and_directions_map), v,
      Principal_curvatures_and_directions<GT>(FT(e.min_curvature), FT(e.max_curvature),
                                              Vector_3(e.min_direction.x(), e.min_direction.y(), e.min_direction.z()),
                                              Vector_3(e.max_direction.x(), e.max_direction.y(), e.max_direction.z())));
  if constexpr (has_parameter<NamedParameters, internal_np::vertex_mean_curvature_map_t>())
    put(get_parameter(np, internal_np::vertex_mean_curvature_map), v, FT(e.mean_curvature()));
  if constexpr (has_parameter<NamedParameters, internal_np::vertex_Gaussian_curvature_map_t>())
    put(get_parameter(np, internal_np::vertex_Gaussian_curvature_map), v, FT(e.gaussian_curvature));
  if constexpr (has_parameter<NamedParameters, internal_np::vertex_estimation_status_map_t>())
    put(get_parameter(np, internal_np::vertex_estimation_status_map), v, e.status);
  if constexpr (has_parameter<NamedParameters, internal_np::vertex_ball_radius_map_t>())
    put(get_parameter(np, internal_np::vertex_ball_radius_map), v, FT(e.radius));
  if constexpr (has_parameter<NamedParameters, internal_np::vertex_noise_map_t>())
    put(get_parameter(np, internal_np::vertex_noise_map), v, FT(e.noise));
  if constexpr (has_parameter<NamedParameters, internal_np::vertex_reach_map_t>())
    put(get_parameter(np, internal_np::vertex_reach_map), v, FT(e.reach));
  (void)np;
  (void)v;
  (void)e;
}

// The given normal at `v` in double (read on the calling thread, see
// for_each_vertex), or zero when no normal map is given.
template <bool given, typename NormalMap, typename VertexDescriptor>
Eigen::Vector3d load_given_normal(const NormalMap& normals, VertexDescriptor v)
{
  if constexpr (given) {
    const auto n = get(normals, v);
    return Eigen::Vector3d(CGAL::to_double(n.x()), CGAL::to_double(n.y()), CGAL::to_double(n.z()));
  } else {
    (void)normals;
    (void)v;
    return Eigen::Vector3d::Zero();
  }
}

} // namespace internal
} // namespace Curvature_estimation
} // namespace CGAL

#endif // CGAL_CURVATURE_ESTIMATION_INTERNAL_SURFACE_ESTIMATE_H
