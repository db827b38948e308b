// SPDX-License-Identifier: GPL-3.0-or-later
#include "summary.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <utility>

namespace ce_tool {

namespace {

void print_range(const char* name, std::vector<double> values)
{
  if (values.empty()) {
    std::cout << name << ": no estimate\n";
    return;
  }
  // The median by selection, not a sort (a sort of 1M values took 5% of the tool's time).
  const auto median = values.begin() + std::ptrdiff_t(values.size() / 2);
  std::nth_element(values.begin(), median, values.end());
  const auto [min, max] = std::minmax_element(values.begin(), values.end());
  std::cout << name << ": min " << *min << ", median " << *median << ", max " << *max << '\n';
}

// --radius: the radius, and the mean number of vertices in a ball (`size`, over
// `vertices` vertices).
void print_ball(double radius, double mean_edge_length, const Ball_size& size, std::size_t vertices)
{
  std::ostringstream mean;
  mean << std::fixed << std::setprecision(1) << size.mean;
  std::cout << "radius: " << radius << " (" << radius / mean_edge_length << " mean edge lengths of " << mean_edge_length
            << ")\n"
            << "mean neighborhood: " << mean.str()
            << " vertices in a ball (the vertex included, before a fit widens it";
  if (size.sampled < vertices)
    std::cout << "; over " << size.sampled << " evenly spaced vertices";
  std::cout << ")\n";
}

// The min, quartiles and max of `values` in the input's units and in units of `h`
// (`units` names them), with `name`; `estimated`: the number of estimated vertices
// (`items`), which the line names where some have no value.
void print_quartiles(const char* name, std::vector<double> values, double h, const char* units, std::size_t estimated,
                     const char* items)
{
  if (values.empty()) {
    std::cout << name << ": no estimate\n";
    return;
  }
  std::sort(values.begin(), values.end());
  const auto at = [&](double q) { return values[std::size_t(std::lround(q * double(values.size() - 1)))]; };
  const double quantiles[] = {at(0), at(0.25), at(0.5), at(0.75), at(1)};
  const char* labels[] = {"min ", ", 25% ", ", median ", ", 75% ", ", max "};
  std::cout << name << ": ";
  for (std::size_t k = 0; k < 5; ++k)
    std::cout << labels[k] << quantiles[k];
  std::cout << " (in " << units << ':';
  for (std::size_t k = 0; k < 5; ++k)
    std::cout << (k == 0 ? " " : ", ") << quantiles[k] / h;
  std::cout << ')';
  if (values.size() < estimated)
    std::cout << ", over " << values.size() << " of " << estimated << " estimated " << items;
  std::cout << '\n';
}

// --radius auto: the range, and the distributions of the chosen radius and of the
// noise over the estimated vertices (`items`); `h` the unit of Nx, `units` its name.
template <typename Rows>
void print_radius_selection(const Rows& rows, std::pair<double, double> range, double h, const char* units,
                            const char* items)
{
  const auto [min, max] = range;
  std::cout << "radius range: " << min << " to " << max << " (" << min / h << " to " << max / h << ' ' << units
            << " of " << h << ")\n";
  std::vector<double> radii, noise;
  std::size_t estimated = 0;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const auto [radius, sigma] = rows.radius_and_noise(i);
    estimated += rows[i].status != CE::Estimation_status::not_estimable;
    if (std::isfinite(radius))
      radii.push_back(radius);
    if (std::isfinite(sigma))
      noise.push_back(sigma);
  }
  print_quartiles("chosen radius", radii, h, units, estimated, items);
  print_quartiles("noise (standard deviation)", noise, h, units, estimated, items);
}

// The summary's lines after the input's: time, ranges of H and K, status counts.
template <typename Rows>
void print_estimates(const Rows& rows, std::size_t vertices, double seconds, const char* item = "vertex")
{
  std::size_t ok = 0, widened = 0, fallback = 0, failed = 0;
  std::vector<double> H, K;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const auto r = rows[i];
    switch (r.status) {
      case CE::Estimation_status::ok:
        ++ok;
        break;
      case CE::Estimation_status::widened:
        ++widened;
        break;
      case CE::Estimation_status::fallback:
        ++fallback;
        break;
      default:
        ++failed;
        continue;
    }
    H.push_back(r.mean);
    K.push_back(r.gaussian);
  }
  std::cout << "time: " << seconds * 1e3 << " ms";
  if (vertices > 0)
    std::cout << " (" << seconds * 1e9 / double(vertices) << " ns per " << item << ")";
  std::cout << '\n';
  print_range("mean curvature H", H);
  print_range("Gaussian curvature K", K);
  std::cout << "ok: " << ok << ", widened: " << widened;
  if (fallback > 0) // the curve network, the paraboloid fit and jet fitting have one
    std::cout << ", fallback: " << fallback;
  std::cout << ", failed (not estimable): " << failed << '\n';
}

} // namespace

