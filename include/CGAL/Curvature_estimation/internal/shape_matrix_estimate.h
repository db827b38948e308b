// SPDX-License-Identifier: GPL-3.0-or-later
// The estimators that end with a 2x2 shape matrix in a tangent frame (Gauss map,
// Taubin, Chen-Schmitt): curvatures from the matrix.
#ifndef CGAL_CURVATURE_ESTIMATION_INTERNAL_SHAPE_MATRIX_ESTIMATE_H
#define CGAL_CURVATURE_ESTIMATION_INTERNAL_SHAPE_MATRIX_ESTIMATE_H

#include <CGAL/Curvature_estimation/Principal_curvatures_and_directions.h>
#include <CGAL/Curvature_estimation/internal/local_coordinates.h>
#include <CGAL/Curvature_estimation/internal/shape_operator.h>
#include <CGAL/Curvature_estimation/internal/surface_estimate.h>
#include <CGAL/Curvature_estimation/internal/tangent_frame.h>
#include <CGAL/Curvature_estimation/parameters.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/number_utils.h>

#include <boost/graph/graph_traits.hpp>

#include <Eigen/Core>

#include <cmath>
#include <limits>

namespace CGAL {
namespace Curvature_estimation {
namespace internal {

// Curvatures and directions from the shape matrix `shape` (normal curvature along
// `tangents * x`: x^T sym(shape) x) in coordinates divided by `scale`; K = det(shape)
// with `gaussian_from_determinant`, else k1 k2. Not estimable where not finite.
inline Surface_estimate shape_estimate_from_matrix(const Eigen::Matrix2d& shape, const Tangent_frame& tangents,
                                                   const Eigen::Vector3d& normal, double scale,
                                                   bool gaussian_from_determinant)
{
  if (!shape.allFinite() || !(scale > 0))
    return Surface_estimate();
  const Eigen::Matrix2d symmetric = 0.5 * (shape + shape.transpose());
  Eigen::Vector2d values;
  Eigen::Matrix2d vectors;
  symmetric_eigen<2>(symmetric, values, vectors);
  const double max_curvature = values[1] / scale, min_curvature = values[0] / scale;
  const double gaussian =
    gaussian_from_determinant ? shape.determinant() / (scale * scale) : max_curvature * min_curvature;
  const Eigen::Vector3d max_direction = tangents * vectors.col(1), min_direction = tangents * vectors.col(0);
  if (!std::isfinite(max_curvature) || !std::isfinite(min_curvature) || !std::isfinite(gaussian) ||
      !max_direction.allFinite() || !min_direction.allFinite())
    return Surface_estimate();
  Surface_estimate result = Surface_estimate::from_principal(Estimation_status::ok, max_curvature, min_curvature,
                                                             max_direction, min_direction, normal);
  result.gaussian_curvature = gaussian;
  return result;
}

} // namespace internal
} // namespace Curvature_estimation
} // namespace CGAL

#endif // CGAL_CURVATURE_ESTIMATION_INTERNAL_SHAPE_MATRIX_ESTIMATE_H
