// curvature: estimates curvature at the vertices of a surface mesh file, or of
// the graph W = f(x, y, z) of a scalar field over a tetrahedral mesh.
//
//   curvature [options] INPUT
//     -m, --method  paraboloid | curve-network | gauss-map | taubin | chen-schmitt | jet
//     -o, --output  FILE.csv | FILE.ply     (without it: print a summary only)
//     --rings N --order N --degree D --monge-degree D --threads N --color-by Q --scalars FILE.sol
//
// Rows of the CSV (and vertices of the PLY) are the vertices of the INPUT file, in
// the file's order, even when the polygon soup had to be repaired before it could
// become a mesh. Errors: one line on stderr, non-zero exit, no output file.
#include <CGAL/Curvature_estimation.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <CGAL/Surface_mesh.h>

#include "mesh_readers.h"

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#endif

#include <algorithm>
#include <array>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <memory>
#include <new>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <system_error>
#include <thread>
#include <tuple>
#include <unistd.h>
#include <vector>

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
using V = Mesh::Vertex_index;
using Polygon = std::vector<std::size_t>;
namespace CE = CGAL::Curvature_estimation;
namespace PMP = CGAL::Polygon_mesh_processing;
namespace fs = std::filesystem;

constexpr const char* usage_text =
  "usage: curvature [options] INPUT\n"
  "Estimates curvature at the vertices of a surface mesh (INPUT: .off .ply .obj .stl), or of the\n"
  "graph W = f(x, y, z) of a scalar field over a tetrahedral mesh (INPUT: Medit .mesh, f from .sol).\n"
  "\n"
  "options:\n"
  "  -m, --method M     paraboloid (default) | curve-network | gauss-map | taubin | chen-schmitt | jet\n"
  "                     (.mesh input: paraboloid only)\n"
  "  -o, --output FILE  FILE.csv or FILE.ply (surfaces only); without it, print a summary only\n"
  "      --rings N      neighbourhood rings a vertex's estimate starts with (default 1;\n"
  "                     paraboloid, gauss-map, taubin, chen-schmitt, jet, and .mesh input)\n"
  "      --order N      extrapolation order of curve-network, 1..4 (default 1)\n"
  "      --degree D     degree of the jet (jet only), 2..4 (default 2)\n"
  "      --monge-degree D  degree of the Monge form (jet only), 2..D (default 2)\n"
  "      --scalars FILE the Medit .sol holding f for a .mesh INPUT (default: INPUT with the\n"
  "                     extension .sol, which must exist)\n"
  "      --threads N    1: sequential; N > 1: at most N threads; 0: all cores (default 0)\n"
  "      --color-by Q   PLY colours: k_max | k_min | mean (default) | gaussian\n"
  "  -h, --help         print this help\n"
  "\n"
  "Surfaces. CSV: header k_max,k_min,mean,gaussian,d_max_x,d_max_y,d_max_z,d_min_x,d_min_y,d_min_z,status,\n"
  "then one row per vertex of INPUT in the file's order; status is ok, widened or failed,\n"
  "and a failed row has nan values. PLY: the input's vertices and faces with these values\n"
  "as vertex properties (status as 0 ok, 1 widened, 2 failed) and RGB colours.\n"
  "OFF is ASCII with an OFF, COFF, NOFF or STOFF header; PLY (ASCII or binary), OBJ and STL\n"
  "are read by CGAL after checks of what its readers do not survive.\n"
  "\n"
  "Tetrahedral meshes. INPUT is an ASCII Medit .mesh (Vertices and Tetrahedra are used, other\n"
  "sections skipped); the .sol has SolAtVertices with one scalar (type 1) per vertex. The\n"
  "curvatures are those of the hypersurface (x, y, z, f) of R^4 with the normal towards increasing f\n"
  "(tetrahedra are oriented accordingly; curvature is positive where the graph bends away from\n"
  "the normal, so a convex f has negative curvatures), by paraboloid fitting over the tetrahedral platelet.\n"
  "CSV only: header k_1,k_2,k_3,mean,gaussian,status (k_1 >= k_2 >= k_3, mean = their average,\n"
  "gaussian = their product), one row per vertex of the .mesh in its order; a vertex in no\n"
  "tetrahedron is failed.\n";

// Every error a user can cause ends here: one line on stderr, exit code.
struct Tool_error : std::runtime_error
{
  int code;
  Tool_error(const std::string& message, int code = 1) : std::runtime_error(message), code(code) {}
};

