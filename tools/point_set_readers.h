// SPDX-License-Identifier: GPL-3.0-or-later
// Strict readers of the tool's point-set text formats: .xyz and .pwn (CGAL's
// points with normals), with the Scanner of mesh_readers.h: a declared count
// checked against the file's size before anything is reserved, every value a
// finite number, every line of the same width, the line of an error named.
#ifndef CE_TOOLS_POINT_SET_READERS_H
#define CE_TOOLS_POINT_SET_READERS_H

#include "mesh_readers.h"

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace ce_tool {

struct Point_set_data
{
  std::vector<std::array<double, 3>> points;
  std::vector<std::array<double, 3>> normals; // one per point, or none
};

// .xyz as CGAL reads and writes it: one point a line, "x y z" or "x y z nx ny nz"
// (every line of the same width), '#' comments and blank lines skipped, and an
// optional first line holding the number of points alone, which must then be the
// number of points that follow. `normals_required`: every line has six values (.pwn).
inline Point_set_data read_xyz(std::string_view text, bool normals_required)
{
  Scanner in(text);
  Point_set_data data;
  std::optional<std::size_t> declared;
  std::size_t width = 0; // of the lines read so far
  if (in.more()) {
    Scanner peek = in;
    peek.token("");
    if (!peek.more_on_line()) {
      declared = in.count("points", 3);
      data.points.reserve(*declared);
    }
  }
  while (in.more()) {
    const std::size_t i = data.points.size();
    const auto what = [i] { return "point " + std::to_string(i); };
    std::array<double, 6> values;
    std::size_t n = 0;
    do {
      if (n == values.size())
        in.fail("more than 6 values on the line of " + what());
      values[n++] = in.real([&] { return "a value of " + what(); });
    } while (in.more_on_line());
    if (n != 3 && n != 6)
      in.fail(what() + " has " + std::to_string(n) + " values (expected x y z, or x y z nx ny nz)");
    if (normals_required && n != 6)
      in.fail(what() + " has no normal (expected x y z nx ny nz)");
    if (width != 0 && n != width)
      in.fail(what() + " has " + std::to_string(n) + " values, the points before it " + std::to_string(width));
    width = n;
    data.points.push_back({values[0], values[1], values[2]});
    if (n == 6)
      data.normals.push_back({values[3], values[4], values[5]});
  }
  if (declared && *declared != data.points.size())
    throw Read_error("the first line declares " + std::to_string(*declared) + " points, the file holds " +
                     std::to_string(data.points.size()));
  return data;
}

// Whether the OFF header at the start of `text` declares no faces (an OFF point
// set); nullopt where `text` ends before the counts or holds no OFF header (then
// the mesh reader reads the file and says what is wrong).
inline std::optional<bool> off_declares_no_faces(std::string_view text)
{
  try {
    Scanner in(text);
    const std::string_view header = in.token("the OFF header");
    if (header.size() < 3 || header.substr(header.size() - 3) != "OFF")
      return std::nullopt;
    in.integer("the number of vertices", 0, LLONG_MAX);
    return in.integer("the number of faces", 0, LLONG_MAX) == 0;
  } catch (const Read_error&) {
    return std::nullopt;
  }
}

} // namespace ce_tool

#endif // CE_TOOLS_POINT_SET_READERS_H
