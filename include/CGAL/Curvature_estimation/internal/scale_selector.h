// SPDX-License-Identifier: GPL-3.0-or-later
// The scale selection at one vertex (scale_selection.h): the fits over nested balls
// grown once through the range, the noise from a quartic fit's residuals.
#ifndef CGAL_CURVATURE_ESTIMATION_INTERNAL_SCALE_SELECTOR_H
#define CGAL_CURVATURE_ESTIMATION_INTERNAL_SCALE_SELECTOR_H

#include <CGAL/Curvature_estimation/Vertex_normal_method.h>
#include <CGAL/Curvature_estimation/internal/fit_attempts.h>
#include <CGAL/Curvature_estimation/internal/fit_settings.h>
#include <CGAL/Curvature_estimation/internal/neighborhood_samples.h>
#include <CGAL/Curvature_estimation/internal/scale_selection.h>
#include <CGAL/Curvature_estimation/internal/shape_operator.h>
#include <CGAL/Curvature_estimation/internal/taylor_fit/taylor_fit.h>

#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Curvature_estimation {
namespace internal {

// The candidate radii of `range`: its bounds and geometric steps of 2^(1/4)
// between them (at most 64 steps: a wider range takes larger ones).
inline std::vector<double> candidate_radii(const Radius_range& range)
{
  constexpr int most_steps = 64;
  const double octaves = std::log2(range.max / range.min);
  const int steps = static_cast<int>((std::min)(std::ceil(4 * octaves - 1e-9), double(most_steps)));
  std::vector<double> radii;
  for (int k = 0; k < steps; ++k)
    radii.push_back(range.min * std::exp2(octaves * k / steps));
  radii.push_back(range.max);
  return radii;
}

template <typename Neighborhood>
class Scale_selector
{
public:
  using Samples = Neighborhood_samples<Neighborhood>;
  static constexpr int D = Samples::D;
  static_assert(D == 2, "the scale selection is that of surfaces");
  using Vertex = typename Samples::Vertex;
  using Vector = typename Samples::Vector;

  Scale_selector(Neighborhood neighborhood, const Fit_settings& settings)
      : samples_(std::move(neighborhood))
      , degree_(settings.degree)
      , intercept_(settings.ring_intercept)
      , radii_(candidate_radii(settings.radius_range))
  {
    candidates_.reserve(radii_.size());
  }

  // The selection at v, in the frame of `normal` (any length) where given, else
  // of the first-order normal by `method`.
  Scale_selection select(Vertex v, const Vector* normal, Vertex_normal_method method)
  {
    Scale_selection selection;
    Vector unit;
    if (!samples_.gather(v, 0) || !samples_.unit_normal(v, normal, method, unit))
      return selection;
    const Frame frame = Samples::frame_of(unit);
    const double scale = samples_.scale();
    selection.default_radius = samples_.one_ring_radius() * scale;
    const double default_variance = intercept_ ? intercept_variance(frame) : one_ring_variance(frame);
    double noise_variance = std::numeric_limits<double>::quiet_NaN();
    const auto nested_balls = [&](auto fit) { noise_variance = fit_nested_balls(fit, frame); };
    if (degree_ == 2)
      nested_balls(Quartic_intercept_fit<2>());
    else if (degree_ == 3)
      nested_balls(Quartic_intercept_fit<3>());
    else
      nested_balls(Intercept_fit<D, 4>());
    if (!(noise_variance >= 0))
      return selection;
    const double noise = std::sqrt(noise_variance);
    selection.noise = noise * scale;
    const std::size_t considered = considered_candidates(candidates_.data(), candidates_.size(), noise_variance);
    if (considered == 0)
      return selection;
    const Least_error least =
      least_error_candidate(candidates_.data(), considered, noise_variance, bias_order(degree_));
    selection.radius = radii_[candidates_[least.index].step];
    selection.error = std::sqrt(least.squared_error) / scale;
    selection.default_deviation = noise * std::sqrt(default_variance) / scale;
    return selection;
  }

  // The radius of the widest ball the selection at v gathered (0: none).
  double widest_ball(Vertex v) { return samples_.neighborhood().widest_ball(v); }

  // The candidates of the last select(), for tests: radii in units of the 1-ring's mean edge.
  const std::vector<Scale_candidate>& candidates() const { return candidates_; }

private:
  using Frame = typename Samples::Frame;
  using Sampling = typename Samples::Sampling;
  using Point = Eigen::Matrix<double, D, 1>;
  using Noise_fit = Intercept_fit<D, 4>;
  static constexpr double unbounded = std::numeric_limits<double>::infinity();