[[noreturn]] void fail(const std::string& message, int code = 1) { throw Tool_error(message, code); }

enum class Method { paraboloid, curve_network, gauss_map, taubin, chen_schmitt, jet };
enum class Quantity { k_max, k_min, mean, gaussian };

struct Options
{
  std::string input;
  std::string output;
  Method method = Method::paraboloid;
  std::string method_name = "paraboloid";
  std::optional<int> rings;
  std::optional<int> order;
  std::optional<int> degree, monge_degree;
  std::string scalars;
  bool tetrahedral = false;  // INPUT is a Medit .mesh
  int threads = 0;
  Quantity color_by = Quantity::mean;
};

std::string lower_extension(const std::string& path)
{
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return ext;
}

int parse_int(const std::string& option, const std::string& text, int min_value, int max_value)
{
  int value = 0;
  const char* first = text.data();
  const char* last = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(first, last, value);
  if (ec != std::errc() || ptr != last || value < min_value || value > max_value)
    fail(option + " expects an integer from " + std::to_string(min_value) + " to " +
           std::to_string(max_value) + ", got '" + text + "'", 2);
  return value;
}

// Returns nullopt when help was printed.
std::optional<Options> parse_arguments(int argc, char** argv)
{
  Options o;
  std::vector<std::string> positional;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    auto value = [&](const std::string& name) -> std::string {
      if (i + 1 >= argc)
        fail("option " + name + " needs a value (see curvature --help)", 2);
      return argv[++i];
    };
    if (arg == "-h" || arg == "--help") {
      std::cout << usage_text;
      return std::nullopt;
    } else if (arg == "-m" || arg == "--method") {
      const std::string m = value(arg);
      o.method_name = m;
      if (m == "paraboloid") o.method = Method::paraboloid;
      else if (m == "curve-network") o.method = Method::curve_network;
      else if (m == "gauss-map") o.method = Method::gauss_map;
      else if (m == "taubin") o.method = Method::taubin;
      else if (m == "chen-schmitt") o.method = Method::chen_schmitt;
      else if (m == "jet") o.method = Method::jet;
      else
        fail("unknown method '" + m + "' (expected paraboloid, curve-network, gauss-map, taubin, chen-schmitt or jet)",
             2);
    } else if (arg == "-o" || arg == "--output") {
      o.output = value(arg);
    } else if (arg == "--rings") {
      o.rings = parse_int(arg, value(arg), 1, 100);
    } else if (arg == "--order") {
      o.order = parse_int(arg, value(arg), 1, 4);
    } else if (arg == "--degree") {
      // Jet degree 1 is a plane: CGAL's Monge form needs degree 2 at least.
      o.degree = parse_int(arg, value(arg), 2, 4);
    } else if (arg == "--monge-degree") {
      o.monge_degree = parse_int(arg, value(arg), 2, 4);
    } else if (arg == "--scalars") {
      o.scalars = value(arg);
    } else if (arg == "--threads") {
      o.threads = parse_int(arg, value(arg), 0, 1024);
    } else if (arg == "--color-by") {
      const std::string q = value(arg);
      if (q == "k_max") o.color_by = Quantity::k_max;
      else if (q == "k_min") o.color_by = Quantity::k_min;
      else if (q == "mean") o.color_by = Quantity::mean;
      else if (q == "gaussian") o.color_by = Quantity::gaussian;
      else fail("unknown --color-by '" + q + "' (expected k_max, k_min, mean or gaussian)", 2);
    } else if (arg.size() > 1 && arg[0] == '-') {
      fail("unknown option '" + arg + "' (see curvature --help)", 2);
    } else {
      positional.push_back(arg);
    }
  }
  if (positional.empty())
    fail("no input file given (usage: curvature [options] INPUT; see --help)", 2);
  if (positional.size() > 1)
    fail("more than one input file given ('" + positional[0] + "', '" + positional[1] + "')", 2);
  o.input = positional[0];

  if (o.order && o.method != Method::curve_network)
    fail("--order applies to the curve-network method only", 2);
  if ((o.degree || o.monge_degree) && o.method != Method::jet)
    fail(std::string(o.degree ? "--degree" : "--monge-degree") + " applies to the jet method only", 2);
  if (o.monge_degree && *o.monge_degree > o.degree.value_or(2))
    fail("--monge-degree " + std::to_string(*o.monge_degree) + " exceeds the jet degree " +
           std::to_string(o.degree.value_or(2)) + " (see --degree)", 2);
  o.tetrahedral = lower_extension(o.input) == ".mesh";
  if (o.tetrahedral) {
    if (o.method != Method::paraboloid)
      fail("method '" + o.method_name + "' does not apply to tetrahedral input (.mesh): use paraboloid", 2);
    if (!o.output.empty() && lower_extension(o.output) == ".ply")
      fail("PLY output is for surfaces: write the curvatures of tetrahedral input (.mesh) as CSV", 2);
  } else if (!o.scalars.empty()) {
    fail("--scalars applies to tetrahedral input (.mesh) only", 2);
  }
  if (o.rings && o.method == Method::curve_network)
    fail("--rings does not apply to the curve-network method (it uses mesh lines; see --order)", 2);
  if (!o.output.empty()) {
    const std::string ext = lower_extension(o.output);
    if (ext != ".csv" && ext != ".ply")
      fail("output '" + o.output + "' must end in .csv or .ply", 2);
  }
  return o;
}

