// SPDX-License-Identifier: GPL-3.0-or-later
// CGAL's jet fitting (Monge_via_jet_fitting, Cazals and Pouget) behind this
// package's interface, neighborhoods and conventions, for like-for-like comparisons.
#ifndef CGAL_CURVATURE_ESTIMATION_JET_FITTING_H
#define CGAL_CURVATURE_ESTIMATION_JET_FITTING_H

#include <CGAL/Curvature_estimation/Principal_curvatures_and_directions.h>
#include <CGAL/Curvature_estimation/internal/estimate_at_vertices.h>
#include <CGAL/Curvature_estimation/internal/face_average_normal.h>
#include <CGAL/Curvature_estimation/internal/fallback_chain.h>
#include <CGAL/Curvature_estimation/internal/rings.h>
#include <CGAL/Curvature_estimation/internal/surface_estimate.h>
#include <CGAL/Curvature_estimation/paraboloid_fitting.h>
#include <CGAL/Curvature_estimation/parameters.h>

#include <CGAL/Monge_via_jet_fitting.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/tags.h>

#include <boost/graph/graph_traits.hpp>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#ifndef CGAL_EIGEN3_ENABLED
#error "jet_fitting_curvatures needs CGAL's Eigen support (link CGAL::Eigen3_support)"
#endif

namespace CGAL {
namespace Curvature_estimation {
namespace internal {

// CGAL's jet fit at one vertex with its fallback chain; one copy per thread
// holds the reusable point buffer.
template <typename FaceGraph, typename VertexPointMap>
class Jet_fitter
{
public:
  using vertex_descriptor = typename boost::graph_traits<FaceGraph>::vertex_descriptor;
  using Local_kernel = CGAL::Simple_cartesian<double>;
  using Monge_fitting = CGAL::Monge_via_jet_fitting<Local_kernel>;

  // `radius_range`: where given, the scale selection's (and no ball_radius).
  Jet_fitter(const FaceGraph& g, VertexPointMap vpm, int jet_degree, int monge_degree, int rings, int max_rings,
             double max_condition, double ball_radius, bool use_fallbacks = true,
             const Radius_range& radius_range = Radius_range())
      : g_(&g)
      , vpm_(vpm)
      , jet_degree_(jet_degree)
      , monge_degree_(monge_degree)
      , rings_(rings)
      , max_rings_(max_rings)
      , max_condition_(max_condition)
      , ball_radius_(ball_radius)
      , use_fallbacks_(use_fallbacks)
      , paraboloid_(g, vpm, Fit_parameters{Fit_settings(), Vertex_normal_method::quadric_fit})
  {
    if (radius_range.given()) {
      Fit_settings selection;
      selection.degree = (std::max)(jet_degree, 2);
      selection.radius_range = radius_range;
      selector_.emplace(Face_graph_neighborhood<FaceGraph, VertexPointMap>(g, vpm, vertex_adjacency(g)), selection);
    }
  }

  // CGAL's fit normal.
  static constexpr bool uses_given_normals = false;

  // The fallback chain: CGAL's fit, else the paraboloid fit with its defaults and fallbacks.
  // Under scale selection, that or CGAL's fit over the ball selected by this package's fits.
  // Its reach: that of the balls gathered about v.
  Surface_estimate estimate(vertex_descriptor v, const Eigen::Vector3d*)
  {
    Surface_estimate estimate;
    estimate_with_fallbacks(
      estimate, use_fallbacks_, [&](Surface_estimate& out) { return final_estimate(out, fit(v, ball_radius_)); },
      fallback(Tried_where::refused,
               [&](Surface_estimate& out) { return final_estimate(out, paraboloid_.estimate(v, nullptr)); }));
    if (selector_)
      estimate = select_estimate(estimate, selector_->select(v, nullptr, Vertex_normal_method::area_weighted),
                                 [&](double radius) { return fit(v, radius); });
    estimate.reach =
      (std::max)(std::sqrt(collector_.widest_squared_ball(v)), selector_ ? selector_->widest_ball(v) : 0.0);
    return estimate;
  }

private:
  // The fit over the rings (the vertex first, as CGAL requires), widened until they hold the
  // jet's coefficients (CGAL checks that only in debug builds) and CGAL's condition number is
  // at most `max_condition_`; or over the ball of `ball_radius` where positive.
  Surface_estimate fit(vertex_descriptor v, double ball_radius)
  {
    const Eigen::Vector3d center = point_in_double(vpm_, v);
    const Eigen::Vector3d orientation = face_average_normal(v, *g_, vpm_, Vertex_normal_method::area_weighted);
    if (!center.allFinite() || !orientation.allFinite() || !(orientation.squaredNorm() > 0))
      return Surface_estimate();
    const int unknowns = (jet_degree_ + 1) * (jet_degree_ + 2) / 2;

    collector_.start(v, *g_);
    Surface_estimate e;
    if (ball_radius > 0) {
      const auto squared_distance = [&](vertex_descriptor w) {
        return (point_in_double(vpm_, w) - center).squaredNorm();
      };
      const int growths = fit_in_growing_ball(
        ball_radius, unknowns,
        [&](double radius) { return collector_.grow_ball(*g_, radius * radius, squared_distance); },
        [&] { return collector_.ball_size(); },
        [&] {
          points_.clear();
          for (std::size_t i = 0; i < collector_.vertices().size(); ++i)
            if (collector_.inside_ball(i))
              add_point(collector_.vertices()[i]);
          return monge_fit(orientation, e);
        });
      return growths != 0 ? with_status(growths > 1 ? Estimation_status::widened : Estimation_status::ok, e)
                          : Surface_estimate();
    }
    for (int rings = 1; rings <= max_rings_; ++rings) {
      if (rings > 1 && !collector_.extend(*g_))
        break;
      if (rings < rings_ || collector_.vertices().size() < std::size_t(unknowns))
        continue;
      points_.clear();
      for (vertex_descriptor w : collector_.vertices())
        add_point(w);
      if (points_.size() >= std::size_t(unknowns) && monge_fit(orientation, e))
        return with_status(rings > rings_ ? Estimation_status::widened : Estimation_status::ok, e);
    }
    return Surface_estimate();
  }

