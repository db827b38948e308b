// SPDX-License-Identifier: GPL-3.0-or-later
#include "surface_estimation.h"

#include "estimation_settings.h"

#include <CGAL/Curvature_estimation.h>
#include <CGAL/Curvature_estimation/internal/rings.h>
#include <CGAL/Curvature_estimation/mean_edge_length.h>

#include <algorithm>
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

// The paraboloid or jet fit (the methods that take a ball) with `np`'s neighborhood.
template <typename Tag, typename NamedParameters>
void run_fit(const Options& o, const Mesh& mesh, const NamedParameters& np)
{
  if (o.method == Method::paraboloid)
    CE::paraboloid_fitting_curvatures<Tag>(mesh, np.fit_degree(o.fit_degree.value_or(2)));
  else
    CE::jet_fitting_curvatures<Tag>(mesh, np.jet_degree(o.degree.value_or(2)).monge_degree(o.monge_degree.value_or(2)));
}

template <typename Tag>
void run_estimator(const Options& o, const Mesh& mesh, double ball_radius, Mesh::Property_map<V, double> H,
                   Mesh::Property_map<V, double> K,
                   Mesh::Property_map<V, CE::Principal_curvatures_and_directions<Kernel>> pcd,
                   Mesh::Property_map<V, CE::Estimation_status> status)
{
  const auto np = CE::parameters::vertex_mean_curvature_map(H)
                    .vertex_Gaussian_curvature_map(K)
                    .vertex_principal_curvatures_and_directions_map(pcd)
                    .vertex_estimation_status_map(status);
  const auto ring_np = with_rings(o, np);
  switch (o.method) {
    case Method::paraboloid:
    case Method::jet:
      if (ball_radius > 0)
        run_fit<Tag>(o, mesh, np.ball_radius(ball_radius));
      else
        run_fit<Tag>(o, mesh, ring_np);
      break;
    case Method::gauss_map:
      if (ball_radius > 0)
        CE::gauss_map_curvatures<Tag>(mesh, np.ball_radius(ball_radius));
      else
        CE::gauss_map_curvatures<Tag>(mesh, ring_np);
      break;
    case Method::taubin:
      CE::taubin_curvatures<Tag>(mesh, ring_np);
      break;
    case Method::chen_schmitt:
      CE::chen_schmitt_curvatures<Tag>(mesh, ring_np);
      break;
    case Method::curve_network:
      CE::curve_network_curvatures<Tag>(mesh, np.extrapolation_order(o.order.value_or(1)));
      break;
  }
}

} // namespace

Row Surface_estimates::operator[](std::size_t i) const
{
  const V v = file_to_mesh[i];
  if (v == V() || status[v] == CE::Estimation_status::not_estimable)
    return failed_row();
  const auto& c = pcd[v];
  return Row{c.max_curvature,
             c.min_curvature,
             H[v],
             K[v],
             {c.max_direction.x(), c.max_direction.y(), c.max_direction.z()},
             {c.min_direction.x(), c.min_direction.y(), c.min_direction.z()},
             status[v]};
}

Surface_estimates estimate(const Options& o, Mesh& mesh, std::vector<V> file_to_mesh)
{
  Surface_estimates e;
  e.H = mesh.add_property_map<V, double>("v:ce_H").first;
  e.K = mesh.add_property_map<V, double>("v:ce_K").first;
  e.pcd = mesh.add_property_map<V, CE::Principal_curvatures_and_directions<Kernel>>("v:ce_pcd").first;
  e.status = mesh.add_property_map<V, CE::Estimation_status>("v:ce_status", CE::Estimation_status::not_estimable).first;
  e.file_to_mesh = std::move(file_to_mesh);
  if (is_empty(mesh))
    return e;
  if (o.radius) {
    e.mean_edge_length = CE::mean_edge_length(mesh);
    e.ball_radius = ball_radius(*o.radius, e.mean_edge_length);
  }
  e.seconds = run_with_threads(
    o.threads, [&](auto tag) { run_estimator<decltype(tag)>(o, mesh, e.ball_radius, e.H, e.K, e.pcd, e.status); });
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
