// SPDX-License-Identifier: GPL-3.0-or-later
#include "command_line.h"

#include "input_files.h"
#include "tool_error.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <iostream>
#include <iterator>
#include <ostream>
#include <system_error>
#include <vector>

namespace ce_tool {

namespace {

// The options that set an integer setting of the registry.
struct Integer_option
{
  const char* flag;
  const char* value_name; // in the help
  Setting setting;
  std::optional<int> Options::*value;
  const char* help;          // after the range and default
  const char* not_read_hint; // after the error that the method does not read it
};
const Integer_option integer_options[] = {
  {"--rings", "N", Setting::rings, &Options::rings,
   "neighborhood rings a vertex's estimate starts\nwith; it widens up to max(3, N)", ""},
  {"--order", "N", Setting::extrapolation_order, &Options::order, "extrapolation order of the curve network", ""},
  {"--fit-degree", "D", Setting::fit_degree, &Options::fit_degree,
   "degree of the paraboloid method's fit: 2 is\nHamann's paraboloid; 3 and 4 are Taylor fits over 2 and 3 rings, of "
   "orders\n"
   "2 and 3 on irregular meshes; .mesh input: 2..3; point sets: the degree of\n"
   "the fit over the neighbors",
   " (--degree is the jet's)"},
  {"--degree", "D", Setting::jet_degree, &Options::degree, "degree of the jet", ""},
  {"--monge-degree", "D", Setting::monge_degree, &Options::monge_degree, "degree of the Monge form, at most --degree",
   ""},
};

// The range of --neighbors.
constexpr int min_neighbors = 3, max_neighbors = 10000;

// "a, b and c" (or "a, b or c" with `last` " or ").
std::string join(const std::vector<std::string>& words, const char* last)
{
  std::string list;
  for (std::size_t i = 0; i < words.size(); ++i)
    list += (i == 0 ? "" : i + 1 == words.size() ? last : ", ") + words[i];
  return list;
}

// The names of the methods `take` accepts.
template <typename Take>
std::vector<std::string> method_names(const Take& take)
{
  std::vector<std::string> names;
  for (const Method& m : methods())
    if (take(m))
      names.push_back(m.name);
  return names;
}

std::vector<std::string> readers(Setting setting)
{
  return method_names([&](const Method& m) { return m.reads_setting(setting); });
}

std::vector<std::string> tetrahedral_methods()
{
  return method_names([](const Method& m) { return m.tetrahedral; });
}

// Whether the method of tetrahedral input reads `setting`.
bool tetrahedral_reads(Setting setting)
{
  for (const Method& m : methods())
    if (m.tetrahedral && m.reads_setting(setting))
      return true;
  return false;
}

// The help of an option: its first line after the 21 columns of the flag, the rest indented.
void print_option(std::ostream& out, const std::string& flag, const std::string& text)
{
  const std::string indent(21, ' ');
  out << "  " << flag << std::string(flag.size() < 18 ? 19 - flag.size() : 1, ' ');
  std::size_t start = 0;
  while (true) {
    const std::size_t end = text.find('\n', start);
    out << text.substr(start, end - start) << '\n';
    if (end == std::string::npos)
      return;
    out << indent;
    start = end + 1;
  }
}

// Where a setting's option applies: "(paraboloid, jet and gauss-map; and .mesh input)".
std::string applies_to(Setting setting)
{
  return "(" + join(readers(setting), ", ") + (tetrahedral_reads(setting) ? "; and .mesh input)" : ")");
}

void print_usage(std::ostream& out)
{
  out << "usage: curvature [options] INPUT\n"
         "Estimates curvature at the vertices of a surface mesh (INPUT: .off .ply .obj .stl), at the points\n"
         "of a point set (INPUT: .xyz .pwn, or .ply .off without faces), or of the graph W = f(x, y, z) of\n"
         "a scalar field over a tetrahedral mesh (INPUT: Medit .mesh, f from .sol).\n"
         "\n"
         "options:\n";
  std::string method_list;
  for (const Method& m : methods())
    method_list +=
      std::string(method_list.empty() ? "" : " | ") + m.name + (&m == &methods().front() ? " (default)" : "");
  print_option(out, "-m, --method M",
               method_list + "\n(.mesh input: " + join(tetrahedral_methods(), " or ") +
                 " only; point sets: the default only, which runs the point-set fit)");
  print_option(out, "-o, --output FILE",
               "FILE.csv or FILE.ply (not for .mesh input); without it, print a summary only");
  for (const Integer_option& option : integer_options) {
    const Integer_range r = integer_range(option.setting);
    print_option(out, std::string("    ") + option.flag + " " + option.value_name,
                 std::to_string(r.min) + ".." + std::to_string(r.max) + " (default " + std::to_string(r.default_value) +
                   "): " + option.help + "\n" + applies_to(option.setting));
  }
  print_option(out, "    --radius R",
               "instead of rings, estimate over the ball of radius R about each vertex (the\n"
               "mesh joined to it by edges inside the ball): R in mesh units, or Nx for N\n"
               "mean edge lengths of INPUT (as in 4x); the ball grows where the fit needs\n"
               "more vertices (status widened); on .mesh input the ball and the edges are in\n"
               "R^4, of the points (x, y, z, f); not with --rings. On a point set, the points\n"
               "within R (neighbor_radius), Nx for N mean distances to the nearest neighbor;\n"
               "not with --neighbors\n" +
                 applies_to(Setting::ball_radius));
  print_option(out, "    --radius auto[:A:B]",
               "choose the ball's radius per vertex between A and B (R or Nx each;\n"
               "default 1x:16x): where the estimated error of H is least, the noise estimated\n"
               "from the fits' residuals (the 1-ring's estimate kept on clean data); the CSV\n"
               "and the PLY gain the radius and the noise per vertex; not with --rings. On a\n"
               "point set, Nx in mean distances to the nearest neighbor (default 2x:32x), the\n"
               "K nearest points' estimate kept on clean data\n"
               "(" +
                 join(readers(Setting::ball_radius_range), ", ") + "; surfaces and point sets)");
  print_option(out, "    --neighbors K",
               std::to_string(min_neighbors) + ".." + std::to_string(max_neighbors) +
                 " (default 16, 32 or 64 at --fit-degree 2, 3 or 4): point sets only:\n"
                 "the fit's K nearest points (number_of_neighbors)");
  out << "      --scalars FILE the Medit .sol holding f for a .mesh INPUT (default: INPUT with the\n"
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
         "With --radius auto, radius (the chosen radius) and noise (the standard deviation of the\n"
         "heights' noise), in mesh units, come before status in the CSV and are PLY properties too.\n"
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
         "tetrahedron is failed.\n"
         "\n"
         "Point sets. .xyz holds x y z or x y z nx ny nz a line, .pwn x y z nx ny nz; a PLY whose\n"
         "header declares no faces (normals from nx, ny, nz) and an OFF of 0 faces (normals from\n"
         "NOFF) are point sets too. Normals of the file orient the result (all zero: ignored);\n"
         "without, the fitted normals are oriented by a spanning-tree propagation, which the summary\n"
         "describes. CSV: the surface header with nx,ny,nz (the unit normal the signs refer to)\n"
         "before status, one row per point in the file's order; with --radius auto, radius and\n"
         "noise (in the points' units) between nz and status. PLY: the points with these values,\n"
         "no faces.\n";
}

// Fails unless the method of `o` reads `setting`, which `flag` set.
void check_read(const Options& o, const std::string& flag, Setting setting, const std::string& hint)
{
  if (o.method->reads_setting(setting))
    return;
  const std::vector<std::string> names = readers(setting);
  if (names.size() == 1)
    fail(flag + " applies to the " + names[0] + " method only" + hint, 2);
  fail(flag + " applies to the " + join(names, " and ") + " methods only, not to '" + o.method->name + "'" + hint, 2);
}

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

} // namespace

Radius_range parse_radius_range(const std::string& option, const std::string& text)
{
  if (text == "auto")
    return default_radius_range;
  const std::size_t colon = text.find(':', 5);
  if (text.compare(0, 5, "auto:") != 0 || colon == std::string::npos)
    fail(option + " expects a length, auto, or auto:A:B with A and B lengths (as in auto:2x:16x), got '" + text + "'",
         2);
  const std::string what = option + " " + text;
  return {parse_radius(what, text.substr(5, colon - 5)), parse_radius(what, text.substr(colon + 1))};
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

void check_options(const Options& o)
{
  for (const Integer_option& option : integer_options)
    if (o.*(option.value))
      check_read(o, option.flag, option.setting, option.not_read_hint);
  if (o.monge_degree && *o.monge_degree > o.degree.value_or(integer_range(Setting::jet_degree).default_value))
    fail("--monge-degree " + std::to_string(*o.monge_degree) + " exceeds the jet degree " +
           std::to_string(o.degree.value_or(integer_range(Setting::jet_degree).default_value)) + " (see --degree)",
         2);
  if (o.tetrahedral) {
    if (!o.method->tetrahedral)
      fail(std::string("method '") + o.method->name + "' does not apply to tetrahedral input (.mesh): use " +
             join(tetrahedral_methods(), " or "),
           2);
    if (o.fit_degree.value_or(2) > 3)
      fail("--fit-degree 4 is for surfaces: tetrahedral input (.mesh) takes 2 or 3", 2);
    if (!o.output.empty() && lower_extension(o.output) == ".ply")
      fail("PLY output is for surfaces: write the curvatures of tetrahedral input (.mesh) as CSV", 2);
  } else if (!o.scalars.empty()) {
    fail("--scalars applies to tetrahedral input (.mesh) only", 2);
  }
  if (o.point_set) {
    if (o.method != &methods().front())
      fail(std::string("method '") + o.method->name + "' needs a mesh: point sets take the default method (" +
             methods().front().name + "), which runs the point-set fit",
           2);
    if (o.rings)
      fail("--rings applies to meshes: on a point set give --neighbors K or --radius R", 2);
    if (o.neighbors && o.radius)
      fail("--neighbors and --radius exclude each other: a neighborhood is the K nearest points or a ball", 2);
  } else if (o.neighbors && lower_extension(o.input) != ".ply" && lower_extension(o.input) != ".off") {
    fail("--neighbors applies to point sets only (.xyz, .pwn, and .ply or .off without faces)", 2);
  }
  if (o.radius)
    check_read(o, "--radius", Setting::ball_radius, "");
  if (o.radius_range) {
    check_read(o, "--radius auto", Setting::ball_radius_range, "");
    if (o.tetrahedral)
      fail("--radius auto is for surfaces: give tetrahedral input (.mesh) a radius", 2);
  }
  if ((o.radius || o.radius_range) && o.rings)
    fail("--radius and --rings exclude each other: a neighborhood is a ball or rings", 2);
  if (!o.output.empty()) {
    const std::string ext = lower_extension(o.output);
    if (ext != ".csv" && ext != ".ply")
      fail("output '" + o.output + "' must end in .csv or .ply", 2);
  }
}

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
    const auto integer = std::find_if(std::begin(integer_options), std::end(integer_options),
                                      [&](const Integer_option& option) { return arg == option.flag; });
    if (integer != std::end(integer_options)) {
      const Integer_range r = integer_range(integer->setting);
      o.*(integer->value) = parse_int(arg, value(arg), r.min, r.max);
    } else if (arg == "-h" || arg == "--help") {
      print_usage(std::cout);
      return std::nullopt;
    } else if (arg == "-m" || arg == "--method") {
      const std::string m = value(arg);
      o.method = find_method(m);
      if (!o.method) {
        fail("unknown method '" + m + "' (expected " + join(method_names([](const Method&) { return true; }), " or ") +
               ")",
             2);
      }
    } else if (arg == "-o" || arg == "--output") {
      o.output = value(arg);
    } else if (arg == "--neighbors") {
      o.neighbors = parse_int(arg, value(arg), min_neighbors, max_neighbors);
    } else if (arg == "--radius") {
      const std::string text = value(arg);
      o.radius.reset();
      o.radius_range.reset();
      if (text.compare(0, 4, "auto") == 0)
        o.radius_range = parse_radius_range(arg, text);
      else
        o.radius = parse_radius(arg, text);
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

  o.tetrahedral = lower_extension(o.input) == ".mesh";
  o.point_set = lower_extension(o.input) == ".xyz" || lower_extension(o.input) == ".pwn";
  check_options(o);
  return o;
}

void read_as(Options& o, bool point_set)
{
  o.point_set = point_set;
  if (!point_set && o.neighbors)
    fail("--neighbors applies to point sets only, and '" + o.input + "' is a mesh (it has faces)", 2);
  check_options(o);
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
