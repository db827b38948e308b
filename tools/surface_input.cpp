// SPDX-License-Identifier: GPL-3.0-or-later
#include "surface_input.h"

#include "input_files.h"
#include "tool_error.h"

#include <CGAL/IO/polygon_soup_io.h>

#include <charconv>
#include <cmath>
#include <cstdint>
#include <exception>
#include <fstream>
#include <limits>
#include <new>
#include <string_view>
#include <system_error>

namespace ce_tool {

// PLY headers that CGAL 5.5's reader does not survive, refused first:
// - it sizes its arrays from the header's counts: a header declaring billions of
//   elements in a small file would exhaust memory before the reader notices the
//   file is short. Every vertex takes at least 6 bytes ("0 0 0\n", or 12 in
//   binary), every face at least 2;
// - it adds a `property` to the last element without checking that there is
//   one: a property before any `element` line crashes it; and it reads a vertex's
//   x, y, z as float or double without checking their declared type: `property
//   uchar x` or `property list uchar float x` crashes it (found by the fuzz target);
// - it resizes a list to the count it reads, cast to size_t: a count of type
//   char, short or int can be -1 (a list of 2^64 - 1 items), of type uint
//   4 billion (a list of 16 GB). uchar and ushort counts are bounded and enough.
// The header is scanned as CGAL's reader scans it: the first two lines are the
// signature and the format, whatever they hold (a second line "end_header ascii
// 1.0" does not end the header), then keyword lines up to the keyword end_header.
Ply_header check_ply_header(const std::string& path, std::uintmax_t bytes)
{
  std::ifstream in(path, std::ios::binary);
  long double vertices = 0, faces = 0;
  std::string line, element;
  bool element_seen = false;
  Ply_header header;
  int normal_coordinates = 0; // of nx, ny, nz declared float or double in the vertex element
  for (int number = 1; std::getline(in, line); ++number) {
    if (number <= 2)
      continue;
    std::istringstream words(line);
    std::string keyword, name, count;
    words >> keyword;
    if (keyword == "end_header")
      break;
    if (keyword == "property") {
      if (!element_seen)
        fail("malformed file '" + path + "': a PLY property before any element");
      std::string type, count_type, item_type;
      words >> type;
      if (type == "list") {
        words >> count_type >> item_type;
        if (count_type != "uchar" && count_type != "uint8" && count_type != "ushort" && count_type != "uint16")
          fail("unsupported file '" + path + "': PLY list with a count of type '" + count_type +
               "' (uchar or ushort expected)");
      }
      words >> name;
      const bool coordinate = name == "x" || name == "y" || name == "z";
      const bool floating = type == "float" || type == "double" || type == "float32" || type == "float64";
      if ((element == "vertex" || element == "vertices") && coordinate && !floating)
        fail("unsupported file '" + path + "': PLY vertex coordinate '" + name + "' of type '" + type +
             "' (float or double expected)");
      if ((element == "vertex" || element == "vertices") && (name == "nx" || name == "ny" || name == "nz"))
        normal_coordinates += floating ? 1 : 4; // any other type: no normals
    }
    if (keyword == "element") {
      element_seen = true;
      if (words >> name >> count) {
        // CGAL reads the count with >> into a size_t: its leading digits ("41et" is
        // 41), and a '-' wraps around (-4 is 2^64 - 4 items, a loop without end).
        if (count[0] == '-')
          fail("malformed file '" + path + "': PLY element '" + name + "' with a negative count");
        unsigned long long n = 0;
        const char* digits = count.data() + (count[0] == '+');
        if (std::from_chars(digits, count.data() + count.size(), n).ec == std::errc::result_out_of_range)
          n = std::numeric_limits<unsigned long long>::max();
        element = name;
        (name == "vertex" ? vertices : faces) += static_cast<long double>(n);
        header.faces = header.faces || ((name == "face" || name == "faces") && n > 0);
      }
    }
  }
  if (6 * vertices + 2 * faces > static_cast<long double>(bytes) + 64)
    fail("malformed file '" + path + "': its header declares more vertices or faces than the file (" +
         std::to_string(bytes) + " bytes) can hold");
  header.normals = normal_coordinates == 3;
  return header;
}

Soup read_input(const std::string& path)
{
  const std::string ext = lower_extension(path);
  if (ext != ".off" && ext != ".ply" && ext != ".obj" && ext != ".stl")
    fail("unknown input extension '" + ext + "' of '" + path +
         "' (expected .off, .ply, .obj, .stl, .xyz, .pwn or .mesh)");

  Soup soup;
  if (ext == ".off") {
    soup = read_strictly(path, [](std::string_view text) { return read_off<Point>(text); });
  } else {
    const std::uintmax_t bytes = check_readable(path);
    if (ext == ".ply")
      check_ply_header(path, bytes);
    std::vector<std::vector<std::size_t>> polygons;
    bool ok = false;
    try {
      Silence_cerr silence;
      ok = CGAL::IO::read_polygon_soup(path, soup.points, polygons);
    } catch (const std::bad_alloc&) {
      fail("malformed file '" + path + "': its header asks for more memory than available");
    } catch (const std::exception& e) {
      fail("malformed file '" + path + "': " + e.what());
    }
    if (!ok)
      fail("malformed file '" + path + "': the " + ext.substr(1) +
           " reader failed (garbage, truncated, or invalid data)");
    soup.faces.append(polygons);
  }
  if (soup.points.empty())
    fail("empty mesh '" + path + "': no vertices");
  if (soup.faces.empty())
    fail("empty mesh '" + path + "': no faces");

  for (std::size_t i = 0; i < soup.points.size(); ++i) {
    const Point& p = soup.points[i];
    if (!std::isfinite(p.x()) || !std::isfinite(p.y()) || !std::isfinite(p.z()))
      fail("invalid file '" + path + "': vertex " + std::to_string(i) +
           " has a non-finite (NaN or infinite) coordinate");
  }
  for (std::size_t f = 0; f < soup.faces.size(); ++f)
    for (std::size_t index : soup.faces[f])
      if (index >= soup.points.size())
        fail("malformed file '" + path + "': face " + std::to_string(f) + " refers to vertex " + std::to_string(index) +
             " but the file has " + std::to_string(soup.points.size()) + " vertices");
  return soup;
}

} // namespace ce_tool
