// SPDX-License-Identifier: GPL-3.0-or-later
#include "writers.h"

#include "tool_error.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <initializer_list>
#include <limits>
#include <tuple>
#include <type_traits>
#include <utility>

namespace ce_tool {

namespace {

// Room for a double's text: "-2.2250738585072014e-308" is 24 characters.
constexpr std::size_t double_room = 32;

// Writes the shortest text that reads back to the same double, "nan" for any
// NaN, at `out` (with double_room characters); returns its end.
char* put_double(char* out, double x)
{
  if (std::isnan(x))
    return std::copy_n("nan", 3, out);
  return std::to_chars(out, out + double_room, x).ptr;
}

// The header line, then a row per vertex: its values, then its status. A row is
// made in a local array and appended once (an append per value and comma: 0.73 s
// for the CSV of a 1M-vertex grid; 0.65 to 0.69 s so).
template <typename Rows>
void write_csv(Atomic_file& file, const char* header, const Rows& rows)
{
  std::string& out = file.text();
  out += header;
  out += '\n';
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const auto r = rows[i];
    const auto values = r.values();
    std::array<char, std::tuple_size_v<decltype(values)>*(double_room + 1)> row;
    char* end = row.data();
    for (double x : values) {
      end = put_double(end, x);
      *end++ = ',';
    }
    out.append(row.data(), end);
    out += status_name(r.status);
    out += '\n';
    file.flush_if_full();
  }
}

double quantity(const Row& r, Quantity q)
{
  switch (q) {
    case Quantity::k_max:
      return r.k_max;
    case Quantity::k_min:
      return r.k_min;
    case Quantity::mean:
      return r.mean;
    default:
      return r.gaussian;
  }
}

// Diverging colours: blue (negative) - white (0) - red (positive), saturated at
// the 95th percentile of |value| over estimated vertices; failed vertices grey.
std::array<unsigned char, 3> colour(double value, double scale)
{
  if (!std::isfinite(value))
    return {128, 128, 128};
  double t = scale > 0 ? std::clamp(value / scale, -1.0, 1.0) : 0.0;
  const auto c = [](double x) { return static_cast<unsigned char>(std::lround(255.0 * x)); };
  if (t >= 0)
    return {255, c(1 - t), c(1 - t)};
  return {c(1 + t), c(1 + t), 255};
}

// Little-endian bytes, whatever the host's byte order.
template <typename Unsigned>
void put_le(std::string& out, Unsigned bits)
{
  for (std::size_t i = 0; i < sizeof(Unsigned); ++i)
    out += static_cast<char>((bits >> (8 * i)) & 0xff);
}

void put_binary(std::string& out, double x)
{
  std::uint64_t bits;
  std::memcpy(&bits, &x, sizeof bits);
  put_le(out, bits);
}

// The PLY of `points` (`what` they are, in a comment), the rows' values() as vertex
// properties named `names`, their status and colours of `q`, then `faces` if given.
template <typename Rows>
void write_ply_of(Atomic_file& file, const char* what, const std::vector<Point>& points, const Rows& rows, Quantity q,
                  std::initializer_list<const char*> names, const Flat_polygons* faces)
{
  std::vector<double> magnitudes;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const Row r = rows[i];
    if (r.status != CE::Estimation_status::not_estimable && std::isfinite(quantity(r, q)))
      magnitudes.push_back(std::abs(quantity(r, q)));
  }
  double scale = 0;
  if (!magnitudes.empty()) {
    const std::size_t k = std::min(magnitudes.size() - 1, magnitudes.size() * 95 / 100);
    std::nth_element(magnitudes.begin(), magnitudes.begin() + k, magnitudes.end());
    scale = magnitudes[k];
  }
  magnitudes = std::vector<double>();

  std::size_t face_count = 0;
  for (std::size_t f = 0; faces && f < faces->size(); ++f) {
    const std::size_t n = (*faces)[f].size();
    if (n > 255)
      fail("a face of the input has more than 255 vertices, which the PLY output does not support");
    face_count += n >= 3;
  }

