// SPDX-License-Identifier: GPL-3.0-or-later
// The settings of the fitting estimators, read from the named parameters once for
// every public function that fits (for its curvatures or for its fitted normal):
// the neighborhood (rings or ball), the condition threshold, the degree and the
// normal method, with the documented defaults, checked.
#ifndef CGAL_CURVATURE_ESTIMATION_INTERNAL_FIT_SETTINGS_H
#define CGAL_CURVATURE_ESTIMATION_INTERNAL_FIT_SETTINGS_H

#include <CGAL/Curvature_estimation/Neighbor_weighting.h>
#include <CGAL/Curvature_estimation/Vertex_normal_method.h>
#include <CGAL/Curvature_estimation/parameters.h>

#include <stdexcept>
#include <string>

namespace CGAL {
namespace Curvature_estimation {
namespace internal {

struct Fit_settings
{
  int rings = 1;          // rings an interior vertex starts with
  int boundary_rings = 1; // rings a boundary vertex starts with
  int max_rings = 3;      // widening stops here
  double max_condition = 1e3;
  int degree = 2;              // fit_degree
  double ball_radius = 0;      // > 0: the fits over the ball of this radius, not the rings
  Radius_range radius_range;   // given: the radius selected per vertex in this range
  bool smooth_weights = false; // in the ball, Neighbor_weighting::smooth (else uniform)
  bool ring_intercept = false; // over rings too, the intercept fit of the degree (point sets)
  // Whether the whitened test may accept the widest neighborhood where the
  // scaled test refuses every one (false: the scaled test alone).
  bool whitened_conditioning = true;

  int start_rings(bool on_border) const { return on_border ? boundary_rings : rings; }
  bool in_ball() const { return ball_radius > 0; }
  bool fits_intercept() const { return in_ball() || ring_intercept; }
  bool selects_radius() const { return radius_range.given(); }
};

struct Fit_parameters
{
  Fit_settings settings;
  Vertex_normal_method normal_method;
};

// The neighborhoods a public function takes besides rings.
enum class Neighborhoods
{
  rings,
  rings_or_ball,          // and ball_radius
  rings_ball_or_selected, // and ball_radius_range
  rings_or_selected       // and ball_radius_range, not ball_radius (point sets)
};

// The parameters from `np`; `caller` names the public function in error messages.
// Throws std::invalid_argument where one is out of its range, or where a
// neighborhood that `neighborhoods` excludes is asked for.
template <typename NamedParameters>
Fit_parameters fit_parameters(const NamedParameters& np, const char* caller,
                              Neighborhoods neighborhoods = Neighborhoods::rings)
{
  if (neighborhoods == Neighborhoods::rings)
    reject_ball_radius<NamedParameters>(caller);
  else if (neighborhoods == Neighborhoods::rings_or_ball)
    reject_scale_selection<NamedParameters>(caller);
  else if (neighborhoods == Neighborhoods::rings_or_selected)
    reject_ball_radius_alone<NamedParameters>(caller);
  Fit_settings settings;
  settings.rings = parameter_or(np, internal_np::neighborhood_rings, 1);
  settings.boundary_rings = parameter_or(np, internal_np::boundary_neighborhood_rings, settings.rings);
  settings.max_rings = parameter_or(np, internal_np::max_neighborhood_rings, 3);
  settings.max_condition = parameter_or(np, internal_np::max_condition_number, 1e3);
  const std::string where = std::string(caller) + ": ";
  if (settings.rings < 1 || settings.boundary_rings < 1)
    throw std::invalid_argument(where + "neighborhood_rings and boundary_neighborhood_rings must be at least 1");
  if (settings.max_rings < settings.rings || settings.max_rings < settings.boundary_rings)
    throw std::invalid_argument(where + "max_neighborhood_rings must be at least the starting rings");
  if (!(settings.max_condition > 1))
    throw std::invalid_argument(where + "max_condition_number must be greater than 1");
  settings.ball_radius = ball_radius_or_zero(np, caller);
  settings.radius_range = ball_radius_range_or_none(np, caller);
  return {settings, parameter_or(np, internal_np::vertex_normal_method, Vertex_normal_method::quadric_fit)};
}

// fit_parameters() and `fit_degree` from `np`, for the functions that take it (the
// paraboloid fits and the quadric_fit normals): 2 to `max_degree`. Throws
// std::invalid_argument where it is out of that range.
template <typename NamedParameters>
Fit_parameters curvature_fit_parameters(const NamedParameters& np, const char* caller, int max_degree,
                                        Neighborhoods neighborhoods)
{
  Fit_parameters fit = fit_parameters(np, caller, neighborhoods);
  const std::string where = std::string(caller) + ": ";
  fit.settings.degree = parameter_or(np, internal_np::fit_degree, 2);
  if (fit.settings.degree < 2 || fit.settings.degree > max_degree)
    throw std::invalid_argument(where + "fit_degree must be in 2.." + std::to_string(max_degree));
  if constexpr (has_parameter<NamedParameters, internal_np::neighbor_weighting_t>()) {
    const Neighbor_weighting weighting = ::CGAL::parameters::get_parameter(np, internal_np::neighbor_weighting);
    if (!(fit.settings.ball_radius > 0) ||
        (weighting != Neighbor_weighting::uniform && weighting != Neighbor_weighting::smooth))
      throw std::invalid_argument(where + "neighbor_weighting is for fits over a ball_radius: uniform or smooth");
    fit.settings.smooth_weights = weighting == Neighbor_weighting::smooth;
  }
  return fit;
}

} // namespace internal
} // namespace Curvature_estimation
} // namespace CGAL

#endif // CGAL_CURVATURE_ESTIMATION_INTERNAL_FIT_SETTINGS_H
