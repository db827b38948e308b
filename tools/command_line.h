// SPDX-License-Identifier: GPL-3.0-or-later
// The command line of `curvature`: its options, their checks, the help text.
#ifndef CE_TOOLS_COMMAND_LINE_H
#define CE_TOOLS_COMMAND_LINE_H

#include <optional>
#include <string>

namespace ce_tool {

enum class Method
{
  paraboloid,
  curve_network,
  gauss_map,
  taubin,
  chen_schmitt,
  jet
};
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

struct Options
{
  std::string input;
  std::string output;
  Method method = Method::paraboloid;
  std::string method_name = "paraboloid";
  std::optional<int> rings;
  std::optional<Radius> radius; // paraboloid and jet, surfaces only
  std::optional<int> order;
  std::optional<int> fit_degree;           // paraboloid
  std::optional<int> degree, monge_degree; // jet
  std::string scalars;
  bool tetrahedral = false; // INPUT is a Medit .mesh
  int threads = 0;
  Quantity color_by = Quantity::mean;
};

// The options of argv, checked together (a Tool_error with code 2 otherwise);
// nullopt when help was printed.
std::optional<Options> parse_arguments(int argc, char** argv);

// The name of `q` as --color-by spells it.
const char* quantity_name(Quantity q);

} // namespace ce_tool

#endif // CE_TOOLS_COMMAND_LINE_H
