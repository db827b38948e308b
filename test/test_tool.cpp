// SPDX-License-Identifier: GPL-3.0-or-later
// Tests of the command-line tool `curvature` (tools/curvature.cpp), run as a
// subprocess on small files written to a temporary directory:
//  - bad input: non-zero exit, exactly one line on stderr, no output file left;
//  - accepted degenerate input: one row per file vertex, nan on failed rows;
//  - the CSV and PLY formats, and the mean curvature of a sphere;
//  - tetrahedral input (Medit .mesh + .sol): the CSV, and the curvature of graphs;
//  - point sets (.xyz, .pwn, PLY and OFF without faces): every format read alike, the
//    rows in the file's order, the sphere's H and its sign, the summary, bad input.
// tools/CMakeLists.txt defines CE_CURVATURE_TOOL (the built tool's path) and links the
// tool's registry of methods.
#include <gtest/gtest.h>

#include <CGAL/Curvature_estimation/mean_edge_length.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/PLY.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Surface_mesh.h>

#include "kuhn_grid.h"
#include "noisy_meshes.h"
#include "random_numbers.h"
#include "registry.h"
#include "surface_mesh_properties.h"
#include "test_surfaces.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <numeric>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>
#include <utility>
#include <vector>

namespace fs = std::filesystem;

namespace {

#ifdef CE_CURVATURE_TOOL
const char* const tool_path = CE_CURVATURE_TOOL;
#else
const char* const tool_path = nullptr;
#endif

const char* const csv_header = "k_max,k_min,mean,gaussian,d_max_x,d_max_y,d_max_z,d_min_x,d_min_y,d_min_z,status";

struct Result
{
  int exit_code = -1;
  std::string out, err;
};

std::string read_text(const fs::path& p)
{
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

void write_text(const fs::path& p, const std::string& text)
{
  std::ofstream out(p, std::ios::binary);
  out << text;
}

std::string quote(const std::string& s)
{
  std::string q = "'";
  for (char c : s)
    q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

std::size_t count_lines(const std::string& s)
{
  std::size_t n = 0;
  for (char c : s)
    n += c == '\n';
  if (!s.empty() && s.back() != '\n')
    ++n;
  return n;
}

// A CSV row: the values of the header's columns, then the status.
struct Row
{
  std::vector<double> values;
  std::string status;
};

class ToolTest : public ::testing::Test
{
protected:
  fs::path dir;

  void SetUp() override
  {
    if (!tool_path)
      GTEST_SKIP() << "the tool is not built (CE_BUILD_TOOLS=OFF)";
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir = fs::temp_directory_path() / ("ce_test_tool_" + std::to_string(::getpid()) + "_" + info->name());
    fs::remove_all(dir);
    fs::create_directories(dir);
  }
  void TearDown() override
  {
    if (!dir.empty() && !HasFailure())
      fs::remove_all(dir);
  }

  fs::path file(const std::string& name, const std::string& text)
  {
    const fs::path p = dir / name;
    write_text(p, text);
    return p;
  }

  Result run(const std::vector<std::string>& args)
  {
    std::string command = quote(tool_path);
    for (const auto& a : args)
      command += " " + quote(a);
    const fs::path out = dir / ".stdout", err = dir / ".stderr";
    command += " >" + quote(out.string()) + " 2>" + quote(err.string()) + " </dev/null";
    const int status = std::system(command.c_str());
    Result r;
    r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
    r.out = read_text(out);
    r.err = read_text(err);
    fs::remove(out);
    fs::remove(err);
    return r;
  }

  // Non-zero exit (not a crash), one line on stderr, nothing written to `dir`.
  void expect_rejected(const std::vector<std::string>& input_args, const std::string& what)
  {
    const std::vector<std::string> before = listing();
    for (const std::string ext : {".csv", ".ply"}) {
      const fs::path output = dir / ("out" + ext);
      std::vector<std::string> args = input_args;
      args.push_back("-o");
      args.push_back(output.string());
      const Result r = run(args);
      EXPECT_NE(r.exit_code, 0) << what;
      EXPECT_LT(r.exit_code, 128) << what << ": crashed (signal " << r.exit_code - 128 << ")";
      EXPECT_EQ(count_lines(r.err), 1u) << what << ": stderr was [" << r.err << "]";
      EXPECT_NE(r.err.find("error"), std::string::npos) << what << ": " << r.err;
      EXPECT_FALSE(fs::exists(output)) << what;
      EXPECT_EQ(listing(), before) << what << ": a file was left in the directory";
    }
    // And without -o (summary mode): the same failure.
    const Result r = run(input_args);
    EXPECT_NE(r.exit_code, 0) << what;
    EXPECT_EQ(count_lines(r.err), 1u) << what << ": stderr was [" << r.err << "]";
  }

  std::vector<std::string> listing() const
  {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(dir))
      names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
  }

  // Runs the tool to a CSV and parses it, checking its format.
  std::vector<Row> csv(const fs::path& input, std::vector<std::string> extra = {},
                       const std::string& header = csv_header)
  {
    const std::size_t columns = std::size_t(std::count(header.begin(), header.end(), ','));
    const fs::path output = dir / "rows.csv";
    fs::remove(output);
    std::vector<std::string> args = extra;
    args.insert(args.end(), {"-o", output.string(), input.string()});
    const Result r = run(args);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    std::vector<Row> rows;
    std::istringstream in(read_text(output));
    std::string line;
    if (!std::getline(in, line)) {
      ADD_FAILURE() << "no CSV written for " << input;
      return rows;
    }
    EXPECT_EQ(line, header);
    while (std::getline(in, line)) {
      Row row;
      row.values.resize(columns);
      std::istringstream fields(line);
      std::string field;
      for (std::size_t i = 0; i < columns; ++i) {
        if (!std::getline(fields, field, ',')) {
          ADD_FAILURE() << "short row: " << line;
          return rows;
        }
        char* end = nullptr;
        row.values[i] = std::strtod(field.c_str(), &end);
        EXPECT_TRUE(!field.empty() && *end == '\0') << "not a number: '" << field << "' in " << line;
        if (field.find("nan") != std::string::npos) {
          EXPECT_EQ(field, "nan") << line;
        }
      }
      EXPECT_TRUE(std::getline(fields, row.status)) << line;
      EXPECT_TRUE(row.status == "ok" || row.status == "widened" || row.status == "fallback" || row.status == "failed")
        << line;
      EXPECT_FALSE(std::getline(fields, field)) << "too many fields: " << line;
      rows.push_back(row);
    }
    return rows;
  }
};

// Failed rows are all nan, the others all finite, with k_max >= k_min.
void expect_consistent(const std::vector<Row>& rows, const std::string& what)
{
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const Row& r = rows[i];
    for (double x : r.values) {
      if (r.status == "failed") {
        EXPECT_TRUE(std::isnan(x)) << what << ", row " << i;
      } else {
        EXPECT_TRUE(std::isfinite(x)) << what << ", row " << i;
      }
    }
    if (r.status != "failed") {
      EXPECT_GE(r.values[0], r.values[1]) << what << ", row " << i;
    }
  }
}

// The rows of a file with `vertices` vertices whose first and last are isolated: those two
// failed, no other.
void expect_only_first_and_last_failed(const std::vector<Row>& rows, std::size_t vertices)
{
  ASSERT_EQ(rows.size(), vertices);
  EXPECT_EQ(rows.front().status, "failed");
  EXPECT_EQ(rows.back().status, "failed");
  for (std::size_t i = 1; i + 1 < rows.size(); ++i)
    EXPECT_NE(rows[i].status, "failed") << "row " << i;
}

// ---------------------------------------------------------------------------
// Meshes
// ---------------------------------------------------------------------------

// Adds a vertex in no face (or cell) before the others, which shifts their indices, and
// one after them.
template <typename Points, typename Elements>
void add_isolated_first_and_last(Points& points, Elements& elements)
{
  points.insert(points.begin(), {5, 5, 5});
  for (auto& element : elements)
    for (auto& i : element)
      ++i;
  points.push_back({7, 7, 7});
}

struct Indexed
{
  std::vector<std::array<double, 3>> points;
  std::vector<std::vector<std::size_t>> faces;
};

Indexed indexed(const ce_test::Soup& soup)
{
  Indexed m;
  for (const Eigen::Vector3d& p : soup.points)
    m.points.push_back({p.x(), p.y(), p.z()});
  for (const auto& f : soup.faces)
    m.faces.push_back({f[0], f[1], f[2]});
  return m;
}

// Icosphere of radius r (outward faces), `levels` subdivisions of an icosahedron.
Indexed icosphere(int levels, double r) { return indexed(ce_test::sphere_soup(r, static_cast<unsigned>(levels))); }

// A closed tetrahedron with outward faces, scaled and shifted.
Indexed tetrahedron(double s = 1, double dx = 0)
{
  return Indexed{{{dx, 0, 0}, {dx + s, 0, 0}, {dx, s, 0}, {dx, 0, s}}, {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}}};
}

void append(Indexed& a, const Indexed& b)
{
  const std::size_t offset = a.points.size();
  a.points.insert(a.points.end(), b.points.begin(), b.points.end());
  for (auto f : b.faces) {
    for (auto& i : f)
      i += offset;
    a.faces.push_back(f);
  }
}

std::string off(const Indexed& m)
{
  std::ostringstream s;
  s.precision(17);
  s << "OFF\n" << m.points.size() << ' ' << m.faces.size() << " 0\n";
  for (const auto& p : m.points)
    s << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
  for (const auto& f : m.faces) {
    s << f.size();
    for (auto i : f)
      s << ' ' << i;
    s << '\n';
  }
  return s.str();
}

std::string obj(const Indexed& m)
{
  std::ostringstream s;
  s.precision(17);
  for (const auto& p : m.points)
    s << "v " << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
  for (const auto& f : m.faces) {
    s << 'f';
    for (auto i : f)
      s << ' ' << i + 1;
    s << '\n';
  }
  return s.str();
}

// An ASCII PLY file: the header's element and property lines `elements`, then `data`.
std::string ascii_ply(const std::string& elements, const std::string& data = "")
{
  return "ply\nformat ascii 1.0\n" + elements + "end_header\n" + data;
}

// The header lines of `count` vertices with float coordinates x, y, z.
std::string ply_vertex_element(std::size_t count)
{
  return "element vertex " + std::to_string(count) + "\nproperty float x\nproperty float y\nproperty float z\n";
}

// The header lines of `count` faces, lists of vertex indices.
std::string ply_face_element(std::size_t count)
{
  return "element face " + std::to_string(count) + "\nproperty list uchar int vertex_indices\n";
}

// Binary STL of the faces of m (triangles), with the given float coordinates.
std::string binary_stl(const Indexed& m)
{
  std::string s(80, ' ');
  std::memcpy(&s[0], "binary stl written by test_tool", 31);
  const std::uint32_t n = static_cast<std::uint32_t>(m.faces.size());
  s.append(reinterpret_cast<const char*>(&n), 4);
  for (const auto& f : m.faces) {
    float values[12] = {0, 0, 0};
    for (int k = 0; k < 3; ++k)
      for (int c = 0; c < 3; ++c)
        values[3 + 3 * k + c] = static_cast<float>(m.points[f[k]][c]);
    s.append(reinterpret_cast<const char*>(values), sizeof values);
    s.append(2, '\0');
  }
  return s;
}

// Every method of the tool's registry.
const std::vector<std::string> methods = [] {
  std::vector<std::string> names;
  for (const ce_tool::Method& m : ce_tool::methods())
    names.push_back(m.name);
  return names;
}();

// ---------------------------------------------------------------------------
// Bad input
// ---------------------------------------------------------------------------

TEST_F(ToolTest, MissingFile) { expect_rejected({(dir / "no_such_file.off").string()}, "missing file"); }

TEST_F(ToolTest, UnreadableFile)
{
  fs::create_directories(dir / "a_directory.off"); // exists, cannot be read as a file (also as root)
  expect_rejected({(dir / "a_directory.off").string()}, "unreadable file");
}

TEST_F(ToolTest, UnknownExtension)
{
  expect_rejected({file("mesh.xyzw", off(tetrahedron())).string()}, "unknown extension");
  expect_rejected({file("mesh", off(tetrahedron())).string()}, "no extension");
}

