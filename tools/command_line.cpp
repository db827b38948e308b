// SPDX-License-Identifier: GPL-3.0-or-later
#include "command_line.h"

#include "input_files.h"
#include "tool_error.h"

#include <charconv>
#include <cmath>
#include <iostream>
#include <system_error>
#include <vector>

namespace ce_tool {

namespace {

constexpr const char* usage_text =
  "usage: curvature [options] INPUT\n"
  "Estimates curvature at the vertices of a surface mesh (INPUT: .off .ply .obj .stl), or of the\n"
  "graph W = f(x, y, z) of a scalar field over a tetrahedral mesh (INPUT: Medit .mesh, f from .sol).\n"
  "\n"
  "options:\n"
  "  -m, --method M     paraboloid (default) | curve-network | gauss-map | taubin | chen-schmitt | jet\n"
  "                     (.mesh input: paraboloid only)\n"
  "  -o, --output FILE  FILE.csv or FILE.ply (surfaces only); without it, print a summary only\n"
  "      --rings N      neighborhood rings a vertex's estimate starts with (default 1;\n"
  "                     paraboloid, gauss-map, taubin, chen-schmitt, jet, and .mesh input)\n"
  "      --radius R     instead of rings, estimate over the ball of radius R about each vertex (the\n"
  "                     mesh joined to it by edges inside the ball): R in mesh units, or Nx for N\n"
  "                     mean edge lengths of INPUT (as in 4x); the ball grows where the fit needs\n"
  "                     more vertices (status widened); paraboloid, jet and gauss-map; on .mesh\n"
  "                     input the ball and the edges are in R^4, of the points (x, y, z, f);\n"
  "                     not with --rings\n"
  "      --order N      extrapolation order of curve-network, 1..4 (default 1)\n"
  "      --fit-degree D degree of the paraboloid method's fit, 2..4 (default 2: Hamann's paraboloid;\n"
  "                     3 and 4: Taylor fits over 2 and 3 rings, orders 2 and 3 on irregular meshes;\n"
  "                     .mesh input: 2..3)\n"
  "      --degree D     degree of the jet (jet only), 2..4 (default 2)\n"
  "      --monge-degree D  degree of the Monge form (jet only), 2..D (default 2)\n"
  "      --scalars FILE the Medit .sol holding f for a .mesh INPUT (default: INPUT with the\n"
  "                     extension .sol, which must exist)\n"
  "      --threads N    1: sequential; N > 1: at most N threads; 0: all cores (default 0)\n"
  "      --color-by Q   PLY colours: k_max | k_min | mean (default) | gaussian\n"
  "  -h, --help         print this help\n"
  "\n"
  "Surfaces. CSV: header k_max,k_min,mean,gaussian,d_max_x,d_max_y,d_max_z,d_min_x,d_min_y,d_min_z,status,\n"
  "then one row per vertex of INPUT in the file's order; status is ok, widened, fallback\n"
  "(the documented fallback: curve-network, where there is no curve network or its curves\n"
  "are no mesh lines, and jet, the paraboloid fit; paraboloid, the Gauss map where no ring\n"
  "determines the fit) or failed, and a failed row has nan values. PLY: the input's\n"
  "vertices and faces with these values as vertex properties (status as 0 ok, 1 widened,\n"
  "2 failed, 3 fallback) and RGB colours.\n"
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

int parse_int(const std::string& option, const std::string& text, int min_value, int max_value)
{
  int value = 0;
  const char* first = text.data();
  const char* last = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(first, last, value);
  if (ec != std::errc() || ptr != last || value < min_value || value > max_value)
    fail(option + " expects an integer from " + std::to_string(min_value) + " to " + std::to_string(max_value) +
           ", got '" + text + "'",
         2);
  return value;
}

// R or Rx: a positive finite number, in mean edge lengths with the x.
Radius parse_radius(const std::string& option, const std::string& text)
{
  const bool in_mean_edges = !text.empty() && text.back() == 'x';
  double value = 0;
  const char* first = text.data();
  const char* last = text.data() + text.size() - (in_mean_edges ? 1 : 0);
  const auto [ptr, ec] = std::from_chars(first, last, value);
  if (ec != std::errc() || ptr != last || !(value > 0) || !std::isfinite(value))
    fail(option +
           " expects a positive length in mesh units, or a positive number of mean edge lengths "
           "followed by x (as in 4x), got '" +
           text + "'",
         2);
  return {value, in_mean_edges};
}

} // namespace

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
      if (m == "paraboloid")
        o.method = Method::paraboloid;
      else if (m == "curve-network")
        o.method = Method::curve_network;
      else if (m == "gauss-map")
        o.method = Method::gauss_map;
      else if (m == "taubin")
        o.method = Method::taubin;
      else if (m == "chen-schmitt")
        o.method = Method::chen_schmitt;
      else if (m == "jet")
        o.method = Method::jet;
      else
        fail("unknown method '" + m + "' (expected paraboloid, curve-network, gauss-map, taubin, chen-schmitt or jet)",
             2);
    } else if (arg == "-o" || arg == "--output") {
      o.output = value(arg);
    } else if (arg == "--rings") {
      o.rings = parse_int(arg, value(arg), 1, 100);
    } else if (arg == "--radius") {
      o.radius = parse_radius(arg, value(arg));
    } else if (arg == "--order") {
      o.order = parse_int(arg, value(arg), 1, 4);
    } else if (arg == "--fit-degree") {
      o.fit_degree = parse_int(arg, value(arg), 2, 4);
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
      if (q == "k_max")
        o.color_by = Quantity::k_max;
      else if (q == "k_min")
        o.color_by = Quantity::k_min;
      else if (q == "mean")
        o.color_by = Quantity::mean;
      else if (q == "gaussian")
        o.color_by = Quantity::gaussian;
      else
        fail("unknown --color-by '" + q + "' (expected k_max, k_min, mean or gaussian)", 2);
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
  if (o.fit_degree && o.method != Method::paraboloid)
    fail("--fit-degree applies to the paraboloid method only (--degree is the jet's)", 2);
  if ((o.degree || o.monge_degree) && o.method != Method::jet)
    fail(std::string(o.degree ? "--degree" : "--monge-degree") + " applies to the jet method only", 2);
  if (o.monge_degree && *o.monge_degree > o.degree.value_or(2))
    fail("--monge-degree " + std::to_string(*o.monge_degree) + " exceeds the jet degree " +
           std::to_string(o.degree.value_or(2)) + " (see --degree)",
         2);
  o.tetrahedral = lower_extension(o.input) == ".mesh";
  if (o.tetrahedral) {
    if (o.method != Method::paraboloid)
      fail("method '" + o.method_name + "' does not apply to tetrahedral input (.mesh): use paraboloid", 2);
    if (o.fit_degree.value_or(2) > 3)
      fail("--fit-degree 4 is for surfaces: tetrahedral input (.mesh) takes 2 or 3", 2);
    if (!o.output.empty() && lower_extension(o.output) == ".ply")
      fail("PLY output is for surfaces: write the curvatures of tetrahedral input (.mesh) as CSV", 2);
  } else if (!o.scalars.empty()) {
    fail("--scalars applies to tetrahedral input (.mesh) only", 2);
  }
  if (o.radius) {
    if (o.method != Method::paraboloid && o.method != Method::jet && o.method != Method::gauss_map)
      fail("--radius applies to the paraboloid, jet and gauss-map methods only, not to '" + o.method_name + "'", 2);
    if (o.rings)
      fail("--radius and --rings exclude each other: a neighborhood is a ball or rings", 2);
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

const char* quantity_name(Quantity q)
{
  switch (q) {
    case Quantity::k_max:
      return "k_max";
    case Quantity::k_min:
      return "k_min";
    case Quantity::mean:
      return "mean";
    default:
      return "gaussian";
  }
}

} // namespace ce_tool
