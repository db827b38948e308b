// SPDX-License-Identifier: GPL-3.0-or-later
#include "tetrahedral.h"

#include "estimation_settings.h"
#include "input_files.h"
#include "mesh_readers.h"
#include "tool_error.h"

#include <CGAL/Curvature_estimation/hypersurface_paraboloid_fitting.h>
#include <CGAL/Curvature_estimation/internal/rings.h>
#include <CGAL/property_map.h>

#include <Eigen/Core>

#include <cmath>
#include <cstddef>
#include <filesystem>
#include <string_view>
#include <system_error>
#include <utility>
#include <vector>

namespace ce_tool {

namespace {

namespace fs = std::filesystem;

// The .sol beside the .mesh (same name, extension .sol) unless --scalars names one.
std::string scalars_path(const std::string& mesh_path, const std::string& scalars)
{
  if (!scalars.empty()) {
    if (lower_extension(scalars) != ".sol")
      fail("--scalars '" + scalars + "' must be a Medit .sol file", 2);
    return scalars;
  }
  const std::string beside = fs::path(mesh_path).replace_extension(".sol").string();
  std::error_code ec;
  if (!fs::exists(beside, ec))
    fail("no scalar field for '" + mesh_path + "': '" + beside +
         "' does not exist (name a Medit .sol with --scalars FILE.sol)");
  return beside;
}

// The vertices' points in R^4, (x, y, z, f), in the .mesh's order.
std::vector<Eigen::Vector4d> graph_points(const Tetrahedral_input& input)
{
  std::vector<Eigen::Vector4d> points;
  points.reserve(input.mesh.points.size());
  for (std::size_t v = 0; v < input.mesh.points.size(); ++v) {
    const Point& p = input.mesh.points[v];
    points.emplace_back(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()), input.scalars[v]);
  }
  return points;
}

// The tetrahedra's edges as a graph of points of R^4, which --radius measures.
struct Graph
{
  explicit Graph(const Tetrahedral_input& input)
      : stars(input.mesh)
      , points(graph_points(input))
  {}

  // The mean length of the edges (each edge once), over those of finite length; 0
  // where there is none.
  double mean_edge_length() const
  {
    double sum = 0;
    std::size_t count = 0;
    for (std::size_t v = 0; v < stars.size(); ++v)
      for (std::size_t k = stars.neighbor_offsets[v]; k < stars.neighbor_offsets[v + 1]; ++k) {
        const std::size_t w = stars.neighbors[k];
        const double length = (points[w] - points[v]).norm();
        if (w > v && std::isfinite(length)) {
          sum += length;
          ++count;
        }
      }
    return count != 0 ? sum / double(count) : 0.0;
  }

  Ball_size mean_ball_size(double radius) const
  {
    CE::internal::Tetrahedral_ring_collector ball;
    return ce_tool::mean_ball_size(stars.size(), [&](std::size_t v) {
      ball.start(v, stars);
      ball.grow_ball(stars, radius * radius, [&](std::size_t w) { return (points[w] - points[v]).squaredNorm(); });
      return ball.ball_size();
    });
  }

  const CE::Tetrahedral_complex_stars<Tetrahedral_mesh> stars;
  const std::vector<Eigen::Vector4d> points;
};

} // namespace

std::optional<std::size_t> orient_tetrahedra(Tetrahedral_mesh& mesh)
{
  for (std::size_t t = 0; t < mesh.cells.size(); ++t) {
    auto& c = mesh.cells[t];
    const auto& p = mesh.points;
    switch (CGAL::orientation(p[c[0]], p[c[1]], p[c[2]], p[c[3]])) {
      case CGAL::COPLANAR:
        return t;
      case CGAL::NEGATIVE:
        std::swap(c[2], c[3]);
        break;
      default:
        break;
    }
  }
  return std::nullopt;
}

Tetrahedral_input read_tetrahedral_input(const std::string& mesh_path, const std::string& scalars)
{
  const Tetrahedral_mesh_data data =
    read_strictly(mesh_path, [](std::string_view text) { return read_medit_mesh(text); });
  Tetrahedral_input input;
  input.mesh.points.reserve(data.points.size());
  for (const auto& p : data.points)
    input.mesh.points.emplace_back(p[0], p[1], p[2]);
  input.mesh.cells = data.cells;
  if (const auto flat = orient_tetrahedra(input.mesh))
    fail("degenerate file '" + mesh_path + "': tetrahedron " + std::to_string(*flat + 1) + " has zero volume");
  const std::size_t vertices = data.points.size();
  input.scalars = read_strictly(scalars_path(mesh_path, scalars),
                                [vertices](std::string_view text) { return read_medit_sol(text, vertices); });
  return input;
}

Tetrahedral_estimates estimate_tetrahedral(const Options& o, const Tetrahedral_input& input)
{
  const std::size_t n = input.mesh.points.size();
  std::vector<CE::Hypersurface_principal_curvatures_and_directions<std::array<double, 4>>> principal(n);
  std::vector<double> H(n), K(n);
  std::vector<CE::Estimation_status> status(n, CE::Estimation_status::not_estimable);
  const auto points =
    CE::make_graph_point_map(CE::Tetrahedral_complex_traits<Tetrahedral_mesh>::default_point_map(input.mesh),
                             CGAL::make_property_map(input.scalars));
  const auto np = CE::parameters::vertex_point_map(points)
                    .vertex_principal_curvatures_and_directions_map(CGAL::make_property_map(principal))
                    .vertex_mean_curvature_map(CGAL::make_property_map(H))
                    .vertex_Gaussian_curvature_map(CGAL::make_property_map(K))
                    .vertex_estimation_status_map(CGAL::make_property_map(status))
                    .fit_degree(o.fit_degree.value_or(2));
  Tetrahedral_estimates e;
  if (o.radius) {
    const Graph graph(input);
    e.mean_edge_length = graph.mean_edge_length();
    e.ball_radius = ball_radius(*o.radius, e.mean_edge_length);
    e.ball_size = graph.mean_ball_size(e.ball_radius);
  }
  e.seconds = timed_estimate([&] {
    with_threads(o.threads, [&](auto tag) {
      using Tag = decltype(tag);
      if (e.ball_radius > 0)
        CE::hypersurface_paraboloid_fitting_curvatures<Tag>(input.mesh, np.ball_radius(e.ball_radius));
      else
        CE::hypersurface_paraboloid_fitting_curvatures<Tag>(
          input.mesh, np.neighborhood_rings(rings(o)).max_neighborhood_rings(max_rings(o)));
    });
  });

  e.rows.resize(n);
  for (std::size_t v = 0; v < n; ++v)
    e.rows[v] = {
      principal[v].max_curvature, principal[v].mid_curvature, principal[v].min_curvature, H[v], K[v], status[v]};
  return e;
}

} // namespace ce_tool
