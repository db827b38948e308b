// SPDX-License-Identifier: GPL-3.0-or-later
// The command line of `curvature`: its options, their checks, the help text.
#ifndef CE_TOOLS_COMMAND_LINE_H
#define CE_TOOLS_COMMAND_LINE_H

#include "registry.h"

#include <optional>
#include <string>

namespace ce_tool {

enum class Quantity
{
  k_max,
  k_min,
  mean,
  gaussian
};

// --radius: the radius of the neighborhood balls, in mesh units or, with a
// trailing x, in mean edge lengths of the input mesh.
struct Radius
{
  double value;
  bool in_mean_edges;
};

// --radius auto[:A:B]: the radius chosen per vertex between A and B (Radius each).
struct Radius_range
{
  Radius min, max;
  bool given = true; // false for auto alone: the default of the input's kind
};
// --radius auto: the range of the manual's measurements of the selection, on meshes and
// on point sets (in mean distances to the nearest neighbor: the balls of 2x to 32x hold
// about as many random points as those of 1x to 16x hold vertices of a mesh).
constexpr Radius_range default_radius_range{{1, true}, {16, true}, false};
constexpr Radius_range default_point_set_radius_range{{2, true}, {32, true}, false};

struct Options
{
  std::string input;
  std::string output;
  const Method* method = &methods().front(); // -m: a method of the registry
  // The options of the registry's settings, checked against the method's.
  std::optional<int> rings;
  std::optional<Radius> radius;
  // --radius auto: ball_radius_range
  std::optional<Radius_range> radius_range;
  std::optional<int> order;                // extrapolation_order
  std::optional<int> fit_degree;           // fit_degree
  std::optional<int> degree, monge_degree; // jet_degree, monge_degree
  std::optional<int> neighbors;            // number_of_neighbors, for point sets
  std::string scalars;
  bool tetrahedral = false; // INPUT is a Medit .mesh
  bool point_set = false;   // INPUT is a point set (.xyz, .pwn; a PLY or OFF once read: see read_as)
  int threads = 0;
  Quantity color_by = Quantity::mean;
};

// Fails (a Tool_error with code 2) where the options of `o` do not go together: a
// setting its method does not read, --monge-degree above the jet degree, --radius with
// --rings, and what tetrahedral input (o.tetrahedral), point sets (o.point_set) or the
// output's extension refuses.
void check_options(const Options& o);

// Once INPUT is read (a PLY or OFF is a mesh or a point set): sets o.point_set and
// checks the options for that kind of input, as check_options does.
void read_as(Options& o, bool point_set);

// --radius `text` (R, or Nx in mean edge lengths) of `option`: a positive finite number
// (a Tool_error with code 2 otherwise).
Radius parse_radius(const std::string& option, const std::string& text);

// --radius `text` of `option`: auto, or auto:A:B with A and B as parse_radius takes
// them (a Tool_error with code 2 otherwise).
Radius_range parse_radius_range(const std::string& option, const std::string& text);

// The options of argv, checked together (a Tool_error with code 2 otherwise);
// nullopt when help was printed.
std::optional<Options> parse_arguments(int argc, char** argv);

// The name of `q` as --color-by spells it.
const char* quantity_name(Quantity q);

} // namespace ce_tool

#endif // CE_TOOLS_COMMAND_LINE_H
