// SPDX-License-Identifier: GPL-3.0-or-later
#include "point_sets.h"

#include "arrays.h"

#include "command_line.h"
#include "kernel.h"
#include "point_set_estimation.h"

#include <CGAL/Curvature_estimation/neighborhood_reach.h>
#include <CGAL/Curvature_estimation/point_set_curvatures.h>

#include <array>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace ce_python {

using ce_tool::Kernel;
namespace CE = CGAL::Curvature_estimation;

py::tuple point_set_curvatures(const py::handle& points, std::optional<long long> number_of_neighbors,
                               std::optional<double> neighbor_radius, const std::optional<std::string>& radius,
                               int fit_degree, const py::object& normals, bool unsigned_curvatures, int threads)
{
  if (number_of_neighbors && neighbor_radius)
    refuse("give number_of_neighbors or neighbor_radius, not both");
  if (radius && neighbor_radius)
    refuse("give neighbor_radius or radius, not both");
  const std::optional<ce_tool::Radius_range> range =
    radius ? std::optional<ce_tool::Radius_range>(ce_tool::parse_radius_range("radius", *radius)) : std::nullopt;
  if (number_of_neighbors && *number_of_neighbors < 0)
    refuse("number_of_neighbors must be at least 3, got " + std::to_string(*number_of_neighbors));
  threads = thread_count(threads);
  const Float_array xyz = real_array(points, "points", 3);
  const std::size_t n = static_cast<std::size_t>(xyz.shape(0));
  std::vector<ce_tool::Point> p;
  p.reserve(n);
  for (std::size_t i = 0; i < n; ++i)
    p.emplace_back(xyz.at(i, 0), xyz.at(i, 1), xyz.at(i, 2));
  std::vector<Kernel::Vector_3> given;
  if (!normals.is_none()) {
    const Float_array values = real_array(normals, "normals", 3);
    if (static_cast<std::size_t>(values.shape(0)) != n)
      refuse("normals must have a row per point (" + std::to_string(n) + "), got " + std::to_string(values.shape(0)));
    given.reserve(n);
    for (std::size_t i = 0; i < n; ++i)
      given.emplace_back(values.at(i, 0), values.at(i, 1), values.at(i, 2));
  }

  ce_tool::Point_set_estimates e;
  {
    py::gil_scoped_release release;
    if (range)
      e.radius_range = ce_tool::point_set_radius_range(*range, ce_tool::mean_spacing(p));
    // The library's default number_of_neighbors, passed as such: one instantiation fewer.
    ce_tool::run_point_set_curvatures(p, given,
                                      number_of_neighbors ? std::size_t(*number_of_neighbors)
                                                          : CE::internal::default_point_set_neighbors(fit_degree),
                                      neighbor_radius, fit_degree, unsigned_curvatures, threads, e);
  }

  auto k_max = new_array(n), k_min = new_array(n), mean = new_array(n), gaussian = new_array(n);
  auto d_max = new_array(n, 3), d_min = new_array(n, 3), normals_out = new_array(n, 3);
  py::array_t<std::uint8_t> status_out(static_cast<py::ssize_t>(n));
  for (std::size_t i = 0; i < n; ++i) {
    k_max.mutable_at(i) = e.pcd[i].max_curvature;
    k_min.mutable_at(i) = e.pcd[i].min_curvature;
    mean.mutable_at(i) = e.H[i];
    gaussian.mutable_at(i) = e.K[i];
    for (int c = 0; c < 3; ++c) {
      d_max.mutable_at(i, c) = e.pcd[i].max_direction[c];
      d_min.mutable_at(i, c) = e.pcd[i].min_direction[c];
      normals_out.mutable_at(i, c) = e.normal[i][c];
    }
    status_out.mutable_at(i) = static_cast<std::uint8_t>(e.status[i]);
  }
  py::object selection = py::none();
  if (range) {
    auto radius_out = new_array(n), noise_out = new_array(n);
    for (std::size_t i = 0; i < n; ++i) { // NaN where not estimated, as the tool's rows
      const std::array<double, 2> values = e.radius_and_noise(i);
      radius_out.mutable_at(i) = values[0];
      noise_out.mutable_at(i) = values[1];
    }
    selection = py::make_tuple(radius_out, noise_out);
  }
  return py::make_tuple(k_max, k_min, mean, gaussian, d_max, d_min, status_out, normals_out, selection);
}

py::tuple point_set_reach(std::optional<long long> number_of_neighbors, std::optional<double> neighbor_radius,
                          int fit_degree)
{
  if (number_of_neighbors && neighbor_radius)
    refuse("give number_of_neighbors or neighbor_radius, not both");
  if (number_of_neighbors && *number_of_neighbors < 0)
    refuse("number_of_neighbors must be at least 3, got " + std::to_string(*number_of_neighbors));
  const auto degree = CE::parameters::fit_degree(fit_degree);
  CE::Neighborhood_reach r;
  try {
    if (neighbor_radius)
      r = CE::neighborhood_reach(CE::Estimator::point_set, degree.neighbor_radius(*neighbor_radius));
    else if (number_of_neighbors)
      r =
        CE::neighborhood_reach(CE::Estimator::point_set, degree.number_of_neighbors(std::size_t(*number_of_neighbors)));
    else
      r = CE::neighborhood_reach(CE::Estimator::point_set, degree);
  } catch (const std::invalid_argument& e) {
    refuse(e.what());
  }
  return py::make_tuple(r.neighbors, r.widened_neighbors, r.distance, r.grown_distance);
}

} // namespace ce_python