// ---------------------------------------------------------------------------
// Input
// ---------------------------------------------------------------------------

struct Soup
{
  std::vector<Point> points;
  std::vector<Polygon> polygons;
};

// CGAL's readers write diagnostics to std::cerr; the tool's contract is one line.
struct Silence_cerr
{
  std::ostringstream sink;
  std::streambuf* saved;
  Silence_cerr() : saved(std::cerr.rdbuf(sink.rdbuf())) {}
  ~Silence_cerr() { std::cerr.rdbuf(saved); }
};

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
void check_ply_header(const std::string& path, std::uintmax_t bytes)
{
  std::ifstream in(path, std::ios::binary);
  long double vertices = 0, faces = 0;
  std::string line, element;
  bool element_seen = false;
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
      }
    }
  }
  if (6 * vertices + 2 * faces > static_cast<long double>(bytes) + 64)
    fail("malformed file '" + path + "': its header declares more vertices or faces than the file (" +
         std::to_string(bytes) + " bytes) can hold");
}

// The size of a readable regular file.
std::uintmax_t check_readable(const std::string& path)
{
  std::error_code ec;
  if (!fs::exists(path, ec))
    fail("cannot read '" + path + "': no such file");
  if (!fs::is_regular_file(path, ec))
    fail("cannot read '" + path + "': not a regular file");
  const std::uintmax_t bytes = fs::file_size(path, ec);
  std::ifstream probe(path, std::ios::binary);
  if (ec || !probe)
    fail("cannot read '" + path + "': cannot open the file");
  return bytes;
}

std::string read_text_file(const std::string& path)
{
  check_readable(path);
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad())
    fail("cannot read '" + path + "': read error");
  return text.str();
}

// Runs one of the strict readers of mesh_readers.h on the file's text.
template <typename Reader>
auto read_strictly(const std::string& path, Reader reader)
{
  const std::string text = read_text_file(path);
  try {
    return reader(text);
  } catch (const ce_tool::Read_error& e) {
    fail("malformed file '" + path + "': " + e.what());
  }
}

Soup read_input(const std::string& path)
{
  const std::string ext = lower_extension(path);
  if (ext != ".off" && ext != ".ply" && ext != ".obj" && ext != ".stl")
    fail("unknown input extension '" + ext + "' of '" + path + "' (expected .off, .ply, .obj, .stl or .mesh)");

  Soup soup;
  if (ext == ".off") {
    const ce_tool::Polygon_soup_data data = read_strictly(path, [](const std::string& text) {
      return ce_tool::read_off(text);
    });
    soup.points.reserve(data.points.size());
    for (const auto& p : data.points)
      soup.points.emplace_back(p[0], p[1], p[2]);
    soup.polygons = data.faces;
  } else {
    const std::uintmax_t bytes = check_readable(path);
    if (ext == ".ply")
      check_ply_header(path, bytes);
    bool ok = false;
    try {
      Silence_cerr silence;
      ok = CGAL::IO::read_polygon_soup(path, soup.points, soup.polygons);
    } catch (const std::bad_alloc&) {
      fail("malformed file '" + path + "': its header asks for more memory than available");
    } catch (const std::exception& e) {
      fail("malformed file '" + path + "': " + e.what());
    }
    if (!ok)
      fail("malformed file '" + path + "': the " + ext.substr(1) +
           " reader failed (garbage, truncated, or invalid data)");
  }
  if (soup.points.empty())
    fail("empty mesh '" + path + "': no vertices");
  if (soup.polygons.empty())
    fail("empty mesh '" + path + "': no faces");

  for (std::size_t i = 0; i < soup.points.size(); ++i) {
    const Point& p = soup.points[i];
    if (!std::isfinite(p.x()) || !std::isfinite(p.y()) || !std::isfinite(p.z()))
      fail("invalid file '" + path + "': vertex " + std::to_string(i) + " has a non-finite (NaN or infinite) coordinate");
  }
  for (std::size_t f = 0; f < soup.polygons.size(); ++f)
    for (std::size_t index : soup.polygons[f])
      if (index >= soup.points.size())
        fail("malformed file '" + path + "': face " + std::to_string(f) + " refers to vertex " +
             std::to_string(index) + " but the file has " + std::to_string(soup.points.size()) + " vertices");
  return soup;
}

