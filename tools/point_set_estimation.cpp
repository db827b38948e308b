// SPDX-License-Identifier: GPL-3.0-or-later
#include "point_set_estimation.h"

#include "registry.h"

#include <CGAL/Curvature_estimation/internal/point_set_search.h>
#include <CGAL/Curvature_estimation/point_set_curvatures.h>
#include <CGAL/property_map.h>

#include <Eigen/Core>

#include <cmath>
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

} // namespace

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
    std::vector<Eigen::Vector3d> coordinates;
    coordinates.reserve(n);
    for (const Point& p : input.points)
      coordinates.emplace_back(p.x(), p.y(), p.z());
    const Search search(coordinates, CGAL::Sequential_tag());
    e.mean_spacing = mean_spacing(search);
    e.radius = ball_radius(*o.radius, e.mean_spacing, "the mean distance to the nearest neighbor");
    Search::Found found;
    e.ball_size = mean_ball_size(n, [&](std::size_t i) {
      search.within(Search::Index(i), e.radius, found);
      return found.size() + 1;
    });
  } else {
    e.neighbors = o.neighbors ? std::size_t(*o.neighbors) : CE::internal::default_point_set_neighbors(degree);
  }
  run_point_set_curvatures(input.points, input.normals, e.neighbors,
                           o.radius ? std::optional<double>(e.radius) : std::nullopt, degree, false, o.threads, e);
  return e;
}

} // namespace ce_tool
