// SPDX-License-Identifier: GPL-3.0-or-later
// curvature_estimation._core.point_set_curvatures: the library's point_set_curvatures over
// an (n, 3) array of points.
#ifndef CE_PYTHON_POINT_SETS_H
#define CE_PYTHON_POINT_SETS_H

#include <pybind11/pybind11.h>

#include <optional>
#include <string>

namespace ce_python {

// The tuple k_max, k_min, mean, gaussian, d_max, d_min, status, normal (the fitted unit
// normal), then (radius, noise) with radius "auto" or "auto:A:B" (the tool's --radius
// auto on a point set), else None; number_of_neighbors and neighbor_radius as the library
// takes them (not both; neither: its default for the fit degree), the normals given or None.
pybind11::tuple point_set_curvatures(const pybind11::handle& points, std::optional<long long> number_of_neighbors,
                                     std::optional<double> neighbor_radius, const std::optional<std::string>& radius,
                                     int fit_degree, const pybind11::object& normals, bool unsigned_curvatures,
                                     int threads);

// The library's neighborhood_reach of point_set_curvatures with these settings: the tuple
// (neighbors, widened neighbors, distance, grown distance).
pybind11::tuple point_set_reach(std::optional<long long> number_of_neighbors, std::optional<double> neighbor_radius,
                                int fit_degree);

} // namespace ce_python

#endif // CE_PYTHON_POINT_SETS_H
