// SPDX-License-Identifier: GPL-3.0-or-later
// Surface estimation: which estimator --method picks, with which named
// parameters, and its outputs as one row per vertex of the input file.
#ifndef CE_TOOLS_SURFACE_ESTIMATION_H
#define CE_TOOLS_SURFACE_ESTIMATION_H

#include "command_line.h"
#include "kernel.h"
#include "soup_repair.h"

#include <CGAL/Curvature_estimation/Principal_curvatures_and_directions.h>

#include <array>
#include <vector>

namespace ce_tool {

struct Row
{
  double k_max, k_min, mean, gaussian;
  std::array<double, 3> d_max, d_min;
  CE::Estimation_status status;

  std::array<double, 10> values() const
  {
    return {k_max, k_min, mean, gaussian, d_max[0], d_max[1], d_max[2], d_min[0], d_min[1], d_min[2]};
  }
};

// The rows of the file's vertices (file_to_mesh from build_mesh), a failed row
// where a vertex is in no face or not estimable; `seconds` is the estimator's
// time. The estimator's output maps are added to `mesh` and removed after.
std::vector<Row> estimate(const Options& o, Mesh& mesh, const std::vector<V>& file_to_mesh, double& seconds);

} // namespace ce_tool

#endif // CE_TOOLS_SURFACE_ESTIMATION_H