struct Point_less
{
  bool operator()(const Point& a, const Point& b) const
  {
    return std::make_tuple(a.x(), a.y(), a.z()) < std::make_tuple(b.x(), b.y(), b.z());
  }
};

// Builds the mesh from a repaired copy of the soup; file_to_mesh[i] is the mesh
// vertex of the file's vertex i (null when the vertex is in no usable face).
Mesh build_mesh(const Soup& soup, std::vector<V>& file_to_mesh)
{
  std::vector<Point> points = soup.points;
  std::vector<Polygon> polygons = soup.polygons;
  {
    Silence_cerr silence;
    PMP::repair_polygon_soup(points, polygons);
  }
  std::vector<std::string> notes;
  const std::size_t distinct_used = points.size();
  const std::size_t faces_kept = polygons.size();
  if (faces_kept < soup.polygons.size())
    notes.push_back("dropped " + std::to_string(soup.polygons.size() - faces_kept) +
                    " degenerate or duplicate faces");

  const std::vector<Polygon> before_orientation = polygons;
  bool oriented = true;
  {
    Silence_cerr silence;
    oriented = PMP::orient_polygon_soup(points, polygons);
  }
  std::size_t reoriented = 0;
  for (std::size_t f = 0; f < polygons.size() && f < before_orientation.size(); ++f)
    reoriented += polygons[f] != before_orientation[f];
  if (reoriented > 0)
    notes.push_back("re-oriented " + std::to_string(reoriented) + " faces");
  if (points.size() > distinct_used)
    notes.push_back("duplicated " + std::to_string(points.size() - distinct_used) + " non-manifold vertices");
  if (!oriented && points.size() == distinct_used)
    notes.push_back("could not orient every face consistently");

  Mesh mesh;
  if (!polygons.empty()) {
    if (!PMP::is_polygon_soup_a_polygon_mesh(polygons))
      fail("the faces cannot be made into a polygon mesh, even after repair");
    PMP::polygon_soup_to_polygon_mesh(points, polygons, mesh);
  }

  std::map<Point, V, Point_less> by_point;
  for (V v : vertices(mesh))
    by_point.emplace(mesh.point(v), v);  // the first copy of a split vertex wins
  file_to_mesh.assign(soup.points.size(), V());
  std::size_t merged = 0, unused = 0;
  std::map<Point, std::size_t, Point_less> first_file_index;
  for (std::size_t i = 0; i < soup.points.size(); ++i) {
    if (!first_file_index.emplace(soup.points[i], i).second)
      ++merged;
    auto it = by_point.find(soup.points[i]);
    if (it != by_point.end())
      file_to_mesh[i] = it->second;
    else
      ++unused;
  }
  if (merged > 0)
    notes.insert(notes.begin(), "merged " + std::to_string(merged) + " duplicate points");
  if (!notes.empty()) {
    std::string line = "curvature: note: repaired the input:";
    for (std::size_t i = 0; i < notes.size(); ++i)
      line += (i ? ", " : " ") + notes[i];
    std::cerr << line << '\n';
  }
  if (unused > 0)
    std::cerr << "curvature: note: " << unused << " of the file's vertices are in no face; their rows are 'failed'\n";
  return mesh;
}

// ---------------------------------------------------------------------------
// Estimation
// ---------------------------------------------------------------------------

struct Row
{
  double k_max, k_min, mean, gaussian;
  std::array<double, 3> d_max, d_min;
  CE::Estimation_status status;

  std::array<double, 10> values() const
  {
    return {k_max, k_min, mean, gaussian, d_max[0], d_max[1], d_max[2], d_min[0], d_min[1], d_min[2]};
  }
};

Row failed_row()
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  return Row{nan, nan, nan, nan, {nan, nan, nan}, {nan, nan, nan}, CE::Estimation_status::not_estimable};
}

