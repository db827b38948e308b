// SPDX-License-Identifier: GPL-3.0-or-later
// The Taylor fits at one vertex, written once for surfaces of R^3 (tangent
// dimension 2) and hypersurfaces of R^4 (tangent dimension 3): gather the
// neighborhood, express it in a frame, walk the attempts of fit_attempts.h, and
// read the curvature or the corrected normal off the first fit accepted. The
// Neighborhood policy is that of neighborhood_samples.h.
#ifndef CGAL_CURVATURE_ESTIMATION_INTERNAL_VERTEX_FITTER_H
#define CGAL_CURVATURE_ESTIMATION_INTERNAL_VERTEX_FITTER_H

#include <CGAL/Curvature_estimation/Principal_curvatures_and_directions.h>
#include <CGAL/Curvature_estimation/Vertex_normal_method.h>
#include <CGAL/Curvature_estimation/internal/attempt_walker.h>
#include <CGAL/Curvature_estimation/internal/fallback_chain.h>
#include <CGAL/Curvature_estimation/internal/fit_attempts.h>
#include <CGAL/Curvature_estimation/internal/fit_kinds.h>
#include <CGAL/Curvature_estimation/internal/fit_settings.h>
#include <CGAL/Curvature_estimation/internal/neighborhood_samples.h>
#include <CGAL/Curvature_estimation/internal/shape_operator.h>
#include <CGAL/Curvature_estimation/internal/taylor_fit/taylor_fit.h>

#include <Eigen/Core>

#include <cmath>
#include <type_traits>
#include <utility>

namespace CGAL {
namespace Curvature_estimation {
namespace internal {

template <typename Neighborhood>
class Vertex_fitter : private Attempt_walker<Neighborhood>
{
  using Walker = Attempt_walker<Neighborhood>;
  using typename Walker::Acceptance;
  using typename Walker::Frame;
  using typename Walker::Intercept_kinds;
  using typename Walker::Sampling;

public:
  using typename Walker::Estimate;
  using typename Walker::Samples;
  using typename Walker::Vector;
  static constexpr int N = Samples::N;
  static constexpr int D = Samples::D;
  using Vertex = typename Samples::Vertex;

  Vertex_fitter(Neighborhood neighborhood, const Fit_settings& settings)
      : Walker(std::move(neighborhood), settings)
      , normal_attempts_{normal_attempts(settings, false), normal_attempts(settings, true)}
      , start_gradient_attempts_(gradient_curvature_attempts(settings, settings.start_rings(false)))
      , start_paraboloid_attempts_{paraboloid_attempts(settings, settings.start_rings(false)),
                                   paraboloid_attempts(settings, settings.start_rings(true))}
  {}

  const Fit_settings& settings() const { return this->settings_; }

  // The fit of the settings' degree in the frame of the given `normal` (any
  // length): Hamann's paraboloid at fit_degree 2 over rings.
  Vertex_fit<Estimate> fit(Vertex v, const Vector& normal)
  {
    if (this->settings_.in_ball())
      return ball_fit(v, &normal, Vertex_normal_method::quadric_fit, this->settings_.ball_radius);
    Vertex_fit<Estimate> result;
    const double length = normal.norm();
    if (!(length > 0) || !std::isfinite(length) || !this->samples_.gather(v, 0))
      return finished(result);
    const Vector unit = normal / length;
    if (this->settings_.fits_intercept())
      result.estimate = intercept_fit(unit);
    else if (this->settings_.degree == 2)
      result.estimate = curvature_fit(start_paraboloid_attempts_[this->samples_.on_border()], unit, result);
    else
      result.estimate = degree_fit(unit, false, result);
    return finished(result);
  }

  // The fit of the settings' degree with the normal estimated by `method`: at
  // fit_degree 2 over rings, that of degree_two_fit; at fit_degree 3 and 4 and in
  // a ball, in the frame of the first-order normal.
  Vertex_fit<Estimate> fit(Vertex v, Vertex_normal_method method)
  {
    if (this->settings_.in_ball())
      return ball_fit(v, nullptr, method, this->settings_.ball_radius);
    Vertex_fit<Estimate> result;
    if (!this->samples_.gather(v, 0))
      return finished(result);
    if (this->settings_.degree == 2 && !this->settings_.fits_intercept())
      result.estimate = degree_two_curvature(v, method, result);
    else {
      Vector normal;
      if (this->samples_.first_order_normal(v, method, true, normal))
        result.estimate = this->settings_.fits_intercept() ? intercept_fit(normal) : degree_fit(normal, true, result);
    }
    return finished(result);
  }

