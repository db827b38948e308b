// SPDX-License-Identifier: GPL-3.0-or-later
#include "point_set_estimation.h"

#include "registry.h"

#include <CGAL/Curvature_estimation/internal/point_set_search.h>
#include <CGAL/Curvature_estimation/point_set_curvatures.h>
#include <CGAL/property_map.h>

#include <Eigen/Core>

#include <cmath>
#include <limits>
#include <numeric>

namespace ce_tool {

namespace {

using Search = CE::internal::Point_set_search;

// The mean over the points of the distance to the nearest other point (0 for a
// point with a duplicate), over the points that have one.
double mean_spacing(const Search& search)
{
  Search::Found found;
  double sum = 0;
  std::size_t counted = 0;
  for (std::size_t i = 0; i < search.size(); ++i) {
    search.nearest(Search::Index(i), 1, found);
    if (!found.empty()) {
      sum += std::sqrt(found.front().first);
      ++counted;
    }
  }
  return counted == 0 ? 0.0 : sum / double(counted);
}

std::vector<Eigen::Vector3d> coordinates_of(const std::vector<Point>& points)
{
  std::vector<Eigen::Vector3d> coordinates;
  coordinates.reserve(points.size());
  for (const Point& p : points)
    coordinates.emplace_back(p.x(), p.y(), p.z());
  return coordinates;
}

const char* const spacing_name = "the mean distance to the nearest neighbor";

} // namespace

double mean_spacing(const std::vector<Point>& points)
{
  return mean_spacing(Search(coordinates_of(points), CGAL::Sequential_tag()));
}

std::pair<double, double> point_set_radius_range(const Radius_range& range, double spacing)
{
  return radius_range(range.given ? range : default_point_set_radius_range, spacing, spacing_name, "the points' units");
}

Point_set_row Point_set_estimates::operator[](std::size_t i) const
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  if (status[i] == CE::Estimation_status::not_estimable)
    return {{nan, nan, nan, nan, {nan, nan, nan}, {nan, nan, nan}, status[i]}, {nan, nan, nan}};
  const auto& c = pcd[i];
  return {{c.max_curvature,
           c.min_curvature,
           H[i],
           K[i],
           {c.max_direction.x(), c.max_direction.y(), c.max_direction.z()},
           {c.min_direction.x(), c.min_direction.y(), c.min_direction.z()},
           status[i]},
          {normal[i].x(), normal[i].y(), normal[i].z()}};
}

std::array<double, 2> Point_set_estimates::radius_and_noise(std::size_t i) const
{
  if (status[i] == CE::Estimation_status::not_estimable)
    return {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN()};
  return {chosen_radius[i], noise[i]};
}

void run_point_set_curvatures(const std::vector<Point>& points, const std::vector<Kernel::Vector_3>& normals,
                              std::size_t neighbors, std::optional<double> radius, int degree, bool unsigned_curvatures,
                              int threads, Point_set_estimates& e)
{
  const std::size_t n = points.size();
  e.H.assign(n, 0);
  e.K.assign(n, 0);
  e.pcd.resize(n);
  e.status.assign(n, CE::Estimation_status::not_estimable);
  e.normal.resize(n);
  e.component.assign(n, std::size_t(-1));
  e.confidence.assign(n, 0);
  e.chosen_radius.assign(e.radius_range ? n : 0, 0);
  e.noise.assign(e.radius_range ? n : 0, 0);
  e.given_normals = !normals.empty();
  std::vector<std::size_t> indices(n);
  std::iota(indices.begin(), indices.end(), std::size_t(0));
  const auto base = CE::parameters::point_map(CGAL::make_property_map(points))
                      .vertex_mean_curvature_map(CGAL::make_property_map(e.H))
                      .vertex_Gaussian_curvature_map(CGAL::make_property_map(e.K))
                      .vertex_principal_curvatures_and_directions_map(CGAL::make_property_map(e.pcd))
                      .vertex_estimation_status_map(CGAL::make_property_map(e.status))
                      .estimated_normal_map(CGAL::make_property_map(e.normal))
                      .orientation_component_map(CGAL::make_property_map(e.component))
                      .orientation_confidence_map(CGAL::make_property_map(e.confidence))
                      .fit_degree(degree)
                      .unsigned_curvatures(unsigned_curvatures);
  const auto run = [&](const auto& np) {
    e.seconds = timed_estimate(
      [&] { with_threads(threads, [&](auto tag) { CE::point_set_curvatures<decltype(tag)>(indices, np); }); });
  };
  const auto with_neighborhood = [&](const auto& np) {
    if (radius)
      run(np.neighbor_radius(*radius));
    else if (e.radius_range)
      run(np.number_of_neighbors(neighbors)
            .ball_radius_range(*e.radius_range)
            .vertex_ball_radius_map(CGAL::make_property_map(e.chosen_radius))
            .vertex_noise_map(CGAL::make_property_map(e.noise)));
    else
      run(np.number_of_neighbors(neighbors));
  };
  if (e.given_normals)
    with_neighborhood(base.normal_map(CGAL::make_property_map(normals)));
  else
    with_neighborhood(base);
}

Point_set_estimates estimate_point_set(const Options& o, const Point_set_input& input)
{
  const std::size_t n = input.points.size();
  Point_set_estimates e;
  const int degree = o.fit_degree.value_or(integer_range(Setting::fit_degree).default_value);
  if (o.radius) {
    const Search search(coordinates_of(input.points), CGAL::Sequential_tag());
    e.mean_spacing = mean_spacing(search);
    e.radius = ball_radius(*o.radius, e.mean_spacing, spacing_name);
    Search::Found found;
    e.ball_size = mean_ball_size(n, [&](std::size_t i) {
      search.within(Search::Index(i), e.radius, found);
      return found.size() + 1;
    });
  } else {
    e.neighbors = o.neighbors ? std::size_t(*o.neighbors) : CE::internal::default_point_set_neighbors(degree);
    if (o.radius_range) {
      e.mean_spacing = mean_spacing(input.points);
      e.radius_range = point_set_radius_range(*o.radius_range, e.mean_spacing);
    }
  }
  run_point_set_curvatures(input.points, input.normals, e.neighbors,
                           o.radius ? std::optional<double>(e.radius) : std::nullopt, degree, false, o.threads, e);
  return e;
}

} // namespace ce_tool
