// SPDX-License-Identifier: GPL-3.0-or-later
// Hamann's paraboloid fitting, on any FaceGraph.
#ifndef CGAL_CURVATURE_ESTIMATION_PARABOLOID_FITTING_H
#define CGAL_CURVATURE_ESTIMATION_PARABOLOID_FITTING_H

#include <CGAL/Curvature_estimation/Principal_curvatures_and_directions.h>
#include <CGAL/Curvature_estimation/Vertex_normal_method.h>
#include <CGAL/Curvature_estimation/internal/estimate_at_vertices.h>
#include <CGAL/Curvature_estimation/internal/face_graph_neighborhood.h>
#include <CGAL/Curvature_estimation/internal/fallback_chain.h>
#include <CGAL/Curvature_estimation/internal/gauss_map_differential.h>
#include <CGAL/Curvature_estimation/parameters.h>
#include <CGAL/Curvature_estimation/vertex_normals.h>

#include <CGAL/tags.h>

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <cstddef>
#include <memory>
#include <optional>
#include <type_traits>

namespace CGAL {
namespace Curvature_estimation {
namespace internal {

// The paraboloid fit at one vertex with its fallback chain (see `estimate`).
template <typename FaceGraph, typename VertexPointMap>
class Paraboloid_estimator
{
public:
  using vertex_descriptor = typename boost::graph_traits<FaceGraph>::vertex_descriptor;

  Paraboloid_estimator(const FaceGraph& g, VertexPointMap vpm, const Fit_parameters& fit, bool use_fallbacks = true)
      : Paraboloid_estimator(g, vpm, fit, use_fallbacks,
                             Surface_fitter<FaceGraph, VertexPointMap>::adjacency_for(g, fit.settings))
  {}

  // The fallback chain: the fit of fit_degree; where it is refused, at fit_degree
  // 3 and 4 over rings, the fit of degree 2; with the fitted normal and no given
  // one, the plane-frame fit (also where only the whitened test accepted the fit
  // of degree 2 at a boundary vertex), then the Gauss map. Under scale selection,
  // that estimate or the fit over the selected ball (select_estimate). Its reach: that of
  // every ball gathered about v, and of the Gauss map's where it was tried.
  Surface_estimate estimate(vertex_descriptor v, const Eigen::Vector3d* given)
  {
    gauss_map_reach_ = 0;
    Surface_estimate estimate;
    estimate_with_fallbacks(
      estimate, use_fallbacks_, [&](Surface_estimate& out) { return fit(v, given, out); },
      fallback(Tried_where::refused, [&](Surface_estimate& out) { return degree_two_fit(v, given, out); }),
      fallback(Tried_where::refused_or_provisional,
               [&](Surface_estimate& out) { return plane_frame_fit(v, given, out); }),
      fallback(Tried_where::refused, [&](Surface_estimate& out) { return gauss_map_fit(v, given, out); }));
    if (selector_)
      estimate = select_estimate(estimate, selector_->select(v, given, method_),
                                 [&](double radius) { return fitter_.ball_estimate(v, given, method_, radius); });
    estimate.reach =
      (std::max)({fitter_.widest_ball(v), selector_ ? selector_->widest_ball(v) : 0.0, gauss_map_reach_});
    return estimate;
  }

private:
  Paraboloid_estimator(const FaceGraph& g, VertexPointMap vpm, const Fit_parameters& fit, bool use_fallbacks,
                       std::shared_ptr<const Vertex_adjacency> adjacency)
      : fitter_(g, vpm, fit.settings, adjacency)
      , method_(fit.normal_method)
      , use_fallbacks_(use_fallbacks)
      , gauss_map_(g, vpm,
                   Vertex_normal_estimator<FaceGraph, VertexPointMap>{
                     Surface_fitter<FaceGraph, VertexPointMap>(g, vpm, fit.settings, nullptr), fit.normal_method, true})
  {
    if (fit.settings.selects_radius())
      selector_.emplace(Face_graph_neighborhood<FaceGraph, VertexPointMap>(g, vpm, adjacency), fit.settings);
  }

  // The links of the chain (fallback_chain.h).
  Verdict fit(vertex_descriptor v, const Eigen::Vector3d* given, Surface_estimate& out)
  {
    const Vertex_fit r = given != nullptr ? fitter_.fit(v, *given, out) : fitter_.fit(v, method_, out);
    const Fit_settings& s = fitter_.settings();
    if (out.status == Estimation_status::not_estimable)
      return r.neighbors < std::size_t(Paraboloid_fit<2>::unknowns) ? Verdict::hopeless : Verdict::refused;
    const bool provisional = fitted_normal(given) && s.degree == 2 && !s.in_ball() && r.on_border && r.whitened;
    return provisional ? Verdict::provisional : Verdict::accepted;
  }

  Verdict degree_two_fit(vertex_descriptor v, const Eigen::Vector3d* given, Surface_estimate& out)
  {
    const Fit_settings& s = fitter_.settings();
    if (s.degree == 2 || s.in_ball())
      return Verdict::refused;
    fitter_.degree_two_fit(v, given, method_, out);
    return accepted_or_refused(out);
  }

