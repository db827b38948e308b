// SPDX-License-Identifier: GPL-3.0-or-later
// From curves on a surface to the surface's curvature (Wollmann 2000, sections 1
// and 4): the surface normal from the curves' tangents, Meusnier's theorem for
// the normal curvature of each curve, and Euler's theorem solved for the
// principal curvatures and directions, exactly for three directions and by least
// squares for more. Pure functions; no mesh.
#ifndef CGAL_CURVATURE_ESTIMATION_INTERNAL_MEUSNIER_EULER_H
#define CGAL_CURVATURE_ESTIMATION_INTERNAL_MEUSNIER_EULER_H

#include <CGAL/Curvature_estimation/internal/euler_fit.h>
#include <CGAL/Curvature_estimation/internal/shape_operator.h>
#include <CGAL/Curvature_estimation/internal/symmetric_eigen.h>
#include <CGAL/Curvature_estimation/internal/tangent_frame.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cmath>
#include <cstddef>
#include <limits>

namespace CGAL {
namespace Curvature_estimation {
namespace internal {

// Meusnier's theorem in the package's sign: a curve with curvature vector kappa h
// through a point of unit normal N has the normal curvature k_n = -kappa <h, N>.
inline double meusnier_normal_curvature(const Eigen::Vector3d& curvature_vector, const Eigen::Vector3d& normal)
{
  return -curvature_vector.dot(normal);
}

// The unit normal of the plane that the `count` tangents (unit vectors) span,
// oriented to have a positive component along `orientation`: for two tangents
// their cross product (the paper's N = X_u x X_v / |X_u x X_v|), for more the
// least-squares normal, the eigenvector of the smallest eigenvalue of
// sum t_i t_i^T. As accurate as the tangents: O(h^2n) with the O(h^2n) tangents.
// Returns false (normal NaN) when the tangents do not span a plane.
inline bool normal_from_tangents(const Eigen::Vector3d* tangents, std::size_t count, const Eigen::Vector3d& orientation,
                                 Eigen::Vector3d& normal)
{
  normal = Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
  if (count < 2)
    return false;
  Eigen::Vector3d candidate;
  if (count == 2) {
    candidate = tangents[0].cross(tangents[1]);
    const double length = candidate.norm();
    // Tangents closer than about 0.06 degree do not span a plane.
    if (!(length > 1e-3))
      return false;
    candidate /= length;
  } else {
    Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
    for (std::size_t i = 0; i < count; ++i)
      scatter += tangents[i] * tangents[i].transpose();
    Eigen::Vector3d values;
    Eigen::Matrix3d vectors;
    if (!symmetric_eigen_accurate<3>(scatter, values, vectors))
      return false;
    // The two larger eigenvalues measure the spread of the tangents in the plane.
    if (!(values[1] > 1e-6 * values[2]))
      return false;
    candidate = vectors.col(0);
  }
  if (!candidate.allFinite())
    return false;
  normal = candidate.dot(orientation) < 0 ? Eigen::Vector3d(-candidate) : candidate;
  return true;
}

// The result of Euler's theorem: principal curvatures (max >= min) and unit
// principal directions, orthogonal to each other and to the normal; `valid`
// false (and NaN fields) when the directions do not determine them.
struct Euler_solution
{
  bool valid = false;
  double max_curvature = std::numeric_limits<double>::quiet_NaN();
  double min_curvature = std::numeric_limits<double>::quiet_NaN();
  Eigen::Vector3d max_direction = Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
  Eigen::Vector3d min_direction = Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
};

// Directions whose Euler system has a 2-norm condition number above this are
// rejected (three directions 60 degrees apart give about 2; beyond this, normal
// curvatures with a few percent error give garbage).
constexpr double euler_max_condition_number = 20;

// Euler's theorem (see Euler_fit) for 3D directions at a vertex of normal
// `normal`: the paper's system (E) in (kappa1, kappa2, phi). `directions` need
// not be unit nor exactly tangent (they are projected); `curvatures` are the
// normal curvatures (package sign, see meusnier_normal_curvature).
inline Euler_solution euler_fit(const Eigen::Vector3d* directions, const double* curvatures, std::size_t count,
                                const Eigen::Vector3d& normal, double max_condition_number = euler_max_condition_number)
{
  Euler_solution result;
  if (count < 3 || !normal.allFinite())
    return result;
  const Eigen::Matrix<double, 3, 2> frame = tangent_basis<3>(normal);
  Euler_fit fit;
  for (std::size_t i = 0; i < count; ++i) {
    const Eigen::Vector2d d = frame.transpose() * directions[i];
    const double length = d.norm();
    if (!(length > 0) || !std::isfinite(length) || !std::isfinite(curvatures[i]))
      return result;
    fit.add(d / length, curvatures[i]);
  }
  Eigen::Matrix2d S;
  if (!fit.solve(max_condition_number, S))
    return result;
  Eigen::Vector2d values;
  Eigen::Matrix2d vectors;
  symmetric_eigen<2>(S, values, vectors);
  if (!values.allFinite() || !vectors.allFinite())
    return result;
  result.valid = true;
  result.max_curvature = values[1];
  result.min_curvature = values[0];
  result.max_direction = (frame * vectors.col(1)).normalized();
  result.min_direction = (frame * vectors.col(0)).normalized();
  return result;
}

} // namespace internal
} // namespace Curvature_estimation
} // namespace CGAL

#endif // CGAL_CURVATURE_ESTIMATION_INTERNAL_MEUSNIER_EULER_H
