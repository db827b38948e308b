// SPDX-License-Identifier: GPL-3.0-or-later
// The choice of a ball radius at one vertex from the fits over nested balls
// about it (the manual's "Scale selection"): the radius of least estimated mean
// squared error of the mean curvature, and whether the estimate over that ball
// or the default one is kept.
#ifndef CGAL_CURVATURE_ESTIMATION_INTERNAL_SCALE_SELECTION_H
#define CGAL_CURVATURE_ESTIMATION_INTERNAL_SCALE_SELECTION_H

#include <CGAL/Curvature_estimation/Principal_curvatures_and_directions.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

namespace CGAL {
namespace Curvature_estimation {
namespace internal {

// The fit over one ball of the nested balls: the index of its radius among the
// candidate radii, that radius in units of the vertex's scale, the mean curvature
// the fit gives, that mean curvature's variance per unit variance of the heights,
// and the variance of the heights about the fit.
struct Scale_candidate
{
  std::size_t step;
  double radius;
  double mean_curvature;
  double variance;
  double residual_variance;
};

// The order of the leading bias of the mean curvature of a fit of `degree` over
// a ball of radius r: r^2 at degrees 2 and 3, r^4 at degree 4 (the odd orders
// cancel in a ball centered at the vertex).
constexpr int bias_order(int degree) { return degree == 4 ? 4 : 2; }

// The candidate of least estimated mean squared error, its index and that error.
struct Least_error
{
  std::size_t index;
  double squared_error;
};

// The slope beta of the candidates' mean curvatures against r^order over
// candidates[0, count), fitted by least squares weighted by the inverse variances.
inline double bias_slope(const Scale_candidate* candidates, std::size_t count, int order)
{
  double weights = 0, mean_t = 0, mean_h = 0;
  for (std::size_t k = 0; k < count; ++k) {
    const double w = 1 / candidates[k].variance;
    weights += w;
    mean_t += w * std::pow(candidates[k].radius, order);
    mean_h += w * candidates[k].mean_curvature;
  }
  mean_t /= weights;
  mean_h /= weights;
  double covariance = 0, spread = 0;
  for (std::size_t k = 0; k < count; ++k) {
    const double w = 1 / candidates[k].variance;
    const double t = std::pow(candidates[k].radius, order) - mean_t;
    covariance += w * t * (candidates[k].mean_curvature - mean_h);
    spread += w * t * t;
  }
  return spread > 0 ? covariance / spread : 0;
}

// Over candidates[0, count) (count > 0): the least estimated mean squared error
// (beta r^order)^2 + noise_variance variance of the mean curvature. The bias
// slope beta is fitted over every candidate, then again over those of radius at
// most twice the one of least error, where the bias is closest to its leading term.
inline Least_error least_error_candidate(const Scale_candidate* candidates, std::size_t count, double noise_variance,
                                         int order)
{
  const auto least_with = [&](double beta) {
    Least_error least{0, std::numeric_limits<double>::infinity()};
    for (std::size_t k = 0; k < count; ++k) {
      const double bias = beta * std::pow(candidates[k].radius, order);
      const double error = bias * bias + noise_variance * candidates[k].variance;
      if (error < least.squared_error)
        least = {k, error};
    }
    return least;
  };
  const Least_error first = least_with(bias_slope(candidates, count, order));
  std::size_t window = 0;
  while (window < count && candidates[window].radius <= 2 * candidates[first.index].radius)
    ++window;
  return least_with(bias_slope(candidates, window >= 2 ? window : (std::min)(count, std::size_t(3)), order));
}

// The number of leading candidates that the selection may consider: none where
// the residual variance over the smallest ball exceeds clean_ratio times the
// noise variance (the fit's own misfit dominates the noise: clean data, which the
// default fit serves), else those before the first whose residual variance exceeds
// misfit_ratio times the noise variance (the ball has outgrown the fit's model).
inline std::size_t considered_candidates(const Scale_candidate* candidates, std::size_t count, double noise_variance)
{
  constexpr double clean_ratio = 10, misfit_ratio = 100;
  if (count == 0 || candidates[0].residual_variance > clean_ratio * noise_variance)
    return 0;
  std::size_t k = 1;
  while (k < count && candidates[k].residual_variance <= misfit_ratio * noise_variance)
    ++k;
  return k;
}

// The selection at one vertex, in the mesh's units: the selected radius (NaN
// where no ball held enough samples) and the estimated root mean squared error of
// the mean curvature there, the noise (the standard deviation of the heights
// about the quartic fit, NaN where too few samples), the standard deviation that
// this noise gives the mean curvature of the default fit, and the radius of the
// default fit's neighborhood.
struct Scale_selection
{
  static constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  double radius = nan;
  double error = nan;
  double noise = nan;
  double default_deviation = nan;
  double default_radius = nan;

  bool selected() const { return std::isfinite(radius) && std::isfinite(error); }
};

// The estimate under scale selection: the default estimate where the noise alone
// would give it a smaller error than the estimated error over the selected ball
// (on clean data), or where no radius was selected; else the estimate over that
// ball, `at_radius(radius)`, unless it is not estimable. With the radius of the
// estimate kept and the noise. Estimate is a Surface_estimate.
template <typename Estimate, typename AtRadius>
Estimate select_estimate(Estimate default_estimate, const Scale_selection& selection, const AtRadius& at_radius)
{
  default_estimate.radius = selection.default_radius;
  default_estimate.noise = selection.noise;
  const bool default_estimable = default_estimate.status != Estimation_status::not_estimable;
  if (!selection.selected() || (default_estimable && selection.default_deviation <= selection.error))
    return default_estimate;
  Estimate selected = at_radius(selection.radius);
  if (selected.status == Estimation_status::not_estimable)
    return default_estimate;
  selected.radius = selection.radius;
  selected.noise = selection.noise;
  return selected;
}

} // namespace internal
} // namespace Curvature_estimation
} // namespace CGAL

#endif // CGAL_CURVATURE_ESTIMATION_INTERNAL_SCALE_SELECTION_H
