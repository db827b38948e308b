// SPDX-License-Identifier: GPL-3.0-or-later
#include "surface_estimation.h"

#include "estimation_settings.h"

#include <CGAL/Curvature_estimation/internal/rings.h>
#include <CGAL/Curvature_estimation/mean_edge_length.h>

#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>

namespace ce_tool {

namespace {

Row failed_row()
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  return Row{nan, nan, nan, nan, {nan, nan, nan}, {nan, nan, nan}, CE::Estimation_status::not_estimable};
}

} // namespace

Row Surface_estimates::operator[](std::size_t i) const
{
  const V v = file_to_mesh[i];
  if (v == V() || maps.status[v] == CE::Estimation_status::not_estimable)
    return failed_row();
  const auto& c = maps.pcd[v];
  return Row{c.max_curvature,
             c.min_curvature,
             maps.H[v],
             maps.K[v],
             {c.max_direction.x(), c.max_direction.y(), c.max_direction.z()},
             {c.min_direction.x(), c.min_direction.y(), c.min_direction.z()},
             maps.status[v]};
}

std::array<double, 2> Surface_estimates::radius_and_noise(std::size_t i) const
{
  const V v = file_to_mesh[i];
  if (v == V() || maps.status[v] == CE::Estimation_status::not_estimable)
    return {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN()};
  return {radius_selection->radius[v], radius_selection->noise[v]};
}

double Surface_estimates::reach(std::size_t i) const
{
  const V v = file_to_mesh[i];
  return v == V() ? 0 : maps.reach[v];
}

Settings settings_of(const Options& o)
{
  Settings settings;
  if (!o.radius && !o.radius_range && o.method->reads_setting(Setting::rings)) {
    settings.rings = rings(o);
    settings.max_rings = max_rings(o);
  }
  settings.fit_degree = o.fit_degree;
  settings.extrapolation_order = o.order;
  settings.jet_degree = o.degree;
  settings.monge_degree = o.monge_degree;
  return settings;
}

Surface_estimates estimate(const Options& o, Mesh& mesh, std::vector<V> file_to_mesh,
                           const std::optional<Normal_map>& given_normals)
{
  Surface_estimates e;
  e.maps = add_outputs(mesh, "v:ce_");
  e.file_to_mesh = std::move(file_to_mesh);
  if (is_empty(mesh))
    return e;
  Settings settings = settings_of(o);
  if (o.radius) {
    e.mean_edge_length = CE::mean_edge_length(mesh);
    e.ball_radius = ball_radius(*o.radius, e.mean_edge_length);
    settings.ball_radius = e.ball_radius;
  } else if (o.radius_range) {
    e.mean_edge_length = CE::mean_edge_length(mesh);
    e.radius_selection = Settings::Radius_selection{
      radius_range(*o.radius_range, e.mean_edge_length, "the mean edge length of the mesh", "mesh units"),
      mesh.add_property_map<V, double>("v:ce_radius").first, mesh.add_property_map<V, double>("v:ce_noise").first};
    settings.radius_selection = e.radius_selection;
  }
  settings.given_normals = given_normals;
  e.seconds = timed_estimate([&] { run(*o.method, mesh, settings, e.maps, o.threads); });
  return e;
}

Ball_size mean_ball_size(const Mesh& mesh, double radius)
{
  CE::internal::Ring_collector<Mesh> ball;
  return mean_ball_size(num_vertices(mesh), [&](std::size_t i) {
    const V v(static_cast<Mesh::size_type>(i));
    const Point& center = mesh.point(v);
    ball.start(v, mesh);
    ball.grow_ball(mesh, radius * radius, [&](V w) { return CGAL::squared_distance(mesh.point(w), center); });
    return ball.ball_size();
  });
}

} // namespace ce_tool
