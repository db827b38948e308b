// SPDX-License-Identifier: GPL-3.0-or-later
// The way from a public estimator's call to its output maps, written once: the
// vertex point map, the given normals, the vertex loop and the outputs. What
// differs between estimators is a local estimator (doc/adding_an_estimator.md):
// `Estimate estimate(vertex, const Normal* given)`, `given` the user's normal or
// null; copyable, one copy per thread.
#ifndef CGAL_CURVATURE_ESTIMATION_INTERNAL_ESTIMATE_AT_VERTICES_H
#define CGAL_CURVATURE_ESTIMATION_INTERNAL_ESTIMATE_AT_VERTICES_H

#include <CGAL/Curvature_estimation/internal/for_each_vertex.h>
#include <CGAL/Curvature_estimation/internal/surface_estimate.h>
#include <CGAL/Curvature_estimation/parameters.h>

#include <CGAL/boost/graph/named_params_helper.h>

#include <boost/graph/graph_traits.hpp>

#include <Eigen/Core>

#include <type_traits>
#include <utility>

namespace CGAL {
namespace Curvature_estimation {
namespace internal {

// Whether a local estimator of type E reads the user's normals (the default).
template <typename E, typename = void>
struct Uses_given_normals : std::true_type
{};

template <typename E>
struct Uses_given_normals<E, std::void_t<decltype(E::uses_given_normals)>> : std::bool_constant<E::uses_given_normals>
{};

// Whether the local estimator of type E gets the normals of `np` (of type NP).
template <typename E, typename NP>
constexpr bool gets_given_normals()
{
  return Uses_given_normals<E>::value && has_parameter<NP, ::CGAL::internal_np::vertex_normal_map_t>();
}

// The vertex loop over `vertices`: `load_normal(v)` reads the user's normal at v
// (called only when `with_normals`), `store(v, estimate)` writes the outputs;
// both run on the worker threads only if `concurrent_maps` (see for_each_vertex).
template <typename ConcurrencyTag, bool concurrent_maps, bool with_normals, typename VertexRange,
          typename LocalEstimator, typename LoadNormal, typename Store>
void estimate_at_vertices(const VertexRange& vertices, const LocalEstimator& estimator, LoadNormal load_normal,
                          Store store)
{
  using Vertex = std::remove_cv_t<std::remove_reference_t<decltype(*std::begin(vertices))>>;
  using Normal = std::remove_cv_t<std::remove_reference_t<decltype(load_normal(std::declval<Vertex>()))>>;

  struct Worker
  {
    LocalEstimator estimator;
    LoadNormal load_normal;

    Normal load(Vertex v) const
    {
      if constexpr (with_normals)
        return load_normal(v);
      else {
        (void)v;
        return Normal::Zero();
      }
    }

    auto compute(Vertex v, const Normal& given) { return estimator.estimate(v, with_normals ? &given : nullptr); }
  };
  for_each_vertex<ConcurrencyTag, concurrent_maps>(vertices, Worker{estimator, load_normal}, store);
}

// The same for a local estimator that takes no given normals (as one of
// normals, or over a precomputed table of them).
template <typename ConcurrencyTag, bool concurrent_maps, typename VertexRange, typename LocalEstimator, typename Store>
void estimate_at_vertices(const VertexRange& vertices, const LocalEstimator& estimator, Store store)
{
  estimate_at_vertices<ConcurrencyTag, concurrent_maps, false>(
    vertices, estimator, [](const auto&) { return Eigen::Vector3d(); }, store);
}

// A surface estimator: the outputs of `np` at every vertex of `g`, from the local
// estimator that `make_estimator(vertex_point_map)` returns. Does nothing when `np`
// asks for no output.
template <typename ConcurrencyTag, typename FaceGraph, typename NamedParameters, typename MakeEstimator>
void estimate_surface_curvatures(const FaceGraph& g, const NamedParameters& np, MakeEstimator make_estimator)
{
  if constexpr (wants_curvature_output<NamedParameters>()) {
    using ::CGAL::parameters::get_parameter;
    using vertex_descriptor = typename boost::graph_traits<FaceGraph>::vertex_descriptor;
    using GT = typename CGAL::GetGeomTraits<FaceGraph, NamedParameters>::type;
    using VPM = typename CGAL::GetVertexPointMap<FaceGraph, NamedParameters>::const_type;
    using LocalEstimator = decltype(make_estimator(std::declval<const VPM&>()));
    constexpr bool with_normals = gets_given_normals<LocalEstimator, NamedParameters>();
    constexpr bool concurrent_maps =
      surface_outputs_accessible_concurrently<NamedParameters>() &&
      (!with_normals || given_map_accessible_concurrently<NamedParameters>(::CGAL::internal_np::vertex_normal_map));

    const VPM vpm = parameter_or(np, ::CGAL::internal_np::vertex_point, get_const_property_map(CGAL::vertex_point, g));
    const auto normals = get_parameter(np, ::CGAL::internal_np::vertex_normal_map);
    estimate_at_vertices<ConcurrencyTag, concurrent_maps, with_normals>(
      vertices(g), make_estimator(vpm),
      [normals](vertex_descriptor v) { return load_given_normal<with_normals>(normals, v); },
      [&np](vertex_descriptor v, const Surface_estimate& e) { put_surface_estimate<GT>(np, v, e); });
  } else {
    (void)g;
    (void)np;
    (void)make_estimator;
  }
}

} // namespace internal
} // namespace Curvature_estimation
} // namespace CGAL

#endif // CGAL_CURVATURE_ESTIMATION_INTERNAL_ESTIMATE_AT_VERTICES_H
