// SPDX-License-Identifier: GPL-3.0-or-later
// Surface input: a polygon soup from an OFF, PLY, OBJ or STL file, checked for
// what the later steps need (vertices, faces, finite coordinates, valid indices).
#ifndef CE_TOOLS_SURFACE_INPUT_H
#define CE_TOOLS_SURFACE_INPUT_H

#include "kernel.h"
#include "mesh_readers.h"

#include <cstdint>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace ce_tool {

// The file's points and polygons (in flat arrays), in the file's order.
using Soup = Polygon_soup_data<Point>;

// CGAL's readers write diagnostics to std::cerr; the tool's contract is one line.
struct Silence_cerr
{
  std::ostringstream sink;
  std::streambuf* saved;
  Silence_cerr()
      : saved(std::cerr.rdbuf(sink.rdbuf()))
  {}
  ~Silence_cerr() { std::cerr.rdbuf(saved); }
};

// What a PLY header declares, as check_ply_header reads it.
struct Ply_header
{
  bool faces = false;   // a face element of one face or more: a mesh, else a point set
  bool normals = false; // vertex properties nx, ny and nz, each float or double
};

// Refuses (a Tool_error) the PLY headers that CGAL's reader does not survive, and those
// declaring more elements than the file's `bytes` can hold; then says what it declares.
Ply_header check_ply_header(const std::string& path, std::uintmax_t bytes);

// The soup of the file at `path`, in the file's order. OFF is read by the strict
// reader of mesh_readers.h, PLY, OBJ and STL by CGAL after checks of what its
// readers do not survive.
Soup read_input(const std::string& path);

} // namespace ce_tool

#endif // CE_TOOLS_SURFACE_INPUT_H
