// SPDX-License-Identifier: GPL-3.0-or-later
// The Taylor fits at one vertex, written once for surfaces of R^3 (tangent
// dimension 2) and hypersurfaces of R^4 (tangent dimension 3): gather the
// neighborhood, express it in a frame, walk the attempts of fit_attempts.h, and
// read the curvature or the corrected normal off the first fit accepted.
//
// The Neighborhood policy is that of neighborhood_samples.h.
#ifndef CGAL_CURVATURE_ESTIMATION_INTERNAL_VERTEX_FITTER_H
#define CGAL_CURVATURE_ESTIMATION_INTERNAL_VERTEX_FITTER_H

#include <CGAL/Curvature_estimation/Principal_curvatures_and_directions.h>
#include <CGAL/Curvature_estimation/Vertex_normal_method.h>
#include <CGAL/Curvature_estimation/internal/ball.h>
#include <CGAL/Curvature_estimation/internal/fit_attempts.h>
#include <CGAL/Curvature_estimation/internal/fit_kinds.h>
#include <CGAL/Curvature_estimation/internal/fit_settings.h>
#include <CGAL/Curvature_estimation/internal/neighborhood_samples.h>
#include <CGAL/Curvature_estimation/internal/shape_operator.h>
#include <CGAL/Curvature_estimation/internal/taylor_fit/taylor_fit.h>

#include <Eigen/Core>

#include <cmath>
#include <cstddef>
#include <type_traits>
#include <utility>

namespace CGAL {
namespace Curvature_estimation {
namespace internal {

// What a fit at one vertex found, for the fallback chain (fallback_chain.h).
template <typename Estimate>
struct Vertex_fit
{
  Estimate estimate;         // not_estimable where no fit was accepted
  std::size_t neighbors = 0; // the neighbors gathered, on every ring reached or in the ball
  bool whitened = false;     // whether the whitened test accepted the fit or its normal's
  bool on_border = false;
};

template <typename Neighborhood>
class Vertex_fitter
{
public:
  using Samples = Neighborhood_samples<Neighborhood>;
  static constexpr int N = Samples::N;
  static constexpr int D = Samples::D;
  using Vertex = typename Samples::Vertex;
  using Vector = typename Samples::Vector;
  using Estimate = typename Neighborhood::Estimate;

  Vertex_fitter(Neighborhood neighborhood, const Fit_settings& settings)
      : samples_(std::move(neighborhood))
      , settings_(settings)
      , normal_attempts_{normal_attempts(settings, false), normal_attempts(settings, true)}
      , start_gradient_attempts_(gradient_curvature_attempts(settings, settings.start_rings(false)))
      , start_paraboloid_attempts_{paraboloid_attempts(settings, settings.start_rings(false)),
                                   paraboloid_attempts(settings, settings.start_rings(true))}
  {}

  const Fit_settings& settings() const { return settings_; }

  // The fit of the settings' degree in the frame of the given `normal` (any
  // length): Hamann's paraboloid at fit_degree 2 over rings.
  Vertex_fit<Estimate> fit(Vertex v, const Vector& normal)
  {
    if (settings_.in_ball())
      return ball_fit(v, &normal, Vertex_normal_method::quadric_fit, settings_.ball_radius);
    Vertex_fit<Estimate> result;
    const double length = normal.norm();
    if (!(length > 0) || !std::isfinite(length) || !samples_.gather(v, 0))
      return finished(result);
    const Vector unit = normal / length;
    if (settings_.fits_intercept())
      result.estimate = intercept_fit(unit);
    else if (settings_.degree == 2)
      result.estimate = curvature_fit(start_paraboloid_attempts_[samples_.on_border()], unit, result);
    else
      result.estimate = degree_fit(unit, false, result);
    return finished(result);
  }

