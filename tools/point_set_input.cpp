// SPDX-License-Identifier: GPL-3.0-or-later
#include "point_set_input.h"

#include "input_files.h"
#include "mesh_readers.h"
#include "point_set_readers.h"
#include "surface_input.h"
#include "tool_error.h"

#include <CGAL/IO/read_ply_points.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <exception>
#include <fstream>
#include <iterator>
#include <new>
#include <string_view>
#include <utility>

namespace ce_tool {

namespace {

bool finite(const Kernel::Vector_3& v) { return std::isfinite(v.x()) && std::isfinite(v.y()) && std::isfinite(v.z()); }

// The checks every point set passes, whatever its reader: points, finite values, and
// normals of all zero (placeholders) dropped.
Point_set_input checked(const std::string& path, Point_set_input input)
{
  if (input.points.empty())
    fail("empty point set '" + path + "': no points");
  for (std::size_t i = 0; i < input.points.size(); ++i)
    if (!finite(input.points[i] - CGAL::ORIGIN) || (!input.normals.empty() && !finite(input.normals[i])))
      fail("invalid file '" + path + "': point " + std::to_string(i) +
           " has a non-finite (NaN or infinite) coordinate or normal");
  if (!input.normals.empty() && std::all_of(input.normals.begin(), input.normals.end(),
                                            [](const Kernel::Vector_3& n) { return n == CGAL::NULL_VECTOR; }))
  {
    input.normals.clear();
    input.zero_normals_ignored = true;
  }
  return input;
}

Point_set_input from_arrays(const Point_set_data& data)
{
  Point_set_input input;
  input.points.reserve(data.points.size());
  for (const auto& p : data.points)
    input.points.emplace_back(p[0], p[1], p[2]);
  input.normals.reserve(data.normals.size());
  for (const auto& n : data.normals)
    input.normals.emplace_back(n[0], n[1], n[2]);
  return input;
}

// CGAL's PLY reader, after check_ply_header, as for meshes.
Point_set_input read_ply_points(const std::string& path, bool normals)
{
  using Point_with_normal = std::pair<Point, Kernel::Vector_3>;
  Point_set_input input;
  std::vector<Point_with_normal> read;
  bool ok = false;
  try {
    Silence_cerr silence;
    if (normals)
      ok = CGAL::IO::read_PLY(path, std::back_inserter(read),
                              CGAL::parameters::point_map(CGAL::First_of_pair_property_map<Point_with_normal>())
                                .normal_map(CGAL::Second_of_pair_property_map<Point_with_normal>()));
    else
      ok = CGAL::IO::read_PLY(path, std::back_inserter(input.points));
  } catch (const std::bad_alloc&) {
    fail("malformed file '" + path + "': its header asks for more memory than available");
  } catch (const std::exception& e) {
    fail("malformed file '" + path + "': " + e.what());
  }
  if (!ok)
    fail("malformed file '" + path + "': the ply reader failed (garbage, truncated, or invalid data)");
  input.points.reserve(read.size());
  input.normals.reserve(read.size());
  for (const Point_with_normal& p : read) {
    input.points.push_back(p.first);
    input.normals.push_back(p.second);
  }
  return input;
}

// The start of the file (up to 64 KiB): where an OFF header's counts are.
std::string start_of(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  std::string text(std::size_t(1) << 16, '\0');
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  text.resize(static_cast<std::size_t>(std::max<std::streamsize>(in.gcount(), 0)));
  return text;
}

} // namespace

std::optional<Point_set_input> read_point_set_input(const std::string& path)
{
  const std::string ext = lower_extension(path);
  if (ext == ".xyz" || ext == ".pwn") {
    const bool pwn = ext == ".pwn";
    return checked(path, from_arrays(read_strictly(path, [&](std::string_view text) { return read_xyz(text, pwn); })));
  }
  if (ext == ".ply") {
    const Ply_header header = check_ply_header(path, check_readable(path));
    if (header.faces)
      return std::nullopt;
    return checked(path, read_ply_points(path, header.normals));
  }
  if (ext == ".off" && off_declares_no_faces(start_of(path)).value_or(false)) {
    Point_set_data data;
    data.points = read_strictly(path, [&](std::string_view text) { return read_off(text, &data.normals); }).points;
    return checked(path, from_arrays(data));
  }
  return std::nullopt;
}

} // namespace ce_tool
