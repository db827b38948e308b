// SPDX-License-Identifier: GPL-3.0-or-later
// Chen and Schmitt's least-squares fit of Euler's formula, on any FaceGraph.
#ifndef CGAL_CURVATURE_ESTIMATION_CHEN_SCHMITT_H
#define CGAL_CURVATURE_ESTIMATION_CHEN_SCHMITT_H

#include <CGAL/Curvature_estimation/Neighbor_weighting.h>
#include <CGAL/Curvature_estimation/Principal_curvatures_and_directions.h>
#include <CGAL/Curvature_estimation/internal/euler_fit.h>
#include <CGAL/Curvature_estimation/internal/normal_curvature_samples.h>
#include <CGAL/Curvature_estimation/parameters.h>
#include <CGAL/Curvature_estimation/vertex_normals.h>

#include <CGAL/tags.h>

#include <Eigen/Core>

#include <stdexcept>
#include <vector>

namespace CGAL {
namespace Curvature_estimation {

namespace internal {

// Whether `np` asks for the paper's fit (`Neighbor_weighting::uniform`), the only
// weighting Chen-Schmitt accepts.
template <typename NamedParameters>
bool chen_schmitt_uniform(const NamedParameters& np)
{
  if constexpr (!has_parameter<NamedParameters, internal_np::neighbor_weighting_t>()) {
    (void)np;
    return false;
  } else {
    if (::CGAL::parameters::get_parameter(np, internal_np::neighbor_weighting) != Neighbor_weighting::uniform)
      throw std::invalid_argument("chen_schmitt_curvatures: neighbor_weighting must be uniform");
    return true;
  }
}

// The rings of the samples: the 1-ring's edges for the paper's fit, else the 2-ring's vertices.
constexpr int chen_schmitt_rings(bool uniform) { return uniform ? 1 : 2; }

// Euler's formula fitted to the samples by least squares: unweighted (`uniform`)
// as Chen and Schmitt, else with weights |q_i - p|^2. A sample's error, that of
// the normal and the cubic remainder, is divided by |q_i - p|: the weights make
// a sample from a very short edge count as little as it knows. The paper measures
// the angles from the first edge, and the fit does not depend on that choice of
// frame. The threshold only refuses directions that are (nearly) not three distinct ones.
inline bool chen_schmitt_shape_matrix(const std::vector<Normal_curvature_sample>& samples, bool uniform,
                                      Eigen::Matrix2d& shape)
{
  Euler_fit fit;
  for (const Normal_curvature_sample& sample : samples)
    fit.add(sample.direction, sample.curvature, uniform ? 1 : sample.squared_length);
  return fit.solve(1e5, shape);
}

} // namespace internal

/// \ingroup PkgCurvatureEstimationRef
///
/// estimates principal curvatures and directions, mean and Gaussian curvature at every vertex of `g` by
/// Chen and Schmitt's method (Chen and Schmitt 1992, as reviewed by Chen, Wu and Chi 2005, section 3.1):
/// the normal curvatures k_i = 2 <p - q_i, N> / |q_i - p|^2 along the unit tangents towards the neighbors
/// q_i of the vertex p are fitted by least squares with Euler's formula
/// k(theta) = C_1 cos^2 theta + C_2 cos theta sin theta + C_3 sin^2 theta, and the principal curvatures and
/// directions are the eigenvalues and eigenvectors of [[C_1, C_2/2], [C_2/2, C_3]]. By default the samples
/// are those of the 2-ring, weighted by |q_i - p|^2; `neighbor_weighting(Neighbor_weighting::uniform)` is the
/// paper's unweighted fit over the 1-ring, which diverges on meshes with slivers (see the User Manual,
/// "Gauss map and the baselines"). A baseline. Normals: as `taubin_curvatures()`.
///
/// Conventions: as `paraboloid_fitting_curvatures()`. A vertex with no normal, or whose samples have fewer
/// than three directions distinct modulo pi, is `not_estimable` (NaN). Only the outputs whose maps are
/// passed are written.
///
/// \ceSurfaceEstimatorParameters
///
/// \cgalNamedParamsBegin
///   \ceSurfaceInputParameters
///   \ceGivenNormalParameter
///   \ceQuadricFitNormalParameters
///   \cgalParamNBegin{neighbor_weighting}
///     \cgalParamDescription{`uniform`: the paper's unweighted fit over the 1-ring (other values are refused)}
///     \cgalParamDefault{none: the fit over the 2-ring with weights `|q_i - p|^2`}
///   \cgalParamNEnd
///   \ceSurfaceOutputParameters{K = k1 k2, `ok` or `not_estimable`}
/// \cgalNamedParamsEnd
///
/// \throws std::invalid_argument if a parameter is out of its range, or if `ball_radius`
///         is given (neighborhoods are set in rings).
template <typename ConcurrencyTag = CGAL::Sequential_tag, typename FaceGraph,
          typename NamedParameters = parameters::Default_named_parameters>
void chen_schmitt_curvatures(const FaceGraph& g, const NamedParameters& np = parameters::default_values())
{
  const bool uniform = internal::chen_schmitt_uniform(np);
  internal::normal_curvature_sample_curvatures<ConcurrencyTag>(
    g, np, "chen_schmitt_curvatures", internal::chen_schmitt_rings(uniform),
    [uniform](const std::vector<internal::Normal_curvature_sample>& samples, Eigen::Matrix2d& shape) {
      return internal::chen_schmitt_shape_matrix(samples, uniform, shape);
    });
}

} // namespace Curvature_estimation
} // namespace CGAL

#endif // CGAL_CURVATURE_ESTIMATION_CHEN_SCHMITT_H
