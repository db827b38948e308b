// SPDX-License-Identifier: GPL-3.0-or-later
#include "point_sets.h"

#include "arrays.h"

#include "command_line.h"
#include "kernel.h"
#include "point_set_estimation.h"
#include "registry.h"

#include <CGAL/Curvature_estimation/point_set_curvatures.h>
#include <CGAL/property_map.h>

#include <cstdint>
#include <limits>
#include <numeric>
#include <optional>
#include <string>
#include <utility>
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

  std::vector<std::size_t> indices(n);
  std::iota(indices.begin(), indices.end(), std::size_t(0));
  std::vector<double> H(n), K(n);
  std::vector<CE::Principal_curvatures_and_directions<Kernel>> pcd(n);
  std::vector<CE::Estimation_status> status(n, CE::Estimation_status::not_estimable);
  std::vector<Kernel::Vector_3> normal(n);
  std::vector<double> chosen_radius(range ? n : 0), noise(range ? n : 0);
  {
    py::gil_scoped_release release;
    const std::optional<std::pair<double, double>> bounds =
      range
        ? std::optional<std::pair<double, double>>(ce_tool::point_set_radius_range(*range, ce_tool::mean_spacing(p)))
        : std::nullopt;
    const auto base = CE::parameters::point_map(CGAL::make_property_map(p))
                        .vertex_mean_curvature_map(CGAL::make_property_map(H))
                        .vertex_Gaussian_curvature_map(CGAL::make_property_map(K))
                        .vertex_principal_curvatures_and_directions_map(CGAL::make_property_map(pcd))
                        .vertex_estimation_status_map(CGAL::make_property_map(status))
                        .estimated_normal_map(CGAL::make_property_map(normal))
                        .fit_degree(fit_degree)
                        .unsigned_curvatures(unsigned_curvatures);
    const auto run = [&](const auto& np) {
      ce_tool::with_threads(threads, [&](auto tag) { CE::point_set_curvatures<decltype(tag)>(indices, np); });
    };
    // The library's default number_of_neighbors, passed as such: one instantiation fewer.
    const auto with_neighborhood = [&](const auto& np) {
      const std::size_t k =
        number_of_neighbors ? std::size_t(*number_of_neighbors) : CE::internal::default_point_set_neighbors(fit_degree);
      if (neighbor_radius)
        run(np.neighbor_radius(*neighbor_radius));
      else if (bounds)
        run(np.number_of_neighbors(k)
              .ball_radius_range(*bounds)
              .vertex_ball_radius_map(CGAL::make_property_map(chosen_radius))
              .vertex_noise_map(CGAL::make_property_map(noise)));
      else
        run(np.number_of_neighbors(k));
    };
    if (given.empty())
      with_neighborhood(base);
    else
      with_neighborhood(base.normal_map(CGAL::make_property_map(given)));
  }

  auto k_max = new_array(n), k_min = new_array(n), mean = new_array(n), gaussian = new_array(n);
  auto d_max = new_array(n, 3), d_min = new_array(n, 3), normals_out = new_array(n, 3);
  py::array_t<std::uint8_t> status_out(static_cast<py::ssize_t>(n));
  for (std::size_t i = 0; i < n; ++i) {
    k_max.mutable_at(i) = pcd[i].max_curvature;
    k_min.mutable_at(i) = pcd[i].min_curvature;
    mean.mutable_at(i) = H[i];
    gaussian.mutable_at(i) = K[i];
    for (int c = 0; c < 3; ++c) {
      d_max.mutable_at(i, c) = pcd[i].max_direction[c];
      d_min.mutable_at(i, c) = pcd[i].min_direction[c];
      normals_out.mutable_at(i, c) = normal[i][c];
    }
    status_out.mutable_at(i) = static_cast<std::uint8_t>(status[i]);
  }
  py::object selection = py::none();
  if (range) {
    auto radius_out = new_array(n), noise_out = new_array(n);
    for (std::size_t i = 0; i < n; ++i) { // NaN where not estimated, as the tool's rows
      const bool estimated = status[i] != CE::Estimation_status::not_estimable;
      radius_out.mutable_at(i) = estimated ? chosen_radius[i] : std::numeric_limits<double>::quiet_NaN();
      noise_out.mutable_at(i) = estimated ? noise[i] : std::numeric_limits<double>::quiet_NaN();
    }
    selection = py::make_tuple(radius_out, noise_out);
  }
  return py::make_tuple(k_max, k_min, mean, gaussian, d_max, d_min, status_out, normals_out, selection);
}

} // namespace ce_python