  void add_point(vertex_descriptor w)
  {
    const Eigen::Vector3d p = point_in_double(vpm_, w);
    if (p.allFinite())
      points_.emplace_back(p.x(), p.y(), p.z());
  }

  static Surface_estimate with_status(Estimation_status status, Surface_estimate e)
  {
    e.status = status;
    return e;
  }

  // CGAL's fit of points_ (the vertex first), its normal oriented as
  // `orientation`; false where its condition number exceeds max_condition_ or
  // its curvatures are not finite.
  bool monge_fit(const Eigen::Vector3d& orientation, Surface_estimate& e) const
  {
    Monge_fitting fitting;
    typename Monge_fitting::Monge_form form =
      fitting(points_.begin(), points_.end(), std::size_t(jet_degree_), std::size_t(monge_degree_));
    if (!(fitting.condition_number() <= max_condition_))
      return false;
    form.comply_wrt_given_normal(Local_kernel::Vector_3(orientation.x(), orientation.y(), orientation.z()));
    // CGAL's curvature is positive where the surface bends towards its normal (convex with
    // outward normals: k < 0); ours is the opposite, so max and min swap.
    const auto to_eigen = [](const Local_kernel::Vector_3& d) { return Eigen::Vector3d(d.x(), d.y(), d.z()); };
    e =
      Surface_estimate::from_principal(Estimation_status::ok, -form.principal_curvatures(1),
                                       -form.principal_curvatures(0), to_eigen(form.minimal_principal_direction()),
                                       to_eigen(form.maximal_principal_direction()), to_eigen(form.normal_direction()));
    return std::isfinite(e.max_curvature) && std::isfinite(e.min_curvature);
  }

