// SPDX-License-Identifier: GPL-3.0-or-later
// Strict readers of the tool's text formats: OFF (surfaces), Medit .mesh
// (tetrahedra) and Medit .sol (a scalar per vertex).
//
// Why our own: CGAL 5.5's OFF reader converts the header's counts from double to
// size_t without a range check (UB on a huge or negative count) and allocates a
// face of whatever size the file claims; its Medit reader needs a C3T3. These
// readers check every count against what the rest of the file can hold before
// anything is allocated, every index against its range, every coordinate for
// being finite, and say where the file is wrong (line number) when it is.
// They know nothing of CGAL: plain arrays in, Read_error out.
#ifndef CE_TOOLS_MESH_READERS_H
#define CE_TOOLS_MESH_READERS_H

#include <algorithm>
#include <array>
#include <charconv>
#include <climits>
#include <cmath>
#include <cstddef>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <system_error>
#include <type_traits>
#include <utility>
#include <vector>

namespace ce_tool {

struct Read_error : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

// How an item is named in messages: a string, or a function that makes one, called
// only when a message needs it (a large file's items then build no strings).
template <typename What>
std::string describe(const What& what)
{
  if constexpr (std::is_invocable_v<const What&>)
    return what();
  else
    return std::string(what);
}

// Whitespace-separated tokens; '#' starts a comment that runs to the end of the line.
class Scanner
{
public:
  explicit Scanner(std::string_view text)
      : text_(text)
  {}

  // Skips whitespace and comments; true if a token follows.
  bool more()
  {
    while (pos_ < text_.size()) {
      const char c = text_[pos_];
      if (c == '#')
        skip_comment();
      else if (is_space(c))
        advance();
      else
        return true;
    }
    return false;
  }

  // True if a token follows on the current line (optional trailing values).
  bool more_on_line()
  {
    while (pos_ < text_.size() && text_[pos_] != '\n' && is_space(text_[pos_]))
      ++pos_;
    if (pos_ < text_.size() && text_[pos_] == '#')
      skip_comment();
    return pos_ < text_.size() && !is_space(text_[pos_]);
  }

  template <typename What>
  std::string_view token(const What& what)
  {
    if (!more())
      fail("the file ends where " + describe(what) + " was expected");
    const std::size_t start = pos_;
    while (pos_ < text_.size() && !is_space(text_[pos_]) && text_[pos_] != '#')
      ++pos_;
    return text_.substr(start, pos_ - start);
  }

  void expect(std::string_view keyword)
  {
    const std::string_view word = token("'" + std::string(keyword) + "'");
    if (word != keyword)
      fail("expected '" + std::string(keyword) + "', got '" + printable(word) + "'");
  }

  template <typename What>
  long long integer(const What& what, long long min_value, long long max_value)
  {
    const std::string_view word = token(what);
    long long value = 0;
    const auto [end, ec] = std::from_chars(word.data(), word.data() + word.size(), value);
    if (ec != std::errc() || end != word.data() + word.size())
      fail("expected an integer for " + describe(what) + ", got '" + printable(word) + "'");
    if (value < min_value || value > max_value)
      fail(describe(what) + " is " + std::to_string(value) + ", out of the range " + std::to_string(min_value) + ".." +
           std::to_string(max_value));
    return value;
  }

  // A count of items of `tokens_per_item` tokens each: each takes at least two
  // bytes a token (the token and a separator), so the rest of the file bounds it,
  // and so the memory reserved for the items.
  template <typename What>
  std::size_t count(const What& what, std::size_t tokens_per_item, long long max_value = LLONG_MAX)
  {
    const long long n = integer([&] { return "the number of " + describe(what); }, 0, max_value);
    const std::size_t bound = (text_.size() - pos_ + 1) / (2 * tokens_per_item);
    if (static_cast<unsigned long long>(n) > bound)
      fail("the file declares " + std::to_string(n) + " " + describe(what) + ", more than the rest of the file (" +
           std::to_string(text_.size() - pos_) + " bytes) can hold");
    return static_cast<std::size_t>(n);
  }

  template <typename What>
  double real(const What& what)
  {
    std::string_view word = token(what);
    const std::string_view original = word;
    if (word.size() > 1 && word[0] == '+') // from_chars does not take a '+' sign
      word.remove_prefix(1);
    double value = 0;
    const auto [end, ec] = std::from_chars(word.data(), word.data() + word.size(), value);
    if (ec == std::errc::result_out_of_range)
      fail(describe(what) + " '" + printable(original) + "' is out of the range of double");
    if (ec != std::errc() || end != word.data() + word.size())
      fail("expected a number for " + describe(what) + ", got '" + printable(original) + "'");
    if (!std::isfinite(value))
      fail(describe(what) + " is not finite ('" + printable(original) + "')");
    return value;
  }

