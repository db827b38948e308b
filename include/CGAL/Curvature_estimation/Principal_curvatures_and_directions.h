// SPDX-License-Identifier: GPL-3.0-or-later
// Output value types shared by every estimator of the package.
#ifndef CGAL_CURVATURE_ESTIMATION_PRINCIPAL_CURVATURES_AND_DIRECTIONS_H
#define CGAL_CURVATURE_ESTIMATION_PRINCIPAL_CURVATURES_AND_DIRECTIONS_H

#include <CGAL/version.h>

#if CGAL_VERSION_MAJOR >= 6
#include <CGAL/Polygon_mesh_processing/interpolated_corrected_curvatures.h>
#endif

#include <ostream>

namespace CGAL {
namespace Curvature_estimation {

/// \ingroup PkgCurvatureEstimationRef
/// Principal curvatures and principal directions at a vertex of a surface in R^3.
/// With CGAL 6 or later this is `CGAL::Polygon_mesh_processing::Principal_curvatures_and_directions<GT>`
/// itself, so that the same property map serves CGAL's `interpolated_corrected_curvatures()`
/// and the estimators of this package; with CGAL 5 it is a struct with the same fields
/// and constructors.
///
/// Conventions: `max_curvature >= min_curvature`; the directions are unit tangent
/// vectors, orthogonal to each other and to the normal. With outward normals a sphere
/// of radius r has `max_curvature == min_curvature == 1/r`.
/// At a vertex whose status is `Estimation_status::not_estimable`, every field is NaN.
///
/// \tparam GT a geometric traits class providing `FT` and `Vector_3`.
#if CGAL_VERSION_MAJOR >= 6 && !defined(DOXYGEN_RUNNING)
template <typename GT>
using Principal_curvatures_and_directions = ::CGAL::Polygon_mesh_processing::Principal_curvatures_and_directions<GT>;
#else
template <typename GT>
struct Principal_curvatures_and_directions
{
  using FT = typename GT::FT;
  using Vector_3 = typename GT::Vector_3;

  FT min_curvature;
  FT max_curvature;
  Vector_3 min_direction;
  Vector_3 max_direction;

  Principal_curvatures_and_directions()
      : min_curvature(0)
      , max_curvature(0)
      , min_direction(0, 0, 0)
      , max_direction(0, 0, 0)
  {}

  Principal_curvatures_and_directions(FT min_curvature, FT max_curvature, const Vector_3& min_direction,
                                      const Vector_3& max_direction)
      : min_curvature(min_curvature)
      , max_curvature(max_curvature)
      , min_direction(min_direction)
      , max_direction(max_direction)
  {}
};
#endif

/// \ingroup PkgCurvatureEstimationRef
/// The outcome of an estimation at one vertex, written to the map given as
/// `vertex_estimation_status_map`.
enum class Estimation_status : unsigned char
{
  ok,            ///< estimated from the neighborhood asked for
  widened,       ///< estimated from a wider neighborhood than asked for (a fit refused there)
  not_estimable, ///< no estimate: isolated vertex, degenerate neighborhood, invalid input; values are NaN
  fallback       ///< estimated by one of the estimator's fallbacks, its own method finding none (see the
                 ///< User Manual, Fallbacks)
};

/// The name of a status: `ok`, `widened`, `not_estimable` or `fallback`.
inline const char* to_string(Estimation_status status)
{
  switch (status) {
    case Estimation_status::ok:
      return "ok";
    case Estimation_status::widened:
      return "widened";
    case Estimation_status::not_estimable:
      return "not_estimable";
    case Estimation_status::fallback:
      return "fallback";
  }
  return "unknown";
}

inline std::ostream& operator<<(std::ostream& os, Estimation_status status) { return os << to_string(status); }

} // namespace Curvature_estimation
} // namespace CGAL

namespace CGAL {
namespace Curvature_estimation {

/// \ingroup PkgCurvatureEstimationRef
/// The three principal curvatures and principal directions at a vertex of a
/// 3-dimensional hypersurface of R^4 (a tetrahedral complex whose vertices are points
/// of R^4, for instance the graph W = f(x, y, z) of a trivariate function).
///
/// Conventions: `max_curvature >= mid_curvature >= min_curvature`; the directions are
/// unit vectors of R^4, tangent (orthogonal to the normal) and orthogonal to each
/// other. Curvatures are positive where the hypersurface bends away from the normal.
/// At a vertex whose status is `Estimation_status::not_estimable`, every field is NaN.
///
/// \tparam Vector_4 a vector type of R^4: `std::array<double, 4>`, `Eigen::Vector4d`,
///         or CGAL's `Epick_d<Dimension_tag<4>>::Vector_d` (constructible from a range
///         of 4 coordinates).
/// \tparam FT the number type of the curvatures.
template <typename Vector_4, typename FT_ = double>
struct Hypersurface_principal_curvatures_and_directions
{
  using FT = FT_;
  FT max_curvature{};
  FT mid_curvature{};
  FT min_curvature{};
  Vector_4 max_direction{};
  Vector_4 mid_direction{};
  Vector_4 min_direction{};
};

} // namespace Curvature_estimation
} // namespace CGAL

#endif // CGAL_CURVATURE_ESTIMATION_PRINCIPAL_CURVATURES_AND_DIRECTIONS_H