  // Fills candidates_ (balls with twice the fit's unknowns); returns the residual variance
  // of the quartic fit over the first ball with three times its unknowns, NaN where none.
  template <typename Fit>
  double fit_nested_balls(Fit& fit, const Frame& frame)
  {
    Noise_fit noise_fit;
    double squared_heights = 0, fit_squared_heights = 0;
    double noise_variance = std::numeric_limits<double>::quiet_NaN();
    bool noise_open = true;
    const auto close_noise = [&](int least_samples) {
      noise_open = false;
      if (noise_fit.size() >= least_samples && noise_fit.solve(unbounded))
        noise_variance = noise_fit.residual_sum_of_squares(squared_heights) / (noise_fit.size() - Noise_fit::unknowns);
    };
    candidates_.clear();
    std::size_t joined = 0;
    for (std::size_t step = 0; step < radii_.size(); ++step) {
      const double r = radii_[step] / samples_.scale();
      const bool more = samples_.reach_ball(r);
      joined = samples_.for_each_joined_sample(frame, joined, [&](const Point& x, double height) {
        fit.add(x, height);
        fit_squared_heights += height * height;
        if (noise_open) {
          noise_fit.add(x, height);
          squared_heights += height * height;
        }
      });
      if (noise_open && noise_fit.size() >= 3 * Noise_fit::unknowns)
        close_noise(3 * Noise_fit::unknowns);
      if (fit.size() >= 2 * Fit::unknowns && fit.solve(unbounded)) {
        const double variance = fit.mean_curvature_variance();
        const double mean = corrected_mean_curvature(fit);
        if (std::isfinite(mean) && variance > 0 && variance < unbounded)
          candidates_.push_back(
            {step, r, mean, variance, fit.residual_sum_of_squares(fit_squared_heights) / (fit.size() - Fit::unknowns)});
      }
      if (!more)
        break;
    }
    if (noise_open)
      close_noise(2 * Noise_fit::unknowns);
    return noise_variance;
  }

  // The mean curvature of `fit` solved again without the curvature's own quartic
  // term where its moments reach it, as the fixed-radius fit gives it.
  template <typename Fit>
  static double corrected_mean_curvature(const Fit& fit)
  {
    if constexpr (Fit::quartic_moments) {
      Fit corrected = fit;
      corrected.subtract_curvature_quartic();
      return graph_mean_curvature<D>(corrected.hessian(), corrected.gradient());
    } else
      return graph_mean_curvature<D>(fit.hessian(), fit.gradient());
  }

  // The 1-ring fit's mean curvature variance per unit height variance, the vertex's own
  // height's included; infinite where the fit is not determined.
  double one_ring_variance(const Frame& frame) const
  {
    using Fit = Gradient_fit<D, 2>;
    Fit fit;
    const Sampling sampling{frame, 1, Sample_weights::uniform};
    const auto samples = [&](const auto& add) { samples_.template for_each_sample<Fit>(sampling, add); };
    samples([&](const Point& x, double height, double weight) { fit.add(x, height, weight); });
    if (!fit.solve(unbounded))
      return unbounded;
    const double own = fit.mean_curvature_variance();
    // l^T M^-1 X^T 1: the fit of unit heights.
    fit.solve_again([&](const auto& add) { samples([&](const Point& x, double, double w) { add(x, 1.0, w); }); });
    const double vertex = fit.hessian().trace() / D;
    return own + vertex * vertex;
  }

  // The same for the default fit with an intercept over the first ring (point sets),
  // the vertex one of its samples.
  double intercept_variance(const Frame& frame) const
  {
    const auto variance = [&](auto fit) {
      samples_.template for_each_sample<decltype(fit)>(
        Sampling{frame, 1, Sample_weights::uniform},
        [&](const Point& x, double height, double weight) { fit.add(x, height, weight); });
      return fit.solve(unbounded) ? fit.mean_curvature_variance() : unbounded;
    };
    return degree_ == 2   ? variance(Intercept_fit<D, 2>())
           : degree_ == 3 ? variance(Intercept_fit<D, 3>())
                          : variance(Intercept_fit<D, 4>());
  }

  Samples samples_;
  int degree_;
  bool intercept_;            // the default fit has an intercept
  std::vector<double> radii_; // in the mesh's units
  std::vector<Scale_candidate> candidates_;
};

} // namespace internal
} // namespace Curvature_estimation
} // namespace CGAL

#endif // CGAL_CURVATURE_ESTIMATION_INTERNAL_SCALE_SELECTOR_H