// Runs `estimate(tag)` with the concurrency tag --threads asks for, and turns
// the library's exceptions into the tool's errors.
template <typename Estimate>
void run_with_threads(int threads, Estimate estimate)
{
  try {
    if (threads == 1) {
      estimate(CGAL::Sequential_tag());
    } else {
#ifdef CGAL_LINKED_WITH_TBB
      std::unique_ptr<tbb::global_control> limit;
      if (threads > 1)
        limit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                                      std::size_t(threads));
      estimate(CGAL::Parallel_tag());
#else
      estimate(CGAL::Sequential_tag());
#endif
    }
  } catch (const std::invalid_argument& e) {
    fail(std::string("invalid parameter: ") + e.what(), 2);
  } catch (const std::bad_alloc&) {
    fail("out of memory while estimating curvature");
  } catch (const std::exception& e) {
    fail(std::string("estimation failed: ") + e.what());
  }
}

// --rings N: start on N rings, widen up to max(3, N), as for every method with rings.
template <typename NamedParameters>
auto with_rings(const Options& o, const NamedParameters& np)
{
  const int rings = o.rings.value_or(1);
  return np.neighborhood_rings(rings).max_neighborhood_rings(std::max(3, rings));
}

template <typename Tag>
void run_estimator(const Options& o, const Mesh& mesh,
                   Mesh::Property_map<V, double> H, Mesh::Property_map<V, double> K,
                   Mesh::Property_map<V, CE::Principal_curvatures_and_directions<Kernel>> pcd,
                   Mesh::Property_map<V, CE::Estimation_status> status)
{
  const auto np = CE::parameters::vertex_mean_curvature_map(H)
                    .vertex_Gaussian_curvature_map(K)
                    .vertex_principal_curvatures_and_directions_map(pcd)
                    .vertex_estimation_status_map(status);
  const auto ring_np = with_rings(o, np);
  switch (o.method) {
    case Method::paraboloid: CE::paraboloid_fitting_curvatures<Tag>(mesh, ring_np); break;
    case Method::gauss_map: CE::gauss_map_curvatures<Tag>(mesh, ring_np); break;
    case Method::taubin: CE::taubin_curvatures<Tag>(mesh, ring_np); break;
    case Method::chen_schmitt: CE::chen_schmitt_curvatures<Tag>(mesh, ring_np); break;
    case Method::jet:
      CE::jet_fitting_curvatures<Tag>(mesh, ring_np.jet_degree(o.degree.value_or(2))
                                              .monge_degree(o.monge_degree.value_or(2)));
      break;
    case Method::curve_network:
      CE::curve_network_curvatures<Tag>(mesh, np.extrapolation_order(o.order.value_or(1)));
      break;
  }
}

std::vector<Row> estimate(const Options& o, const Mesh& mesh_in, const std::vector<V>& file_to_mesh,
                          double& seconds)
{
  Mesh& mesh = const_cast<Mesh&>(mesh_in);  // property maps only; geometry untouched
  auto H = mesh.add_property_map<V, double>("v:ce_H").first;
  auto K = mesh.add_property_map<V, double>("v:ce_K").first;
  auto pcd = mesh.add_property_map<V, CE::Principal_curvatures_and_directions<Kernel>>("v:ce_pcd").first;
  auto status = mesh.add_property_map<V, CE::Estimation_status>("v:ce_status", CE::Estimation_status::not_estimable).first;

  const auto start = std::chrono::steady_clock::now();
  if (!is_empty(mesh))
    run_with_threads(o.threads, [&](auto tag) { run_estimator<decltype(tag)>(o, mesh, H, K, pcd, status); });
  seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  std::vector<Row> rows(file_to_mesh.size(), failed_row());
  for (std::size_t i = 0; i < file_to_mesh.size(); ++i) {
    const V v = file_to_mesh[i];
    if (v == V() || status[v] == CE::Estimation_status::not_estimable)
      continue;
    const auto& c = pcd[v];
    Row r{c.max_curvature, c.min_curvature, H[v], K[v],
          {c.max_direction.x(), c.max_direction.y(), c.max_direction.z()},
          {c.min_direction.x(), c.min_direction.y(), c.min_direction.z()},
          status[v]};
    rows[i] = r;
  }
  mesh.remove_property_map(H);
  mesh.remove_property_map(K);
  mesh.remove_property_map(pcd);
  mesh.remove_property_map(status);
  return rows;
}

// ---------------------------------------------------------------------------
// Tetrahedral input: the graph W = f(x, y, z) over a Medit .mesh, f from a .sol
// ---------------------------------------------------------------------------