  // Trailing numbers on the current line: between min_count and max_count of them.
  template <typename What>
  void skip_numbers_on_line(const What& what, int min_count, int max_count)
  {
    int n = 0;
    while (more_on_line()) {
      if (n == max_count)
        fail("too many values on the line of " + describe(what));
      real([&] { return "a value of " + describe(what); });
      ++n;
    }
    if (n < min_count)
      fail("too few values on the line of " + describe(what));
  }

  [[noreturn]] void fail(const std::string& message) const
  {
    throw Read_error("line " + std::to_string(line_) + ": " + message);
  }

  // At most 24 characters of a token, non-printable bytes as '?': for messages.
  static std::string printable(std::string_view word)
  {
    std::string s(word.substr(0, 24));
    for (char& c : s)
      if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) > 0x7e)
        c = '?';
    return word.size() > 24 ? s + "..." : s;
  }

private:
  static bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v'; }
  void advance() { line_ += text_[pos_++] == '\n'; }
  void skip_comment()
  {
    while (pos_ < text_.size() && text_[pos_] != '\n')
      ++pos_;
  }

  std::string_view text_;
  std::size_t pos_ = 0;
  std::size_t line_ = 1;
};

// Polygons in two flat arrays: the vertex indices of all polygons one after the
// other, and where each polygon starts (a vector per polygon would cost more than
// its three indices).
class Flat_polygons
{
public:
  // The vertex indices of one polygon.
  struct Polygon
  {
    const std::size_t* first;
    std::size_t count;
    std::size_t size() const { return count; }
    std::size_t operator[](std::size_t k) const { return first[k]; }
    const std::size_t* begin() const { return first; }
    const std::size_t* end() const { return first + count; }
  };

  std::size_t size() const { return start_.size() - 1; }
  bool empty() const { return size() == 0; }
  Polygon operator[](std::size_t f) const { return {indices_.data() + start_[f], start_[f + 1] - start_[f]}; }

  void reserve(std::size_t polygons, std::size_t indices)
  {
    start_.reserve(polygons + 1);
    indices_.reserve(indices);
  }
  // Appends an index to the polygon being built, which end_polygon() closes.
  void add_index(std::size_t index) { indices_.push_back(index); }
  void end_polygon() { start_.push_back(indices_.size()); }
  // Appends polygons of another form (a range of ranges of indices).
  template <typename Polygon_range>
  void append(const Polygon_range& polygons)
  {
    std::size_t indices = 0;
    for (const auto& polygon : polygons)
      indices += polygon.size();
    reserve(size() + polygons.size(), indices_.size() + indices);
    for (const auto& polygon : polygons) {
      indices_.insert(indices_.end(), polygon.begin(), polygon.end());
      end_polygon();
    }
  }

private:
  std::vector<std::size_t> start_{0};
  std::vector<std::size_t> indices_;
};

template <typename Point3>
struct Polygon_soup_data
{
  std::vector<Point3> points;
  Flat_polygons faces;
};

