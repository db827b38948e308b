// SPDX-License-Identifier: GPL-3.0-or-later
// Taubin's estimator of the tensor of curvature (Taubin 1995), on any FaceGraph.
#ifndef CGAL_CURVATURE_ESTIMATION_TAUBIN_H
#define CGAL_CURVATURE_ESTIMATION_TAUBIN_H

#include <CGAL/Curvature_estimation/Neighbor_weighting.h>
#include <CGAL/Curvature_estimation/Principal_curvatures_and_directions.h>
#include <CGAL/Curvature_estimation/internal/normal_curvature_samples.h>
#include <CGAL/Curvature_estimation/parameters.h>
#include <CGAL/Curvature_estimation/vertex_normals.h>

#include <CGAL/tags.h>

#include <Eigen/Core>

#include <cmath>
#include <stdexcept>

#include <vector>

namespace CGAL {
namespace Curvature_estimation {

namespace internal {

// The rings of Taubin's samples: the 1-ring's edges.
constexpr int taubin_rings = 1;

// Taubin's tensor (Taubin 1995; eq. 17): M = sum_i w_i k_i t_i t_i^T with the
// weights normalised to sum 1; its eigenvalues m1 >= m2 give k1 = 3 m1 - m2,
// k2 = 3 m2 - m1 with the same eigenvectors, i.e. the shape matrix 4 M - tr(M) I.
// False when the weights vanish or the tangents do not span the plane.
inline bool taubin_shape_matrix(const std::vector<Normal_curvature_sample>& samples, bool area_weights,
                                Eigen::Matrix2d& shape)
{
  Eigen::Matrix2d tensor = Eigen::Matrix2d::Zero(), spread = Eigen::Matrix2d::Zero();
  double weight_sum = 0;
  for (const Normal_curvature_sample& s : samples) {
    const double w = area_weights ? s.area_weight : s.centroid_weight;
    const Eigen::Matrix2d tt = s.direction * s.direction.transpose();
    tensor += (w * s.curvature) * tt;
    spread += w * tt;
    weight_sum += w;
  }
  if (!(weight_sum > 0) || !std::isfinite(weight_sum))
    return false;
  tensor /= weight_sum;
  spread /= weight_sum;
  // det(spread) is sum_{i<j} w_i w_j sin^2(t_i, t_j): zero when all tangents are parallel.
  if (!(spread.determinant() > 1e-12))
    return false;
  shape = 4 * tensor - tensor.trace() * Eigen::Matrix2d::Identity();
  return true;
}

} // namespace internal

/// \ingroup PkgCurvatureEstimationRef
///
/// estimates principal curvatures and directions, mean and Gaussian curvature at every vertex of `g` by
/// Taubin's tensor of curvature (Taubin 1995, as reviewed by Chen, Wu and Chi 2005, section 3.2): with t_i
/// the unit projection of q_i - p on the tangent plane for each neighbor q_i joined to p by an edge, and
/// k_i = 2 <p - q_i, N> / |q_i - p|^2, the tensor M = sum_i w_i k_i t_i t_i^T (weights of
/// `neighbor_weighting`, summing to 1) has tangent eigenvalues m_1 >= m_2, and k_1 = 3 m_1 - m_2,
/// k_2 = 3 m_2 - m_1 with the same eigenvectors. A baseline: it is not consistent on irregular meshes.
/// Normals come from `vertex_normal_map` when given, else from `vertex_normal_method` (Taubin used the
/// area-weighted normal, Chen, Wu and Chi the centroid-weighted one: pass them to reproduce their settings).
///
/// Conventions: as `paraboloid_fitting_curvatures()`. A vertex with no normal, or whose neighbors'
/// tangents do not span the tangent plane, is `not_estimable` (NaN). Only the outputs whose maps are
/// passed are written.
///
/// \ceSurfaceEstimatorParameters
///
/// \cgalNamedParamsBegin
///   \ceSurfaceInputParameters
///   \ceGivenNormalParameter
///   \ceQuadricFitNormalParameters
///   \cgalParamNBegin{neighbor_weighting}
///     \cgalParamDescription{the weights of the neighbors: `area` or `centroid` (the others are refused)}
///     \cgalParamDefault{`Neighbor_weighting::area` (Taubin's)}
///   \cgalParamNEnd
///   \ceSurfaceOutputParameters{K = k1 k2, `ok` or `not_estimable`}
/// \cgalNamedParamsEnd
///
/// \throws std::invalid_argument if a parameter is out of its range, or if `ball_radius`
///         is given (neighborhoods are set in rings).
template <typename ConcurrencyTag = CGAL::Sequential_tag, typename FaceGraph,
          typename NamedParameters = parameters::Default_named_parameters>
void taubin_curvatures(const FaceGraph& g, const NamedParameters& np = parameters::default_values())
{
  const Neighbor_weighting weighting =
    internal::parameter_or(np, internal_np::neighbor_weighting, Neighbor_weighting::area);
  if (weighting != Neighbor_weighting::area && weighting != Neighbor_weighting::centroid)
    throw std::invalid_argument("taubin_curvatures: neighbor_weighting must be area or centroid");
  const bool area_weights = weighting == Neighbor_weighting::area;
  internal::normal_curvature_sample_curvatures<ConcurrencyTag>(
    g, np, "taubin_curvatures", internal::taubin_rings,
    [area_weights](const std::vector<internal::Normal_curvature_sample>& samples, Eigen::Matrix2d& shape) {
      return internal::taubin_shape_matrix(samples, area_weights, shape);
    });
}

} // namespace Curvature_estimation
} // namespace CGAL

#endif // CGAL_CURVATURE_ESTIMATION_TAUBIN_H