  const FaceGraph* g_;
  VertexPointMap vpm_;
  int jet_degree_, monge_degree_, rings_, max_rings_;
  double max_condition_;
  double ball_radius_; // > 0: the ball's, instead of the rings
  bool use_fallbacks_;
  Ring_collector<FaceGraph> collector_;
  std::vector<Local_kernel::Point_3> points_;
  Paraboloid_estimator<FaceGraph, VertexPointMap> paraboloid_;
  std::optional<Surface_scale_selector<FaceGraph, VertexPointMap>> selector_; // under scale selection
};

// The starting and the widest rings of `np` (max_neighborhood_rings by default 3 rings
// beyond the first, as CGAL's jet fitting widens). Throws std::invalid_argument where
// they are not 1 <= neighborhood_rings <= max_neighborhood_rings.
template <typename NamedParameters>
std::pair<int, int> jet_rings(const NamedParameters& np, const char* caller)
{
  const int rings = parameter_or(np, internal_np::neighborhood_rings, 1);
  const int max_rings = parameter_or(np, internal_np::max_neighborhood_rings, rings + 3);
  if (rings < 1 || max_rings < rings)
    throw std::invalid_argument(std::string(caller) + ": needs 1 <= neighborhood_rings <= max_neighborhood_rings");
  return {rings, max_rings};
}

} // namespace internal

/// \ingroup PkgCurvatureEstimationRef
///
/// estimates curvature with CGAL's jet fitting (`CGAL::Monge_via_jet_fitting`, Cazals and Pouget 2005)
/// over the vertex's rings or ball, with this package's outputs and conventions, for like-for-like
/// comparisons. The fit starts on `neighborhood_rings` rings and is widened, up to
/// `max_neighborhood_rings`, until the rings hold the jet's (d+1)(d+2)/2 points and CGAL's condition
/// number is at most `max_condition_number` (status `widened` where it grew). With `ball_radius(r)` the
/// neighborhood is the ball of `paraboloid_fitting_curvatures()`, grown as there; `ball_radius_range`
/// chooses its radius per vertex as there. The Monge normal is
/// oriented like the area-weighted vertex normal, and CGAL's curvatures are converted to this package's
/// sign (a sphere with outward normals has curvature 1/r). Where the fit is refused on every
/// neighborhood, the fallback is `paraboloid_fitting_curvatures()` with its defaults (status `fallback`);
/// see the User Manual, "Jet fitting".
///
/// \ceSurfaceEstimatorParameters
///
/// \cgalNamedParamsBegin
///   \ceSurfaceInputParameters
///   \cgalParamNBegin{jet_degree}
///     \cgalParamDescription{the degree d of the fitted jet, 1 to 4}
///     \cgalParamDefault{`2`}
///   \cgalParamNEnd
///   \cgalParamNBegin{monge_degree}
///     \cgalParamDescription{the degree of the Monge form, 2 to the jet degree}
///     \cgalParamDefault{`2`}
///   \cgalParamNEnd
///   \cgalParamNBegin{neighborhood_rings}
///     \cgalParamDescription{the rings the fit starts with, at least 1}
///     \cgalParamDefault{`1`}
///   \cgalParamNEnd
///   \cgalParamNBegin{max_neighborhood_rings}
///     \cgalParamDescription{the widest neighborhood a fit is widened to, at least `neighborhood_rings`}
///     \cgalParamDefault{`neighborhood_rings + 3`}
///   \cgalParamNEnd
///   \ceBallRadiusParameter
///   \ceScaleSelectionParameters
///   \cgalParamNBegin{max_condition_number}
///     \cgalParamDescription{fits whose condition number (as CGAL computes it) is larger are widened; above 1}
///     \cgalParamDefault{`1e3`}
///   \cgalParamNEnd
///   \ceUseFallbacksParameter
///   \ceSurfaceOutputParameters{K = k1 k2, `ok`\, `widened`\, `fallback` or `not_estimable`}
///   \ceReachOutputParameter
/// \cgalNamedParamsEnd
///
/// \throws std::invalid_argument if a parameter is out of its range.
template <typename ConcurrencyTag = CGAL::Sequential_tag, typename FaceGraph,
          typename NamedParameters = parameters::Default_named_parameters>
void jet_fitting_curvatures(const FaceGraph& g, const NamedParameters& np = parameters::default_values())
{
  const int jet_degree = internal::parameter_or(np, internal_np::jet_degree, 2);
  const int monge_degree = internal::parameter_or(np, internal_np::monge_degree, 2);
  const std::pair<int, int> widening = internal::jet_rings(np, "jet_fitting_curvatures");
  const int rings = widening.first, max_rings = widening.second; // captured below: no structured binding
  const double max_condition = internal::parameter_or(np, internal_np::max_condition_number, 1e3);
  const double ball_radius = internal::ball_radius_or_zero(np, "jet_fitting_curvatures");
  const internal::Radius_range radius_range = internal::ball_radius_range_or_none(np, "jet_fitting_curvatures");
  const bool use_fallbacks = internal::parameter_or(np, internal_np::use_fallbacks, true);
  const std::string where = "jet_fitting_curvatures: ";
  if (jet_degree < 1 || jet_degree > 4 || monge_degree < 2 || monge_degree > jet_degree)
    throw std::invalid_argument(where + "needs 2 <= monge_degree <= jet_degree <= 4");
  if (!(max_condition > 1))
    throw std::invalid_argument(where + "max_condition_number must be greater than 1");

  internal::estimate_surface_curvatures<ConcurrencyTag>(g, np, [&](const auto& vpm) {
    return internal::Jet_fitter<FaceGraph, std::decay_t<decltype(vpm)>>(
      g, vpm, jet_degree, monge_degree, rings, max_rings, max_condition, ball_radius, use_fallbacks, radius_range);
  });
}

} // namespace Curvature_estimation
} // namespace CGAL

#endif // CGAL_CURVATURE_ESTIMATION_JET_FITTING_H