TEST_F(ToolTest, BadOptions)
{
  const fs::path p = file("tet.off", off(tetrahedron()));
  expect_rejected({"-m", "nonsense", p.string()}, "unknown method");
  expect_rejected({"--rings", "0", p.string()}, "rings 0");
  expect_rejected({"--rings", "x", p.string()}, "rings x");
  expect_rejected({"-m", "curve-network", "--order", "5", p.string()}, "order 5");
  expect_rejected({"--order", "2", p.string()}, "order without curve-network");
  expect_rejected({"--color-by", "blue", p.string()}, "color-by");
  expect_rejected({"--bogus", p.string()}, "unknown option");
  expect_rejected({"-m", "jet", "--degree", "1", p.string()}, "jet degree 1");
  expect_rejected({"-m", "jet", "--degree", "5", p.string()}, "jet degree 5");
  expect_rejected({"-m", "jet", "--monge-degree", "3", p.string()}, "Monge degree above the jet degree");
  expect_rejected({"-m", "jet", "--degree", "3", "--monge-degree", "4", p.string()}, "Monge degree 4 > 3");
  expect_rejected({"--degree", "3", p.string()}, "degree without jet");
  expect_rejected({"-m", "taubin", "--monge-degree", "2", p.string()}, "Monge degree without jet");
  expect_rejected({"--fit-degree", "1", p.string()}, "fit degree 1");
  expect_rejected({"--fit-degree", "5", p.string()}, "fit degree 5");
  expect_rejected({"-m", "jet", "--fit-degree", "3", p.string()}, "fit degree without paraboloid");
  expect_rejected({"--scalars", (dir / "f.sol").string(), p.string()}, "--scalars on a surface");
  expect_rejected({}, "no input");
  const Result r = run({"-o", (dir / "out.txt").string(), p.string()});
  EXPECT_NE(r.exit_code, 0);
  EXPECT_FALSE(fs::exists(dir / "out.txt"));
}

TEST_F(ToolTest, GarbageFiles)
{
  const std::string garbage = "this is not a mesh\n\x01\x02\x03\xff\xfe garbage 12 ; ,,\n";
  for (const std::string ext : {".off", ".ply", ".obj", ".stl", ".xyz", ".pwn"})
    expect_rejected({file("garbage" + ext, garbage).string()}, "garbage " + ext);
  expect_rejected({file("zero_bytes.off", "").string()}, "zero-byte file");
}

TEST_F(ToolTest, TruncatedFiles)
{
  const std::string full = off(icosphere(1, 1));
  expect_rejected({file("truncated_vertices.off", full.substr(0, full.size() / 3)).string()},
                  "truncated OFF (vertices)");
  expect_rejected({file("truncated_faces.off", full.substr(0, full.size() - 12)).string()}, "truncated OFF (faces)");
  expect_rejected({file("header_only.off", "OFF\n4 4 0\n").string()}, "OFF header only");
  expect_rejected({file("huge_header.off", "OFF\n2000000000 2000000000 0\n0 0 0\n").string()}, "OFF huge counts");
  // Counts that CGAL 5.5's OFF reader converts from double to size_t unchecked (UB), and
  // a face claiming billions of vertices (it allocates them): found by the fuzz target.
  const std::string triangle = "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  expect_rejected({file("negative_count.off", "OFF\n-3 1 0\n" + triangle).string()}, "OFF negative count");
  expect_rejected({file("real_count.off", "OFF\n1e30 1 0\n" + triangle).string()}, "OFF count 1e30");
  expect_rejected({file("fraction_count.off", "OFF\n3.5 1 0\n" + triangle).string()}, "OFF count 3.5");
  expect_rejected({file("huge_face.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n2000000000 0 1 2\n").string()},
                  "OFF face with 2e9 vertices");
  expect_rejected({file("empty_face.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n0\n").string()}, "OFF face of 0 vertices");
  expect_rejected({file("binary.off", "OFF BINARY\n3 1 0\n" + triangle).string()}, "binary OFF");
  expect_rejected({file("4d.off", "4OFF\n3 1 0\n" + triangle).string()}, "4OFF");
  expect_rejected({file("extra_values.off", "OFF\n3 1 0\n0 0 0 7\n1 0 0\n0 1 0\n3 0 1 2\n").string()},
                  "OFF vertex with a fourth value");
  expect_rejected(
    {file("too_many_colours.off", "OFF\n3 1 0\n" + triangle.substr(0, triangle.size() - 1) + " 1 1 1 1 1\n").string()},
    "OFF face with 5 colour values");
  const std::string stl = binary_stl(icosphere(1, 1));
  expect_rejected({file("truncated.stl", stl.substr(0, stl.size() / 2)).string()}, "truncated binary STL");
  const std::string ply = ascii_ply(ply_vertex_element(4) + ply_face_element(4), "0 0 0\n1 0 0\n0 1 0\n");
  expect_rejected({file("truncated.ply", ply).string()}, "truncated PLY");
  // Found by the fuzz target: a property before any element crashes CGAL 5.5's PLY reader.
  const std::string four_points = "0 0 0\n1 0 0\n0 1 0\n0 0 1\n";
  const std::string no_element =
    ascii_ply("elemnt vertex 4\nproperty float x\nproperty float y\nproperty float z\n", four_points);
  expect_rejected({file("property_before_element.ply", no_element).string()}, "PLY property before any element");
  // Also found by the fuzz target: CGAL 5.5 reads x, y, z as float or double whatever their declared type.
  const std::string uchar_x = ascii_ply(
    "element vertex 3\nproperty uchar x\nproperty float y\nproperty float z\n" + ply_face_element(1), triangle);
  expect_rejected({file("uchar_coordinate.ply", uchar_x).string()}, "PLY coordinate of integer type");
  const std::string list_y = ascii_ply(
    "element vertex 3\nproperty float x\nproperty list uchar float y\nproperty float z\n" + ply_face_element(1),
    "0 1 0 0\n1 1 0 0\n0 1 1 0\n3 0 1 2\n");
  expect_rejected({file("list_coordinate.ply", list_y).string()}, "PLY coordinate of list type");
  // Found by the fuzz target: a negative count (read as size_t: 2^64 - 4 items, a
  // reader that never ends), made to look small by a positive one of another element.
  const std::string negative = ascii_ply("element other -4\n" + ply_vertex_element(4), four_points);
  expect_rejected({file("negative_count.ply", negative).string()}, "PLY negative element count");
  // And a count with trailing letters, which CGAL reads as its leading digits.
  const std::string trailing = ascii_ply("element vertex 419999999999999999et\n");
  expect_rejected({file("count_with_letters.ply", trailing).string()}, "PLY count with trailing letters");
  // And a second line starting with end_header: CGAL reads it as the format line.
  const std::string format_line = "ply\nend_header_ ascii 1.0\nproperty float y\nelement face 0\nend_header\n";
  expect_rejected({file("end_header_format.ply", format_line).string()}, "PLY end_header on the format line");
  // A list count of a signed or 32-bit type: CGAL resizes the list to it, cast to size_t.
  const std::string int_count =
    ascii_ply(ply_vertex_element(3) + "element face 1\nproperty list int int vertex_indices\n",
              "0 0 0\n1 0 0\n0 1 0\n-1 0 1 2\n");
  expect_rejected({file("int_list_count.ply", int_count).string()}, "PLY list count of type int");
}

TEST_F(ToolTest, IndicesOutOfRange)
{
  Indexed m = tetrahedron();
  m.faces.push_back({0, 1, 7});
  expect_rejected({file("range.off", off(m)).string()}, "OFF index out of range");
  expect_rejected({file("range.obj", obj(m)).string()}, "OBJ index out of range");
  expect_rejected({file("negative.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 -1\n").string()}, "OFF negative index");
  expect_rejected({file("zero.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n").string()}, "OBJ index 0");
  const std::string ply = ascii_ply(ply_vertex_element(3) + ply_face_element(1), "0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n");
  expect_rejected({file("range.ply", ply).string()}, "PLY index out of range");
}

TEST_F(ToolTest, EmptyMesh)
{
  expect_rejected({file("empty.off", "OFF\n0 0 0\n").string()}, "empty OFF");
  expect_rejected({file("empty.obj", "# nothing\n").string()}, "empty OBJ");
  const std::string ply = ascii_ply(ply_vertex_element(0) + ply_face_element(0));
  expect_rejected({file("empty.ply", ply).string()}, "empty PLY");
  std::string stl(80, ' ');
  stl.append(4, '\0');
  expect_rejected({file("empty.stl", stl).string()}, "empty binary STL");
}

TEST_F(ToolTest, OffHeaderVariants)
{
  // The same sphere as OFF, COFF (RGBA per vertex, RGB per face), NOFF (normals),
  // with comments and without the edge count: the same rows.
  const Indexed m = icosphere(1, 1);
  std::ostringstream coff, noff;
  coff.precision(17);
  noff.precision(17);
  coff << "# a comment\nCOFF\n" << m.points.size() << ' ' << m.faces.size() << " # no edge count\n";
  noff << "NOFF\n" << m.points.size() << ' ' << m.faces.size() << " 0\n";
  for (const auto& p : m.points) {
    coff << p[0] << ' ' << p[1] << ' ' << p[2] << " 0.5 0.5 1 1\n";
    noff << p[0] << ' ' << p[1] << ' ' << p[2] << ' ' << p[0] << ' ' << p[1] << ' ' << p[2] << "\n";
  }
  for (const auto& f : m.faces) {
    coff << "3 " << f[0] << ' ' << f[1] << ' ' << f[2] << " 255 0 0\n";
    noff << "3 " << f[0] << ' ' << f[1] << ' ' << f[2] << "\n";
  }
  const std::vector<Row> plain = csv(file("plain.off", off(m)));
  ASSERT_EQ(plain.size(), m.points.size());
  for (const auto& [name, text] : {std::pair<std::string, std::string>("c.off", coff.str()), {"n.off", noff.str()}}) {
    const std::vector<Row> rows = csv(file(name, text));
    ASSERT_EQ(rows.size(), plain.size()) << name;
    for (std::size_t i = 0; i < rows.size(); ++i)
      EXPECT_EQ(rows[i].values[2], plain[i].values[2]) << name << ", row " << i;
  }
}

TEST_F(ToolTest, NonFiniteCoordinates)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  for (double bad : {nan, inf, -inf}) {
    Indexed m = icosphere(1, 1);
    m.points[5][1] = bad;
    const std::string name = std::isnan(bad) ? "nan" : bad > 0 ? "inf" : "minus_inf";
    const fs::path stl = file(name + ".stl", binary_stl(m));
    expect_rejected({stl.string()}, "binary STL with " + name);
    // Binary STL reaches the tool's own check: the message names the problem.
    const Result r = run({stl.string()});
    EXPECT_NE(r.err.find("non-finite"), std::string::npos) << r.err;
    // As text (the readers may reject the token itself; either way it is an error).
    expect_rejected({file(name + ".off", off(m)).string()}, "OFF with " + name);
    expect_rejected({file(name + ".obj", obj(m)).string()}, "OBJ with " + name);
  }
  expect_rejected({file("overflow.off", "OFF\n3 1 0\n0 0 0\n1e400 0 0\n0 1 0\n3 0 1 2\n").string()}, "OFF overflow");
}

TEST_F(ToolTest, ExistingOutputIsKeptOnError)
{
  const fs::path output = file("keep.csv", "previous content\n");
  const Result r = run({"-o", output.string(), (dir / "missing.off").string()});
  EXPECT_NE(r.exit_code, 0);
  EXPECT_EQ(read_text(output), "previous content\n");
}

// ---------------------------------------------------------------------------
// Accepted degenerate input: one row per file vertex, for every method
// ---------------------------------------------------------------------------

class DegenerateTest : public ToolTest
{
public:
  std::vector<std::vector<Row>> all_methods(const fs::path& input, std::size_t vertices, const std::string& what)
  {
    std::vector<std::vector<Row>> result;
    for (const auto& m : methods) {
      const std::vector<Row> rows = csv(input, {"-m", m});
      EXPECT_EQ(rows.size(), vertices) << what << ", " << m;
      expect_consistent(rows, what + ", " + m);
      result.push_back(rows);
    }
    return result;
  }
};

TEST_F(DegenerateTest, IsolatedVertices)
{
  Indexed m = icosphere(1, 1);
  add_isolated_first_and_last(m.points, m.faces);
  const auto all = all_methods(file("isolated.off", off(m)), m.points.size(), "isolated vertices");
  for (const auto& rows : all)
    expect_only_first_and_last_failed(rows, m.points.size());
}

TEST_F(DegenerateTest, DegenerateFaces)
{
  Indexed m = icosphere(1, 1);
  const std::size_t n = m.points.size();
  // Zero-area faces: three collinear points (a separate component), and a face
  // repeating an index, and a two-vertex "face".
  m.points.push_back({3, 0, 0});
  m.points.push_back({4, 0, 0});
  m.points.push_back({5, 0, 0});
  m.faces.push_back({n, n + 1, n + 2});
  m.faces.push_back({0, 0, 1});
  m.faces.push_back({2, 3});
  const auto all = all_methods(file("degenerate.off", off(m)), m.points.size(), "degenerate faces");
  for (const auto& rows : all)
    for (std::size_t i = 0; i < n && i < rows.size(); ++i)
      EXPECT_NE(rows[i].status, "failed") << "sphere row " << i;
}

TEST_F(DegenerateTest, DuplicatePoints)
{
  Indexed m = icosphere(1, 1);
  // The last vertex is a copy of vertex 0, used by half of vertex 0's faces.
  m.points.push_back(m.points[0]);
  const std::size_t copy = m.points.size() - 1;
  bool flip = false;
  for (auto& f : m.faces)
    for (auto& i : f)
      if (i == 0 && (flip = !flip))
        i = copy;
  const auto all = all_methods(file("duplicates.off", off(m)), m.points.size(), "duplicate points");
  for (const auto& rows : all) {
    ASSERT_EQ(rows.size(), m.points.size());
    EXPECT_NE(rows[0].status, "failed");
    EXPECT_EQ(rows[0].status, rows[copy].status);
    for (std::size_t k = 0; k < 10; ++k)
      EXPECT_EQ(rows[0].values[k], rows[copy].values[k]);
  }
  // An STL file repeats every point in every triangle: still one row per distinct vertex.
  const std::vector<Row> stl = csv(file("sphere.stl", binary_stl(icosphere(1, 1))));
  expect_consistent(stl, "STL");
  EXPECT_GT(stl.size(), 0u);
}