void print_surface_summary(const Options& o, const Soup& soup, const Mesh& mesh, const Surface_estimates& rows)
{
  std::cout << "input: " << o.input << '\n'
            << "vertices: " << soup.points.size() << " in the file (" << num_vertices(mesh) << " in the mesh, "
            << num_faces(mesh) << " faces)\n"
            << "method: " << o.method->name << '\n';
  if (rows.ball_radius > 0)
    print_ball(rows.ball_radius, rows.mean_edge_length, mean_ball_size(mesh, rows.ball_radius), num_vertices(mesh));
  if (rows.radius_selection)
    print_radius_selection(rows, rows.radius_selection->range, rows.mean_edge_length, "mean edge lengths", "vertices");
  print_estimates(rows, num_vertices(mesh), rows.seconds);
}

void print_tetrahedral_summary(const Options& o, const Tetrahedral_input& input, const Tetrahedral_estimates& estimates)
{
  const std::size_t vertices = input.mesh.points.size();
  std::cout << "input: " << o.input << '\n'
            << "vertices: " << vertices << '\n'
            << "tetrahedra: " << input.mesh.cells.size() << '\n'
            << "method: " << o.method->name << " (hypersurface of R^4)\n";
  if (estimates.ball_radius > 0)
    print_ball(estimates.ball_radius, estimates.mean_edge_length, estimates.ball_size, vertices);
  print_estimates(estimates.rows, vertices, estimates.seconds);
}

void print_point_set_summary(const Options& o, const Point_set_input& input, const Point_set_estimates& e)
{
  const std::size_t n = input.points.size();
  std::cout << "input: " << o.input << '\n'
            << "points: " << n << (e.given_normals ? " with normals" : "") << '\n'
            << "method: point-set fit of degree " << o.fit_degree.value_or(2) << '\n';
  if (e.radius > 0) {
    std::ostringstream mean;
    mean << std::fixed << std::setprecision(1) << e.ball_size.mean;
    std::cout << "neighbors: the points within " << e.radius << " (" << e.radius / e.mean_spacing
              << " mean distances to the nearest neighbor of " << e.mean_spacing << ")\n"
              << "mean neighborhood: " << mean.str() << " points in a ball (the point included, before a fit widens it";
    if (e.ball_size.sampled < n)
      std::cout << "; over " << e.ball_size.sampled << " evenly spaced points";
    std::cout << ")\n";
  } else {
    std::cout << "neighbors: the " << e.neighbors << " nearest points"
              << (e.radius_range ? ", or the ball of the chosen radius" : "") << '\n';
  }
  if (e.radius_range)
    print_radius_selection(e, *e.radius_range, e.mean_spacing, "mean distances to the nearest neighbor", "points");
  if (e.given_normals) {
    std::cout << "normals: the file's, which orient the result\n";
  } else {
    std::size_t components = 0, doubtful = 0;
    for (std::size_t i = 0; i < n; ++i)
      if (e.component[i] != std::size_t(-1)) {
        components = std::max(components, e.component[i] + 1);
        doubtful += e.confidence[i] < low_orientation_confidence;
      }
    std::cout << "normals: " << (input.zero_normals_ignored ? "the file's are all zero, ignored; " : "")
              << "fitted, oriented by spanning-tree propagation: " << components << " component"
              << (components == 1 ? "" : "s") << " (each oriented on its own), " << doubtful
              << " points with orientation confidence below " << low_orientation_confidence
              << " (where the sign may flip)\n";
  }
  print_estimates(e, n, e.seconds, "point");
}

} // namespace ce_tool
