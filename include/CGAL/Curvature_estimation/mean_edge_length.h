// SPDX-License-Identifier: GPL-3.0-or-later
// The mean edge length of a surface mesh: the unit in which to give a
// `ball_radius` as a number of edges.
#ifndef CGAL_CURVATURE_ESTIMATION_MEAN_EDGE_LENGTH_H
#define CGAL_CURVATURE_ESTIMATION_MEAN_EDGE_LENGTH_H

#include <CGAL/Curvature_estimation/internal/local_coordinates.h>
#include <CGAL/Curvature_estimation/parameters.h>

#include <CGAL/boost/graph/named_params_helper.h>

#include <boost/graph/graph_traits.hpp>

#include <cmath>
#include <cstddef>

namespace CGAL {
namespace Curvature_estimation {

/// \ingroup PkgCurvatureEstimationRef
///
/// The mean length of the finite edges of `g` (0 where there is none), in double:
/// `ball_radius(3 * mean_edge_length(g))` is "a radius of 3 edges" on any mesh.
///
/// \tparam FaceGraph a model of `FaceGraph`
/// \tparam NamedParameters a sequence of named parameters
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{a property map associating points to the vertices of `g`}
///     \cgalParamType{a model of `ReadablePropertyMap` with `%Point_3` as value type}
///     \cgalParamDefault{`boost::get(CGAL::vertex_point, g)`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
template <typename FaceGraph, typename NamedParameters = parameters::Default_named_parameters>
double mean_edge_length(const FaceGraph& g, const NamedParameters& np = parameters::default_values())
{
  const auto vpm =
    internal::parameter_or(np, ::CGAL::internal_np::vertex_point, get_const_property_map(CGAL::vertex_point, g));
  double sum = 0;
  std::size_t count = 0;
  for (auto e : edges(g)) {
    const auto h = halfedge(e, g);
    const double length = internal::safe_norm(
      Eigen::Vector3d(internal::point_in_double(vpm, source(h, g)) - internal::point_in_double(vpm, target(h, g))));
    if (std::isfinite(length)) {
      sum += length;
      ++count;
    }
  }
  return count != 0 ? sum / double(count) : 0.0;
}

} // namespace Curvature_estimation
} // namespace CGAL

#endif // CGAL_CURVATURE_ESTIMATION_MEAN_EDGE_LENGTH_H
