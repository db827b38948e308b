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

  // The radius of the widest ball the fits at v gathered since the fitter moved to v (0: none).
  double widest_ball(Vertex v) { return this->samples_.neighborhood().widest_ball(v); }

  // Each fit below writes its estimate into `out`, not estimable on entry, and
  // returns what else it found.

  // The fit of the settings' degree in the frame of the given `normal` (any
  // length): Hamann's paraboloid at fit_degree 2 over rings.
  Vertex_fit fit(Vertex v, const Vector& normal, Estimate& out)
  {
    if (this->settings_.in_ball())
      return ball_fit(v, &normal, Vertex_normal_method::quadric_fit, this->settings_.ball_radius, out);
    Vertex_fit result;
    const double length = normal.norm();
    if (length > 0 && std::isfinite(length) && this->samples_.gather(v, 0)) {
      const Vector unit = normal / length;
      if (this->settings_.fits_intercept())
        intercept_fit(unit, out);
      else if (this->settings_.degree == 2)
        curvature_fit(start_paraboloid_attempts_[this->samples_.on_border()], unit, result, out);
      else
        degree_fit(unit, false, result, out);
    }
    finish(result);
    return result;
  }

  // The fit of the settings' degree with the normal estimated by `method`: at
  // fit_degree 2 over rings, that of degree_two_fit; at fit_degree 3 and 4 and in
  // a ball, in the frame of the first-order normal.
  Vertex_fit fit(Vertex v, Vertex_normal_method method, Estimate& out)
  {
    if (this->settings_.in_ball())
      return ball_fit(v, nullptr, method, this->settings_.ball_radius, out);
    Vertex_fit result;
    Vector normal;
    if (this->samples_.gather(v, 0)) {
      if (this->settings_.degree == 2 && !this->settings_.fits_intercept())
        degree_two_curvature(v, method, result, out);
      else if (this->samples_.first_order_normal(v, method, true, normal)) {
        if (this->settings_.fits_intercept())
          intercept_fit(normal, out);
        else
          degree_fit(normal, true, result, out);
      }
    }
    finish(result);
    return result;
  }

  // The fit of the settings' degree with an intercept over the ball of `radius` (mesh units, grown
  // as with ball_radius), in the frame of `normal` (any length), else of the first-order normal by `method`.
  Vertex_fit ball_fit(Vertex v, const Vector* normal, Vertex_normal_method method, double radius, Estimate& out)
  {
    Vertex_fit result;
    Vector unit;
    if (this->samples_.gather(v, radius) && this->samples_.unit_normal(v, normal, method, unit))
      this->ball_walk(unit, [&](auto& fit, const Sampling& sampling, int reach) {
        this->set_curvature_estimate(out, fit, sampling, reach, 1);
        return true;
      });
    finish(result, true);
    return result;
  }

  // The estimate of ball_fit, by value (the scale selection's, at the radius it chose).
  Estimate ball_estimate(Vertex v, const Vector* normal, Vertex_normal_method method, double radius)
  {
    Estimate e;
    ball_fit(v, normal, method, radius, e);
    return e;
  }

  // At fit_degree 2 over rings what fit(v, *normal, out), or fit(v, method, out)
  // where `normal` is null, gives at fit_degree 2: at fit_degree 3 and 4, for the
  // vertices whose own fit is refused.
  Vertex_fit degree_two_fit(Vertex v, const Vector* normal, Vertex_normal_method method, Estimate& out)
  {
    Vertex_fit result;
    const double length = normal != nullptr ? normal->norm() : 1.0;
    if (length > 0 && std::isfinite(length) && this->samples_.gather(v, this->settings_.ball_radius)) {
      if (normal != nullptr)
        curvature_fit(start_paraboloid_attempts_[this->samples_.on_border()], *normal / length, result, out);
      else
        degree_two_curvature(v, method, result, out);
    }
    finish(result);
    return result;
  }

  // The plane-frame fit (plane_frame_attempts), status fallback.
  void plane_frame_fit(Vertex v, Estimate& out)
  {
    Vector normal;
    if (!this->samples_.gather(v, this->settings_.ball_radius) ||
        !this->samples_.first_order_normal(v, Vertex_normal_method::quadric_fit, true, normal))
      return;
    this->walk(Fit_kinds<Fit_kind::intercept_2>(), plane_frame_attempts(this->settings_, this->samples_.on_border()),
               normal, [&](auto& fit, const Sampling& sampling, int) {
                 const Graph_curvature<N> curvature =
                   graph_curvature<N>(fit.hessian(), fit.gradient(), sampling.frame.tangents, sampling.frame.normal);
                 if (!Samples::all_finite(curvature.curvatures) || !Samples::all_finite(curvature.directions))
                   return false;
                 Neighborhood::set_estimate(out, Estimation_status::fallback, curvature, this->samples_.scale());
                 return true;
               });
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

  void finish(Vertex_fit& result, bool in_ball = false) const
  {
    result.on_border = this->samples_.on_border();
    result.neighbors = this->samples_.neighbors(in_ball);
  }

  // The curvature at fit_degree 2 over rings with the normal of estimate_normal:
  // the gradient fit's attempts at an interior vertex with the fitted normal,
  // then (or else) Hamann's; both start on the rings the normal's fit took where
  // only the whitened test accepted it. After gather(v).
  void degree_two_curvature(Vertex v, Vertex_normal_method method, Vertex_fit& result, Estimate& out)
  {
    Vector normal;
    const Acceptance normal_fit = estimate_normal(v, method, true, normal);
    if (!normal_fit)
      return;
    result.whitened = normal_fit.whitened;
    const bool border = this->samples_.on_border();
    const int first = normal_fit.whitened ? (std::min)(normal_fit.reach, this->settings_.max_rings) : start_rings();
    const bool from_start = first == this->settings_.start_rings(border);
    Fit_attempts other; // where the normal's fit started further out
    if (method == Vertex_normal_method::quadric_fit && !border) {
      if (!from_start)
        other = gradient_curvature_attempts(this->settings_, first);
      curvature_fit(from_start ? start_gradient_attempts_ : other, normal, result, out);
      if (out.status != Estimation_status::not_estimable)
        return;
    }
    if (!from_start)
      other = paraboloid_attempts(this->settings_, first);
    curvature_fit(from_start ? start_paraboloid_attempts_[border] : other, normal, result, out);
  }

  // The curvature of the first of `attempts` accepted in the frame of `normal`.
  void curvature_fit(const Fit_attempts& attempts, const Vector& normal, Vertex_fit& result, Estimate& out)
  {
    const Acceptance accepted =
      this->walk(Curvature_kinds(), attempts, normal, [&](auto& fit, const Sampling& sampling, int reach) {
        this->set_curvature_estimate(out, fit, sampling, reach, 1);
        return true;
      });
    result.whitened = result.whitened || accepted.whitened;
  }

  // fit_degree 3 or 4 over rings, in the frame of `normal` (first order at least).
  void degree_fit(const Vector& normal, bool estimated_normal, Vertex_fit& result, Estimate& out)
  {
    const int asked = first_rings_of_degree(this->settings_, this->samples_.on_border());
    const Acceptance accepted =
      this->walk(Degree_kinds(), degree_attempts(this->settings_, this->samples_.on_border(), estimated_normal), normal,
                 [&](auto& fit, const Sampling& sampling, int reach) {
                   this->set_curvature_estimate(out, fit, sampling, reach, asked);
                   return true;
                 });
    result.whitened = result.whitened || accepted.whitened;
  }

  // The fit of the settings' degree with an intercept over the rings, in the frame of `normal`.
  void intercept_fit(const Vector& normal, Estimate& out)
  {
    this->walk(Intercept_kinds(), ring_intercept_attempts(this->settings_), normal,
               [&](auto& fit, const Sampling& sampling, int reach) {
                 this->set_curvature_estimate(out, fit, sampling, reach, 1);
                 return true;
               });
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
