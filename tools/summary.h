// SPDX-License-Identifier: GPL-3.0-or-later
// The summary the tool prints on stdout when no output file is asked for: the
// input, the method (with --radius, the radius and the mean number of vertices in
// a ball; with --radius auto, the range and the quartiles of the chosen radius and
// of the noise), the time, the ranges of H and K and the status counts.
#ifndef CE_TOOLS_SUMMARY_H
#define CE_TOOLS_SUMMARY_H

#include "command_line.h"
#include "point_set_estimation.h"
#include "point_set_input.h"
#include "soup_repair.h"
#include "surface_estimation.h"
#include "surface_input.h"
#include "tetrahedral.h"

#include <vector>

namespace ce_tool {

void print_surface_summary(const Options& o, const Soup& soup, const Mesh& mesh, const Surface_estimates& rows);

// With how the normals were oriented: given, or by the propagation (its components and
// the points of low orientation confidence).
void print_point_set_summary(const Options& o, const Point_set_input& input, const Point_set_estimates& e);

void print_tetrahedral_summary(const Options& o, const Tetrahedral_input& input,
                               const Tetrahedral_estimates& estimates);

} // namespace ce_tool

#endif // CE_TOOLS_SUMMARY_H