  // The fit of the settings' degree with an intercept over the ball of `radius` (mesh units, grown
  // as with ball_radius), in the frame of `normal` (any length), else of the first-order normal by `method`.
  Vertex_fit<Estimate> ball_fit(Vertex v, const Vector* normal, Vertex_normal_method method, double radius)
  {
    Vertex_fit<Estimate> result;
    Vector unit;
    if (this->samples_.gather(v, radius) && this->samples_.unit_normal(v, normal, method, unit))
      this->ball_walk(unit, [&](auto& fit, const Sampling& sampling, int reach) {
        result.estimate = this->curvature_estimate(fit, sampling, reach, 1);
        return true;
      });
    return finished(result, true);
  }

  // At fit_degree 2 over rings what fit(v, *normal), or fit(v, method) where
  // `normal` is null, gives at fit_degree 2: at fit_degree 3 and 4, for the
  // vertices whose own fit is refused.
  Vertex_fit<Estimate> degree_two_fit(Vertex v, const Vector* normal, Vertex_normal_method method)
  {
    Vertex_fit<Estimate> result;
    const double length = normal != nullptr ? normal->norm() : 1.0;
    if (!(length > 0) || !std::isfinite(length) || !this->samples_.gather(v, this->settings_.ball_radius))
      return finished(result);
    result.estimate = normal != nullptr ? curvature_fit(start_paraboloid_attempts_[this->samples_.on_border()],
                                                        *normal / length, result)
                                        : degree_two_curvature(v, method, result);
    return finished(result);
  }

