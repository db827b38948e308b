// SPDX-License-Identifier: GPL-3.0-or-later
// The weights of a vertex's neighbors or faces, a parameter of Taubin's estimator and of the Gauss map.
#ifndef CGAL_CURVATURE_ESTIMATION_NEIGHBOR_WEIGHTING_H
#define CGAL_CURVATURE_ESTIMATION_NEIGHBOR_WEIGHTING_H

namespace CGAL {
namespace Curvature_estimation {

/// \ingroup PkgCurvatureEstimationRef
/// The weights of the faces around a vertex p. In `taubin_curvatures()` each
/// neighbor q joined to p by an edge is weighted by the faces on the edge (p, q)
/// (two, or one at the boundary), the weights normalised to sum 1. In
/// `gauss_map_curvatures()`, when given, they weight the per-face Jacobians of the
/// normal (the paper's differential).
enum class Neighbor_weighting : unsigned char
{
  /// The areas of the faces (Taubin 1995).
  area,
  /// The centroid weights `1/|G_f - p|^2` of the faces, `G_f` the centroid of
  /// face f (Chen and Wu 2004; Chen, Wu and Chi 2005, eq. 23).
  centroid
};

} // namespace Curvature_estimation
} // namespace CGAL

#endif // CGAL_CURVATURE_ESTIMATION_NEIGHBOR_WEIGHTING_H
