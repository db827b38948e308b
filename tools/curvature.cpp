// curvature: estimates curvature at the vertices of a surface mesh file.
//
//   curvature [options] INPUT
//     -m, --method  paraboloid | curve-network | gauss-map | taubin | chen-schmitt | jet
//     -o, --output  FILE.csv | FILE.ply     (without it: print a summary only)
//     --rings N --order N --degree D --threads N --color-by k_max|k_min|mean|gaussian
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
  "Estimates curvature at the vertices of a surface mesh (INPUT: .off .ply .obj .stl).\n"
  "\n"
  "options:\n"
  "  -m, --method M     paraboloid (default) | curve-network | gauss-map | taubin | chen-schmitt | jet\n"
  "  -o, --output FILE  FILE.csv or FILE.ply; without it, print a summary only\n"
  "      --rings N      neighbourhood rings a vertex's estimate starts with (default 1;\n"
  "                     paraboloid, gauss-map, taubin, chen-schmitt)\n"
  "      --order N      extrapolation order of curve-network, 1..4 (default 1)\n"
  "      --degree D     degree of the jet fit (jet only)\n"
  "      --threads N    1: sequential; N > 1: at most N threads; 0: all cores (default 0)\n"
  "      --color-by Q   PLY colours: k_max | k_min | mean (default) | gaussian\n"
  "  -h, --help         print this help\n"
  "\n"
  "CSV: header k_max,k_min,mean,gaussian,d_max_x,d_max_y,d_max_z,d_min_x,d_min_y,d_min_z,status,\n"
  "then one row per vertex of INPUT in the file's order; status is ok, widened or failed,\n"
  "and a failed row has nan values. PLY: the input's vertices and faces with these values\n"
  "as vertex properties (status as 0 ok, 1 widened, 2 failed) and RGB colours.\n";

// Every error a user can cause ends here: one line on stderr, exit code.
struct Tool_error : std::runtime_error
{
  int code;
  Tool_error(const std::string& message, int code = 1) : std::runtime_error(message), code(code) {}
};

[[noreturn]] void fail(const std::string& message, int code = 1) { throw Tool_error(message, code); }

enum class Method { paraboloid, curve_network, gauss_map, taubin, chen_schmitt };
enum class Quantity { k_max, k_min, mean, gaussian };

