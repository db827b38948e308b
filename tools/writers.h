// SPDX-License-Identifier: GPL-3.0-or-later
// The tool's output files: CSV (surfaces and tetrahedral input) and binary PLY
// with the colour map (surfaces), as text ready for write_file_atomically.
#ifndef CE_TOOLS_WRITERS_H
#define CE_TOOLS_WRITERS_H

#include "command_line.h"
#include "surface_estimation.h"
#include "surface_input.h"
#include "tetrahedral.h"

#include <string>
#include <vector>

namespace ce_tool {

// CSV of a surface: the header k_max,...,status, then a row per vertex of the file.
std::string surface_csv_text(const std::vector<Row>& rows);

// CSV of tetrahedral input: the header k_1,...,status, then a row per vertex of the .mesh.
std::string tetrahedral_csv_text(const std::vector<Tetrahedral_row>& rows);

// Binary little-endian PLY of the file's vertices and faces, the rows as vertex
// properties and colours of `color_by`: exact values, and NaN on failed rows
// (ASCII "nan" is not read back by CGAL's PLY reader, nor by most others).
std::string ply_text(const Soup& soup, const std::vector<Row>& rows, Quantity color_by);

} // namespace ce_tool

#endif // CE_TOOLS_WRITERS_H
