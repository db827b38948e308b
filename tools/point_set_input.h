// SPDX-License-Identifier: GPL-3.0-or-later
// Point-set input: the points (and the normals, where the file gives them) of an
// .xyz or .pwn file, or of a PLY or OFF file that declares no faces.
#ifndef CE_TOOLS_POINT_SET_INPUT_H
#define CE_TOOLS_POINT_SET_INPUT_H

#include "kernel.h"

#include <optional>
#include <string>
#include <vector>

namespace ce_tool {

struct Point_set_input
{
  std::vector<Point> points;             // in the file's order
  std::vector<Kernel::Vector_3> normals; // one per point, or none
  // The file gave normals, all of them zero (placeholders, as in CGAL's blobby.xyz):
  // `normals` is then empty and the normals are estimated.
  bool zero_normals_ignored = false;
};

// The point set of the file at `path` if it is one: .xyz and .pwn (strict readers of
// point_set_readers.h), a PLY whose header declares no faces (CGAL's reader after
// check_ply_header, with normals where the vertices have nx, ny and nz), an OFF that
// declares 0 faces (the strict OFF reader, with the normals of NOFF). nullopt for
// other files, which are meshes. Bad input: a Tool_error, as for meshes.
std::optional<Point_set_input> read_point_set_input(const std::string& path);

} // namespace ce_tool

#endif // CE_TOOLS_POINT_SET_INPUT_H
