// SPDX-License-Identifier: GPL-3.0-or-later
// How far each estimator reads around a vertex or a point, with its settings, its
// normals and its fallbacks: the halo a tile needs for its own vertices' estimates.
#ifndef CGAL_CURVATURE_ESTIMATION_NEIGHBORHOOD_REACH_H
#define CGAL_CURVATURE_ESTIMATION_NEIGHBORHOOD_REACH_H

#include <CGAL/Curvature_estimation/Estimator.h>
#include <CGAL/Curvature_estimation/chen_schmitt.h>
#include <CGAL/Curvature_estimation/curve_network.h>
#include <CGAL/Curvature_estimation/gauss_map.h>
#include <CGAL/Curvature_estimation/internal/ball.h>
#include <CGAL/Curvature_estimation/internal/fit_attempts.h>
#include <CGAL/Curvature_estimation/internal/fit_settings.h>
#include <CGAL/Curvature_estimation/internal/gauss_map_differential.h>
#include <CGAL/Curvature_estimation/jet_fitting.h>
#include <CGAL/Curvature_estimation/paraboloid_fitting.h>
#include <CGAL/Curvature_estimation/parameters.h>
#include <CGAL/Curvature_estimation/point_set_curvatures.h>
#include <CGAL/Curvature_estimation/taubin.h>

#include <algorithm>
#include <cstddef>
#include <initializer_list>

