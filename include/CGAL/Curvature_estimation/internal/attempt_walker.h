// SPDX-License-Identifier: GPL-3.0-or-later
// Walking a table of fit attempts (fit_attempts.h) at one vertex, over rings or
// a growing ball, and reading an estimate off the fit accepted: the part of
// Vertex_fitter (vertex_fitter.h) that knows no estimator's policy.
#ifndef CGAL_CURVATURE_ESTIMATION_INTERNAL_ATTEMPT_WALKER_H
#define CGAL_CURVATURE_ESTIMATION_INTERNAL_ATTEMPT_WALKER_H

#include <CGAL/Curvature_estimation/Principal_curvatures_and_directions.h>
#include <CGAL/Curvature_estimation/internal/ball.h>
#include <CGAL/Curvature_estimation/internal/fit_attempts.h>
#include <CGAL/Curvature_estimation/internal/fit_kinds.h>
#include <CGAL/Curvature_estimation/internal/fit_settings.h>
#include <CGAL/Curvature_estimation/internal/neighborhood_samples.h>
#include <CGAL/Curvature_estimation/internal/shape_operator.h>
#include <CGAL/Curvature_estimation/internal/taylor_fit/taylor_fit.h>

#include <Eigen/Core>

#include <type_traits>
#include <utility>

namespace CGAL {
namespace Curvature_estimation {
namespace internal {

template <typename Neighborhood>
class Attempt_walker
{
public:
  using Samples = Neighborhood_samples<Neighborhood>;
  static constexpr int N = Samples::N;
  static constexpr int D = Samples::D;
  using Vector = typename Samples::Vector;
  using Estimate = typename Neighborhood::Estimate;
  using Frame = typename Samples::Frame;
  using Sampling = typename Samples::Sampling;

  Attempt_walker(Neighborhood neighborhood, const Fit_settings& settings)
      : samples_(std::move(neighborhood))
      , settings_(settings)
  {}

protected:
  // How far an accepted fit reached (its rings, or 1 + the growths of its ball;
  // 0 where none was accepted), and whether the whitened test accepted it.
  struct Acceptance
  {
    int reach = 0;
    bool whitened = false;
    explicit operator bool() const { return reach != 0; }
  };

  using Intercept_kinds =
    std::conditional_t<D == 2, Fit_kinds<Fit_kind::intercept_2, Fit_kind::intercept_3, Fit_kind::intercept_4>,
                       Fit_kinds<Fit_kind::intercept_2, Fit_kind::intercept_3>>;

  static bool corrected_normal(const Frame& frame, const Eigen::Matrix<double, D, 1>& gradient, Vector& normal)
  {
    normal = (frame.normal - frame.tangents * gradient).normalized();
    return Samples::all_finite(normal);
  }

  // Walks `attempts` (of the fits `kinds`) in order, starting in the frame of
  // `normal`: at each ring of an attempt under the scaled test, at the widest ring
  // reached under the whitened one, a fit, until one is accepted and
  // use(fit, sampling, reach) takes it (false: the walk goes on as if refused).
  template <typename Kinds, typename Use>
  Acceptance walk(Kinds kinds, const Fit_attempts& attempts, const Vector& normal, const Use& use)
  {
    const Frame normal_frame = Samples::frame_of(normal);
    for (const Fit_attempt& attempt : attempts) {
      Acceptance accepted;
      with_fit<D>(kinds, attempt.fit, [&](auto& fit) {
        using Fit = std::remove_reference_t<decltype(fit)>;
        const Fit_use<Fit> erased{&use, [](const void* u, Fit& f, const Sampling& s, int reach) {
                                    return (*static_cast<const Use*>(u))(f, s, reach);
                                  }};
        accepted = try_attempt(attempt, normal_frame, fit, erased);
      });
      if (accepted)
        return accepted;
    }
    return {};
  }

  // A `use` of walk without its type: one try_attempt per fit, whatever the
  // caller (each copy of its loops and solves costs instruction cache).
  template <typename Fit>
  struct Fit_use
  {
    const void* use;
    bool (*call)(const void*, Fit&, const Sampling&, int);
    bool operator()(Fit& fit, const Sampling& sampling, int reach) const { return call(use, fit, sampling, reach); }
  };