  std::string& out = file.text();
  out += "ply\nformat binary_little_endian 1.0\n";
  out += std::string("comment written by curvature: ") + what + ", in its order\n";
  out += "comment status: 0 = ok, 1 = widened, 2 = failed (its curvature values are NaN), 3 = fallback\n";
  out += std::string("comment colours: ") + quantity_name(q) +
         ", blue < 0 < red, saturated at the 95th percentile of |value|; failed grey\n";
  out += "element vertex " + std::to_string(points.size()) + "\n";
  for (const char* coordinate : {"x", "y", "z"})
    out += std::string("property double ") + coordinate + "\n";
  for (const char* name : names)
    out += std::string("property double ") + name + "\n";
  out += "property uchar status\nproperty uchar red\nproperty uchar green\nproperty uchar blue\n";
  if (faces) {
    out += "element face " + std::to_string(face_count) + "\n";
    out += "property list uchar int vertex_indices\n";
  }
  out += "end_header\n";
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const Point& p = points[i];
    const auto r = rows[i];
    for (double x : {p.x(), p.y(), p.z()})
      put_binary(out, x);
    for (double x : r.values())
      put_binary(out, x);
    out += static_cast<char>(r.status);
    for (unsigned char c : colour(quantity(r, q), scale))
      out += static_cast<char>(c);
    file.flush_if_full();
  }
  for (std::size_t f = 0; faces && f < faces->size(); ++f) {
    const Flat_polygons::Polygon p = (*faces)[f];
    if (p.size() < 3)
      continue;
    out += static_cast<char>(p.size());
    for (std::size_t index : p) {
      if (index > std::size_t(std::numeric_limits<std::int32_t>::max()))
        fail("a vertex index does not fit the PLY output's int");
      put_le(out, static_cast<std::uint32_t>(index));
    }
    file.flush_if_full();
  }
}

// The rows of --radius auto: a row of `Rows` (for the colours), with the radius and the noise after its values.
template <typename Rows>
struct Rows_with_radius
{
  const Rows& rows;

  using Base = std::decay_t<decltype(std::declval<const Rows&>()[0])>;
  static constexpr std::size_t columns = std::tuple_size<decltype(std::declval<Base>().values())>::value + 2;
  struct Values : Base
  {
    std::array<double, columns> all;
    const std::array<double, columns>& values() const { return all; }
  };
  std::size_t size() const { return rows.size(); }
  Values operator[](std::size_t i) const
  {
    Values v{rows[i], {}};
    const auto row = v.Base::values();
    const auto radius_and_noise = rows.radius_and_noise(i);
    std::copy(row.begin(), row.end(), v.all.begin());
    std::copy(radius_and_noise.begin(), radius_and_noise.end(), v.all.begin() + row.size());
    return v;
  }
};
template <typename Rows>
Rows_with_radius(const Rows&) -> Rows_with_radius<Rows>;

} // namespace

void write_surface_csv(Atomic_file& out, const Surface_estimates& rows)
{
  if (rows.radius_selection)
    write_csv(out, "k_max,k_min,mean,gaussian,d_max_x,d_max_y,d_max_z,d_min_x,d_min_y,d_min_z,radius,noise,status",
              Rows_with_radius{rows});
  else
    write_csv(out, "k_max,k_min,mean,gaussian,d_max_x,d_max_y,d_max_z,d_min_x,d_min_y,d_min_z,status", rows);
}

void write_tetrahedral_csv(Atomic_file& out, const std::vector<Tetrahedral_row>& rows)
{
  write_csv(out, "k_1,k_2,k_3,mean,gaussian,status", rows);
}

void write_ply(Atomic_file& file, const Soup& soup, const Surface_estimates& rows, Quantity q)
{
  const char* what = "the vertices and faces of the input file";
  if (rows.radius_selection)
    write_ply_of(file, what, soup.points, Rows_with_radius{rows}, q,
                 {"k_max", "k_min", "mean", "gaussian", "d_max_x", "d_max_y", "d_max_z", "d_min_x", "d_min_y",
                  "d_min_z", "radius", "noise"},
                 &soup.faces);
  else
    write_ply_of(
      file, what, soup.points, rows, q,
      {"k_max", "k_min", "mean", "gaussian", "d_max_x", "d_max_y", "d_max_z", "d_min_x", "d_min_y", "d_min_z"},
      &soup.faces);
}

void write_point_set_csv(Atomic_file& out, const Point_set_estimates& rows)
{
  if (rows.radius_range)
    write_csv(out,
              "k_max,k_min,mean,gaussian,d_max_x,d_max_y,d_max_z,d_min_x,d_min_y,d_min_z,nx,ny,nz,radius,noise,status",
              Rows_with_radius{rows});
  else
    write_csv(out, "k_max,k_min,mean,gaussian,d_max_x,d_max_y,d_max_z,d_min_x,d_min_y,d_min_z,nx,ny,nz,status", rows);
}

void write_point_set_ply(Atomic_file& file, const std::vector<Point>& points, const Point_set_estimates& rows,
                         Quantity q)
{
  const char* what = "the points of the input file, without faces";
  if (rows.radius_range)
    write_ply_of(file, what, points, Rows_with_radius{rows}, q,
                 {"k_max", "k_min", "mean", "gaussian", "d_max_x", "d_max_y", "d_max_z", "d_min_x", "d_min_y",
                  "d_min_z", "nx", "ny", "nz", "radius", "noise"},
                 nullptr);
  else
    write_ply_of(file, what, points, rows, q,
                 {"k_max", "k_min", "mean", "gaussian", "d_max_x", "d_max_y", "d_max_z", "d_min_x", "d_min_y",
                  "d_min_z", "nx", "ny", "nz"},
                 nullptr);
}

} // namespace ce_tool