namespace CGAL {
namespace Curvature_estimation {

namespace internal {

// The rings a fitted normal (quadric_fit) reads at a vertex, inside or on the border;
// 1 for the other methods, 0 for given normals.
template <typename NamedParameters>
int normal_rings(const Fit_parameters& fit)
{
  if (has_parameter<NamedParameters, ::CGAL::internal_np::vertex_normal_map_t>())
    return 0;
  if (fit.normal_method != Vertex_normal_method::quadric_fit)
    return 1;
  const Fit_settings& s = fit.settings;
  int rings = 1;
  for (const bool border : {false, true}) {
    rings = (std::max)(rings, normal_attempts(s, border).widest_rings());
    if (s.degree != 2)
      rings = (std::max)(rings, degree_attempts(s, border, true).widest_rings());
  }
  return rings;
}

// The paraboloid estimator over rings: its fits (of fit_degree, then of degree 2, the
// plane-frame fit: none reads past max_rings but a fit of degree 3 or 4), its normal,
// and the Gauss map over the normals of its vertices, the last of its fallbacks.
template <typename NamedParameters>
int paraboloid_rings(const Fit_parameters& fit)
{
  const Fit_settings& s = fit.settings;
  const int normal = normal_rings<NamedParameters>(fit);
  int rings = (std::max)(s.max_rings, normal);
  if (s.degree != 2)
    for (const bool border : {false, true})
      rings = (std::max)(rings, degree_attempts(s, border, true).widest_rings());
  return (std::max)(rings, gauss_map_rings + normal);
}

// The paraboloid estimator with its defaults, the fallback of the curve network and of jet fitting.
inline int default_paraboloid_rings()
{
  return paraboloid_rings<parameters::Default_named_parameters>({Fit_settings(), Vertex_normal_method::quadric_fit});
}

// A reach over a ball of `radius` about each vertex read, then `rings`.
inline Neighborhood_reach ball_reach(double radius, int rings)
{
  Neighborhood_reach reach;
  reach.rings = rings;
  reach.distance = radius;
  reach.grown_distance = ball_growth_for_conditioning * radius;
  return reach;
}

inline Neighborhood_reach ring_reach(int rings)
{
  Neighborhood_reach reach;
  reach.rings = rings;
  return reach;
}

template <typename NamedParameters>
Neighborhood_reach point_set_reach(const NamedParameters& np)
{
  const Point_set_parameters parameters = point_set_parameters(np, "neighborhood_reach");
  const Fit_settings& s = parameters.fit.settings;
  if (parameters.neighbors == 0)
    return ball_reach(s.ball_radius, 0);
  Neighborhood_reach reach = s.selects_radius() ? ball_reach(s.radius_range.max, 0) : Neighborhood_reach();
  // Ring r of a point is its k 2^(r - 1) nearest neighbors (point_set_neighborhood.h).
  reach.neighbors = parameters.neighbors << (s.rings - 1);
  reach.widened_neighbors = parameters.neighbors << (s.max_rings - 1);
  return reach;
}

} // namespace internal

/// \ingroup PkgCurvatureEstimationRef
///
/// returns how far `estimator` with the named parameters `np` reads around each vertex or point it
/// estimates at: its fits and their widening, its normals (each fitted over its own neighborhood) and
/// its fallbacks. The named parameters, their defaults and their checks are the estimator's own: pass
/// this function the parameters the estimator is called with. A tile of a mesh whose halo holds this
/// reach around the tile's vertices gives those vertices the values of the whole mesh (the User Manual's
/// "Tiles" says how). A ball may grow past `grown_distance`: the mesh estimators' output `vertex_reach_map`
/// gives, per vertex, how far the balls it read reached.
///
/// Without given normals, the signs of a point set's curvatures follow an orientation propagated over the
/// whole set (see `point_set_curvatures()`): the reach bounds its values up to that sign.
///
/// \tparam NamedParameters a sequence of named parameters, built with the functions of
///         `CGAL::Curvature_estimation::parameters`
/// \param estimator the estimator
/// \param np the named parameters the estimator is called with
///
/// \throws std::invalid_argument where a parameter of the neighborhood is out of its range, or where `estimator`
///         does not take it.
template <typename NamedParameters = parameters::Default_named_parameters>
Neighborhood_reach neighborhood_reach(Estimator estimator, const NamedParameters& np = parameters::default_values())
{
  using internal::Neighborhoods;
  const char* const caller = "neighborhood_reach";
  switch (estimator) {
    case Estimator::paraboloid_fitting: {
      const internal::Fit_parameters fit =
        internal::curvature_fit_parameters(np, caller, 4, Neighborhoods::rings_ball_or_selected);
      if (fit.settings.in_ball()) // the normal's ball about each vertex of the curvature's, then the rings
        // of the plane-frame fit and of the Gauss map's normals (the fallbacks)
        return internal::ball_reach(2 * fit.settings.ball_radius,
                                    (std::max)(fit.settings.max_rings, internal::gauss_map_rings + 1));
      const int rings = internal::paraboloid_rings<NamedParameters>(fit);
      return fit.settings.selects_radius() ? internal::ball_reach(2 * fit.settings.radius_range.max, rings)
                                           : internal::ring_reach(rings);
    }
    case Estimator::gauss_map: {
      const internal::Fit_parameters fit = internal::fit_parameters(np, caller, Neighborhoods::rings_or_ball);
      if (fit.settings.in_ball())
        return internal::ball_reach(2 * fit.settings.ball_radius, 1);
      return internal::ring_reach(internal::gauss_map_rings + internal::normal_rings<NamedParameters>(fit));
    }
    case Estimator::taubin:
    case Estimator::chen_schmitt: {
      const internal::Fit_parameters fit = internal::fit_parameters(np, caller);
      const int samples = estimator == Estimator::taubin
                            ? internal::taubin_rings
                            : internal::chen_schmitt_rings(internal::chen_schmitt_uniform(np));
      return internal::ring_reach((std::max)(samples, internal::normal_rings<NamedParameters>(fit)));
    }
    case Estimator::curve_network: {
      internal::reject_ball_radius<NamedParameters>(caller);
      const int order = internal::parameter_or(np, internal_np::extrapolation_order, 1);
      return internal::ring_reach((std::max)(order, internal::default_paraboloid_rings()));
    }
    case Estimator::jet_fitting: {
      const int max_rings = internal::jet_rings(np, caller).second;
      const double radius = internal::ball_radius_or_zero(np, caller);
      const internal::Radius_range range = internal::ball_radius_range_or_none(np, caller);
      const int fallback = internal::default_paraboloid_rings();
      if (radius > 0 || range.given())
        return internal::ball_reach(radius > 0 ? radius : range.max, fallback);
      return internal::ring_reach((std::max)(max_rings, fallback));
    }
    case Estimator::point_set:
      return internal::point_set_reach(np);
  }
  return {};
}

} // namespace Curvature_estimation
} // namespace CGAL

#endif // CGAL_CURVATURE_ESTIMATION_NEIGHBORHOOD_REACH_H