  // The fit of the settings' degree with the normal estimated by `method`: at
  // fit_degree 2 over rings, that of degree_two_fit; at fit_degree 3 and 4 and in
  // a ball, in the frame of the first-order normal.
  Vertex_fit<Estimate> fit(Vertex v, Vertex_normal_method method)
  {
    if (settings_.in_ball())
      return ball_fit(v, nullptr, method, settings_.ball_radius);
    Vertex_fit<Estimate> result;
    if (!samples_.gather(v, 0))
      return finished(result);
    if (settings_.degree == 2 && !settings_.fits_intercept())
      result.estimate = degree_two_curvature(v, method, result);
    else {
      Vector normal;
      if (samples_.first_order_normal(v, method, true, normal))
        result.estimate = settings_.fits_intercept() ? intercept_fit(normal) : degree_fit(normal, true, result);
    }
    return finished(result);
  }

  // The fit of the settings' degree over the ball of `radius` (in the mesh's
  // units, grown as with ball_radius) in the frame of `normal` (any length) where
  // given, else of the first-order normal by `method`.
  Vertex_fit<Estimate> ball_fit(Vertex v, const Vector* normal, Vertex_normal_method method, double radius)
  {
    Vertex_fit<Estimate> result;
    Vector unit;
    if (samples_.gather(v, radius) && samples_.unit_normal(v, normal, method, unit))
      result.estimate = intercept_fit(unit);
    return finished(result, true);
  }

  // At fit_degree 2 over rings what fit(v, *normal), or fit(v, method) where
  // `normal` is null, gives at fit_degree 2: at fit_degree 3 and 4, for the
  // vertices whose own fit is refused.
  Vertex_fit<Estimate> degree_two_fit(Vertex v, const Vector* normal, Vertex_normal_method method)
  {
    Vertex_fit<Estimate> result;
    const double length = normal != nullptr ? normal->norm() : 1.0;
    if (!(length > 0) || !std::isfinite(length) || !samples_.gather(v, settings_.ball_radius))
      return finished(result);
    result.estimate = normal != nullptr
                        ? curvature_fit(start_paraboloid_attempts_[samples_.on_border()], *normal / length, result)
                        : degree_two_curvature(v, method, result);
    return finished(result);
  }

  // The plane-frame fit (plane_frame_attempts), status fallback.
  Estimate plane_frame_fit(Vertex v)
  {
    Vector normal;
    Estimate estimate;
    if (!samples_.gather(v, settings_.ball_radius) ||
        !samples_.first_order_normal(v, Vertex_normal_method::quadric_fit, true, normal))
      return estimate;
    walk(Fit_kinds<Fit_kind::intercept_2>(), plane_frame_attempts(settings_, samples_.on_border()), normal,
         [&](auto& fit, const Sampling& sampling, int) {
           const Graph_curvature<N> curvature =
             graph_curvature<N>(fit.hessian(), fit.gradient(), sampling.frame.tangents, sampling.frame.normal);
           if (!Samples::all_finite(curvature.curvatures) || !Samples::all_finite(curvature.directions))
             return false;
           estimate = Neighborhood::estimate(Estimation_status::fallback, curvature, samples_.scale());
           return true;
         });
    return estimate;
  }

  // The unit normal by `method`; false where there is none. With quadric_fit: at
  // fit_degree 2 that of estimate_normal; at 3 and 4 the first-order normal
  // corrected by the gradient of the fit of that degree (where that is refused,
  // as at degree 2); in a ball, by the gradient of the fit over the ball.
  bool normal(Vertex v, Vertex_normal_method method, Vector& normal)
  {
    const bool gathered = Neighborhood::gathers_for_normal(method);
    if (gathered && !samples_.gather(v, settings_.ball_radius))
      return false;
    if (method == Vertex_normal_method::quadric_fit && (settings_.in_ball() || settings_.degree != 2)) {
      if (!samples_.first_order_normal(v, method, gathered, normal))
        return false;
      bool corrected = false;
      const auto correct = [&](auto& fit, const Sampling& sampling, int) {
        corrected = corrected_normal(sampling.frame, fit.gradient(), normal);
        return true;
      };
      if (settings_.in_ball()) {
        ball_walk(normal, correct);
        return corrected;
      }
      if (walk(Degree_kinds(), degree_attempts(settings_, samples_.on_border(), true), normal, correct) && corrected)
        return true;
    }
    return estimate_normal(v, method, gathered, normal).reach != 0;
  }

private:
  using Frame = typename Samples::Frame;
  using Sampling = typename Samples::Sampling;

