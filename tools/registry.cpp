// SPDX-License-Identifier: GPL-3.0-or-later
#include "registry.h"

#include <CGAL/Curvature_estimation.h>

#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>

namespace ce_tool {

namespace {

int default_of(Setting s) { return integer_range(s).default_value; }

auto output_parameters(const Outputs& o)
{
  return CE::parameters::vertex_mean_curvature_map(o.H)
    .vertex_Gaussian_curvature_map(o.K)
    .vertex_principal_curvatures_and_directions_map(o.pcd)
    .vertex_estimation_status_map(o.status)
    .vertex_reach_map(o.reach);
}

// The output maps and the normal method of `s`.
auto outputs_and_normal_method(const Settings& s, const Outputs& o)
{
  return output_parameters(o).vertex_normal_method(s.normal_method.value_or(CE::Vertex_normal_method::quadric_fit));
}

// The neighborhood a method reads from the settings.
enum class Neighborhood
{
  none,
  rings,
  rings_or_ball,
  rings_ball_or_selected // or the radius chosen per vertex
};

// Calls `estimate(tag, np)`: `tag` the concurrency `threads` asks for, `np` = `base` with the
// neighborhood N of `s` (its radius selection or its ball where it has one and N allows,
// else its rings, max_rings the library's default where not set) and, with GivenNormals,
// the given normals of `s` if it has any.
template <Neighborhood N, bool GivenNormals, typename NamedParameters, typename Estimate>
void estimate_with(const Settings& s, int threads, const NamedParameters& base, const Estimate& estimate)
{
  with_threads(threads, [&](auto tag) {
    const auto with_normals = [&](const auto& np) {
      if constexpr (GivenNormals) {
        if (s.given_normals) {
          estimate(tag, np.vertex_normal_map(*s.given_normals));
          return;
        }
      }
      estimate(tag, np);
    };
    if constexpr (N == Neighborhood::none) {
      with_normals(base);
    } else {
      if constexpr (N == Neighborhood::rings_ball_or_selected) {
        if (s.radius_selection) {
          const Settings::Radius_selection& r = *s.radius_selection;
          with_normals(base.ball_radius_range(r.range).vertex_ball_radius_map(r.radius).vertex_noise_map(r.noise));
          return;
        }
      }
      if constexpr (N != Neighborhood::rings) {
        if (s.ball_radius) {
          with_normals(base.ball_radius(*s.ball_radius));
          return;
        }
      }
      const auto with_rings = base.neighborhood_rings(s.rings.value_or(default_of(Setting::rings)));
      if (s.max_rings)
        with_normals(with_rings.max_neighborhood_rings(*s.max_rings));
      else
        with_normals(with_rings);
    }
  });
}

// Calls the library's estimator E on `mesh` with `np`.
template <CE::Estimator E, typename Tag, typename NamedParameters>
void estimate(const Mesh& mesh, const NamedParameters& np)
{
  if constexpr (E == CE::Estimator::paraboloid_fitting)
    CE::paraboloid_fitting_curvatures<Tag>(mesh, np);
  else if constexpr (E == CE::Estimator::curve_network)
    CE::curve_network_curvatures<Tag>(mesh, np);
  else if constexpr (E == CE::Estimator::gauss_map)
    CE::gauss_map_curvatures<Tag>(mesh, np);
  else if constexpr (E == CE::Estimator::taubin)
    CE::taubin_curvatures<Tag>(mesh, np);
  else if constexpr (E == CE::Estimator::chen_schmitt)
    CE::chen_schmitt_curvatures<Tag>(mesh, np);
  else
    CE::jet_fitting_curvatures<Tag>(mesh, np);
}

// Calls `call(tag, np)` with the named parameters of estimator E from the settings `s` (see estimate_with).
template <CE::Estimator E, typename Call>
void with_parameters(const Settings& s, const Outputs& o, int threads, const Call& call)
{
  if constexpr (E == CE::Estimator::paraboloid_fitting) {
    estimate_with<Neighborhood::rings_ball_or_selected, true>(
      s, threads, outputs_and_normal_method(s, o).fit_degree(s.fit_degree.value_or(default_of(Setting::fit_degree))),
      call);
  } else if constexpr (E == CE::Estimator::curve_network) {
    estimate_with<Neighborhood::none, true>(s, threads,
                                            output_parameters(o).extrapolation_order(
                                              s.extrapolation_order.value_or(default_of(Setting::extrapolation_order))),
                                            call);
  } else if constexpr (E == CE::Estimator::gauss_map) {
    estimate_with<Neighborhood::rings_or_ball, true>(s, threads, outputs_and_normal_method(s, o), call);
  } else if constexpr (E == CE::Estimator::taubin || E == CE::Estimator::chen_schmitt) {
    estimate_with<Neighborhood::rings, true>(s, threads, outputs_and_normal_method(s, o), call);
  } else {
    estimate_with<Neighborhood::rings_ball_or_selected, false>(
      s, threads,
      output_parameters(o)
        .jet_degree(s.jet_degree.value_or(default_of(Setting::jet_degree)))
        .monge_degree(s.monge_degree.value_or(default_of(Setting::monge_degree))),
      call);
  }
}

template <CE::Estimator E>
void run_method(const Mesh& mesh, const Settings& s, const Outputs& o, int threads)
{
  with_parameters<E>(s, o, threads, [&](auto tag, const auto& np) { estimate<E, decltype(tag)>(mesh, np); });
}

template <CE::Estimator E>
CE::Neighborhood_reach reach_of_method(const Settings& s)
{
  CE::Neighborhood_reach reach;
  with_parameters<E>(s, Outputs(), 1, [&](auto, const auto& np) { reach = CE::neighborhood_reach(E, np); });
  return reach;
}

} // namespace

const char* setting_name(Setting s)
{
  switch (s) {
    case Setting::rings:
      return "neighborhood_rings";
    case Setting::ball_radius:
      return "ball_radius";
    case Setting::fit_degree:
      return "fit_degree";
    case Setting::extrapolation_order:
      return "extrapolation_order";
    case Setting::jet_degree:
      return "jet_degree";
    case Setting::monge_degree:
      return "monge_degree";
    case Setting::normals:
      return "vertex_normal_method";
    case Setting::given_normals:
      return "vertex_normal_map";
    case Setting::ball_radius_range:
      return "ball_radius_range";
  }
  return "unknown setting";
}

unsigned given_settings(const Settings& s)
{
  unsigned given = 0;
  const auto add = [&](bool is_set, Setting setting) {
    if (is_set)
      given = given | setting;
  };
  add(s.rings || s.max_rings, Setting::rings);
  add(bool(s.ball_radius), Setting::ball_radius);
  add(bool(s.fit_degree), Setting::fit_degree);
  add(bool(s.extrapolation_order), Setting::extrapolation_order);
  add(bool(s.jet_degree), Setting::jet_degree);
  add(bool(s.monge_degree), Setting::monge_degree);
  add(bool(s.normal_method), Setting::normals);
  add(bool(s.given_normals), Setting::given_normals);
  add(bool(s.radius_selection), Setting::ball_radius_range);
  return given;
}

Integer_range integer_range(Setting setting)
{
  switch (setting) {
    case Setting::rings:
      return {1, 100, 1};
    case Setting::fit_degree:
      return {2, 4, 2};
    case Setting::extrapolation_order:
      return {1, 4, 1};
    case Setting::jet_degree: // 1 is a plane: CGAL's Monge form needs degree 2 at least
      return {2, 4, 2};
    case Setting::monge_degree:
      return {2, 4, 2};
    default:
      throw std::logic_error(std::string("ce_tool::integer_range: ") + setting_name(setting) + " is no integer");
  }
}

Outputs add_outputs(Mesh& mesh, const std::string& prefix)
{
  return {
    mesh.add_property_map<V, double>(prefix + "H").first, mesh.add_property_map<V, double>(prefix + "K").first,
    mesh.add_property_map<V, CE::Principal_curvatures_and_directions<Kernel>>(prefix + "pcd").first,
    mesh.add_property_map<V, CE::Estimation_status>(prefix + "status", CE::Estimation_status::not_estimable).first,
    mesh.add_property_map<V, double>(prefix + "reach").first};
}

void remove_outputs(Mesh& mesh, Outputs& outputs)
{
  mesh.remove_property_map(outputs.H);
  mesh.remove_property_map(outputs.K);
  mesh.remove_property_map(outputs.pcd);
  mesh.remove_property_map(outputs.status);
  mesh.remove_property_map(outputs.reach);
}

const std::vector<Method>& methods()
{
  // Every surface estimator reads the given normals and the normal method but curve
  // network, which reads the given normals only, and jet fitting, which fits its own frame.
  // Fields: name, label, settings read, quantities, parallel, tetrahedral input, CGAL's fit, run, reach.
  using E = CE::Estimator;
  static const std::vector<Method> all = {
    {"paraboloid", "paraboloid fit",
     Setting::rings | Setting::ball_radius | Setting::ball_radius_range | Setting::fit_degree | Setting::normals |
       Setting::given_normals,
     gives_all, true, true, false, run_method<E::paraboloid_fitting>, reach_of_method<E::paraboloid_fitting>},
    {"curve-network", "curve network", Setting::extrapolation_order | Setting::given_normals, gives_all, true, false,
     false, run_method<E::curve_network>, reach_of_method<E::curve_network>},
    {"gauss-map", "Gauss map", Setting::rings | Setting::ball_radius | Setting::normals | Setting::given_normals,
     gives_all, true, false, false, run_method<E::gauss_map>, reach_of_method<E::gauss_map>},
    {"taubin", "Taubin", Setting::rings | Setting::normals | Setting::given_normals, gives_all, true, false, false,
     run_method<E::taubin>, reach_of_method<E::taubin>},
    {"chen-schmitt", "Chen-Schmitt", Setting::rings | Setting::normals | Setting::given_normals, gives_all, true, false,
     false, run_method<E::chen_schmitt>, reach_of_method<E::chen_schmitt>},
    {"jet", "jet fitting",
     Setting::rings | Setting::ball_radius | Setting::ball_radius_range | Setting::jet_degree | Setting::monge_degree,
     gives_all, true, false, true, run_method<E::jet_fitting>, reach_of_method<E::jet_fitting>},
  };
  return all;
}

const Method* find_method(const std::string& name)
{
  for (const Method& m : methods())
    if (name == m.name)
      return &m;
  return nullptr;
}

namespace {

// Throws std::invalid_argument where `settings` holds a setting `method` does not read, or one out of its range.
void check(const Method& method, const Settings& settings)
{
  // The messages are built only on failure: a benchmark counts the allocations of a run.
  const auto refuse = [&](const std::string& what) {
    throw std::invalid_argument(std::string("curvature method '") + method.name + "': " + what);
  };
  for (unsigned bit = 1; bit <= static_cast<unsigned>(Setting::ball_radius_range); bit <<= 1)
    if ((given_settings(settings) & bit) && !(method.reads & bit))
      refuse(std::string("does not read ") + setting_name(Setting(bit)));
  if (settings.ball_radius && settings.radius_selection)
    refuse("ball_radius and ball_radius_range exclude each other");
  const auto check = [&](const std::optional<int>& value, Setting setting, int max) {
    const int min = integer_range(setting).min;
    if (value && (*value < min || *value > max))
      refuse(std::string(setting_name(setting)) + " must be in " + std::to_string(min) + ".." + std::to_string(max));
  };
  for (const auto& [value, setting] :
       {std::pair(settings.rings, Setting::rings), std::pair(settings.fit_degree, Setting::fit_degree),
        std::pair(settings.extrapolation_order, Setting::extrapolation_order),
        std::pair(settings.jet_degree, Setting::jet_degree)})
    check(value, setting, integer_range(setting).max);
  check(settings.monge_degree, Setting::monge_degree,
        settings.jet_degree.value_or(integer_range(Setting::jet_degree).default_value));
}

} // namespace

void run(const Method& method, const Mesh& mesh, const Settings& settings, const Outputs& outputs, int threads)
{
  check(method, settings);
  method.run(mesh, settings, outputs, threads);
}

CE::Neighborhood_reach reach(const Method& method, const Settings& settings)
{
  check(method, settings);
  return method.reach(settings);
}

} // namespace ce_tool