// OFF as Geomview defines it and CGAL writes it: a header [ST][C][N]OFF, the
// counts of vertices, faces and (optionally) edges, one vertex a line (x y z, then
// the normal, colour and texture coordinates the header announces), one face a line
// (n, n indices from 0, then an optional colour of up to 4 values).
// 4OFF, nOFF (other dimensions) and binary OFF are refused. Point3 is built from
// {x, y, z}. With `normals`, the normals of an N header (the three values after x y z)
// are appended to it, one per vertex; other values are checked and skipped.
template <typename Point3 = std::array<double, 3>>
Polygon_soup_data<Point3> read_off(std::string_view text, std::vector<std::array<double, 3>>* normals = nullptr)
{
  Scanner in(text);
  std::string_view header = in.token("the OFF header");
  int extra_min = 0, extra_max = 0; // per-vertex values after x y z
  const auto prefix = [&](std::string_view p, int values_min, int values_max) {
    if (header.substr(0, p.size()) != p)
      return false;
    header.remove_prefix(p.size());
    extra_min += values_min;
    extra_max += values_max;
    return true;
  };
  prefix("ST", 2, 2);
  prefix("C", 3, 4); // RGB or RGBA
  const bool read_normals = prefix("N", 3, 3) && normals != nullptr;
  if (read_normals) { // they come first after x y z, before a colour and texture coordinates
    extra_min -= 3;
    extra_max -= 3;
  }
  if (header != "OFF")
    in.fail("unsupported or missing OFF header (expected OFF, COFF, NOFF, STOFF or a combination)");
  if (in.more_on_line()) {
    Scanner peek = in;
    if (peek.token("") == "BINARY")
      in.fail("binary OFF is not supported");
  }
  const std::size_t vertices = in.count("vertices", 3);
  const std::size_t faces = in.count("faces", 2);
  if (in.more_on_line())
    in.integer("the number of edges", 0, LLONG_MAX); // unused, and optional in practice

  Polygon_soup_data<Point3> soup;
  soup.points.reserve(vertices);
  if (read_normals)
    normals->reserve(normals->size() + vertices);
  for (std::size_t v = 0; v < vertices; ++v) {
    const auto what = [v] { return "vertex " + std::to_string(v); };
    const auto coordinate = [&] { return "a coordinate of " + what(); };
    const double x = in.real(coordinate);
    const double y = in.real(coordinate);
    const double z = in.real(coordinate);
    if (read_normals) {
      const auto normal = [&] { return "the normal of " + what(); };
      const double nx = in.real(normal), ny = in.real(normal), nz = in.real(normal);
      normals->push_back({nx, ny, nz});
    }
    in.skip_numbers_on_line(what, extra_min, extra_max);
    soup.points.push_back(Point3{x, y, z});
  }
  soup.faces.reserve(faces, 3 * faces);
  const long long last = static_cast<long long>(vertices) - 1;
  for (std::size_t f = 0; f < faces; ++f) {
    const auto what = [f] { return "face " + std::to_string(f); };
    const std::size_t n = in.count([&] { return "vertices of " + what(); }, 1, static_cast<long long>(vertices));
    if (n == 0)
      in.fail(what() + " has no vertices");
    for (std::size_t k = 0; k < n; ++k)
      soup.faces.add_index(
        static_cast<std::size_t>(in.integer([&] { return "a vertex index of " + what(); }, 0, last)));
    soup.faces.end_polygon();
    in.skip_numbers_on_line(what, 0, 4);
  }
  // Whatever follows the declared faces is ignored, as by Geomview and CGAL: some
  // files (CGAL's data/meshes/prim.off) hold more faces than their header declares.
  return soup;
}

struct Tetrahedral_mesh_data
{
  std::vector<std::array<double, 3>> points;
  std::vector<std::array<std::size_t, 4>> cells; // indices from 0
};

namespace internal {

// "MeshVersionFormatted 1|2" and "Dimension 3", the start of ASCII .mesh and .sol files.
inline void read_medit_preamble(Scanner& in)
{
  in.expect("MeshVersionFormatted");
  in.integer("the MeshVersionFormatted (1 or 2 for an ASCII file)", 1, 2);
  in.expect("Dimension");
  in.integer("the Dimension (only 3 is supported)", 3, 3);
}

// Sections of a .mesh file the tool does not use, with the numbers an item has.
inline int ignored_medit_section_width(std::string_view keyword)
{
  static const std::pair<std::string_view, int> sections[] = {{"Edges", 3},
                                                              {"Triangles", 4},
                                                              {"Quadrilaterals", 5},
                                                              {"Hexahedra", 9},
                                                              {"Prisms", 7},
                                                              {"Corners", 1},
                                                              {"Ridges", 1},
                                                              {"RequiredVertices", 1},
                                                              {"RequiredEdges", 1},
                                                              {"RequiredTriangles", 1},
                                                              {"RequiredQuadrilaterals", 1},
                                                              {"RequiredTetrahedra", 1},
                                                              {"Normals", 3},
                                                              {"NormalAtVertices", 2},
                                                              {"Tangents", 3},
                                                              {"TangentAtVertices", 2}};
  for (const auto& [name, width] : sections)
    if (name == keyword)
      return width;
  return 0;
}

} // namespace internal

// Two tetrahedra with the same four vertices (indices from 0, the first before the
// second), if there are any.
inline std::optional<std::pair<std::size_t, std::size_t>>
same_tetrahedra(const std::vector<std::array<std::size_t, 4>>& cells)
{
  std::vector<std::pair<std::array<std::size_t, 4>, std::size_t>> sorted;
  sorted.reserve(cells.size());
  for (std::size_t t = 0; t < cells.size(); ++t) {
    std::array<std::size_t, 4> cell = cells[t];
    std::sort(cell.begin(), cell.end());
    sorted.emplace_back(cell, t);
  }
  std::sort(sorted.begin(), sorted.end());
  for (std::size_t i = 1; i < sorted.size(); ++i)
    if (sorted[i].first == sorted[i - 1].first)
      return std::pair(sorted[i - 1].second, sorted[i].second);
  return std::nullopt;
}

