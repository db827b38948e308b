// SPDX-License-Identifier: GPL-3.0-or-later
// The choice of a ball radius at one vertex from the fits over nested balls about
// it (the manual's "Choosing the radius per vertex").
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

// The fit over one ball of the nested balls.
struct Scale_candidate
{
  std::size_t step;         // the index of its radius among the candidate radii
  double radius;            // in units of the vertex's scale
  double mean_curvature;    // of the fit
  double variance;          // of that mean curvature, per unit variance of the heights
  double residual_variance; // of the heights about the fit
};

// The order of the leading bias of the mean curvature of a fit of `degree` over a ball.
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

// Over candidates[0, count) (count > 0): the least (beta r^order)^2 + noise_variance
// variance, beta fitted over every candidate; then, among the candidates up to twice
// that one's radius, the least with beta fitted over them.
inline Least_error least_error_candidate(const Scale_candidate* candidates, std::size_t count, double noise_variance,
                                         int order)
{
  const auto least_of = [&](std::size_t first_candidates) {
    const double beta = bias_slope(candidates, first_candidates, order);
    Least_error least{0, std::numeric_limits<double>::infinity()};
    for (std::size_t k = 0; k < first_candidates; ++k) {
      const double bias = beta * std::pow(candidates[k].radius, order);
      const double error = bias * bias + noise_variance * candidates[k].variance;
      if (error < least.squared_error)
        least = {k, error};
    }
    return least;
  };
  const Least_error first = least_of(count);
  std::size_t window = 0;
  while (window < count && candidates[window].radius <= 2 * candidates[first.index].radius)
    ++window;
  return least_of(window >= 2 ? window : (std::min)(count, std::size_t(3)));
}

// The number of leading candidates the selection may consider: none where the smallest
// ball's residual variance exceeds clean_ratio times the noise variance (clean data),
// else those before the first whose residual variance exceeds misfit_ratio times it.
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

// The selection at one vertex, in the mesh's units; NaN where not determined.
struct Scale_selection
{
  static constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  double radius = nan;            // the selected radius
  double error = nan;             // the estimated RMS error of the mean curvature there
  double noise = nan;             // the heights' standard deviation about the quartic fit
  double default_deviation = nan; // the standard deviation it gives the default fit's mean curvature
  double default_radius = nan;    // the radius of the default fit's neighborhood

  bool selected() const { return std::isfinite(radius) && std::isfinite(error); }
};

// The default estimate where its noise deviation is at most the selected ball's error
// or nothing was selected, else `at_radius(radius)` where estimable; with radius and noise.
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