using Tetrahedral_mesh = CE::Indexed_tetrahedral_mesh<Point>;

struct Tetrahedral_input
{
  Tetrahedral_mesh mesh;
  std::vector<double> scalars;  // f at the vertices
};

// The .sol beside the .mesh (same name, extension .sol) unless --scalars names one.
std::string scalars_path(const std::string& mesh_path, const std::string& scalars)
{
  if (!scalars.empty()) {
    if (lower_extension(scalars) != ".sol")
      fail("--scalars '" + scalars + "' must be a Medit .sol file", 2);
    return scalars;
  }
  const std::string beside = fs::path(mesh_path).replace_extension(".sol").string();
  std::error_code ec;
  if (!fs::exists(beside, ec))
    fail("no scalar field for '" + mesh_path + "': '" + beside +
         "' does not exist (name a Medit .sol with --scalars FILE.sol)");
  return beside;
}

// The syntax and the combinatorics are the reader's; the geometry is checked here,
// with CGAL's exact orientation predicate: a flat tetrahedron is an error, and each
// tetrahedron is made positively oriented, which orients the hypersurface's normal
// towards increasing f (see hypersurface_paraboloid_fitting_curvatures).
Tetrahedral_input read_tetrahedral_input(const std::string& mesh_path, const std::string& scalars)
{
  const ce_tool::Tetrahedral_mesh_data data =
    read_strictly(mesh_path, [](const std::string& text) { return ce_tool::read_medit_mesh(text); });
  Tetrahedral_input input;
  input.mesh.points.reserve(data.points.size());
  for (const auto& p : data.points)
    input.mesh.points.emplace_back(p[0], p[1], p[2]);
  input.mesh.cells = data.cells;
  for (std::size_t t = 0; t < input.mesh.cells.size(); ++t) {
    auto& c = input.mesh.cells[t];
    const auto& p = input.mesh.points;
    switch (CGAL::orientation(p[c[0]], p[c[1]], p[c[2]], p[c[3]])) {
      case CGAL::COPLANAR:
        fail("degenerate file '" + mesh_path + "': tetrahedron " + std::to_string(t + 1) + " has zero volume");
      case CGAL::NEGATIVE: std::swap(c[2], c[3]); break;
      default: break;
    }
  }
  const std::size_t vertices = data.points.size();
  input.scalars = read_strictly(scalars_path(mesh_path, scalars), [vertices](const std::string& text) {
    return ce_tool::read_medit_sol(text, vertices);
  });
  return input;
}

struct Tetrahedral_row
{
  double k_1, k_2, k_3, mean, gaussian;
  CE::Estimation_status status;

  std::array<double, 5> values() const { return {k_1, k_2, k_3, mean, gaussian}; }
};

std::vector<Tetrahedral_row> estimate_tetrahedral(const Options& o, const Tetrahedral_input& input, double& seconds)
{
  const std::size_t n = input.mesh.points.size();
  std::vector<CE::Hypersurface_principal_curvatures_and_directions<std::array<double, 4>>> principal(n);
  std::vector<double> H(n), K(n);
  std::vector<CE::Estimation_status> status(n, CE::Estimation_status::not_estimable);
  const auto points =
    CE::make_graph_point_map(CE::Tetrahedral_complex_traits<Tetrahedral_mesh>::default_point_map(input.mesh),
                             CGAL::make_property_map(input.scalars));
  const auto np = with_rings(o, CE::parameters::vertex_point_map(points)
                                  .vertex_principal_curvatures_and_directions_map(CGAL::make_property_map(principal))
                                  .vertex_mean_curvature_map(CGAL::make_property_map(H))
                                  .vertex_Gaussian_curvature_map(CGAL::make_property_map(K))
                                  .vertex_estimation_status_map(CGAL::make_property_map(status)));
  const auto start = std::chrono::steady_clock::now();
  run_with_threads(o.threads, [&](auto tag) {
    CE::hypersurface_paraboloid_fitting_curvatures<decltype(tag)>(input.mesh, np);
  });
  seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  std::vector<Tetrahedral_row> rows(n);
  for (std::size_t v = 0; v < n; ++v)
    rows[v] = {principal[v].max_curvature, principal[v].mid_curvature, principal[v].min_curvature, H[v], K[v],
               status[v]};
  return rows;
}

// ---------------------------------------------------------------------------
// Output
// ---------------------------------------------------------------------------