// ASCII Medit .mesh: the preamble, then sections "Keyword count items" in any
// order: Vertices (x y z ref), Tetrahedra (four indices from 1, ref), others
// skipped (their items must still be numbers), up to End or the end of the file.
// A tetrahedron that repeats a vertex, or two with the same four vertices, are errors.
inline Tetrahedral_mesh_data read_medit_mesh(std::string_view text)
{
  Scanner in(text);
  internal::read_medit_preamble(in);
  Tetrahedral_mesh_data mesh;
  bool have_vertices = false, have_cells = false;
  while (in.more()) {
    const std::string_view keyword = in.token("a section");
    if (keyword == "End")
      break;
    if (keyword == "Vertices") {
      if (have_vertices)
        in.fail("a second Vertices section");
      have_vertices = true;
      const std::size_t n = in.count("vertices", 4);
      mesh.points.reserve(n);
      for (std::size_t v = 0; v < n; ++v) {
        const std::string what = "vertex " + std::to_string(v + 1);
        std::array<double, 3> p;
        for (double& c : p)
          c = in.real("a coordinate of " + what);
        in.integer("the reference of " + what, INT_MIN, INT_MAX);
        mesh.points.push_back(p);
      }
    } else if (keyword == "Tetrahedra") {
      if (have_cells)
        in.fail("a second Tetrahedra section");
      if (!have_vertices)
        in.fail("the Tetrahedra section comes before the Vertices section");
      have_cells = true;
      const std::size_t n = in.count("tetrahedra", 5);
      mesh.cells.reserve(n);
      const auto vertices = static_cast<long long>(mesh.points.size());
      for (std::size_t t = 0; t < n; ++t) {
        const std::string what = "tetrahedron " + std::to_string(t + 1);
        std::array<std::size_t, 4> cell;
        for (std::size_t& index : cell)
          index = static_cast<std::size_t>(in.integer("a vertex index of " + what, 1, vertices) - 1);
        in.integer("the reference of " + what, INT_MIN, INT_MAX);
        std::array<std::size_t, 4> sorted = cell;
        std::sort(sorted.begin(), sorted.end());
        if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end())
          in.fail(what + " repeats a vertex");
        mesh.cells.push_back(cell);
      }
    } else if (const int width = internal::ignored_medit_section_width(keyword)) {
      const std::string what = "an item of " + std::string(keyword);
      for (std::size_t i = in.count(std::string(keyword), std::size_t(width)) * std::size_t(width); i > 0; --i)
        in.real(what);
    } else {
      in.fail("unknown section '" + Scanner::printable(keyword) + "'");
    }
  }
  if (in.more())
    in.fail("unexpected '" + Scanner::printable(in.token("")) + "' after End");
  if (!have_vertices || !have_cells)
    throw Read_error(std::string("no ") + (have_vertices ? "Tetrahedra" : "Vertices") + " section");

  if (const auto same = same_tetrahedra(mesh.cells))
    throw Read_error("tetrahedra " + std::to_string(same->first + 1) + " and " + std::to_string(same->second + 1) +
                     " have the same four vertices");
  return mesh;
}

// ASCII Medit .sol with one scalar per vertex: the preamble, then
// "SolAtVertices count 1 1" (one solution, of type 1 = scalar) and the values.
inline std::vector<double> read_medit_sol(std::string_view text, std::size_t vertices)
{
  Scanner in(text);
  internal::read_medit_preamble(in);
  in.expect("SolAtVertices");
  const std::size_t n = in.count("solution values", 1);
  if (n != vertices)
    in.fail("SolAtVertices has " + std::to_string(n) + " values but the mesh has " + std::to_string(vertices) +
            " vertices");
  in.integer("the number of solutions per vertex (only 1 is supported)", 1, 1);
  in.integer("the solution type (only 1, a scalar, is supported)", 1, 1);
  std::vector<double> values;
  values.reserve(n);
  for (std::size_t v = 0; v < n; ++v)
    values.push_back(in.real("the value of vertex " + std::to_string(v + 1)));
  if (in.more()) {
    const std::string_view word = in.token("End");
    if (word != "End")
      in.fail("expected End after the values, got '" + Scanner::printable(word) + "'");
    if (in.more())
      in.fail("unexpected '" + Scanner::printable(in.token("")) + "' after End");
  }
  return values;
}

} // namespace ce_tool

#endif // CE_TOOLS_MESH_READERS_H
