// SPDX-License-Identifier: GPL-3.0-or-later
// The names of the estimators and how far one reads around a vertex: the types that
// `neighborhood_reach()` takes and returns, apart from the estimators themselves.
#ifndef CGAL_CURVATURE_ESTIMATION_ESTIMATOR_H
#define CGAL_CURVATURE_ESTIMATION_ESTIMATOR_H

#include <cstddef>

namespace CGAL {
namespace Curvature_estimation {

/// \ingroup PkgCurvatureEstimationRef
/// The estimators of the package, as `neighborhood_reach()` names them.
enum class Estimator
{
  paraboloid_fitting, ///< `paraboloid_fitting_curvatures()`
  curve_network,      ///< `curve_network_curvatures()`
  gauss_map,          ///< `gauss_map_curvatures()`
  taubin,             ///< `taubin_curvatures()`
  chen_schmitt,       ///< `chen_schmitt_curvatures()`
  jet_fitting,        ///< `jet_fitting_curvatures()`
  point_set           ///< `point_set_curvatures()`
};

/// \ingroup PkgCurvatureEstimationRef
/// How far an estimator reads around the vertex (or point) it estimates at: on a mesh, every vertex whose
/// position (or given normal) can change the estimate lies within `rings` rings of faces of the vertices
/// within `distance` of it; on a point set, among its `neighbors` nearest points or within `distance` of it.
struct Neighborhood_reach
{
  int rings = 0;             ///< rings of faces (a vertex's own faces are its first ring)
  double distance = 0;       ///< over a ball: its radius (for a normal read over its own ball, twice it)
  double grown_distance = 0; ///< `distance` where a ball grew to condition its fit (status `widened`); a ball grown
                             ///< for lack of vertices may reach farther
  std::size_t neighbors = 0; ///< point sets over nearest neighbors: at status `ok`
  std::size_t widened_neighbors = 0; ///< point sets over nearest neighbors: at any other status
};

} // namespace Curvature_estimation
} // namespace CGAL

#endif // CGAL_CURVATURE_ESTIMATION_ESTIMATOR_H