TEST_F(DegenerateTest, NonManifoldVertexAndEdge)
{
  // Two tetrahedra sharing vertex 0 (a non-manifold vertex).
  Indexed bowtie = tetrahedron();
  Indexed other = tetrahedron(1, 0);
  for (auto& p : other.points)
    for (auto& c : p)
      c = -c;
  other.points.erase(other.points.begin());
  for (auto& f : other.faces)
    for (auto& i : f)
      i = i == 0 ? 0 : i + 3;
  for (const auto& p : other.points)
    bowtie.points.push_back(p);
  for (auto f : other.faces) {
    std::swap(f[0], f[1]); // the mirror image reverses orientation: restore outward
    bowtie.faces.push_back(f);
  }
  all_methods(file("bowtie.off", off(bowtie)), bowtie.points.size(), "non-manifold vertex");

  // Three triangles on one edge (0,1): a non-manifold edge.
  const Indexed fan{{{0, 0, 0}, {1, 0, 0}, {0.5, 1, 0}, {0.5, -1, 0}, {0.5, 0, 1}}, {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}}};
  all_methods(file("fan.off", off(fan)), fan.points.size(), "non-manifold edge");
  all_methods(file("fan.obj", obj(fan)), fan.points.size(), "non-manifold edge (OBJ)");
}

TEST_F(DegenerateTest, InconsistentOrientation)
{
  Indexed m = icosphere(1, 1);
  for (std::size_t f = 0; f < m.faces.size(); f += 3)
    std::swap(m.faces[f][0], m.faces[f][1]);
  const auto all = all_methods(file("flipped.off", off(m)), m.points.size(), "inconsistent orientation");
  for (const auto& rows : all)
    for (const auto& r : rows)
      EXPECT_NE(r.status, "failed");
}

TEST_F(DegenerateTest, BoundaryAndTinyComponents)
{
  // A single triangle, a dangling two-vertex face, a tetrahedron and a quad: tiny components.
  Indexed m{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {2, 2, 2}, {3, 2, 2}}, {{0, 1, 2}, {3, 4}}};
  append(m, tetrahedron(0.5, 10));
  append(m, Indexed{{{20, 0, 0}, {21, 0, 0}, {21, 1, 0}, {20, 1, 0}}, {{0, 1, 2, 3}}});
  // A strip of two triangles: its end vertices have two neighbors, one of them on one face.
  append(m, Indexed{{{30, 0, 0}, {31, 0, 0}, {30, 1, 0.2}, {31, 1, 0.1}}, {{0, 1, 2}, {1, 3, 2}}});
  const auto all = all_methods(file("tiny.off", off(m)), m.points.size(), "tiny components");
  for (const auto& rows : all) {
    ASSERT_EQ(rows.size(), m.points.size());
    EXPECT_EQ(rows[3].status, "failed"); // only in the two-vertex face
    EXPECT_EQ(rows[4].status, "failed");
  }
}

TEST_F(ToolTest, ThreadsGiveTheSameRows)
{
  const fs::path p = file("sphere.off", off(icosphere(2, 1)));
  const std::vector<Row> one = csv(p, {"--threads", "1"});
  const std::vector<Row> two = csv(p, {"--threads", "2"});
  ASSERT_EQ(one.size(), two.size());
  for (std::size_t i = 0; i < one.size(); ++i) {
    EXPECT_EQ(one[i].status, two[i].status);
    for (std::size_t k = 0; k < 10; ++k)
      EXPECT_EQ(one[i].values[k], two[i].values[k]) << "row " << i;
  }
}

// A mesh large enough that the file's text, the soup and the mesh's arrays are
// blocks of 8 MB or more, which the tool puts on huge pages (tools/huge_pages.cpp):
// every row is there and estimated, as on small meshes.
TEST_F(ToolTest, LargeMeshGivesEveryRow)
{
  const double r = 2.5;
  const Indexed m = icosphere(7, r); // 163,842 vertices, an OFF of about 10 MB
  const fs::path p = file("large_sphere.off", off(m));
  ASSERT_GE(fs::file_size(p), 8u << 20);
  const std::vector<Row> rows = csv(p);
  ASSERT_EQ(rows.size(), m.points.size());
  double max_error_H = 0;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    ASSERT_NE(rows[i].status, "failed") << "row " << i;
    max_error_H = std::max(max_error_H, std::abs(rows[i].values[2] * r - 1));
  }
  std::cout << "max |H r - 1| = " << max_error_H << '\n';
  // The default fit is of fourth order on spheres (quadric_fit.h): measured 7e-10.
  EXPECT_LT(max_error_H, 1e-6);
}

// ---------------------------------------------------------------------------
// Formats and values
// ---------------------------------------------------------------------------

TEST_F(ToolTest, SphereMeanCurvatureIsOneOverR)
{
  const double r = 2.5;
  const Indexed m = icosphere(3, r); // 642 vertices
  const fs::path p = file("sphere.off", off(m));
  for (const auto& method : methods) {
    const std::vector<Row> rows = csv(p, {"-m", method});
    ASSERT_EQ(rows.size(), m.points.size()) << method;
    expect_consistent(rows, method);
    double max_error_H = 0, max_error_K = 0;
    for (std::size_t i = 0; i < rows.size(); ++i) {
      EXPECT_NE(rows[i].status, "failed") << method << ", row " << i;
      max_error_H = std::max(max_error_H, std::abs(rows[i].values[2] * r - 1));
      max_error_K = std::max(max_error_K, std::abs(rows[i].values[3] * r * r - 1));
      // Directions: unit, orthogonal to each other.
      const auto& v = rows[i].values;
      EXPECT_NEAR(v[4] * v[4] + v[5] * v[5] + v[6] * v[6], 1, 1e-9);
      EXPECT_NEAR(v[7] * v[7] + v[8] * v[8] + v[9] * v[9], 1, 1e-9);
      EXPECT_NEAR(v[4] * v[7] + v[5] * v[8] + v[6] * v[9], 0, 1e-9);
    }
    std::cout << method << ": max |H r - 1| = " << max_error_H << ", max |K r^2 - 1| = " << max_error_K << '\n';
    EXPECT_LT(max_error_H, 0.05) << method; // positive: outward faces
    EXPECT_LT(max_error_K, 0.1) << method;
  }
}

// Higher jets on the same sphere (more coefficients, so fits widen to the 2-ring):
// measured max |H r - 1| 0.028 for degree 3 (odd jets fit the symmetric
// neighborhood worse) and 0.0009 for degree 4, within the tolerance above.
TEST_F(ToolTest, JetDegreesAndMongeDegrees)
{
  const double r = 2.5;
  const fs::path p = file("sphere.off", off(icosphere(3, r)));
  for (const auto& [degree, monge] : {std::pair<std::string, std::string>("3", "2"), {"3", "3"}, {"4", "4"}}) {
    const std::vector<Row> rows = csv(p, {"-m", "jet", "--degree", degree, "--monge-degree", monge});
    expect_consistent(rows, "jet " + degree + "/" + monge);
    double max_error_H = 0;
    for (const Row& row : rows) {
      EXPECT_NE(row.status, "failed");
      max_error_H = std::max(max_error_H, std::abs(row.values[2] * r - 1));
    }
    std::cout << "jet degree " << degree << ", Monge degree " << monge << ": max |H r - 1| = " << max_error_H << '\n';
    EXPECT_LT(max_error_H, 0.05);
  }
}

// --fit-degree 3 and 4 on the same sphere (Taylor fits over 2 and 3 rings): every row estimated,
// H within 1% of 1/r.
TEST_F(ToolTest, FitDegrees)
{
  const double r = 2.5;
  const fs::path p = file("sphere.off", off(icosphere(3, r)));
  for (const std::string degree : {"3", "4"}) {
    const std::vector<Row> rows = csv(p, {"--fit-degree", degree});
    expect_consistent(rows, "fit degree " + degree);
    double max_error_H = 0;
    for (const Row& row : rows) {
      EXPECT_NE(row.status, "failed");
      max_error_H = std::max(max_error_H, std::abs(row.values[2] * r - 1));
    }
    std::cout << "fit degree " << degree << ": max |H r - 1| = " << max_error_H << '\n';
    EXPECT_LT(max_error_H, 0.01);
  }
}

// The mean edge length of m as the tool's mesh of off(m) has it: the same points
// (the OFF has 17 digits) and the same edges, in the same order.
double tool_mean_edge_length(const Indexed& m)
{
  using Point = CGAL::Exact_predicates_inexact_constructions_kernel::Point_3;
  std::vector<Point> points;
  for (const auto& q : m.points)
    points.emplace_back(q[0], q[1], q[2]);
  CGAL::Surface_mesh<Point> mesh;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, m.faces, mesh);
  return CGAL::Curvature_estimation::mean_edge_length(mesh);
}

// A length with 17 digits, which the tool reads back to the same double.
std::string exact_text(double x)
{
  std::ostringstream s;
  s.precision(17);
  s << x;
  return s.str();
}

// --radius: the ball's radius in mesh units, or with x in mean edge lengths of
// the input (an irregular ellipsoid, 642 vertices).
class RadiusTest : public ToolTest
{
protected:
  const Indexed m = indexed(ce_test::ellipsoid_soup(1.2, 1, 0.8, 3, 0.2));
  fs::path p;

  void SetUp() override
  {
    ToolTest::SetUp();
    if (!IsSkipped())
      p = file("ellipsoid.off", off(m));
  }

  double mean_edge_length() const { return tool_mean_edge_length(m); }

  // Rejected with one line on stderr that holds every string of `words`.
  void expect_rejected_saying(const std::vector<std::string>& args, const std::vector<std::string>& words)
  {
    std::string what;
    for (const std::string& a : args)
      what += a + " ";
    expect_rejected(args, what);
    const Result r = run(args);
    for (const std::string& word : words)
      EXPECT_NE(r.err.find(word), std::string::npos) << what << ": " << r.err;
  }
};

// --radius 4x is --radius 4 * (mean edge length), to the last bit, for the
// methods that take it; and the ball is used (the rows differ from the rings').
TEST_F(RadiusTest, InMeanEdgesIsInMeshUnits)
{
  const std::string radius = exact_text(4 * mean_edge_length());
  for (const std::vector<std::string>& method : {std::vector<std::string>{"-m", "paraboloid"},
                                                 {"-m", "paraboloid", "--fit-degree", "3"},
                                                 {"-m", "jet", "--degree", "3"},
                                                 {"-m", "gauss-map"}})
  {
    auto with = [&](const std::string& r) {
      std::vector<std::string> args = method;
      args.insert(args.end(), {"--radius", r});
      return csv(p, args);
    };
    const std::vector<Row> in_edges = with("4x"), in_units = with(radius), rings = csv(p, method);
    ASSERT_EQ(in_edges.size(), m.points.size()) << method[1];
    ASSERT_EQ(in_units.size(), m.points.size()) << method[1];
    std::size_t differ_from_rings = 0;
    for (std::size_t i = 0; i < in_edges.size(); ++i) {
      EXPECT_NE(in_edges[i].status, "failed") << method[1] << ", row " << i;
      EXPECT_EQ(in_edges[i].status, in_units[i].status) << method[1] << ", row " << i;
      EXPECT_EQ(in_edges[i].values, in_units[i].values) << method[1] << ", row " << i;
      differ_from_rings += in_edges[i].values != rings[i].values;
    }
    EXPECT_EQ(differ_from_rings, in_edges.size()) << method[1];
  }
}

TEST_F(RadiusTest, BadValuesAreRejected)
{
  for (const std::string bad : {"0", "-1", "abc", "x", "inf", "nan", "0x", "-2x", "4xx", "4 x", "1e400", ""})
    expect_rejected_saying({"--radius", bad, p.string()}, {"--radius", "'" + bad + "'"});
  // Finite, but not in mesh units (mean edge length 10).
  expect_rejected_saying({"--radius", "1e308x", file("large.off", off(tetrahedron(10))).string()},
                         {"--radius", "mean edge length"});
}

TEST_F(RadiusTest, MethodsWithoutBallsRejectIt)
{
  for (const std::string method : {"curve-network", "taubin", "chen-schmitt"})
    expect_rejected_saying({"-m", method, "--radius", "4x", p.string()}, {"--radius", method});
  expect_rejected_saying({"--radius", "4x", "--rings", "2", p.string()}, {"--radius", "--rings"});
}