// Shortest text that reads back to the same double; "nan" for any NaN.
void put_double(std::string& out, double x)
{
  if (std::isnan(x)) {
    out += "nan";
    return;
  }
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, x);
  out.append(buffer, result.ptr);
}

double quantity(const Row& r, Quantity q)
{
  switch (q) {
    case Quantity::k_max: return r.k_max;
    case Quantity::k_min: return r.k_min;
    case Quantity::mean: return r.mean;
    default: return r.gaussian;
  }
}

// The header line, then a row per vertex: its values, then its status.
template <typename Row_type>
std::string csv_text(const char* header, const std::vector<Row_type>& rows)
{
  std::string out = std::string(header) + "\n";
  out.reserve(rows.size() * 16 * (Row_type().values().size() + 1) + out.size());
  for (const Row_type& r : rows) {
    for (double x : r.values()) {
      put_double(out, x);
      out += ',';
    }
    out += CE::to_string(r.status);
    out += '\n';
  }
  return out;
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

// Binary little-endian PLY: exact values, and NaN on failed rows (ASCII "nan" is
// not read back by CGAL's PLY reader, nor by most others).
std::string ply_text(const Soup& soup, const std::vector<Row>& rows, Quantity q, const std::string& quantity_name)
{
  std::vector<double> magnitudes;
  for (const Row& r : rows)
    if (r.status != CE::Estimation_status::not_estimable && std::isfinite(quantity(r, q)))
      magnitudes.push_back(std::abs(quantity(r, q)));
  double scale = 0;
  if (!magnitudes.empty()) {
    const std::size_t k = std::min(magnitudes.size() - 1, magnitudes.size() * 95 / 100);
    std::nth_element(magnitudes.begin(), magnitudes.begin() + k, magnitudes.end());
    scale = magnitudes[k];
  }

  std::size_t faces = 0;
  for (const Polygon& p : soup.polygons) {
    if (p.size() > 255)
      fail("a face of the input has more than 255 vertices, which the PLY output does not support");
    faces += p.size() >= 3;
  }

  std::string out;
  out += "ply\nformat binary_little_endian 1.0\n";
  out += "comment written by curvature: the vertices and faces of the input file, in its order\n";
  out += "comment status: 0 = ok, 1 = widened, 2 = failed (its curvature values are NaN)\n";
  out += "comment colours: " + quantity_name + ", blue < 0 < red, saturated at the 95th percentile of |value|; "
         "failed grey\n";
  out += "element vertex " + std::to_string(soup.points.size()) + "\n";
  for (const char* name : {"x", "y", "z", "k_max", "k_min", "mean", "gaussian", "d_max_x", "d_max_y", "d_max_z",
                           "d_min_x", "d_min_y", "d_min_z"})
    out += std::string("property double ") + name + "\n";
  out += "property uchar status\nproperty uchar red\nproperty uchar green\nproperty uchar blue\n";
  out += "element face " + std::to_string(faces) + "\n";
  out += "property list uchar int vertex_indices\n";
  out += "end_header\n";
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const Point& p = soup.points[i];
    const Row& r = rows[i];
    for (double x : {p.x(), p.y(), p.z()})
      put_binary(out, x);
    for (double x : r.values())
      put_binary(out, x);
    out += static_cast<char>(r.status);
    for (unsigned char c : colour(quantity(r, q), scale))
      out += static_cast<char>(c);
  }
  for (const Polygon& p : soup.polygons) {
    if (p.size() < 3)
      continue;
    out += static_cast<char>(p.size());
    for (std::size_t index : p) {
      if (index > std::size_t(std::numeric_limits<std::int32_t>::max()))
        fail("a vertex index does not fit the PLY output's int");
      put_le(out, static_cast<std::uint32_t>(index));
    }
  }
  return out;
}

// Writes to a temporary name beside `path` and renames on success only.
void write_file_atomically(const std::string& path, const std::string& text)
{
  const fs::path target(path);
  const fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
  const fs::path tmp = dir / ("." + target.filename().string() + ".tmp" + std::to_string(::getpid()));
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out)
      fail("cannot write '" + path + "': cannot create a file in '" + dir.string() + "'");
    out.write(text.data(), static_cast<std::streamsize>(text.size()));
    out.close();
    if (!out) {
      std::error_code ec;
      fs::remove(tmp, ec);
      fail("cannot write '" + path + "': write error");
    }
  }
  std::error_code ec;
  fs::rename(tmp, target, ec);
  if (ec) {
    std::error_code ignored;
    fs::remove(tmp, ignored);
    fail("cannot write '" + path + "': " + ec.message());
  }
}

