// SPDX-License-Identifier: GPL-3.0-or-later
// CGAL's jet fitting (Monge_via_jet_fitting, Cazals and Pouget) behind this
// package's interface, neighborhoods and conventions, for like-for-like comparisons.
#ifndef CGAL_CURVATURE_ESTIMATION_JET_FITTING_H
#define CGAL_CURVATURE_ESTIMATION_JET_FITTING_H

#include <CGAL/Curvature_estimation/Principal_curvatures_and_directions.h>
#include <CGAL/Curvature_estimation/internal/estimate_at_vertices.h>
#include <CGAL/Curvature_estimation/internal/face_average_normal.h>
#include <CGAL/Curvature_estimation/internal/neighborhood.h>
#include <CGAL/Curvature_estimation/internal/surface_estimate.h>
#include <CGAL/Curvature_estimation/paraboloid_fitting.h>
#include <CGAL/Curvature_estimation/parameters.h>

#include <CGAL/Monge_via_jet_fitting.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/tags.h>

#include <boost/graph/graph_traits.hpp>

#include <Eigen/Core>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#ifndef CGAL_EIGEN3_ENABLED
#error "jet_fitting_curvatures needs CGAL's Eigen support (link CGAL::Eigen3_support)"
#endif

namespace CGAL {
namespace Curvature_estimation {
namespace internal {

// One vertex's jet fit; one copy per thread holds the reusable point buffer.
template <typename FaceGraph, typename VertexPointMap>
class Jet_fitter
{
public:
  using vertex_descriptor = typename boost::graph_traits<FaceGraph>::vertex_descriptor;
  using Local_kernel = CGAL::Simple_cartesian<double>;
  using Monge_fitting = CGAL::Monge_via_jet_fitting<Local_kernel>;

  Jet_fitter(const FaceGraph& g, VertexPointMap vpm, int jet_degree, int monge_degree, int rings, int max_rings,
             double max_condition, double ball_radius)
      : g_(&g)
      , vpm_(vpm)
      , jet_degree_(jet_degree)
      , monge_degree_(monge_degree)
      , rings_(rings)
      , max_rings_(max_rings)
      , max_condition_(max_condition)
      , ball_radius_(ball_radius)
      , fallback_(g, vpm, Fit_parameters{Platelet_fit_settings(), Vertex_normal_method::quadric_fit})
  {}

  // CGAL's fit normal.
  static constexpr bool uses_given_normals = false;

