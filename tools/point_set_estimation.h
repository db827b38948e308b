// SPDX-License-Identifier: GPL-3.0-or-later
// Point-set estimation: the library's point_set_curvatures with the options'
// neighborhood (--neighbors K, --radius R|Nx with N times the mean distance to the
// nearest neighbor, or --radius auto[:A:B] with A and B so) and fit degree, one row
// per point of the file.
#ifndef CE_TOOLS_POINT_SET_ESTIMATION_H
#define CE_TOOLS_POINT_SET_ESTIMATION_H

#include "command_line.h"
#include "estimation_settings.h"
#include "kernel.h"
#include "point_set_input.h"
#include "surface_estimation.h"

#include <CGAL/Curvature_estimation/Principal_curvatures_and_directions.h>

#include <array>
#include <cstddef>
#include <optional>
#include <utility>
#include <vector>

namespace ce_tool {

// A point's row: the mesh's row, then the unit normal the signs refer to.
struct Point_set_row : Row
{
  std::array<double, 3> normal;

  std::array<double, 13> values() const
  {
    return {k_max,    k_min,    mean,     gaussian,  d_max[0],  d_max[1], d_max[2],
            d_min[0], d_min[1], d_min[2], normal[0], normal[1], normal[2]};
  }
};

// The confidence below which the summary counts a point's orientation as doubtful.
constexpr double low_orientation_confidence = 0.1;

struct Point_set_estimates
{
  std::vector<double> H, K;
  std::vector<CE::Principal_curvatures_and_directions<Kernel>> pcd;
  std::vector<CE::Estimation_status> status;
  std::vector<Kernel::Vector_3> normal; // the estimated normal, oriented as the result
  std::vector<std::size_t> component;   // of the propagation; std::size_t(-1) where not oriented
  std::vector<double> confidence;       // of the propagation's orientation, in [0, 1]
  bool given_normals = false;           // the file's normals oriented the result
  double seconds = 0;                   // the estimator's time
  std::size_t neighbors = 0;            // number_of_neighbors; 0 with --radius
  // With --radius: the radius and the mean distance to the nearest neighbor, and the
  // mean number of points within the radius (the point included); zeros without it.
  double radius = 0, mean_spacing = 0;
  Ball_size ball_size;
  // With --radius auto (mean_spacing too): the range, and the radius chosen and the noise per point.
  std::optional<std::pair<double, double>> radius_range;
  std::vector<double> chosen_radius, noise;

  std::size_t size() const { return status.size(); }
  Point_set_row operator[](std::size_t i) const;
  // With --radius auto: the chosen radius and the noise of point i; NaN where not estimated.
  std::array<double, 2> radius_and_noise(std::size_t i) const;
};

Point_set_estimates estimate_point_set(const Options& o, const Point_set_input& input);

// The library's point_set_curvatures on `points`, as the tool and the Python module call it:
// `normals` none, or one per point (given, they orient the result); the `neighbors` nearest
// points or, with a `radius`, the points within it; with e.radius_range set (points' units),
// the radius chosen per point in that range from about the `neighbors` nearest; `threads` as
// with_threads takes it. Fills e's values, statuses, normals, orientation and seconds, and
// with e.radius_range its chosen_radius and noise.
void run_point_set_curvatures(const std::vector<Point>& points, const std::vector<Kernel::Vector_3>& normals,
                              std::size_t neighbors, std::optional<double> radius, int degree, bool unsigned_curvatures,
                              int threads, Point_set_estimates& e);

// The mean over the points of the distance to the nearest other point: the unit of Nx.
double mean_spacing(const std::vector<Point>& points);

// --radius auto[:A:B] on points of that mean spacing, in their units (auto alone:
// default_point_set_radius_range). Fails where A > B.
std::pair<double, double> point_set_radius_range(const Radius_range& range, double spacing);

} // namespace ce_tool

#endif // CE_TOOLS_POINT_SET_ESTIMATION_H