struct Options
{
  std::string input;
  std::string output;
  Method method = Method::paraboloid;
  std::string method_name = "paraboloid";
  std::optional<int> rings;
  std::optional<int> order;
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
      else if (m == "jet")
        fail("method 'jet' (CGAL's jet fitting) is not implemented yet; use paraboloid, curve-network, "
             "gauss-map, taubin or chen-schmitt", 2);
      else
        fail("unknown method '" + m + "' (expected paraboloid, curve-network, gauss-map, taubin or chen-schmitt)", 2);
    } else if (arg == "-o" || arg == "--output") {
      o.output = value(arg);
    } else if (arg == "--rings") {
      o.rings = parse_int(arg, value(arg), 1, 100);
    } else if (arg == "--order") {
      o.order = parse_int(arg, value(arg), 1, 4);
    } else if (arg == "--degree") {
      (void)value(arg);
      fail("--degree applies to the jet method only, which is not implemented yet", 2);
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

// Headers that CGAL 5.5's OFF and PLY readers do not survive, refused first:
// - the readers size their arrays from the header's counts: a header declaring
//   billions of elements in a small file would exhaust memory before the reader
//   notices the file is short. Every vertex takes at least 6 bytes ("0 0 0\n",
//   or 12 in binary), every face at least 2;
// - the PLY reader adds a `property` to the last element without checking that
//   there is one: a property before any `element` line crashes it; and it reads
//   a vertex's x, y, z as float or double without checking their declared type:
//   `property uchar x` crashes it (both found by the fuzz target).
void check_header(const std::string& path, const std::string& ext)
{
  if (ext != ".off" && ext != ".ply")
    return;
  std::error_code ec;
  const auto bytes = fs::file_size(path, ec);
  if (ec)
    return;
  std::ifstream in(path, std::ios::binary);
  std::string word;
  long double vertices = 0, faces = 0;
  if (ext == ".off") {
    in >> word;
    if (word.find("OFF") == std::string::npos)
      return;
    while (in >> std::ws && in.peek() == '#')
      std::getline(in, word);
    long double v = 0, f = 0;
    if (in >> v >> f) {
      vertices = v;
      faces = f;
    }
  } else {
    std::string line, element;
    bool element_seen = false;
    for (int lines = 0; lines < 1000 && std::getline(in, line) && line.rfind("end_header", 0) != 0; ++lines) {
      std::istringstream words(line);
      std::string keyword, name;
      long double n = 0;
      words >> keyword;
      if (keyword == "property") {
        if (!element_seen)
          fail("malformed file '" + path + "': a PLY property before any element");
        std::string type;
        words >> type >> name;
        const bool coordinate = name == "x" || name == "y" || name == "z";
        const bool floating = type == "float" || type == "double" || type == "float32" || type == "float64";
        if ((element == "vertex" || element == "vertices") && coordinate && !floating)
          fail("unsupported file '" + path + "': PLY vertex coordinate '" + name + "' of type '" + type +
               "' (float or double expected)");
      }
      if (keyword == "element") {
        element_seen = true;
        if (words >> name >> n) {
          element = name;
          (name == "vertex" ? vertices : faces) += n;
        }
      }
    }
  }
  if (vertices < 0 || faces < 0 || 6 * vertices + 2 * faces > static_cast<long double>(bytes) + 64)
    fail("malformed file '" + path + "': its header declares more vertices or faces than the file (" +
         std::to_string(bytes) + " bytes) can hold");
}

Soup read_input(const std::string& path)
{
  const std::string ext = lower_extension(path);
  if (ext == ".mesh")
    fail("tetrahedral input (Medit .mesh) is not supported yet: '" + path + "'");
  if (ext != ".off" && ext != ".ply" && ext != ".obj" && ext != ".stl")
    fail("unknown input extension '" + ext + "' of '" + path + "' (expected .off, .ply, .obj or .stl)");

  std::error_code ec;
  if (!fs::exists(path, ec))
    fail("cannot read '" + path + "': no such file");
  if (!fs::is_regular_file(path, ec))
    fail("cannot read '" + path + "': not a regular file");
  {
    std::ifstream probe(path, std::ios::binary);
    if (!probe)
      fail("cannot read '" + path + "': cannot open the file");
  }

  check_header(path, ext);

  Soup soup;
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
    fail("malformed file '" + path + "': the " + ext.substr(1) + " reader failed (garbage, truncated, or invalid data)");
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
};

Row failed_row()
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  return Row{nan, nan, nan, nan, {nan, nan, nan}, {nan, nan, nan}, CE::Estimation_status::not_estimable};
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
  const int rings = o.rings.value_or(1);
  const auto ring_np = np.neighborhood_rings(rings).max_neighborhood_rings(std::max(3, rings));
  switch (o.method) {
    case Method::paraboloid: CE::paraboloid_fitting_curvatures<Tag>(mesh, ring_np); break;
    case Method::gauss_map: CE::gauss_map_curvatures<Tag>(mesh, ring_np); break;
    case Method::taubin: CE::taubin_curvatures<Tag>(mesh, ring_np); break;
    case Method::chen_schmitt: CE::chen_schmitt_curvatures<Tag>(mesh, ring_np); break;
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
  if (!is_empty(mesh)) {
    try {
      if (o.threads == 1) {
        run_estimator<CGAL::Sequential_tag>(o, mesh, H, K, pcd, status);
      } else {
#ifdef CGAL_LINKED_WITH_TBB
        std::unique_ptr<tbb::global_control> limit;
        if (o.threads > 1)
          limit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                                        std::size_t(o.threads));
        run_estimator<CGAL::Parallel_tag>(o, mesh, H, K, pcd, status);
#else
        run_estimator<CGAL::Sequential_tag>(o, mesh, H, K, pcd, status);
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

std::string csv_text(const std::vector<Row>& rows)
{
  std::string out = "k_max,k_min,mean,gaussian,d_max_x,d_max_y,d_max_z,d_min_x,d_min_y,d_min_z,status\n";
  out.reserve(rows.size() * 160 + out.size());
  for (const Row& r : rows) {
    for (double x : {r.k_max, r.k_min, r.mean, r.gaussian, r.d_max[0], r.d_max[1], r.d_max[2],
                     r.d_min[0], r.d_min[1], r.d_min[2]}) {
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
    for (double x : {p.x(), p.y(), p.z(), r.k_max, r.k_min, r.mean, r.gaussian, r.d_max[0], r.d_max[1],
                     r.d_max[2], r.d_min[0], r.d_min[1], r.d_min[2]})
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

int run(int argc, char** argv)
{
  const std::optional<Options> parsed = parse_arguments(argc, argv);
  if (!parsed)
    return 0;
  const Options& o = *parsed;

  const Soup soup = read_input(o.input);
  std::vector<V> file_to_mesh;
  const Mesh mesh = build_mesh(soup, file_to_mesh);
  double seconds = 0;
  const std::vector<Row> rows = estimate(o, mesh, file_to_mesh, seconds);

  std::size_t ok = 0, widened = 0, failed = 0;
  std::vector<double> H, K;
  for (const Row& r : rows) {
    switch (r.status) {
      case CE::Estimation_status::ok: ++ok; break;
      case CE::Estimation_status::widened: ++widened; break;
      default: ++failed; continue;
    }
    H.push_back(r.mean);
    K.push_back(r.gaussian);
  }

  if (!o.output.empty()) {
    const std::string text = lower_extension(o.output) == ".csv"
                               ? csv_text(rows)
                               : ply_text(soup, rows, o.color_by, quantity_name(o.color_by));
    write_file_atomically(o.output, text);
    return 0;
  }

  std::cout << "input: " << o.input << '\n'
            << "vertices: " << soup.points.size() << " in the file (" << num_vertices(mesh) << " in the mesh, "
            << num_faces(mesh) << " faces)\n"
            << "method: " << o.method_name << '\n'
            << "time: " << seconds * 1e3 << " ms";
  if (num_vertices(mesh) > 0)
    std::cout << " (" << seconds * 1e9 / double(num_vertices(mesh)) << " ns per vertex)";
  std::cout << '\n';
  print_range("mean curvature H", H);
  print_range("Gaussian curvature K", K);
  std::cout << "ok: " << ok << ", widened: " << widened << ", failed (not estimable): " << failed << '\n';
  return 0;
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
