// SPDX-License-Identifier: GPL-3.0-or-later
// The tool's output files: CSV (surfaces, point sets and tetrahedral input) and
// binary PLY with the colour map (surfaces and point sets), streamed to an Atomic_file.
#ifndef CE_TOOLS_WRITERS_H
#define CE_TOOLS_WRITERS_H

#include "atomic_file.h"
#include "command_line.h"
#include "point_set_estimation.h"
#include "surface_estimation.h"
#include "surface_input.h"
#include "tetrahedral.h"

#include <vector>

namespace ce_tool {

// CSV of a surface: the header k_max,...,status, then a row per vertex of the file.
void write_surface_csv(Atomic_file& out, const Surface_estimates& rows);

// CSV of a point set: the surface's header with nx,ny,nz before status, a row per point of the file.
void write_point_set_csv(Atomic_file& out, const Point_set_estimates& rows);

// CSV of tetrahedral input: the header k_1,...,status, then a row per vertex of the .mesh.
void write_tetrahedral_csv(Atomic_file& out, const std::vector<Tetrahedral_row>& rows);

// Binary little-endian PLY of the file's vertices and faces, the rows as vertex
// properties and colours of `color_by`: exact values, and NaN on failed rows
// (ASCII "nan" is not read back by CGAL's PLY reader, nor by most others).
void write_ply(Atomic_file& out, const Soup& soup, const Surface_estimates& rows, Quantity color_by);

// Binary PLY of a point set, as write_ply without faces, the normal nx, ny, nz after the values.
void write_point_set_ply(Atomic_file& out, const std::vector<Point>& points, const Point_set_estimates& rows,
                         Quantity color_by);

} // namespace ce_tool

#endif // CE_TOOLS_WRITERS_H