// The summary: the radius in mesh units and in mean edges, and the mean number of
// vertices in a ball; a ball wider than the closed surface holds all its vertices.
TEST_F(RadiusTest, Summary)
{
  const Result r = run({"--radius", "4x", p.string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::ostringstream radius;
  radius << "radius: " << 4 * mean_edge_length() << " (4 mean edge lengths of " << mean_edge_length() << ")";
  EXPECT_NE(r.out.find(radius.str()), std::string::npos) << radius.str() << " in\n" << r.out;
  const std::string neighborhood = "mean neighborhood: ";
  const std::size_t at = r.out.find(neighborhood);
  ASSERT_NE(at, std::string::npos) << r.out;
  // About pi (4 h)^2 over the area per vertex, (sqrt(3) / 2) h^2: 58.
  const double size = std::strtod(r.out.c_str() + at + neighborhood.size(), nullptr);
  std::cout << "--radius 4x: " << size << " vertices in a ball on average\n";
  EXPECT_GT(size, 40);
  EXPECT_LT(size, 80);
  const Result all = run({"-m", "jet", "--radius", "3", p.string()});
  ASSERT_EQ(all.exit_code, 0) << all.err;
  EXPECT_NE(all.out.find(neighborhood + std::to_string(m.points.size()) + ".0 vertices"), std::string::npos) << all.out;
  EXPECT_EQ(all.out.find("evenly spaced"), std::string::npos) << all.out;
  // Over 1000 vertices, the mean is over a sample, and the summary says so: every
  // third of 2562.
  const Result sampled = run({"--radius", "2x", file("sphere.off", off(icosphere(4, 1))).string()});
  ASSERT_EQ(sampled.exit_code, 0) << sampled.err;
  EXPECT_NE(sampled.out.find("over 854 evenly spaced vertices"), std::string::npos) << sampled.out;
}

const char* const auto_radius_header =
  "k_max,k_min,mean,gaussian,d_max_x,d_max_y,d_max_z,d_min_x,d_min_y,d_min_z,radius,noise,status";

// The median of `values` (the upper one of an even count).
double median(std::vector<double> values)
{
  std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(values.size() / 2), values.end());
  return values[values.size() / 2];
}

// --radius auto[:A:B]: the radius chosen per vertex (ball_radius_range) on the noisy
// ellipsoid of the ball_radius tests (2,562 vertices, Gaussian noise of 7% of the mean
// edge length), and the refusals on the clean one of RadiusTest.
class AutoRadiusTest : public RadiusTest
{
protected:
  const ce_test::Noisy_ellipsoid_soup noisy = ce_test::noisy_ellipsoid_soup(4, 1);
  const Indexed noisy_mesh = indexed(noisy.soup);
  fs::path noisy_path;

  void SetUp() override
  {
    RadiusTest::SetUp();
    if (!IsSkipped())
      noisy_path = file("noisy_ellipsoid.off", off(noisy_mesh));
  }

  // The RMS of the H column against the exact H over the rows that are not failed
  // (all of them, checked).
  double H_rms(const std::vector<Row>& rows) const
  {
    double sum = 0;
    for (std::size_t i = 0; i < rows.size(); ++i) {
      EXPECT_NE(rows[i].status, "failed") << "row " << i;
      const double e = rows[i].values[2] - noisy.exact[i].H;
      sum += e * e;
    }
    return std::sqrt(sum / double(rows.size()));
  }
};

// The columns radius and noise hold finite values on every row (none fails); H is
// far closer to the exact value than the default 1-ring's, the noise's median is
// that of the noise added, and the chosen radii lie in the range.
TEST_F(AutoRadiusTest, RadiusAndNoiseColumns)
{
  const std::vector<Row> chosen = csv(noisy_path, {"--radius", "auto"}, auto_radius_header), rings = csv(noisy_path);
  ASSERT_EQ(chosen.size(), noisy_mesh.points.size());
  ASSERT_EQ(rings.size(), noisy_mesh.points.size());
  expect_consistent(chosen, "--radius auto");
  const double auto_rms = H_rms(chosen), rings_rms = H_rms(rings);
  std::vector<double> radii, noise;
  for (const Row& r : chosen) {
    radii.push_back(r.values[10]);
    noise.push_back(r.values[11]);
  }
  const double h = tool_mean_edge_length(noisy_mesh);
  std::cout << "noisy ellipsoid, H RMS: 1 ring " << rings_rms << ", --radius auto " << auto_rms << "; median radius "
            << median(radii) / h << " mean edges, median noise " << median(noise) << " for sigma " << noisy.sigma
            << '\n';
  EXPECT_LT(auto_rms, 0.05 * rings_rms);
  EXPECT_GT(median(noise), 0.7 * noisy.sigma);
  EXPECT_LT(median(noise), 1.4 * noisy.sigma);
  EXPECT_GE(median(radii), h);
  EXPECT_LE(median(radii), 16 * h);
}

// The bounds in mean edges and in mesh units give the same rows, to the last bit;
// jet fitting and the fit of degree 3 take them too.
TEST_F(AutoRadiusTest, BoundsAndMethods)
{
  const double h = tool_mean_edge_length(noisy_mesh);
  const std::vector<Row> in_edges = csv(noisy_path, {"--radius", "auto:2x:8x"}, auto_radius_header),
                         in_units = csv(noisy_path, {"--radius", "auto:" + exact_text(2 * h) + ":" + exact_text(8 * h)},
                                        auto_radius_header);
  ASSERT_EQ(in_edges.size(), noisy_mesh.points.size());
  ASSERT_EQ(in_units.size(), noisy_mesh.points.size());
  for (std::size_t i = 0; i < in_edges.size(); ++i) {
    EXPECT_EQ(in_edges[i].status, in_units[i].status) << "row " << i;
    EXPECT_EQ(in_edges[i].values, in_units[i].values) << "row " << i;
  }
  for (const std::vector<std::string>& method :
       {std::vector<std::string>{"-m", "jet"}, {"-m", "paraboloid", "--fit-degree", "3"}})
  {
    std::vector<std::string> args = method;
    args.insert(args.end(), {"--radius", "auto:2x:8x"});
    std::string what;
    for (const std::string& a : args)
      what += a + " ";
    const std::vector<Row> chosen = csv(noisy_path, args, auto_radius_header), rings = csv(noisy_path, method);
    ASSERT_EQ(chosen.size(), noisy_mesh.points.size()) << what;
    expect_consistent(chosen, what);
    const double auto_rms = H_rms(chosen), rings_rms = H_rms(rings);
    std::cout << what << "H RMS " << auto_rms << ", without --radius " << rings_rms << '\n';
    EXPECT_LT(auto_rms, 0.2 * rings_rms) << what;
  }
}

// The PLY holds the radius and the noise as vertex properties, the CSV's values.
TEST_F(AutoRadiusTest, PlyProperties)
{
  const fs::path output = dir / "auto.ply";
  const Result r = run({"--radius", "auto", "-o", output.string(), noisy_path.string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3> mesh;
  std::ifstream in(output, std::ios::binary);
  ASSERT_TRUE(CGAL::IO::read_PLY(in, mesh));
  const std::vector<Row> rows = csv(noisy_path, {"--radius", "auto"}, auto_radius_header);
  ASSERT_EQ(num_vertices(mesh), rows.size());
  std::size_t column = 10;
  for (const char* name : {"v:radius", "v:noise"}) {
    const auto values = ce_test::find_property_map<decltype(mesh)::Vertex_index, double>(mesh, name);
    ASSERT_TRUE(values) << "no vertex property " << name;
    for (auto v : vertices(mesh))
      EXPECT_EQ((*values)[v], rows[std::size_t(v)].values[column]) << name;
    ++column;
  }
}

// The summary: the range, and the quartiles of the chosen radius and of the noise in
// mesh units and in mean edges; the noise's median is that of the noise added.
TEST_F(AutoRadiusTest, Summary)
{
  const Result r = run({"--radius", "auto", noisy_path.string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const double h = tool_mean_edge_length(noisy_mesh);
  std::ostringstream range;
  range << "radius range: " << h << " to " << 16 * h << " (1 to 16 mean edge lengths of " << h << ")";
  EXPECT_NE(r.out.find(range.str()), std::string::npos) << range.str() << " in\n" << r.out;
  for (const std::string line : {"chosen radius: ", "noise (standard deviation): "}) {
    const std::size_t at = r.out.find(line + "min ");
    ASSERT_NE(at, std::string::npos) << line << " in\n" << r.out;
    const std::string text = r.out.substr(at, r.out.find('\n', at) - at);
    for (const char* part : {", 25% ", ", median ", ", 75% ", ", max ", " (in mean edge lengths: "})
      EXPECT_NE(text.find(part), std::string::npos) << part << " in " << text;
  }
  const std::string noise_median = "noise (standard deviation): ";
  const std::size_t at = r.out.find(", median ", r.out.find(noise_median));
  ASSERT_NE(at, std::string::npos) << r.out;
  const double noise = std::strtod(r.out.c_str() + at + 9, nullptr);
  EXPECT_GT(noise, 0.7 * noisy.sigma) << r.out;
  EXPECT_LT(noise, 1.4 * noisy.sigma) << r.out;
  EXPECT_EQ(r.out.find("mean neighborhood"), std::string::npos) << r.out;
  // Without --radius auto, none of it.
  const Result rings = run({noisy_path.string()});
  ASSERT_EQ(rings.exit_code, 0) << rings.err;
  for (const char* line : {"radius range", "chosen radius", "noise"})
    EXPECT_EQ(rings.out.find(line), std::string::npos) << line << " in\n" << rings.out;
}

TEST_F(AutoRadiusTest, BadValuesAreRejected)
{
  for (const std::string bad : {"auto:0x:2x", "auto:4x:2x", "auto:abc", "auto:2x", "auto:2x:", "auto::2x",
                                "auto:1x:2x:3x", "autox", "auto:-1:2"})
    expect_rejected_saying({"--radius", bad, p.string()}, {"--radius"});
  expect_rejected_saying({"--radius", "auto:4x:2x", p.string()}, {"A <= B"});
  // The bounds in different units are compared in mesh units: 1 is more than 4 mean edges here.
  expect_rejected_saying({"--radius", "auto:1:4x", p.string()}, {"A <= B"});
  for (const std::string method : {"curve-network", "gauss-map", "taubin", "chen-schmitt"})
    expect_rejected_saying({"-m", method, "--radius", "auto", p.string()}, {"--radius auto", method});
  expect_rejected_saying({"--radius", "auto", "--rings", "2", p.string()}, {"--radius", "--rings"});
}

TEST_F(ToolTest, CsvRowsFollowTheFileOrder)
{
  // Same sphere, vertices written in reverse order: rows reverse too.
  const Indexed m = icosphere(2, 1);
  Indexed reversed = m;
  const std::size_t n = m.points.size();
  for (std::size_t i = 0; i < n; ++i)
    reversed.points[i] = m.points[n - 1 - i];
  for (auto& f : reversed.faces)
    for (auto& i : f)
      i = n - 1 - i;
  const std::vector<Row> a = csv(file("a.off", off(m)), {"-m", "gauss-map"});
  const std::vector<Row> b = csv(file("b.off", off(reversed)), {"-m", "gauss-map"});
  ASSERT_EQ(a.size(), n);
  ASSERT_EQ(b.size(), n);
  for (std::size_t i = 0; i < n; ++i)
    EXPECT_NEAR(a[i].values[2], b[n - 1 - i].values[2], 1e-12) << i;
}

TEST_F(ToolTest, PlyOutputReadsBack)
{
  Indexed m = icosphere(2, 1);
  const std::size_t n = m.points.size();
  const fs::path p = file("sphere.off", off(m));
  for (const std::string by : {"k_max", "k_min", "mean", "gaussian"}) {
    const fs::path output = dir / ("sphere_" + by + ".ply");
    const Result r = run({"-o", output.string(), "--color-by", by, p.string()});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3> mesh;
    std::ifstream in(output, std::ios::binary);
    ASSERT_TRUE(CGAL::IO::read_PLY(in, mesh)) << by;
    EXPECT_EQ(num_vertices(mesh), n);
    EXPECT_EQ(num_faces(mesh), m.faces.size());
    // The properties are there, with the CSV's values.
    const auto H = ce_test::find_property_map<decltype(mesh)::Vertex_index, double>(mesh, "v:mean");
    ASSERT_TRUE(H) << "no vertex property 'mean'";
    const std::vector<Row> rows = csv(p);
    ASSERT_EQ(rows.size(), n);
    for (auto v : vertices(mesh))
      EXPECT_EQ((*H)[v], rows[std::size_t(v)].values[2]);
  }
  // With an isolated vertex, read back as a soup: same vertex count as the file.
  m.points.push_back({9, 9, 9});
  const fs::path q = file("isolated.off", off(m));
  const fs::path output = dir / "isolated.ply";
  ASSERT_EQ(run({"-o", output.string(), q.string()}).exit_code, 0);
  std::vector<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3> points;
  std::vector<std::vector<std::size_t>> faces;
  ASSERT_TRUE(CGAL::IO::read_PLY(output.string(), points, faces));
  EXPECT_EQ(points.size(), m.points.size());
  EXPECT_EQ(faces.size(), m.faces.size());
  // As a mesh: the isolated vertex's values are NaN, its status 2 (failed).
  CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3> mesh;
  std::ifstream in(output, std::ios::binary);
  ASSERT_TRUE(CGAL::IO::read_PLY(in, mesh));
  ASSERT_EQ(num_vertices(mesh), m.points.size());
  const auto H = ce_test::find_property_map<decltype(mesh)::Vertex_index, double>(mesh, "v:mean");
  ASSERT_TRUE(H);
  const auto last = *std::prev(vertices(mesh).end());
  EXPECT_TRUE(std::isnan((*H)[last]));
  EXPECT_TRUE(std::isfinite((*H)[*vertices(mesh).begin()]));
  const auto status = ce_test::find_property_map<decltype(mesh)::Vertex_index, unsigned char>(mesh, "v:status");
  ASSERT_TRUE(status);
  EXPECT_EQ(int((*status)[last]), 2);
}

// An error while the output is written (a face the PLY's uchar count cannot hold)
// leaves no file, not even the temporary one, and keeps an existing output.
TEST_F(ToolTest, ErrorWhileWritingLeavesNoFile)
{
  Indexed disk;
  std::vector<std::size_t> face;
  for (std::size_t i = 0; i < 300; ++i) {
    const double a = 2 * M_PI * double(i) / 300;
    disk.points.push_back({std::cos(a), std::sin(a), 0});
    face.push_back(i);
  }
  disk.faces.push_back(face);
  const fs::path p = file("disk.off", off(disk));
  const std::vector<std::string> before = listing();
  const Result r = run({"-o", (dir / "out.ply").string(), p.string()});
  EXPECT_NE(r.exit_code, 0);
  EXPECT_EQ(count_lines(r.err), 1u) << r.err;
  EXPECT_NE(r.err.find("255"), std::string::npos) << r.err;
  EXPECT_EQ(listing(), before);
  const fs::path existing = file("existing.ply", "previous content\n");
  EXPECT_NE(run({"-o", existing.string(), p.string()}).exit_code, 0);
  EXPECT_EQ(read_text(existing), "previous content\n");
  EXPECT_EQ(csv(p).size(), disk.points.size()); // CSV has no such limit
}

TEST_F(ToolTest, SummaryAndHelp)
{
  const fs::path p = file("sphere.off", off(icosphere(2, 1)));
  const Result r = run({p.string()});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(r.err.empty()) << r.err;
  for (const char* s :
       {"vertices: 162", "time:", "mean curvature H: min", "Gaussian curvature K: min", "widened: ", "failed"})
    EXPECT_NE(r.out.find(s), std::string::npos) << s << " in\n" << r.out;
  const Result h = run({"--help"});
  EXPECT_EQ(h.exit_code, 0);
  EXPECT_NE(h.out.find("usage: curvature"), std::string::npos);
  const Result obj_run = run({file("sphere.obj", obj(icosphere(1, 1))).string()});
  EXPECT_EQ(obj_run.exit_code, 0) << obj_run.err;
}

TEST_F(ToolTest, RepairIsReportedOnStderr)
{
  Indexed m = icosphere(1, 1);
  std::swap(m.faces[0][0], m.faces[0][1]);
  const fs::path p = file("flipped.off", off(m));
  const Result r = run({"-o", (dir / "out.csv").string(), p.string()});
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_NE(r.err.find("repaired"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("re-oriented"), std::string::npos) << r.err;
}

// A soup that needs no repair takes the tool's direct path, the others CGAL's repair:
// each defect the direct path's check looks for is repaired (and said on stderr), and
// the rows of the vertices the files share are the clean file's, byte for byte.
class RepairPathTest : public ToolTest
{
public:
  struct Csv
  {
    std::vector<std::string> lines; // header, then a row per vertex
    std::string err;
  };

  Csv csv_lines(const fs::path& input, const std::string& method)
  {
    const fs::path output = dir / "lines.csv";
    fs::remove(output);
    const Result r = run({"-m", method, "-o", output.string(), input.string()});
    EXPECT_EQ(r.exit_code, 0) << r.err;
    Csv c{{}, r.err};
    std::istringstream in(read_text(output));
    for (std::string line; std::getline(in, line);)
      c.lines.push_back(line);
    return c;
  }

  // The variant's note contains `note`; its first rows are the clean mesh's.
  void expect_repaired_like(const Indexed& clean, const Indexed& variant, const std::string& note)
  {
    for (const std::string method : {"paraboloid", "gauss-map", "jet"}) {
      const Csv a = csv_lines(file("clean.off", off(clean)), method);
      const Csv b = csv_lines(file("variant.off", off(variant)), method);
      EXPECT_TRUE(a.err.empty()) << method << ": " << a.err;
      EXPECT_NE(b.err.find(note), std::string::npos) << method << ", " << note << ": " << b.err;
      ASSERT_EQ(a.lines.size(), clean.points.size() + 1);
      ASSERT_EQ(b.lines.size(), variant.points.size() + 1);
      for (std::size_t i = 0; i < a.lines.size(); ++i)
        EXPECT_EQ(a.lines[i], b.lines[i]) << method << ", " << note << ", line " << i;
    }
  }
};

TEST_F(RepairPathTest, CleanInputSaysNothing)
{
  const Result r = run({"-o", (dir / "out.csv").string(), file("sphere.off", off(icosphere(2, 1))).string()});
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_TRUE(r.err.empty()) << r.err;
}

TEST_F(RepairPathTest, FlippedFace)
{
  const Indexed clean = icosphere(2, 1);
  Indexed flipped = clean;
  std::swap(flipped.faces[7][0], flipped.faces[7][1]);
  expect_repaired_like(clean, flipped, "re-oriented 1 faces");
}

TEST_F(RepairPathTest, DuplicatePoint)
{
  const Indexed clean = icosphere(2, 1);
  Indexed variant = clean;
  // A copy of vertex 5 at the end, used by one of vertex 5's faces: its row is vertex 5's.
  variant.points.push_back(clean.points[5]);
  for (auto& f : variant.faces)
    if (std::find(f.begin(), f.end(), 5) != f.end()) {
      std::replace(f.begin(), f.end(), std::size_t(5), clean.points.size());
      break;
    }
  expect_repaired_like(clean, variant, "merged 1 duplicate points");
  const Csv b = csv_lines(file("variant.off", off(variant)), "paraboloid");
  ASSERT_EQ(b.lines.size(), variant.points.size() + 1);
  EXPECT_EQ(b.lines.back(), b.lines[6]);
}

TEST_F(RepairPathTest, DegenerateAndDuplicateFaces)
{
  const Indexed clean = icosphere(2, 1);
  Indexed repeated_index = clean;
  repeated_index.faces.push_back({3, 3, 4});
  expect_repaired_like(clean, repeated_index, "dropped 1 degenerate or duplicate faces");
  Indexed two_vertices = clean;
  two_vertices.faces.push_back({3, 4});
  expect_repaired_like(clean, two_vertices, "dropped 1 degenerate or duplicate faces");
  // A separate triangle twice, in opposite orientations: each of its edges is in two faces
  // of opposite orientations, which the edge check alone would accept.
  Indexed pillow = clean;
  const std::size_t n = clean.points.size();
  pillow.points.insert(pillow.points.end(), {{3, 0, 0}, {4, 0, 0}, {3, 1, 0}});
  pillow.faces.push_back({n, n + 1, n + 2});
  pillow.faces.push_back({n + 2, n + 1, n});
  expect_repaired_like(clean, pillow, "dropped 1 degenerate or duplicate faces");
}

TEST_F(RepairPathTest, IsolatedVertex)
{
  const Indexed clean = icosphere(2, 1);
  Indexed variant = clean;
  variant.points.push_back({3, 3, 3});
  expect_repaired_like(clean, variant, "1 of the file's vertices are in no face");
  const Csv b = csv_lines(file("variant.off", off(variant)), "paraboloid");
  ASSERT_FALSE(b.lines.empty());
  EXPECT_EQ(b.lines.back(), "nan,nan,nan,nan,nan,nan,nan,nan,nan,nan,failed");
}

TEST_F(RepairPathTest, NonManifoldVertex)
{
  // Two closed tetrahedra sharing one vertex: every edge is in two faces of opposite
  // orientations, but the faces around the shared vertex are two fans.
  Indexed m = tetrahedron();
  Indexed other = tetrahedron(1, 1); // its vertex 0 is m's vertex 1
  m.points.insert(m.points.end(), other.points.begin() + 1, other.points.end());
  for (auto face : other.faces) {
    for (auto& i : face)
      i = i == 0 ? 1 : i + 3;
    m.faces.push_back(face);
  }
  const Result r = run({"-o", (dir / "out.csv").string(), file("bowtie.off", off(m)).string()});
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_NE(r.err.find("duplicated 1 non-manifold vertices"), std::string::npos) << r.err;
}

// ---------------------------------------------------------------------------
// Tetrahedral input: Medit .mesh + .sol, the graph W = f(x, y, z)
// ---------------------------------------------------------------------------

const char* const tetrahedral_header = "k_1,k_2,k_3,mean,gaussian,status";

using Tetrahedra = ce_test::Tetrahedral_grid;

// The n^3 grid over [-1, 1]^3, every cube split into the 6 Kuhn tetrahedra around
// its diagonal; half of them negatively oriented, as a file may have them (the
// tool orients them).
Tetrahedra kuhn_grid(int n)
{
  return ce_test::kuhn_grid(n, ce_test::Kuhn_diagonal::main, ce_test::Kuhn_orientation::as_built);
}

std::string medit_mesh(const Tetrahedra& t, const std::string& extra_sections = "")
{
  std::ostringstream s;
  s.precision(17);
  s << "MeshVersionFormatted 2\n# written by test_tool\nDimension 3\n\nVertices\n" << t.points.size() << '\n';
  for (const auto& p : t.points)
    s << p[0] << ' ' << p[1] << ' ' << p[2] << " 0\n";
  s << extra_sections << "\nTetrahedra\n" << t.cells.size() << '\n';
  for (const auto& c : t.cells)
    s << c[0] + 1 << ' ' << c[1] + 1 << ' ' << c[2] + 1 << ' ' << c[3] + 1 << " 1\n";
  s << "\nEnd\n";
  return s.str();
}

std::string medit_sol(const std::vector<double>& values)
{
  std::ostringstream s;
  s.precision(17);
  s << "MeshVersionFormatted 2\n\nDimension 3\n\nSolAtVertices\n" << values.size() << "\n1 1\n\n";
  for (double v : values)
    s << v << '\n';
  s << "\nEnd\n";
  return s.str();
}

template <typename F>
std::vector<double> sample(const Tetrahedra& t, F f)
{
  std::vector<double> values;
  for (const auto& p : t.points)
    values.push_back(f(p[0], p[1], p[2]));
  return values;
}

class TetrahedralTest : public ToolTest
{
public:
  // NAME.mesh and NAME.sol beside it; returns the .mesh.
  fs::path graph(const std::string& name, const Tetrahedra& t, const std::vector<double>& f,
                 const std::string& extra_sections = "")
  {
    file(name + ".sol", medit_sol(f));
    return file(name + ".mesh", medit_mesh(t, extra_sections));
  }

  std::vector<Row> rows(const fs::path& mesh, std::vector<std::string> extra = {})
  {
    const std::vector<Row> r = csv(mesh, extra, tetrahedral_header);
    expect_consistent(r, mesh.filename().string());
    for (const Row& row : r)
      if (row.status != "failed") {
        const auto& k = row.values;
        EXPECT_GE(k[1], k[2]);
        EXPECT_NEAR(k[3], (k[0] + k[1] + k[2]) / 3, 1e-12 * (1 + std::abs(k[3])));
        EXPECT_NEAR(k[4], k[0] * k[1] * k[2], 1e-12 * (1 + std::abs(k[4])));
      }
    return r;
  }
};

TEST_F(TetrahedralTest, LinearGraphIsFlat)
{
  const Tetrahedra t = kuhn_grid(9);
  const fs::path p =
    graph("linear", t, sample(t, [](double x, double y, double z) { return 0.2 * x - 0.3 * y + 0.1 * z + 1; }));
  const std::vector<Row> r = rows(p);
  ASSERT_EQ(r.size(), t.points.size());
  for (std::size_t v = 0; v < r.size(); ++v) {
    EXPECT_NE(r[v].status, "failed") << "row " << v;
    for (std::size_t k = 0; k < 5; ++k)
      EXPECT_NEAR(r[v].values[k], 0, 1e-9) << "row " << v << ", column " << k;
  }
}

// f = (x^2 + y^2 + z^2) / 2: grad f = p, Hess f = I. The shape operator of the graph
// (normal (-p, 1)/l, l = sqrt(1 + |p|^2)) is G^-1 Hess f / l with the metric
// G = I + p p^T, whose eigenvalues are 1 + |p|^2 (along p) and 1, 1: the graph's
// principal curvatures are 1/l^3 and 1/l, 1/l. The normal points to increasing f,
// away from which the graph does not bend: in the package's convention (positive
// where it bends away from the normal) k_1 = -1/l^3 >= k_2 = k_3 = -1/l.
TEST_F(TetrahedralTest, QuadraticGraphHasTheExactCurvatureInside)
{
  const int n = 11;
  const Tetrahedra t = kuhn_grid(n);
  // Sections the tool skips, as Medit writers add them.
  const std::string extra = "Triangles\n1\n1 2 3 7\nEdges\n2\n1 2 0\n2 3 0\nCorners\n1\n1\nRidges\n1\n1\n";
  const fs::path p =
    graph("bowl", t, sample(t, [](double x, double y, double z) { return (x * x + y * y + z * z) / 2; }), extra);
  const std::vector<Row> r = rows(p);
  ASSERT_EQ(r.size(), t.points.size());
  double max_error_k = 0, max_error_H = 0;
  for (std::size_t v = 0; v < r.size(); ++v) {
    EXPECT_NE(r[v].status, "failed") << "row " << v;
    const auto& q = t.points[v];
    if (std::max({std::abs(q[0]), std::abs(q[1]), std::abs(q[2])}) > 0.99)
      continue; // boundary
    const double l = std::sqrt(1 + q[0] * q[0] + q[1] * q[1] + q[2] * q[2]);
    const double k[3] = {-1 / (l * l * l), -1 / l, -1 / l};
    for (int i = 0; i < 3; ++i)
      max_error_k = std::max(max_error_k, std::abs(r[v].values[i] - k[i]));
    max_error_H = std::max(max_error_H, std::abs(r[v].values[3] - (k[0] + k[1] + k[2]) / 3));
  }
  std::cout << "tetrahedral paraboloid fit of |p|^2/2, h = " << 2.0 / (n - 1) << ": max |k - exact| = " << max_error_k
            << ", max |H - exact| = " << max_error_H << " (interior)\n";
  // The fit's error is O(h^2); measured 0.011 (k) and 0.0072 (H) at h = 0.2: a
  // margin of 2.5 for other compilers and the library's changes, an order of
  // magnitude below the curvatures themselves (0.6 to 1).
  EXPECT_LT(max_error_k, 0.03);
  EXPECT_LT(max_error_H, 0.02);
  // At the centre, where the tangent space is horizontal, the paraboloid is exact.
  const std::size_t centre = std::size_t((n / 2 * n + n / 2) * n + n / 2);
  for (int i = 0; i < 3; ++i)
    EXPECT_NEAR(r[centre].values[i], -1, 1e-9);

  // The summary.
  const Result s = run({p.string()});
  EXPECT_EQ(s.exit_code, 0) << s.err;
  for (const std::string& line : std::vector<std::string>{
         "vertices: " + std::to_string(t.points.size()), "tetrahedra: " + std::to_string(t.cells.size()),
         "time:", "mean curvature H: min", "Gaussian curvature K: min", "failed (not estimable): 0"})
    EXPECT_NE(s.out.find(line), std::string::npos) << line << " in\n" << s.out;
}

TEST_F(TetrahedralTest, RowsFollowTheFileOrderAndScalarsNamesTheSol)
{
  const Tetrahedra t = kuhn_grid(5);
  const auto f = [](double x, double y, double z) { return std::sin(x) + x * y - 0.5 * z * z; };
  const std::vector<Row> a = rows(graph("a", t, sample(t, f)));

  // The vertices in reverse order, f from a .sol of another name given by --scalars.
  const std::size_t n = t.points.size();
  Tetrahedra reversed = t;
  for (std::size_t i = 0; i < n; ++i)
    reversed.points[i] = t.points[n - 1 - i];
  for (auto& c : reversed.cells)
    for (auto& i : c)
      i = n - 1 - i;
  const fs::path mesh = file("b.mesh", medit_mesh(reversed));
  const fs::path sol = file("other_name.sol", medit_sol(sample(reversed, f)));
  const std::vector<Row> b = rows(mesh, {"--scalars", sol.string()});
  ASSERT_EQ(a.size(), n);
  ASSERT_EQ(b.size(), n);
  for (std::size_t i = 0; i < n; ++i) {
    EXPECT_EQ(a[i].status, b[n - 1 - i].status) << i;
    for (std::size_t k = 0; k < 5 && a[i].status != "failed"; ++k)
      EXPECT_NEAR(a[i].values[k], b[n - 1 - i].values[k], 1e-9) << i;
  }
  // Without --scalars, b.sol is looked for beside b.mesh: there is none.
  expect_rejected({mesh.string()}, "no .sol beside the .mesh");
  const Result r = run({mesh.string()});
  EXPECT_NE(r.err.find("--scalars"), std::string::npos) << r.err;
  expect_rejected({"--scalars", (dir / "missing.sol").string(), mesh.string()}, "--scalars names a missing file");
  expect_rejected({"--scalars", (dir / "a.mesh").string(), mesh.string()}, "--scalars names a .mesh");
  expect_rejected({"--fit-degree", "4", mesh.string()}, "fit degree 4 on tetrahedral input");
}

TEST_F(TetrahedralTest, IsolatedVerticesAreFailed)
{
  Tetrahedra t = kuhn_grid(4);
  add_isolated_first_and_last(t.points, t.cells);
  const std::vector<Row> r =
    rows(graph("isolated", t, sample(t, [](double x, double y, double z) { return x * x - y * z; })));
  expect_only_first_and_last_failed(r, t.points.size());
}

TEST_F(TetrahedralTest, OptionsThatDoNotApply)
{
  const Tetrahedra t = kuhn_grid(3);
  const fs::path p = graph("g", t, sample(t, [](double x, double, double) { return x; }));
  expect_rejected({"-m", "gauss-map", p.string()}, "gauss-map on .mesh");
  expect_rejected({"-m", "jet", p.string()}, "jet on .mesh");
  expect_rejected({"-m", "jet", "--radius", "2x", p.string()}, "jet with --radius on .mesh");
  expect_rejected({"--radius", "2x", "--rings", "2", p.string()}, "--radius with --rings on .mesh");
  expect_rejected({"--radius", "auto", p.string()}, "--radius auto on .mesh");
  const fs::path ply = dir / "out.ply";
  const Result r = run({"-o", ply.string(), p.string()});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(count_lines(r.err), 1u) << r.err;
  EXPECT_NE(r.err.find("CSV"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(ply));
  // --rings applies.
  EXPECT_EQ(rows(p, {"--rings", "2"}).size(), t.points.size());
}

// --radius on .mesh input: the ball, and the mean edge length that Nx multiplies, are
// those of R^4 (the points (x, y, z, f)): 3x is 3 times that length, to the last bit,
// computed here over the tetrahedra's edges, each once; the summary shows the radius
// and the mean number of vertices in a ball. On the bowl of QuadraticGraphHasTheExactCurvatureInside
// with noise in f, the ball averages the noise that the 1-ring fit measures.
TEST_F(TetrahedralTest, RadiusIsABallOfR4)
{
  const int n = 13;
  const Tetrahedra t = kuhn_grid(n);
  std::mt19937 random(1);
  std::vector<double> f = sample(t, [](double x, double y, double z) { return (x * x + y * y + z * z) / 2; });
  for (double& value : f)
    value += 0.005 * ce_test::uniform_symmetric(random);
  const fs::path p = graph("noisy_bowl", t, f);

  std::set<std::pair<std::size_t, std::size_t>> edges;
  for (const auto& c : t.cells)
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j)
        edges.emplace(std::min(c[i], c[j]), std::max(c[i], c[j]));
  double length_sum = 0;
  for (const auto& [a, b] : edges) {
    const auto& q = t.points[a];
    const auto& r = t.points[b];
    length_sum += std::sqrt((q[0] - r[0]) * (q[0] - r[0]) + (q[1] - r[1]) * (q[1] - r[1]) +
                            (q[2] - r[2]) * (q[2] - r[2]) + (f[a] - f[b]) * (f[a] - f[b]));
  }
  const double mean_edge = length_sum / double(edges.size());
  const std::string radius = exact_text(3 * mean_edge);

  const std::vector<Row> in_edges = rows(p, {"--radius", "3x"}), in_units = rows(p, {"--radius", radius}),
                         rings = rows(p);
  ASSERT_EQ(in_edges.size(), t.points.size());
  ASSERT_EQ(in_units.size(), t.points.size());
  double ball_sum = 0, rings_sum = 0;
  std::size_t interior = 0;
  for (std::size_t v = 0; v < in_edges.size(); ++v) {
    EXPECT_NE(in_edges[v].status, "failed") << "row " << v;
    EXPECT_EQ(in_edges[v].status, in_units[v].status) << "row " << v;
    EXPECT_EQ(in_edges[v].values, in_units[v].values) << "row " << v;
    const auto& q = t.points[v];
    if (std::max({std::abs(q[0]), std::abs(q[1]), std::abs(q[2])}) > 0.5)
      continue; // within the ball's reach of the boundary
    const double l = std::sqrt(1 + q[0] * q[0] + q[1] * q[1] + q[2] * q[2]);
    const double H = (-1 / (l * l * l) - 2 / l) / 3;
    ball_sum += (in_edges[v].values[3] - H) * (in_edges[v].values[3] - H);
    rings_sum += (rings[v].values[3] - H) * (rings[v].values[3] - H);
    ++interior;
  }
  const double ball_rms = std::sqrt(ball_sum / double(interior)), rings_rms = std::sqrt(rings_sum / double(interior));
  std::cout << "noisy bowl (" << interior << " interior vertices), H RMS: 1 ring " << rings_rms << ", radius 3x "
            << ball_rms << '\n';
  EXPECT_LT(ball_rms, rings_rms / 2);

  const Result s = run({"--radius", "3x", p.string()});
  EXPECT_EQ(s.exit_code, 0) << s.err;
  std::ostringstream line;
  line << "radius: " << 3 * mean_edge << " (3 mean edge lengths of " << mean_edge << ")";
  EXPECT_NE(s.out.find(line.str()), std::string::npos) << line.str() << " in\n" << s.out;
  EXPECT_NE(s.out.find("mean neighborhood: "), std::string::npos) << s.out;
}

TEST_F(TetrahedralTest, BadInput)
{
  const Tetrahedra t = kuhn_grid(2); // 8 vertices, 6 tetrahedra
  const std::string mesh = medit_mesh(t);
  const std::string sol = medit_sol(sample(t, [](double x, double y, double z) { return x + y * z; }));
  auto replaced = [](std::string text, const std::string& from, const std::string& to) {
    const std::size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    return at == std::string::npos ? text : text.replace(at, from.size(), to);
  };
  auto with_cell = [&](std::array<std::size_t, 4> cell) {
    Tetrahedra u = t;
    u.cells.push_back(cell);
    return medit_mesh(u);
  };
  auto with_point = [&](const std::string& coordinate) {
    return replaced(mesh, "Vertices\n8\n-1 -1 -1 0\n", "Vertices\n8\n-1 " + coordinate + " -1 0\n");
  };
  const std::vector<std::pair<std::string, std::string>> bad_meshes = {
    {"empty", ""},
    {"garbage", "this is not a mesh\n\x01\x02\xff"},
    {"truncated", mesh.substr(0, mesh.size() / 2)},
    {"no_end_of_cells", replaced(mesh, "Tetrahedra\n6\n", "Tetrahedra\n7\n")},
    {"vertex_count_too_large", replaced(mesh, "Vertices\n8\n", "Vertices\n9\n")},
    {"vertex_count_huge", replaced(mesh, "Vertices\n8\n", "Vertices\n2000000000\n")},
    {"vertex_count_negative", replaced(mesh, "Vertices\n8\n", "Vertices\n-8\n")},
    {"index_too_large", with_cell({0, 1, 2, 8})},
    {"index_zero", replaced(mesh, "Tetrahedra\n6\n1 ", "Tetrahedra\n6\n0 ")},
    {"repeated_vertex", with_cell({0, 1, 1, 7})},
    {"zero_volume", with_cell({0, 1, 2, 3})}, // the square z = -1
    {"duplicate_tetrahedron", with_cell({t.cells[2][3], t.cells[2][1], t.cells[2][0], t.cells[2][2]})},
    {"nan", with_point("nan")},
    {"inf", with_point("-inf")},
    {"overflow", with_point("1e400")},
    {"word_for_a_number", with_point("one")},
    {"dimension_2", replaced(mesh, "Dimension 3", "Dimension 2")},
    {"version_3", replaced(mesh, "MeshVersionFormatted 2", "MeshVersionFormatted 3")},
    {"unknown_section", replaced(mesh, "Tetrahedra", "Spheres\n1\n0 0 0 1\nTetrahedra")},
    {"no_tetrahedra", mesh.substr(0, mesh.find("Tetrahedra")) + "End\n"},
    {"tetrahedra_first", "MeshVersionFormatted 1\nDimension 3\nTetrahedra\n0\nVertices\n0\nEnd\n"},
    {"after_end", mesh + "Vertices\n"},
  };
  for (const auto& [name, text] : bad_meshes) {
    file(name + ".sol", sol);
    expect_rejected({file(name + ".mesh", text).string()}, name + ".mesh");
  }
  const std::vector<std::pair<std::string, std::string>> bad_sols = {
    {"sol_empty", ""},
    {"sol_truncated", sol.substr(0, sol.size() - 12)},
    {"sol_count_too_small", replaced(sol, "SolAtVertices\n8\n", "SolAtVertices\n7\n")},
    {"sol_count_too_large", replaced(sol, "SolAtVertices\n8\n", "SolAtVertices\n9\n")},
    {"sol_vector", replaced(sol, "\n1 1\n", "\n1 2\n")},
    {"sol_two_solutions", replaced(sol, "\n1 1\n", "\n2 1 1\n")},
    {"sol_nan", replaced(sol, "\n1 1\n\n", "\n1 1\n\nnan\n")},
    {"sol_at_tetrahedra", replaced(sol, "SolAtVertices", "SolAtTetrahedra")},
    {"sol_extra_values", replaced(sol, "\nEnd\n", "\n1\nEnd\n")},
  };
  for (const auto& [name, text] : bad_sols) {
    file(name + ".sol", text);
    expect_rejected({file(name + ".mesh", mesh).string()}, name);
  }
}

// ---------------------------------------------------------------------------
// Point sets
// ---------------------------------------------------------------------------

const char* const point_set_csv_header =
  "k_max,k_min,mean,gaussian,d_max_x,d_max_y,d_max_z,d_min_x,d_min_y,d_min_z,nx,ny,nz,status";

using Vec3 = std::array<double, 3>;

struct Points
{
  std::vector<Vec3> points, normals; // normals: none, or one per point
};

// n points of a Fibonacci spiral on the sphere of radius r about `center`, with the
// outward normals; each value a multiple of 2^-10, so that every format holds exactly
// the same values (CGAL's ASCII PLY reader does not round 17 digits to the nearest
// float or double, as the tool's readers do: the rows differed in the last bits).
Points sphere_points(std::size_t n, double r, const Vec3& center)
{
  Points s;
  const double golden = M_PI * (3 - std::sqrt(5.0));
  for (std::size_t i = 0; i < n; ++i) {
    const double z = 1 - 2 * (double(i) + 0.5) / double(n), rho = std::sqrt(1 - z * z), a = golden * double(i);
    const Vec3 u = {rho * std::cos(a), rho * std::sin(a), z};
    Vec3 p, normal;
    for (int c = 0; c < 3; ++c) {
      p[c] = std::round(1024 * (center[c] + r * u[c])) / 1024;
      normal[c] = std::round(1024 * u[c]) / 1024;
    }
    s.points.push_back(p);
    s.normals.push_back(normal);
  }
  return s;
}

std::string values_line(const Vec3& a, const Vec3* b = nullptr)
{
  std::ostringstream s;
  s.precision(17);
  s << a[0] << ' ' << a[1] << ' ' << a[2];
  if (b)
    s << ' ' << (*b)[0] << ' ' << (*b)[1] << ' ' << (*b)[2];
  return s.str() + "\n";
}

// .xyz (or .pwn) text: a point a line, with its normal where the points have normals.
std::string xyz(const Points& s, const std::string& first_line = "")
{
  std::string text = first_line;
  for (std::size_t i = 0; i < s.points.size(); ++i)
    text += values_line(s.points[i], s.normals.empty() ? nullptr : &s.normals[i]);
  return text;
}

std::string ply_point_properties(const Points& s, const char* type)
{
  std::string header = "element vertex " + std::to_string(s.points.size()) + "\n";
  for (const char* name : {"x", "y", "z", "nx", "ny", "nz"})
    if (name[0] != 'n' || !s.normals.empty())
      header += std::string("property ") + type + " " + name + "\n";
  return header;
}

std::string ascii_ply_points(const Points& s) { return ascii_ply(ply_point_properties(s, "float"), xyz(s)); }

std::string binary_ply_points(const Points& s)
{
  std::string text = "ply\nformat binary_little_endian 1.0\n" + ply_point_properties(s, "double") + "end_header\n";
  for (std::size_t i = 0; i < s.points.size(); ++i) {
    std::vector<double> values(s.points[i].begin(), s.points[i].end());
    if (!s.normals.empty())
      values.insert(values.end(), s.normals[i].begin(), s.normals[i].end());
    text.append(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(double));
  }
  return text;
}

std::string off_points(const Points& s)
{
  Points plain{s.points, {}};
  return "OFF\n" + std::to_string(s.points.size()) + " 0 0\n" + xyz(plain);
}

// NOFF without faces: a point and its normal a line.
std::string noff_points(const Points& s) { return "NOFF\n" + std::to_string(s.points.size()) + " 0 0\n" + xyz(s); }

Points without_normals(const Points& s) { return Points{s.points, {}}; }

const Vec3 sphere_center = {1, -2, 0.5};
constexpr double sphere_radius = 2;

// Every format gives the same points: the rows of the files without normals are
// equal to the last bit, and so are those of the files with normals; on the sphere
// H is 1/r (the outward normals of the file, or the propagation's, outward on a
// closed surface), and the normal column is the outward normal, row by row in the
// file's order.
TEST_F(ToolTest, PointSetFormatsGiveTheSameRows)
{
  const Points s = sphere_points(2000, sphere_radius, sphere_center);
  const Points plain = without_normals(s);
  const std::vector<std::pair<std::string, std::string>> without = {
    {"three_columns.xyz", xyz(plain)},
    {"counted.xyz", xyz(plain, "# a comment, then the count\n2000\n")},
    {"ascii.ply", ascii_ply_points(plain)},
    {"binary.ply", binary_ply_points(plain)},
    {"faceless.off", off_points(s)},
    {"zero_faces.ply", ascii_ply(ply_point_properties(plain, "float") + ply_face_element(0), xyz(plain))}};
  const std::vector<std::pair<std::string, std::string>> with = {{"six_columns.xyz", xyz(s)},
                                                                 {"points.pwn", xyz(s)},
                                                                 {"normals_ascii.ply", ascii_ply_points(s)},
                                                                 {"normals_binary.ply", binary_ply_points(s)},
                                                                 {"normals.off", noff_points(s)}};
  for (const auto* files : {&without, &with}) {
    std::vector<Row> first;
    for (const auto& [name, text] : *files) {
      const std::vector<Row> rows = csv(file(name, text), {}, point_set_csv_header);
      ASSERT_EQ(rows.size(), s.points.size()) << name;
      if (first.empty())
        first = rows;
      std::size_t beyond_one_percent = 0;
      for (std::size_t i = 0; i < rows.size(); ++i) {
        EXPECT_EQ(rows[i].values, first[i].values) << name << ", row " << i;
        EXPECT_EQ(rows[i].status, first[i].status) << name << ", row " << i;
        ASSERT_NE(rows[i].status, "failed") << name << ", row " << i;
        EXPECT_NEAR(rows[i].values[2], 1 / sphere_radius, 0.05 / sphere_radius) << name << ", row " << i;
        double along = 0;
        for (int c = 0; c < 3; ++c)
          along += rows[i].values[10 + c] * s.normals[i][c];
        EXPECT_GT(along, 0.99) << name << ", row " << i;
        beyond_one_percent += std::abs(rows[i].values[2] * sphere_radius - 1) > 0.01;
      }
      std::cout << name << ": " << beyond_one_percent << " of " << rows.size()
                << " rows with H off 1/r by more than 1%\n";
    }
  }
}

// Given normals orient the result (a .pwn's, a NOFF's): inward normals give H = -1/r.
TEST_F(ToolTest, PointSetGivenNormalsSetTheSign)
{
  Points s = sphere_points(2000, sphere_radius, sphere_center);
  for (Vec3& n : s.normals)
    for (double& c : n)
      c = -c;
  for (const auto& [name, text] :
       {std::pair<std::string, std::string>{"inward.pwn", xyz(s)}, {"inward.off", noff_points(s)}})
  {
    const std::vector<Row> rows = csv(file(name, text), {}, point_set_csv_header);
    ASSERT_EQ(rows.size(), s.points.size()) << name;
    for (std::size_t i = 0; i < rows.size(); ++i)
      EXPECT_NEAR(rows[i].values[2], -1 / sphere_radius, 0.05 / sphere_radius) << name << ", row " << i;
  }
}

// Rows follow the file's order: the points in another order give the same rows in that order.
TEST_F(ToolTest, PointSetRowsFollowTheFileOrder)
{
  const Points s = without_normals(sphere_points(500, sphere_radius, sphere_center));
  Points shuffled = s;
  std::vector<std::size_t> order(s.points.size());
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::shuffle(order.begin(), order.end(), std::mt19937(7));
  for (std::size_t i = 0; i < order.size(); ++i)
    shuffled.points[i] = s.points[order[i]];
  const std::vector<Row> a = csv(file("a.xyz", xyz(s)), {}, point_set_csv_header);
  const std::vector<Row> b = csv(file("b.xyz", xyz(shuffled)), {}, point_set_csv_header);
  ASSERT_EQ(a.size(), s.points.size());
  ASSERT_EQ(b.size(), s.points.size());
  for (std::size_t i = 0; i < order.size(); ++i)
    for (std::size_t c = 0; c < a[0].values.size(); ++c)
      EXPECT_NEAR(b[i].values[c], a[order[i]].values[c], 1e-9) << "row " << i << ", column " << c;
}

// Few points: rows of failed, nan values; the CSV still has a row per point.
TEST_F(ToolTest, PointSetTooSmallToFitIsFailedRows)
{
  const std::vector<Row> rows = csv(file("three.off", "OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n"), {}, point_set_csv_header);
  ASSERT_EQ(rows.size(), 3u);
  for (const Row& r : rows)
    EXPECT_EQ(r.status, "failed");
  expect_consistent(rows, "three points");
}

// The PLY output: the points, the CSV's values and normals, a status and colours; no faces.
TEST_F(ToolTest, PointSetPlyOutput)
{
  const Points s = without_normals(sphere_points(300, sphere_radius, sphere_center));
  const fs::path p = file("sphere.xyz", xyz(s));
  const fs::path output = dir / "out.ply";
  const Result r = run({"-o", output.string(), p.string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string text = read_text(output);
  const std::size_t end = text.find("end_header\n");
  ASSERT_NE(end, std::string::npos);
  const std::string header = text.substr(0, end);
  EXPECT_EQ(header.find("element face"), std::string::npos) << header;
  EXPECT_NE(header.find("element vertex 300\n"), std::string::npos) << header;
  const std::vector<std::string> names = {"x",        "y",       "z",       "k_max",   "k_min",   "mean",
                                          "gaussian", "d_max_x", "d_max_y", "d_max_z", "d_min_x", "d_min_y",
                                          "d_min_z",  "nx",      "ny",      "nz"};
  std::string properties;
  for (const std::string& name : names)
    properties += "property double " + name + "\n";
  properties += "property uchar status\nproperty uchar red\nproperty uchar green\nproperty uchar blue\n";
  EXPECT_NE(header.find(properties), std::string::npos) << header;
  const std::size_t record = names.size() * sizeof(double) + 4;
  ASSERT_EQ(text.size(), end + 11 + s.points.size() * record);
  const std::vector<Row> rows = csv(p, {}, point_set_csv_header);
  ASSERT_EQ(rows.size(), s.points.size());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    std::vector<double> values(names.size());
    std::memcpy(values.data(), text.data() + end + 11 + i * record, names.size() * sizeof(double));
    for (int c = 0; c < 3; ++c)
      EXPECT_EQ(values[std::size_t(c)], s.points[i][std::size_t(c)]) << i;
    for (std::size_t c = 0; c < rows[i].values.size(); ++c)
      EXPECT_EQ(values[3 + c], rows[i].values[c]) << "row " << i << ", column " << c;
    const std::map<std::string, int> codes = {{"ok", 0}, {"widened", 1}, {"failed", 2}, {"fallback", 3}};
    EXPECT_EQ(int(text[end + 11 + i * record + names.size() * sizeof(double)]), codes.at(rows[i].status)) << i;
  }
}

// The summary: the neighborhood, and how the normals were oriented.
TEST_F(ToolTest, PointSetSummary)
{
  const Points one = sphere_points(400, sphere_radius, sphere_center);
  const Result given = run({file("given.pwn", xyz(one)).string()});
  ASSERT_EQ(given.exit_code, 0) << given.err;
  for (const char* s : {"points: 400 with normals", "neighbors: the 16 nearest points", "normals: the file's",
                        "time:", "mean curvature H: min", "ok: "})
    EXPECT_NE(given.out.find(s), std::string::npos) << s << " in\n" << given.out;
  // Two spheres far apart: two components of the propagation, each oriented on its own.
  Points two = without_normals(one);
  const Points other = sphere_points(400, 1, {20, 0, 0});
  two.points.insert(two.points.end(), other.points.begin(), other.points.end());
  const Result fitted = run({"--neighbors", "24", "--fit-degree", "3", file("two.xyz", xyz(two)).string()});
  ASSERT_EQ(fitted.exit_code, 0) << fitted.err;
  for (const char* s : {"points: 800\n", "method: point-set fit of degree 3", "neighbors: the 24 nearest points",
                        "spanning-tree propagation: 2 components", "orientation confidence below 0.1"})
    EXPECT_NE(fitted.out.find(s), std::string::npos) << s << " in\n" << fitted.out;
  // Normals all zero (placeholders) are ignored, and the summary says so.
  Points zero = one;
  for (Vec3& n : zero.normals)
    n = {0, 0, 0};
  const Result zeros = run({file("zero.xyz", xyz(zero)).string()});
  ASSERT_EQ(zeros.exit_code, 0) << zeros.err;
  EXPECT_NE(zeros.out.find("normals: the file's are all zero, ignored; fitted"), std::string::npos) << zeros.out;
}

// The mean distance to the nearest neighbor, by brute force.
double brute_force_mean_spacing(const Points& s)
{
  double sum = 0;
  for (std::size_t i = 0; i < s.points.size(); ++i) {
    double nearest = std::numeric_limits<double>::infinity();
    for (std::size_t j = 0; j < s.points.size(); ++j)
      if (j != i) {
        double d2 = 0;
        for (int c = 0; c < 3; ++c)
          d2 += (s.points[i][c] - s.points[j][c]) * (s.points[i][c] - s.points[j][c]);
        nearest = std::min(nearest, std::sqrt(d2));
      }
    sum += nearest;
  }
  return sum / double(s.points.size());
}

// --radius Nx is N mean distances to the nearest neighbor (computed here by brute force).
TEST_F(ToolTest, PointSetRadiusInMeanSpacings)
{
  const Points s = without_normals(sphere_points(600, sphere_radius, sphere_center));
  const double spacing = brute_force_mean_spacing(s);
  const fs::path p = file("sphere.xyz", xyz(s));
  const Result r = run({"--radius", "3x", p.string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string key = "neighbors: the points within ";
  const std::size_t at = r.out.find(key);
  ASSERT_NE(at, std::string::npos) << r.out;
  char* end = nullptr;
  const double radius = std::strtod(r.out.c_str() + at + key.size(), &end);
  EXPECT_NEAR(radius, 3 * spacing, 1e-5 * spacing) << r.out;
  EXPECT_EQ(std::string(end, 4), " (3 ") << r.out;
  EXPECT_NE(r.out.find("mean distances to the nearest neighbor"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("points in a ball"), std::string::npos) << r.out;
  const std::vector<Row> rows = csv(p, {"--radius", "3x"}, point_set_csv_header);
  ASSERT_EQ(rows.size(), s.points.size());
  for (std::size_t i = 0; i < rows.size(); ++i)
    EXPECT_NEAR(rows[i].values[2], 1 / sphere_radius, 0.05 / sphere_radius) << i;
}

const char* const point_set_auto_radius_header =
  "k_max,k_min,mean,gaussian,d_max_x,d_max_y,d_max_z,d_min_x,d_min_y,d_min_z,nx,ny,nz,radius,noise,status";

// --radius auto on a point set: 2000 points of the sphere moved along the radius by Gaussian noise of 10% of the
// mean distance to the nearest neighbor.
class PointSetAutoRadiusTest : public RadiusTest
{
protected:
  Points noisy;
  double spacing = 0, sigma = 0;
  fs::path path;

  void SetUp() override
  {
    RadiusTest::SetUp();
    if (IsSkipped())
      return;
    noisy = without_normals(sphere_points(2000, sphere_radius, sphere_center));
    sigma = 0.1 * brute_force_mean_spacing(noisy);
    std::mt19937 gen(3);
    for (Vec3& p : noisy.points) {
      const double moved = 1 + sigma * ce_test::standard_normal(gen) / sphere_radius;
      for (int c = 0; c < 3; ++c)
        p[c] = sphere_center[c] + moved * (p[c] - sphere_center[c]);
    }
    spacing = brute_force_mean_spacing(noisy);
    path = file("noisy_sphere.xyz", xyz(noisy));
  }

  double H_rms(const std::vector<Row>& rows) const
  {
    double sum = 0;
    for (const Row& r : rows) {
      EXPECT_NE(r.status, "failed");
      sum += (r.values[2] - 1 / sphere_radius) * (r.values[2] - 1 / sphere_radius);
    }
    return std::sqrt(sum / double(rows.size()));
  }
};

// The radius and noise columns: finite on every row, the radius within the default range 2x to 32x or the 16 nearest
// points' (kept on clean data), the noise's median that of the noise added, H closer to the exact value than the
// 16 nearest points give it.
TEST_F(PointSetAutoRadiusTest, RadiusAndNoiseColumns)
{
  const std::vector<Row> chosen = csv(path, {"--radius", "auto"}, point_set_auto_radius_header),
                         nearest = csv(path, {}, point_set_csv_header);
  ASSERT_EQ(chosen.size(), noisy.points.size());
  ASSERT_EQ(nearest.size(), noisy.points.size());
  std::vector<double> radii, noise;
  for (const Row& r : chosen) {
    ASSERT_TRUE(std::isfinite(r.values[13]) && std::isfinite(r.values[14]));
    radii.push_back(r.values[13]);
    noise.push_back(r.values[14]);
  }
  const double auto_rms = H_rms(chosen), nearest_rms = H_rms(nearest);
  std::cout << "noisy sphere points, H RMS: 16 nearest " << nearest_rms << ", --radius auto " << auto_rms
            << "; median radius " << median(radii) / spacing << " mean spacings, median noise " << median(noise)
            << " for sigma " << sigma << '\n';
  EXPECT_LT(auto_rms, 0.5 * nearest_rms);
  EXPECT_GT(median(noise), 0.7 * sigma);
  EXPECT_LT(median(noise), 1.4 * sigma);
  EXPECT_GE(*std::min_element(radii.begin(), radii.end()), spacing);
  EXPECT_LE(*std::max_element(radii.begin(), radii.end()), 32 * spacing * (1 + 1e-9));
}

// The bounds in mean spacings and in the points' units give the same rows (to rounding: the spacing here is summed
// in another order than the tool's).
TEST_F(PointSetAutoRadiusTest, BoundsInSpacingsOrUnits)
{
  const std::vector<Row> in_spacings = csv(path, {"--radius", "auto:4x:16x"}, point_set_auto_radius_header),
                         in_units =
                           csv(path, {"--radius", "auto:" + exact_text(4 * spacing) + ":" + exact_text(16 * spacing)},
                               point_set_auto_radius_header);
  ASSERT_EQ(in_spacings.size(), noisy.points.size());
  ASSERT_EQ(in_units.size(), noisy.points.size());
  for (std::size_t i = 0; i < in_spacings.size(); ++i) {
    EXPECT_EQ(in_spacings[i].status, in_units[i].status) << "row " << i;
    for (std::size_t c = 0; c < in_units[i].values.size(); ++c)
      EXPECT_NEAR(in_spacings[i].values[c], in_units[i].values[c], 1e-9 * (1 + std::abs(in_units[i].values[c])))
        << "row " << i << ", column " << c;
  }
}

// The PLY holds radius and noise after nz, the CSV's values.
TEST_F(PointSetAutoRadiusTest, PlyProperties)
{
  const fs::path output = dir / "auto.ply";
  const Result r = run({"--radius", "auto", "-o", output.string(), path.string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string text = read_text(output);
  const std::size_t end = text.find("end_header\n");
  ASSERT_NE(end, std::string::npos);
  EXPECT_NE(text.find("property double nz\nproperty double radius\nproperty double noise\nproperty uchar status\n"),
            std::string::npos)
    << text.substr(0, end);
  const std::size_t columns = 3 + 15, record = columns * sizeof(double) + 4;
  ASSERT_EQ(text.size(), end + 11 + noisy.points.size() * record);
  const std::vector<Row> rows = csv(path, {"--radius", "auto"}, point_set_auto_radius_header);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    double values[2];
    std::memcpy(values, text.data() + end + 11 + i * record + 16 * sizeof(double), sizeof values);
    EXPECT_EQ(values[0], rows[i].values[13]) << i;
    EXPECT_EQ(values[1], rows[i].values[14]) << i;
  }
}

// The summary: the range in mean spacings, and the quartiles of the chosen radius and of the noise.
TEST_F(PointSetAutoRadiusTest, Summary)
{
  const Result r = run({"--radius", "auto", path.string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* line : {"neighbors: the 16 nearest points, or the ball of the chosen radius\nradius range: ",
                           " (2 to 32 mean distances to the nearest neighbor of ", "chosen radius: min ",
                           "noise (standard deviation): min ", " (in mean distances to the nearest neighbor: "})
    EXPECT_NE(r.out.find(line), std::string::npos) << line << " in\n" << r.out;
  const std::size_t at = r.out.find(", median ", r.out.find("noise (standard deviation): "));
  ASSERT_NE(at, std::string::npos) << r.out;
  const double noise = std::strtod(r.out.c_str() + at + 9, nullptr);
  EXPECT_GT(noise, 0.7 * sigma) << r.out;
  EXPECT_LT(noise, 1.4 * sigma) << r.out;
  const Result nearest = run({path.string()});
  ASSERT_EQ(nearest.exit_code, 0) << nearest.err;
  for (const char* line : {"radius range", "chosen radius", "noise"})
    EXPECT_EQ(nearest.out.find(line), std::string::npos) << line << " in\n" << nearest.out;
}

TEST_F(PointSetAutoRadiusTest, BadValuesAreRejected)
{
  expect_rejected_saying({"--radius", "auto:8x:2x", path.string()}, {"A <= B"});
  expect_rejected_saying({"--radius", "auto:1:4x", path.string()}, {"A <= B", "the points' units"});
  expect_rejected_saying({"--radius", "auto:0x:2x", path.string()}, {"--radius"});
  expect_rejected_saying({"--radius", "auto", "--rings", "2", path.string()}, {"--rings"});
  expect_rejected_saying({"-m", "taubin", "--radius", "auto", path.string()}, {"taubin"});
}

TEST_F(ToolTest, PointSetOptionsThatDoNotApply)
{
  const Points s = without_normals(sphere_points(100, 1, {0, 0, 0}));
  const std::string p = file("points.xyz", xyz(s)).string();
  const std::string ply = file("points.ply", ascii_ply_points(s)).string();
  for (const std::string& input : {p, ply}) {
    expect_rejected({"-m", "taubin", input}, "taubin on a point set");
    expect_rejected({"--rings", "2", input}, "--rings on a point set");
    expect_rejected({"--neighbors", "8", "--radius", "1", input}, "--neighbors with --radius");
    expect_rejected({"--degree", "3", input}, "--degree on a point set");
  }
  for (const std::string bad : {"2", "0", "-5", "abc", "10001"})
    expect_rejected({"--neighbors", bad, p}, "--neighbors " + bad);
  expect_rejected({"--neighbors", "8", file("tet.off", off(tetrahedron())).string()}, "--neighbors on a mesh");
  expect_rejected({"--neighbors", "8", file("tet.obj", obj(tetrahedron())).string()}, "--neighbors on an OBJ");
}

TEST_F(ToolTest, PointSetBadInput)
{
  const Points s = sphere_points(20, 1, {0, 0, 0});
  const std::string six = xyz(s), three = xyz(without_normals(s));
  const std::vector<std::pair<std::string, std::string>> bad = {
    {"empty.xyz", ""},
    {"comments_only.xyz", "# nothing\n\n"},
    {"four_values.xyz", "0 0 0 1\n" + three},
    {"seven_values.xyz", "0 0 0 1 0 0 5\n"},
    {"mixed_widths.xyz", three + six},
    {"word.xyz", three + "0 zero 0\n"},
    {"nan.xyz", three + "0 nan 0\n"},
    {"inf.xyz", "inf 0 0\n" + three},
    {"overflow.xyz", three + "1e400 0 0\n"},
    {"nan_normal.xyz", six + "0 0 0 nan 0 1\n"},
    {"truncated_line.xyz", three + "0 0\n"},
    {"count_too_large.xyz", "21\n" + three},
    {"count_too_small.xyz", "19\n" + three},
    {"huge_count.xyz", "2000000000\n" + three},
    {"negative_count.xyz", "-20\n" + three},
    {"three_columns.pwn", three},
    {"truncated.pwn", six.substr(0, six.rfind(' '))},
    {"empty.pwn", ""},
    {"garbage.pwn", "this is not a point set\n\x01\x02\xff\n"},
    {"truncated.ply", ascii_ply(ply_point_properties(without_normals(s), "float"), three.substr(0, three.size() / 2))},
    {"truncated_binary.ply", binary_ply_points(s).substr(0, binary_ply_points(s).size() - 20)},
    {"huge_count.ply",
     ascii_ply("element vertex 2000000000\nproperty float x\nproperty float y\nproperty float z\n", three)},
    {"no_points.ply", ascii_ply(ply_point_properties(Points{}, "float"))},
    {"nan.ply", ascii_ply(ply_point_properties(without_normals(s), "float"), "nan 0 0\n" + three)},
    {"truncated.off", "OFF\n21 0 0\n" + three},
    {"nan.off", "OFF\n21 0 0\n" + three + "0 nan 0\n"},
    {"no_points.off", "OFF\n0 0 0\n"},
    {"noff_without_normals.off", "NOFF\n20 0 0\n" + three},
    {"noff_nan_normal.off", "NOFF\n21 0 0\n" + six + "0 0 0 0 0 nan\n"},
  };
  for (const auto& [name, text] : bad)
    expect_rejected({file(name, text).string()}, name);
  // Non-finite values in a binary PLY reach the tool's own check, which names them.
  Points with_nan = s;
  with_nan.normals[3][1] = std::numeric_limits<double>::quiet_NaN();
  const fs::path p = file("nan_normal.ply", binary_ply_points(with_nan));
  expect_rejected({p.string()}, "binary PLY with a NaN normal");
  EXPECT_NE(run({p.string()}).err.find("non-finite"), std::string::npos);
}

} // namespace