void print_range(const char* name, std::vector<double> values)
{
  if (values.empty()) {
    std::cout << name << ": no estimate\n";
    return;
  }
  std::sort(values.begin(), values.end());
  std::cout << name << ": min " << values.front() << ", median " << values[values.size() / 2]
            << ", max " << values.back() << '\n';
}

const char* quantity_name(Quantity q)
{
  switch (q) {
    case Quantity::k_max: return "k_max";
    case Quantity::k_min: return "k_min";
    case Quantity::mean: return "mean";
    default: return "gaussian";
  }
}

// The summary's lines after the input's: time, ranges of H and K, status counts.
template <typename Row_type>
void print_estimates(const std::vector<Row_type>& rows, std::size_t vertices, double seconds)
{
  std::size_t ok = 0, widened = 0, failed = 0;
  std::vector<double> H, K;
  for (const Row_type& r : rows) {
    switch (r.status) {
      case CE::Estimation_status::ok: ++ok; break;
      case CE::Estimation_status::widened: ++widened; break;
      default: ++failed; continue;
    }
    H.push_back(r.mean);
    K.push_back(r.gaussian);
  }
  std::cout << "time: " << seconds * 1e3 << " ms";
  if (vertices > 0)
    std::cout << " (" << seconds * 1e9 / double(vertices) << " ns per vertex)";
  std::cout << '\n';
  print_range("mean curvature H", H);
  print_range("Gaussian curvature K", K);
  std::cout << "ok: " << ok << ", widened: " << widened << ", failed (not estimable): " << failed << '\n';
}

int run_surface(const Options& o)
{
  const Soup soup = read_input(o.input);
  std::vector<V> file_to_mesh;
  const Mesh mesh = build_mesh(soup, file_to_mesh);
  double seconds = 0;
  const std::vector<Row> rows = estimate(o, mesh, file_to_mesh, seconds);

  if (!o.output.empty()) {
    const std::string text =
      lower_extension(o.output) == ".csv"
        ? csv_text("k_max,k_min,mean,gaussian,d_max_x,d_max_y,d_max_z,d_min_x,d_min_y,d_min_z,status", rows)
        : ply_text(soup, rows, o.color_by, quantity_name(o.color_by));
    write_file_atomically(o.output, text);
    return 0;
  }
  std::cout << "input: " << o.input << '\n'
            << "vertices: " << soup.points.size() << " in the file (" << num_vertices(mesh) << " in the mesh, "
            << num_faces(mesh) << " faces)\n"
            << "method: " << o.method_name << '\n';
  print_estimates(rows, num_vertices(mesh), seconds);
  return 0;
}

int run_tetrahedral(const Options& o)
{
  const Tetrahedral_input input = read_tetrahedral_input(o.input, o.scalars);
  double seconds = 0;
  const std::vector<Tetrahedral_row> rows = estimate_tetrahedral(o, input, seconds);
  if (!o.output.empty()) {  // CSV: parse_arguments refuses PLY for tetrahedral input
    write_file_atomically(o.output, csv_text("k_1,k_2,k_3,mean,gaussian,status", rows));
    return 0;
  }
  std::cout << "input: " << o.input << '\n'
            << "vertices: " << input.mesh.points.size() << '\n'
            << "tetrahedra: " << input.mesh.cells.size() << '\n'
            << "method: " << o.method_name << " (hypersurface of R^4)\n";
  print_estimates(rows, input.mesh.points.size(), seconds);
  return 0;
}

int run(int argc, char** argv)
{
  const std::optional<Options> parsed = parse_arguments(argc, argv);
  if (!parsed)
    return 0;
  return parsed->tetrahedral ? run_tetrahedral(*parsed) : run_surface(*parsed);
}

} // namespace

// One line: messages from libraries may hold newlines.
std::string one_line(std::string s)
{
  for (char& c : s)
    if (c == '\n' || c == '\r')
      c = ' ';
  return s;
}

#ifndef CE_CURVATURE_NO_MAIN
int main(int argc, char** argv)
{
  try {
    return run(argc, argv);
  } catch (const Tool_error& e) {
    std::cerr << "curvature: error: " << one_line(e.what()) << '\n';
    return e.code;
  } catch (const std::bad_alloc&) {
    std::cerr << "curvature: error: out of memory\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "curvature: error: " << one_line(e.what()) << '\n';
    return 1;
  } catch (...) {
    std::cerr << "curvature: error: unexpected failure\n";
    return 1;
  }
}
#endif // CE_CURVATURE_NO_MAIN