  // How far an accepted fit reached (its rings, or 1 + the growths of its ball;
  // 0 where none was accepted), and whether the whitened test accepted it.
  struct Acceptance
  {
    int reach = 0;
    bool whitened = false;
    explicit operator bool() const { return reach != 0; }
  };

  using Curvature_kinds = Fit_kinds<Fit_kind::paraboloid, Fit_kind::gradient_2, Fit_kind::gradient_3>;
  using Normal_kinds = Fit_kinds<Fit_kind::gradient_2, Fit_kind::gradient_3>;
  using Degree_kinds =
    std::conditional_t<D == 2, Fit_kinds<Fit_kind::gradient_3, Fit_kind::gradient_4>, Fit_kinds<Fit_kind::gradient_3>>;
  using Intercept_kinds =
    std::conditional_t<D == 2, Fit_kinds<Fit_kind::intercept_2, Fit_kind::intercept_3, Fit_kind::intercept_4>,
                       Fit_kinds<Fit_kind::intercept_2, Fit_kind::intercept_3>>;

  int start_rings() const { return settings_.start_rings(samples_.on_border()); }

  Vertex_fit<Estimate>& finished(Vertex_fit<Estimate>& result, bool in_ball = false) const
  {
    result.on_border = samples_.on_border();
    result.neighbors = samples_.neighbors(in_ball);
    return result;
  }

  // The curvature at fit_degree 2 over rings with the normal of estimate_normal:
  // the gradient fit's attempts at an interior vertex with the fitted normal,
  // then (or else) Hamann's; both start on the rings the normal's fit took where
  // only the whitened test accepted it. After gather(v).
  Estimate degree_two_curvature(Vertex v, Vertex_normal_method method, Vertex_fit<Estimate>& result)
  {
    Vector normal;
    const Acceptance normal_fit = estimate_normal(v, method, true, normal);
    if (!normal_fit)
      return Estimate();
    result.whitened = normal_fit.whitened;
    const bool border = samples_.on_border();
    const int first = normal_fit.whitened ? (std::min)(normal_fit.reach, settings_.max_rings) : start_rings();
    const bool from_start = first == settings_.start_rings(border);
    Fit_attempts other; // where the normal's fit started further out
    if (method == Vertex_normal_method::quadric_fit && !border) {
      if (!from_start)
        other = gradient_curvature_attempts(settings_, first);
      const Estimate estimate = curvature_fit(from_start ? start_gradient_attempts_ : other, normal, result);
      if (estimate.status != Estimation_status::not_estimable)
        return estimate;
    }
    if (!from_start)
      other = paraboloid_attempts(settings_, first);
    return curvature_fit(from_start ? start_paraboloid_attempts_[border] : other, normal, result);
  }

  // The curvature of the first of `attempts` accepted in the frame of `normal`.
  Estimate curvature_fit(const Fit_attempts& attempts, const Vector& normal, Vertex_fit<Estimate>& result)
  {
    Estimate estimate;
    const Acceptance accepted =
      walk(Curvature_kinds(), attempts, normal, [&](auto& fit, const Sampling& sampling, int reach) {
        estimate = curvature_estimate(fit, sampling, reach, 1);
        return true;
      });
    result.whitened = result.whitened || accepted.whitened;
    return estimate;
  }

