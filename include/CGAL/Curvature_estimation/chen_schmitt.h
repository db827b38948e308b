// SPDX-License-Identifier: GPL-3.0-or-later
// Chen and Schmitt's least-squares fit of Euler's formula, on any FaceGraph.
#ifndef CGAL_CURVATURE_ESTIMATION_CHEN_SCHMITT_H
#define CGAL_CURVATURE_ESTIMATION_CHEN_SCHMITT_H

#include <CGAL/Curvature_estimation/Principal_curvatures_and_directions.h>
#include <CGAL/Curvature_estimation/parameters.h>
#include <CGAL/Curvature_estimation/vertex_normals.h>
#include <CGAL/Curvature_estimation/internal/euler_fit.h>
#include <CGAL/Curvature_estimation/internal/normal_curvature_samples.h>

#include <CGAL/tags.h>

#include <Eigen/Core>

#include <vector>

namespace CGAL {
namespace Curvature_estimation {

namespace internal {

// Euler's formula fitted to the samples by unweighted least squares, as Chen and
// Schmitt; the paper measures the angles from the first edge, and the fit does not
// depend on that choice of frame. The threshold only refuses directions that are
// (nearly) not three distinct ones.
inline bool chen_schmitt_shape_matrix(const std::vector<Normal_curvature_sample>& samples, Eigen::Matrix2d& shape)
{
  Euler_fit fit;
  for (const Normal_curvature_sample& sample : samples)
    fit.add(sample.direction, sample.curvature);
  return fit.solve(1e5, shape);
}

} // namespace internal

/// \ingroup PkgCurvatureEstimationRef
///
/// Estimates principal curvatures and directions, mean and Gaussian curvature at
/// every vertex of a surface mesh by Chen and Schmitt's method (Chen and Schmitt
/// 1992, as reviewed by Chen, Wu and Chi 2005, section 3.1): the normal curvatures
/// `k_i = 2 <p - q_i, N> / |q_i - p|^2` along the unit
/// tangents `t_i = (costheta_i, sintheta_i)` towards the neighbors
/// `q_i` joined to the vertex p by an edge (as in `taubin_curvatures()`) are
/// fitted by unweighted least squares with Euler's formula
/// `k(theta) = C_1 cos^2theta + C_2 costheta sintheta + C_3 sin^2theta`;
/// the principal curvatures and directions are the eigenvalues and eigenvectors
/// of `[[C_1, C_2/2], [C_2/2, C_3]]` (eqs. 12-13). The angles are measured
/// in a tangent frame of the normal; the fit does not depend on which (the paper
/// measures them from the first edge).
///
/// A baseline: not consistent on irregular meshes. Normals come from
/// `vertex_normal_map` when given, else from `vertex_normal_method` (default
/// `Vertex_normal_method::quadric_fit`, the package's second-order normal).
///
/// **Conventions.** A sphere with outward normals has `max_curvature == min_curvature == 1/r`;
/// `max_curvature >= min_curvature`; directions are unit, tangent and orthogonal;
/// K is `max_curvature * min_curvature`. A vertex with no normal, or with fewer
/// than three neighbor directions distinct modulo pi (for instance a corner of a
/// grid), gets NaN in every output and the status `Estimation_status::not_estimable`.
///
/// Only the outputs whose maps are passed are written; passing none does nothing.
///
/// \ceConcurrencyTag
/// \tparam FaceGraph a model of `FaceGraph` (faces may be any polygons).
/// \tparam NamedParameters a sequence of named parameters, built with the functions of `CGAL::Curvature_estimation::parameters`
///
/// \param g the mesh
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \ceSurfaceInputParameters
///   \ceGivenNormalParameter
///   \ceQuadricFitNormalParameters
///   \ceSurfaceOutputParameters{K = k1 k2, `ok` or `not_estimable`}
/// \cgalNamedParamsEnd
///
/// \throws std::invalid_argument if a parameter is out of its range, or if `ball_radius`
///         is given (neighborhoods are set in rings).
template <typename ConcurrencyTag = CGAL::Sequential_tag,
          typename FaceGraph,
          typename NamedParameters = parameters::Default_named_parameters>
void chen_schmitt_curvatures(const FaceGraph& g, const NamedParameters& np = parameters::default_values())
{
  internal::normal_curvature_sample_curvatures<ConcurrencyTag>(
    g, np, "chen_schmitt_curvatures",
    [](const std::vector<internal::Normal_curvature_sample>& samples, Eigen::Matrix2d& shape) {
      return internal::chen_schmitt_shape_matrix(samples, shape);
    });
}

} // namespace Curvature_estimation
} // namespace CGAL

#endif // CGAL_CURVATURE_ESTIMATION_CHEN_SCHMITT_H
