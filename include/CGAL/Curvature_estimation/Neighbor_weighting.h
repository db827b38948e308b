// SPDX-License-Identifier: GPL-3.0-or-later
// The weights of a vertex's neighbors or faces, a parameter of Taubin's estimator, of the Gauss map, of
// Chen-Schmitt and of the paraboloid fits over a ball.
#ifndef CGAL_CURVATURE_ESTIMATION_NEIGHBOR_WEIGHTING_H
#define CGAL_CURVATURE_ESTIMATION_NEIGHBOR_WEIGHTING_H

namespace CGAL {
namespace Curvature_estimation {

/// \ingroup PkgCurvatureEstimationRef
/// The weights of the neighbors or faces around a vertex p: of the edges' faces in
/// `taubin_curvatures()` and of the per-face Jacobians in `gauss_map_curvatures()` (`area`,
/// `centroid`), of Chen and Schmitt's fit (`uniform`), of the fits over a ball (`uniform`,
/// `smooth`). A function given a value it does not list throws `std::invalid_argument`.
enum class Neighbor_weighting : unsigned char
{
  /// The areas of the faces (Taubin 1995).
  area,
  /// The centroid weights `1/|G_f - p|^2` of the faces, `G_f` the centroid of
  /// face f (Chen and Wu 2004; Chen, Wu and Chi 2005, eq. 23).
  centroid,
  /// Equal weights (Chen and Schmitt 1992).
  uniform,
  /// The weight (1 - |q - p|^2 / r^2)^2 of a neighbor q in the ball of radius r about p
  /// (`ball_radius`, or the radius it grew to): 1 at p, falling smoothly to 0 at r.
  smooth
};

} // namespace Curvature_estimation
} // namespace CGAL

#endif // CGAL_CURVATURE_ESTIMATION_NEIGHBOR_WEIGHTING_H