  // CGAL's fit, or where it is ill-conditioned on every ring the paraboloid fit
  // with its defaults (status fallback). CGAL's condition number is that of the
  // fit in its own tangent coordinates, scaled by one length: a neighborhood of
  // long thin triangles is ill-conditioned there, whatever its number of rings
  // (1,648 of the 8,231 vertices of CGAL's blade.off). The paraboloid fit tests
  // conditioning in coordinates whitened by the neighborhood's own second
  // moments, which accept it. At those vertices of blade.off the paraboloid fit
  // and the Gauss map, two independent estimates, differ by a median 0.51 in H;
  // CGAL's fit accepted up to a condition number of 1e6 differs from them by 1.5
  // and 2.3 (median |H| 1.8).
  Surface_estimate estimate(vertex_descriptor v, const Eigen::Vector3d*)
  {
    const Surface_estimate result = fit(v);
    return result.status != Estimation_status::not_estimable ? result : as_fallback(fallback_.estimate(v, nullptr));
  }

private:
  // The fit over the k-ring (the vertex first, as CGAL requires), from `rings_`
  // rings on, widened until there are enough points for the jet's
  // (d+1)(d+2)/2 coefficients (a precondition CGAL checks only in debug builds)
  // and CGAL's condition number is at most `max_condition_`: on a few rows of a
  // grid boundary the system is nearly singular and the jet is garbage.
  // CGAL's fit estimates the normal itself.
  Surface_estimate fit(vertex_descriptor v)
  {
    const Eigen::Vector3d center = point_in_double(vpm_, v);
    const Eigen::Vector3d orientation = face_average_normal(v, *g_, vpm_, Vertex_normal_method::area_weighted);
    if (!center.allFinite() || !orientation.allFinite() || !(orientation.squaredNorm() > 0))
      return Surface_estimate();
    const int unknowns = (jet_degree_ + 1) * (jet_degree_ + 2) / 2;

    collector_.start(v, *g_);
    Surface_estimate e;
    if (ball_radius_ > 0) {
      const auto squared_distance = [&](vertex_descriptor w) {
        return (point_in_double(vpm_, w) - center).squaredNorm();
      };
      const int growths = fit_in_growing_ball(
        ball_radius_, unknowns,
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
    // CGAL's curvature is positive where the surface bends towards its
    // normal: with the outward normal a convex surface has k < 0. This
    // package's convention is the opposite, so max and min swap.
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
  Ring_collector<FaceGraph> collector_;
  std::vector<Local_kernel::Point_3> points_;
  Paraboloid_estimator<FaceGraph, VertexPointMap> fallback_;
};

} // namespace internal

/// \ingroup PkgCurvatureEstimationRef
///
/// Estimates curvature with CGAL's jet fitting (`CGAL::Monge_via_jet_fitting`,
/// Cazals and Pouget 2005) over the vertex's k-ring, with this package's outputs and
/// conventions, so that it can be compared like for like with the other estimators.
///
/// The fit starts on `neighborhood_rings` rings and is widened, up to
/// `max_neighborhood_rings`, until the k-ring has at least (d+1)(d+2)/2 points
/// for the degree-d jet and CGAL's condition number is at most `max_condition_number`:
/// enough points on few rows of a grid boundary still give condition numbers up to
/// 1e17 and curvature errors of order 1. The Monge normal is oriented like the
/// area-weighted vertex normal, and CGAL's curvatures (positive towards that normal)
/// are converted to this package's convention (a sphere with outward normals has
/// curvature 1/r). Where the fit is ill-conditioned on every k-ring up to
/// `max_neighborhood_rings` (CGAL's condition number, in its own tangent coordinates
/// scaled by one length, is large on neighborhoods of long thin triangles however
/// wide), the estimate is that of `paraboloid_fitting_curvatures()` with its defaults,
/// whose conditioning test accepts anisotropic neighborhoods, with the status
/// `fallback`; a vertex that neither estimates is not estimable (NaN).
///
/// With `ball_radius(r)` the neighborhood is the ball of `paraboloid_fitting_curvatures()`
/// (the part of the mesh inside the ball of radius r about the vertex, joined to it by
/// edges inside the ball), grown as there until it holds twice the jet's coefficients
/// and then, while CGAL's condition number exceeds `max_condition_number`, up to twice
/// that radius (status `widened` where it grew): the same neighborhoods as the
/// paraboloid fit's, for like-for-like comparisons at a scale.
///
/// \tparam ConcurrencyTag `CGAL::Sequential_tag` (default), `CGAL::Parallel_tag` or
///         `CGAL::Parallel_if_available_tag`. Sequential and parallel runs give
///         identical results. In parallel the vertex point map is read from several
///         threads; the property maps of `Surface_mesh` (and `Point_set_3`) are read and
///         written by the worker threads, every other map by the calling thread only.
/// \tparam FaceGraph a model of `FaceGraph`
/// \tparam NamedParameters a sequence of named parameters, built with the functions of
///         `CGAL::Curvature_estimation::parameters`
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{a property map associating points to the vertices of `g`}
///     \cgalParamType{a model of `ReadablePropertyMap` with `%Point_3` as value type}
///     \cgalParamDefault{`boost::get(CGAL::vertex_point, g)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{geom_traits}
///     \cgalParamDescription{an instance of a geometric traits class}
///     \cgalParamType{a class model of `Kernel`}
///     \cgalParamDefault{a \cgal Kernel deduced from the point type}
///   \cgalParamNEnd
///   \cgalParamNBegin{jet_degree}
///     \cgalParamDescription{the degree d of the fitted jet}
///     \cgalParamType{`int`, from 1 to 4}
///     \cgalParamDefault{`2`}
///   \cgalParamNEnd
///   \cgalParamNBegin{monge_degree}
///     \cgalParamDescription{the degree of the Monge form}
///     \cgalParamType{`int`, from 2 to the jet degree}
///     \cgalParamDefault{`2`}
///   \cgalParamNEnd
///   \cgalParamNBegin{neighborhood_rings}
///     \cgalParamDescription{the rings the fit starts with}
///     \cgalParamType{`int`, at least 1}
///     \cgalParamDefault{`1`}
///   \cgalParamNEnd
///   \cgalParamNBegin{max_neighborhood_rings}
///     \cgalParamDescription{the widest neighborhood a fit is widened to}
///     \cgalParamType{`int`, at least `neighborhood_rings`}
///     \cgalParamDefault{`neighborhood_rings + 3`}
///   \cgalParamNEnd
///   \cgalParamNBegin{ball_radius}
///     \cgalParamDescription{the radius of the ball that is the neighborhood instead of the rings (see above)}
///     \cgalParamType{`double`, positive, in the units of the mesh (see `mean_edge_length()`)}
///     \cgalParamDefault{none: the rings}
///   \cgalParamNEnd
///   \cgalParamNBegin{max_condition_number}
///     \cgalParamDescription{fits whose condition number (as CGAL computes it) is larger are widened}
///     \cgalParamType{`double`, greater than 1}
///     \cgalParamDefault{`1e3`}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_principal_curvatures_and_directions_map}
///     \cgalParamDescription{output: principal curvatures and directions}
///     \cgalParamType{a model of `WritablePropertyMap` with `Principal_curvatures_and_directions<GT>` as value type}
///     \cgalParamDefault{not computed}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_mean_curvature_map}
///     \cgalParamDescription{output: mean curvature}
///     \cgalParamType{a model of `WritablePropertyMap` with `GT::FT` as value type}
///     \cgalParamDefault{not computed}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_Gaussian_curvature_map}
///     \cgalParamDescription{output: Gaussian curvature}
///     \cgalParamType{a model of `WritablePropertyMap` with `GT::FT` as value type}
///     \cgalParamDefault{not computed}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_estimation_status_map}
///     \cgalParamDescription{output: `ok` on the starting rings, `widened` beyond, `fallback` (the paraboloid fit),
///     `not_estimable`} \cgalParamType{a model of `WritablePropertyMap` with `Estimation_status` as value type}
///     \cgalParamDefault{not computed}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \throws std::invalid_argument if a parameter is out of its range.
template <typename ConcurrencyTag = CGAL::Sequential_tag, typename FaceGraph,
          typename NamedParameters = parameters::Default_named_parameters>
void jet_fitting_curvatures(const FaceGraph& g, const NamedParameters& np = parameters::default_values())
{
  const int jet_degree = internal::parameter_or(np, internal_np::jet_degree, 2);
  const int monge_degree = internal::parameter_or(np, internal_np::monge_degree, 2);
  const int rings = internal::parameter_or(np, internal_np::neighborhood_rings, 1);
  const int max_rings = internal::parameter_or(np, internal_np::max_neighborhood_rings, rings + 3);
  const double max_condition = internal::parameter_or(np, internal_np::max_condition_number, 1e3);
  const double ball_radius = internal::ball_radius_or_zero(np, "jet_fitting_curvatures");
  const std::string where = "jet_fitting_curvatures: ";
  if (jet_degree < 1 || jet_degree > 4 || monge_degree < 2 || monge_degree > jet_degree)
    throw std::invalid_argument(where + "needs 2 <= monge_degree <= jet_degree <= 4");
  if (rings < 1 || max_rings < rings)
    throw std::invalid_argument(where + "needs 1 <= neighborhood_rings <= max_neighborhood_rings");
  if (!(max_condition > 1))
    throw std::invalid_argument(where + "max_condition_number must be greater than 1");

  internal::estimate_surface_curvatures<ConcurrencyTag>(g, np, [&](const auto& vpm) {
    return internal::Jet_fitter<FaceGraph, std::decay_t<decltype(vpm)>>(g, vpm, jet_degree, monge_degree, rings,
                                                                        max_rings, max_condition, ball_radius);
  });
}

} // namespace Curvature_estimation
} // namespace CGAL

#endif // CGAL_CURVATURE_ESTIMATION_JET_FITTING_H
