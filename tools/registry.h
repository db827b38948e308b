// SPDX-License-Identifier: GPL-3.0-or-later
// The registry of the surface estimators: for each, the name `curvature -m` takes,
// a label, the settings it reads, the quantities it gives, whether it runs in
// parallel, the inputs it takes, and one run function. The tool (its options, help
// and checks), the benchmark programs and, through them, the report read it:
// adding an estimator is its header, its test and one entry in registry.cpp.
#ifndef CE_TOOLS_REGISTRY_H
#define CE_TOOLS_REGISTRY_H

#include "kernel.h"

#include <CGAL/Curvature_estimation/Estimator.h>
#include <CGAL/Curvature_estimation/Principal_curvatures_and_directions.h>
#include <CGAL/Curvature_estimation/Vertex_normal_method.h>
#include <CGAL/tags.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#endif

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace ce_tool {

using Normal_map = Mesh::Property_map<V, Kernel::Vector_3>;

// The settings of a run; an empty one is the method's default. Each names the
// library's named parameter it sets.
struct Settings
{
  std::optional<int> rings;          // neighborhood_rings (default 1)
  std::optional<int> max_rings;      // max_neighborhood_rings (default: the library's)
  std::optional<double> ball_radius; // ball_radius, in mesh units; instead of the rings
  // ball_radius_range (min, max), in mesh units, with its outputs vertex_ball_radius_map and
  // vertex_noise_map: the radius chosen per vertex; instead of the rings and of ball_radius.
  struct Radius_selection
  {
    std::pair<double, double> range;
    Mesh::Property_map<V, double> radius, noise;
  };
  std::optional<Radius_selection> radius_selection;
  std::optional<int> fit_degree, extrapolation_order, jet_degree, monge_degree;
  std::optional<CE::Vertex_normal_method> normal_method; // vertex_normal_method (default quadric_fit)
  std::optional<Normal_map> given_normals;               // vertex_normal_map (default: none, estimated)
};

// The settings a method may read (Method::reads, a bit set): rings stands for rings and
// max_rings, normals for normal_method.
enum class Setting : unsigned
{
  rings = 1 << 0,
  ball_radius = 1 << 1,
  fit_degree = 1 << 2,
  extrapolation_order = 1 << 3,
  jet_degree = 1 << 4,
  monge_degree = 1 << 5,
  normals = 1 << 6,
  given_normals = 1 << 7,
  ball_radius_range = 1 << 8 // and its outputs
};
constexpr unsigned operator|(unsigned bits, Setting s) { return bits | static_cast<unsigned>(s); }
constexpr unsigned operator|(Setting a, Setting b) { return static_cast<unsigned>(a) | b; }

// The name of `s` as the library's named parameter (rings: neighborhood_rings).
const char* setting_name(Setting s);

// The settings set in `s`, as Setting bits.
unsigned given_settings(const Settings& s);

// The range and default of an integer setting, the same for every method that reads it;
// monge_degree is also at most the jet degree.
struct Integer_range
{
  int min, max, default_value;
};
Integer_range integer_range(Setting setting);

// The quantities a method gives (a bit set).
enum Quantities : unsigned
{
  gives_principal = 1, // k_max, k_min and the principal directions
  gives_H = 2,
  gives_K = 4,
  gives_all = gives_principal | gives_H | gives_K
};

// The output maps every run writes.
struct Outputs
{
  Mesh::Property_map<V, double> H, K;
  Mesh::Property_map<V, CE::Principal_curvatures_and_directions<Kernel>> pcd;
  Mesh::Property_map<V, CE::Estimation_status> status;
  Mesh::Property_map<V, double> reach; // vertex_reach_map: the tiles check it
};

// The five maps added to `mesh` as PREFIX + H, K, pcd, status (not_estimable until written) and reach.
Outputs add_outputs(Mesh& mesh, const std::string& prefix);
void remove_outputs(Mesh& mesh, Outputs& outputs);

struct Method
{
  const char* name;  // as -m takes it, and the benchmark's name of its defaults with _ for -
  const char* label; // for the report
  unsigned reads;    // the Settings it reads (Setting bits)
  unsigned quantities = gives_all;
  bool parallel = true;     // runs on several threads when asked
  bool tetrahedral = false; // the tool also runs it on tetrahedral input (.mesh), as a hypersurface of R^4
  bool cgal_fit = false;    // its fit is CGAL's (jet fitting): the report does not count it as ours
  // Writes `outputs` for every vertex of `mesh`; the library's exceptions pass through.
  void (*run)(const Mesh& mesh, const Settings& settings, const Outputs& outputs, int threads);
  // How far it reads around a vertex with `settings` (the library's neighborhood_reach).
  CE::Neighborhood_reach (*reach)(const Settings& settings);

  bool reads_setting(Setting s) const { return (reads & static_cast<unsigned>(s)) != 0; }
};

// Every method, the default (paraboloid) first.
const std::vector<Method>& methods();

// The method named `name`, or null.
const Method* find_method(const std::string& name);

// Runs `method` on `mesh`, with `threads` as --threads takes it (1: sequential, N > 1: at
// most N threads, 0: all cores). Throws std::invalid_argument where `settings` holds a
// setting the method does not read, or one out of its range, and whatever the estimator throws.
void run(const Method& method, const Mesh& mesh, const Settings& settings, const Outputs& outputs, int threads);

// How far `method` with `settings` reads around a vertex, its normals and fallbacks included;
// throws as run does.
CE::Neighborhood_reach reach(const Method& method, const Settings& settings);

// Calls `estimate(tag)` with the concurrency tag `threads` asks for (as run takes it).
template <typename Estimate>
void with_threads(int threads, Estimate estimate)
{
  if (threads == 1) {
    estimate(CGAL::Sequential_tag());
    return;
  }
#ifdef CGAL_LINKED_WITH_TBB
  std::unique_ptr<tbb::global_control> limit;
  if (threads > 1)
    limit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, std::size_t(threads));
  estimate(CGAL::Parallel_tag());
#else
  estimate(CGAL::Sequential_tag());
#endif
}

} // namespace ce_tool

#endif // CE_TOOLS_REGISTRY_H