  // fit_degree 3 or 4 over rings, in the frame of `normal` (first order at least).
  Estimate degree_fit(const Vector& normal, bool estimated_normal, Vertex_fit<Estimate>& result)
  {
    Estimate estimate;
    const int asked = first_rings_of_degree(settings_, samples_.on_border());
    const Acceptance accepted = walk(Degree_kinds(), degree_attempts(settings_, samples_.on_border(), estimated_normal),
                                     normal, [&](auto& fit, const Sampling& sampling, int reach) {
                                       estimate = curvature_estimate(fit, sampling, reach, asked);
                                       return true;
                                     });
    result.whitened = result.whitened || accepted.whitened;
    return estimate;
  }

  // The fit of the settings' degree with an intercept over the ball or the rings, in the frame of `normal`.
  Estimate intercept_fit(const Vector& normal)
  {
    Estimate estimate;
    const auto use = [&](auto& fit, const Sampling& sampling, int reach) {
      estimate = curvature_estimate(fit, sampling, reach, 1);
      return true;
    };
    if (settings_.in_ball())
      ball_walk(normal, use);
    else
      walk(Intercept_kinds(), ring_intercept_attempts(settings_), normal, use);
    return estimate;
  }

  // The neighborhood's first-order normal, or for quadric_fit that normal
  // corrected by the gradient of the first of normal_attempts accepted; the
  // acceptance of that fit (reach 1 for the other methods), 0 where there is none.
  // `gathered`: whether gather(v) has succeeded.
  Acceptance estimate_normal(Vertex v, Vertex_normal_method method, bool gathered, Vector& normal)
  {
    if (!samples_.first_order_normal(v, method, gathered, normal))
      return {};
    if (method != Vertex_normal_method::quadric_fit)
      return {1, false};
    const Vector first = normal;
    const Acceptance fitted = fit_normal(normal);
    if (fitted || !Neighborhood::restart_from_hyperplane)
      return fitted;
    // Start again from the normal of the best-fitting hyperplane through the
    // 1-ring, oriented as the first one (see Tetrahedral_neighborhood).
    normal = samples_.one_ring_hyperplane_normal();
    if (normal.dot(first) < 0)
      normal = -normal;
    return Samples::all_finite(normal) ? fit_normal(normal) : Acceptance();
  }

  Acceptance fit_normal(Vector& normal)
  {
    bool corrected = false;
    const Acceptance accepted = walk(Normal_kinds(), normal_attempts_[samples_.on_border()], normal,
                                     [&](auto& fit, const Sampling& sampling, int) {
                                       corrected = corrected_normal(sampling.frame, fit.gradient(), normal);
                                       return true;
                                     });
    return corrected ? accepted : Acceptance();
  }

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
      with_fit<D>(kinds, attempt.fit, [&](auto& fit) { accepted = try_attempt(attempt, normal_frame, fit, use); });
      if (accepted)
        return accepted;
    }
    return {};
  }

  template <typename Fit, typename Use>
  Acceptance try_attempt(const Fit_attempt& attempt, const Frame& normal_frame, Fit& fit, const Use& use)
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

  // The estimate from an accepted fit (status widened where `reach` is more than
  // `asked`); on surfaces, a fit with the gradient and no quartic terms is first
  // solved again without the curvature's own quartic term.
  template <typename Fit>
  Estimate curvature_estimate(Fit& fit, const Sampling& sampling, int reach, int asked) const
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
      return Estimate();
    return Neighborhood::estimate(reach > asked ? Estimation_status::widened : Estimation_status::ok, curvature,
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
  // The attempts of the default's every vertex, made once: interior, border.
  Fit_attempts normal_attempts_[2];
  Fit_attempts start_gradient_attempts_; // interior vertices only
  Fit_attempts start_paraboloid_attempts_[2];
};

} // namespace internal
} // namespace Curvature_estimation
} // namespace CGAL

#endif // CGAL_CURVATURE_ESTIMATION_INTERNAL_VERTEX_FITTER_H
