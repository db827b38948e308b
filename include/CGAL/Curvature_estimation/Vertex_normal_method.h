// SPDX-License-Identifier: GPL-3.0-or-later
// The ways of estimating a vertex normal, a parameter of every estimator that needs normals.
#ifndef CGAL_CURVATURE_ESTIMATION_VERTEX_NORMAL_METHOD_H
#define CGAL_CURVATURE_ESTIMATION_VERTEX_NORMAL_METHOD_H

namespace CGAL {
namespace Curvature_estimation {

/// \ingroup PkgCurvatureEstimationRef
/// How a normal is estimated at a vertex of a surface mesh: fitted, or the normalised
/// weighted sum \f$ \sum_f w_f\, n_f \f$ of the unit normals of the faces incident to the
/// vertex (first order in general; see the User Manual, "Vertex normals").
enum class Vertex_normal_method : unsigned char
{
  /// The area-weighted normal corrected by the gradient of a local Taylor fit: a
  /// second-order estimate, also at boundary vertices. The default of
  /// `estimate_vertex_normals()` and of the curvature estimators that need normals.
  quadric_fit,
  /// Weights are the face areas.
  area_weighted,
  /// Weights are the interior angles of the faces at the vertex (Thürmer and Wüthrich 1998).
  /// At a reflex vertex of a non-convex polygonal face the angle is larger than \f$ \pi \f$.
  angle_weighted,
  /// Centroid weights \f$ w_f = 1/\|G_f - v\|^2 \f$, with \f$ G_f \f$ the centroid (mean of
  /// the vertices) of face \f$ f \f$ (Chen and Wu 2004; Chen, Wu and Chi 2005, eq. 23 and 25).
  centroid_weighted
};

} // namespace Curvature_estimation
} // namespace CGAL

#endif // CGAL_CURVATURE_ESTIMATION_VERTEX_NORMAL_METHOD_H