  // The plane-frame fit (plane_frame_attempts), status fallback.
  Estimate plane_frame_fit(Vertex v)
  {
    Vector normal;
    Estimate estimate;
    if (!this->samples_.gather(v, this->settings_.ball_radius) ||
        !this->samples_.first_order_normal(v, Vertex_normal_method::quadric_fit, true, normal))
      return estimate;
    this->walk(Fit_kinds<Fit_kind::intercept_2>(), plane_frame_attempts(this->settings_, this->samples_.on_border()),
               normal, [&](auto& fit, const Sampling& sampling, int) {
                 const Graph_curvature<N> curvature =
                   graph_curvature<N>(fit.hessian(), fit.gradient(), sampling.frame.tangents, sampling.frame.normal);
                 if (!Samples::all_finite(curvature.curvatures) || !Samples::all_finite(curvature.directions))
                   return false;
                 estimate = Neighborhood::estimate(Estimation_status::fallback, curvature, this->samples_.scale());
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
    if (gathered && !this->samples_.gather(v, this->settings_.ball_radius))
      return false;
    if (method == Vertex_normal_method::quadric_fit && (this->settings_.in_ball() || this->settings_.degree != 2)) {
      if (!this->samples_.first_order_normal(v, method, gathered, normal))
        return false;
      bool corrected = false;
      const auto correct = [&](auto& fit, const Sampling& sampling, int) {
        corrected = Walker::corrected_normal(sampling.frame, fit.gradient(), normal);
        return true;
      };
      if (this->settings_.in_ball()) {
        this->ball_walk(normal, correct);
        return corrected;
      }
      if (this->walk(Degree_kinds(), degree_attempts(this->settings_, this->samples_.on_border(), true), normal,
                     correct) &&
          corrected)
        return true;
    }
    return estimate_normal(v, method, gathered, normal).reach != 0;
  }

private:
  using Curvature_kinds = Fit_kinds<Fit_kind::paraboloid, Fit_kind::gradient_2, Fit_kind::gradient_3>;
  using Normal_kinds = Fit_kinds<Fit_kind::gradient_2, Fit_kind::gradient_3>;
  using Degree_kinds =
    std::conditional_t<D == 2, Fit_kinds<Fit_kind::gradient_3, Fit_kind::gradient_4>, Fit_kinds<Fit_kind::gradient_3>>;
  int start_rings() const { return this->settings_.start_rings(this->samples_.on_border()); }

  Vertex_fit<Estimate>& finished(Vertex_fit<Estimate>& result, bool in_ball = false) const
  {
    result.on_border = this->samples_.on_border();
    result.neighbors = this->samples_.neighbors(in_ball);
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
    const bool border = this->samples_.on_border();
    const int first = normal_fit.whitened ? (std::min)(normal_fit.reach, this->settings_.max_rings) : start_rings();
    const bool from_start = first == this->settings_.start_rings(border);
    Fit_attempts other; // where the normal's fit started further out
    if (method == Vertex_normal_method::quadric_fit && !border) {
      if (!from_start)
        other = gradient_curvature_attempts(this->settings_, first);
      const Estimate estimate = curvature_fit(from_start ? start_gradient_attempts_ : other, normal, result);
      if (estimate.status != Estimation_status::not_estimable)
        return estimate;
    }
    if (!from_start)
      other = paraboloid_attempts(this->settings_, first);
    return curvature_fit(from_start ? start_paraboloid_attempts_[border] : other, normal, result);
  }

  // The curvature of the first of `attempts` accepted in the frame of `normal`.
  Estimate curvature_fit(const Fit_attempts& attempts, const Vector& normal, Vertex_fit<Estimate>& result)
  {
    Estimate estimate;
    const Acceptance accepted =
      this->walk(Curvature_kinds(), attempts, normal, [&](auto& fit, const Sampling& sampling, int reach) {
        estimate = this->curvature_estimate(fit, sampling, reach, 1);
        return true;
      });
    result.whitened = result.whitened || accepted.whitened;
    return estimate;
  }

  // fit_degree 3 or 4 over rings, in the frame of `normal` (first order at least).
  Estimate degree_fit(const Vector& normal, bool estimated_normal, Vertex_fit<Estimate>& result)
  {
    Estimate estimate;
    const int asked = first_rings_of_degree(this->settings_, this->samples_.on_border());
    const Acceptance accepted =
      this->walk(Degree_kinds(), degree_attempts(this->settings_, this->samples_.on_border(), estimated_normal), normal,
                 [&](auto& fit, const Sampling& sampling, int reach) {
                   estimate = this->curvature_estimate(fit, sampling, reach, asked);
                   return true;
                 });
    result.whitened = result.whitened || accepted.whitened;
    return estimate;
  }

  // The fit of the settings' degree with an intercept over the rings, in the frame of `normal`.
  Estimate intercept_fit(const Vector& normal)
  {
    Estimate estimate;
    this->walk(Intercept_kinds(), ring_intercept_attempts(this->settings_), normal,
               [&](auto& fit, const Sampling& sampling, int reach) {
                 estimate = this->curvature_estimate(fit, sampling, reach, 1);
                 return true;
               });
    return estimate;
  }

  // The neighborhood's first-order normal, or for quadric_fit that normal
  // corrected by the gradient of the first of normal_attempts accepted; the
  // acceptance of that fit (reach 1 for the other methods), 0 where there is none.
  // `gathered`: whether gather(v) has succeeded.
  Acceptance estimate_normal(Vertex v, Vertex_normal_method method, bool gathered, Vector& normal)
  {
    if (!this->samples_.first_order_normal(v, method, gathered, normal))
      return {};
    if (method != Vertex_normal_method::quadric_fit)
      return {1, false};
    const Vector first = normal;
    const Acceptance fitted = fit_normal(normal);
    if (fitted || !Neighborhood::restart_from_hyperplane)
      return fitted;
    // Start again from the normal of the best-fitting hyperplane through the
    // 1-ring, oriented as the first one (see Tetrahedral_neighborhood).
    normal = this->samples_.one_ring_hyperplane_normal();
    if (normal.dot(first) < 0)
      normal = -normal;
    return Samples::all_finite(normal) ? fit_normal(normal) : Acceptance();
  }

  Acceptance fit_normal(Vector& normal)
  {
    bool corrected = false;
    const Acceptance accepted = this->walk(Normal_kinds(), normal_attempts_[this->samples_.on_border()], normal,
                                           [&](auto& fit, const Sampling& sampling, int) {
                                             corrected =
                                               Walker::corrected_normal(sampling.frame, fit.gradient(), normal);
                                             return true;
                                           });
    return corrected ? accepted : Acceptance();
  }

  Fit_attempts normal_attempts_[2];      // made once, as the two below: [interior, border]
  Fit_attempts start_gradient_attempts_; // interior vertices only
  Fit_attempts start_paraboloid_attempts_[2];
};

} // namespace internal
} // namespace Curvature_estimation
} // namespace CGAL

#endif // CGAL_CURVATURE_ESTIMATION_INTERNAL_VERTEX_FITTER_H