  Verdict plane_frame_fit(vertex_descriptor v, const Eigen::Vector3d* given, Surface_estimate& out)
  {
    if (!fitted_normal(given))
      return Verdict::refused;
    fitter_.plane_frame_fit(v, out);
    return accepted_or_refused(out);
  }

  Verdict gauss_map_fit(vertex_descriptor v, const Eigen::Vector3d* given, Surface_estimate& out)
  {
    if (!fitted_normal(given))
      return Verdict::refused;
    const Verdict verdict = final_estimate(out, gauss_map_.estimate(v, nullptr));
    gauss_map_reach_ = out.reach;
    return verdict;
  }

  bool fitted_normal(const Eigen::Vector3d* given) const
  {
    return given == nullptr && method_ == Vertex_normal_method::quadric_fit;
  }

  Surface_fitter<FaceGraph, VertexPointMap> fitter_;
  Vertex_normal_method method_;
  bool use_fallbacks_;
  Gauss_map_estimator<FaceGraph, VertexPointMap, Vertex_normal_estimator<FaceGraph, VertexPointMap>> gauss_map_;
  std::optional<Surface_scale_selector<FaceGraph, VertexPointMap>> selector_; // under scale selection
  double gauss_map_reach_ = 0;                                                // of the last fallback to the Gauss map
};

} // namespace internal

/// \ingroup PkgCurvatureEstimationRef
///
/// estimates principal curvatures and directions, mean and Gaussian curvature at every vertex of `g`
/// by Hamann's paraboloid fitting (Hamann 1993): the Taylor polynomial of the height over the tangent
/// plane is fitted by least squares to the vertex's neighborhood, and the curvatures are those of the
/// fitted graph at the vertex.
///
/// With a `vertex_normal_map` the fit is Hamann's paraboloid in the frame of the given normals. By
/// default the normal is fitted too (second order, also at boundary vertices) and the curvature fit
/// keeps the gradient. `fit_degree(3)` and `fit_degree(4)` fit polynomials of those degrees over 2 and
/// 3 rings; `ball_radius(r)` fits over the ball of radius r instead of rings, for noisy meshes;
/// `ball_radius_range(min, max)` chooses that radius per vertex (scale selection). A fit
/// whose normal equations are ill-conditioned is widened ring by ring (status `widened`); where no
/// ring determines it, the fallbacks serve (status `fallback`). The User Manual ("Paraboloid fitting")
/// gives the details and the measurements behind each choice.
///
/// Conventions: a sphere of radius r with outward normals has `max_curvature == min_curvature == 1/r`;
/// H = (k1 + k2) / 2, K = k1 k2. Scaling the mesh by s scales the curvatures by 1/s. A vertex that
/// cannot be estimated gets NaN in every output. Only the outputs whose maps are passed are written.
///
/// \ceSurfaceEstimatorParameters
///
/// \cgalNamedParamsBegin
///   \ceSurfaceInputParameters
///   \ceGivenNormalParameter
///   \cgalParamNBegin{vertex_normal_method}
///     \cgalParamDescription{how normals are estimated when no `vertex_normal_map` is given}
///     \cgalParamDefault{`Vertex_normal_method::quadric_fit`}
///   \cgalParamNEnd
///   \cgalParamNBegin{fit_degree}
///     \cgalParamDescription{the degree of the fitted polynomial: 2, 3 or 4}
///     \cgalParamDefault{`2`}
///   \cgalParamNEnd
///   \ceBallRadiusParameter
///   \ceScaleSelectionParameters
///   \ceBallWeightingParameter
///   \ceRingParameters
///   \ceUseFallbacksParameter
///   \ceSurfaceOutputParameters{K = k1 k2, `ok`\, `widened`\, `fallback` or `not_estimable`}
///   \ceReachOutputParameter
/// \cgalNamedParamsEnd
///
/// \throws std::invalid_argument if a parameter is out of its range.
template <typename ConcurrencyTag = CGAL::Sequential_tag, typename FaceGraph,
          typename NamedParameters = parameters::Default_named_parameters>
void paraboloid_fitting_curvatures(const FaceGraph& g, const NamedParameters& np = parameters::default_values())
{
  const internal::Fit_parameters fit = internal::curvature_fit_parameters(
    np, "paraboloid_fitting_curvatures", 4, internal::Neighborhoods::rings_ball_or_selected);
  const bool use_fallbacks = internal::parameter_or(np, internal_np::use_fallbacks, true);
  internal::estimate_surface_curvatures<ConcurrencyTag>(g, np, [&](const auto& vpm) {
    return internal::Paraboloid_estimator<FaceGraph, std::decay_t<decltype(vpm)>>(g, vpm, fit, use_fallbacks);
  });
}

} // namespace Curvature_estimation
} // namespace CGAL

#endif // CGAL_CURVATURE_ESTIMATION_PARABOLOID_FITTING_H