  template <typename Fit>
  Acceptance try_attempt(const Fit_attempt& attempt, const Frame& normal_frame, Fit& fit, const Fit_use<Fit>& use)
  {
    if (attempt.test == Condition_test::whitened) {
      int widest = 0;
      for (int rings = attempt.first_rings; rings <= attempt.last_rings && samples_.reach(rings); ++rings)
        widest = rings;
      const Sampling sampling{normal_frame, widest, attempt.weights};
      const auto samples = [&](const auto& add) { samples_.template for_each_sample<Fit>(sampling, add); };
      if (widest == 0 || !fit.solve_whitened(attempt.max_condition, samples) || !use(fit, sampling, widest))
        return {};
      return {widest, true};
    }
    for (int rings = attempt.first_rings; rings <= attempt.last_rings && samples_.reach(rings); ++rings) {
      Sampling sampling{normal_frame, rings, attempt.weights};
      if (attempt.frame == Frame_choice::plane && !samples_.plane_frame(rings, sampling.frame))
        continue;
      if (fit_in_frame(fit, sampling, attempt.max_condition) && use(fit, sampling, rings))
        return {rings, false};
    }
    return {};
  }

  // The fit over the ball of radius ball_radius, at each radius it grows to
  // (fit_in_growing_ball) under ball_attempts' tests, in the frame of `normal`;
  // use(fit, sampling, reach) takes the first accepted.
  template <typename Use>
  void ball_walk(const Vector& normal, const Use& use)
  {
    const Fit_attempts attempts = ball_attempts(settings_);
    const Sampling sampling{Samples::frame_of(normal), 0, attempts.begin()->weights};
    with_fit<D>(Intercept_kinds(), attempts.begin()->fit, [&](auto& fit) {
      using Fit = std::remove_reference_t<decltype(fit)>;
      const auto accepted = [&] {
        for (const Fit_attempt& attempt : attempts) {
          const auto samples = [&](const auto& add) { samples_.template for_each_sample<Fit>(sampling, add); };
          if (attempt.test == Condition_test::scaled ? fit_in_frame(fit, sampling, attempt.max_condition)
                                                     : fit.solve_whitened(attempt.max_condition, samples))
            return true;
        }
        return false;
      };
      const int reach = fit_in_growing_ball(
        1.0, Fit::unknowns, [&](double radius) { return samples_.reach_ball(radius); },
        [&] { return samples_.neighborhood().ball_size(); }, accepted);
      if (reach != 0)
        use(fit, sampling, reach);
    });
  }

  // Sets `e` to the estimate from an accepted fit (status widened where `reach` is
  // more than `asked`; not estimable where the curvature is not finite); on
  // surfaces, a fit with the gradient and no quartic terms is first solved again
  // without the curvature's own quartic term.
  template <typename Fit>
  void set_curvature_estimate(Estimate& e, Fit& fit, const Sampling& sampling, int reach, int asked) const
  {
    if constexpr (Fit::quartic_moments)
      fit.subtract_curvature_quartic();
    else if constexpr (D == 2 && Fit::linear_terms && Fit::last_order < 4) {
      const Eigen::Matrix<double, D, D> first_hessian = fit.hessian();
      fit.solve_again([&](const auto& add) {
        samples_.template for_each_sample<Fit>(sampling, [&](const auto& x, double height, double weight) {
          add(x, height - curvature_quartic<D>(first_hessian, x), weight);
        });
      });
    }
    const Graph_curvature<N> curvature =
      graph_curvature<N>(fit.hessian(), fit.gradient(), sampling.frame.tangents, sampling.frame.normal);
    if (!Samples::all_finite(curvature.curvatures) || !Samples::all_finite(curvature.directions))
      e = Estimate();
    else
      Neighborhood::set_estimate(e, reach > asked ? Estimation_status::widened : Estimation_status::ok, curvature,
                                 samples_.scale());
  }

  template <typename Fit>
  CGAL_CURVATURE_ESTIMATION_INLINE bool fit_in_frame(Fit& fit, const Sampling& sampling, double max_condition) const
  {
    fit.clear();
    samples_.template for_each_sample<Fit>(
      sampling, [&](const auto& x, double height, double weight) { fit.add(x, height, weight); });
    return fit.solve(max_condition);
  }

  Samples samples_;
  Fit_settings settings_;
};

} // namespace internal
} // namespace Curvature_estimation
} // namespace CGAL

#endif // CGAL_CURVATURE_ESTIMATION_INTERNAL_ATTEMPT_WALKER_H
