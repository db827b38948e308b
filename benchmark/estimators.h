// SPDX-License-Identifier: GPL-3.0-or-later
// The estimators the benchmark report compares, and the inputs it times, in one
// place: the speed benchmark (bench_estimators.cpp) and the accuracy runner
// (accuracy_runner.cpp) both iterate over `estimators()`, so that an estimator
// shows up in every table and plot of benchmark/REPORT.md under the same name, and
// the accuracy runner writes the list for benchmark/make_report.py (estimators.json).
// Our estimators are the methods of the tool's registry (tools/registry.h), each
// with its defaults and with the variants listed here; configured against CGAL 6
// or later, the list also holds CGAL's own curvature estimators (interpolated
// corrected curvatures, the discrete operators), which are not in the registry.
#ifndef CE_BENCHMARK_ESTIMATORS_H
#define CE_BENCHMARK_ESTIMATORS_H

#include "registry.h"
#include "test_surfaces.h"

#include <CGAL/Curvature_estimation.h>

#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/version.h>

#include <sys/resource.h>

#if CGAL_VERSION_MAJOR >= 6
#include <CGAL/Polygon_mesh_processing/curvature.h>
#include <CGAL/Polygon_mesh_processing/interpolated_corrected_curvatures.h>
#endif

#include <algorithm>
#include <array>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

namespace ce_bench {

using ce_tool::Kernel;
using ce_tool::Mesh;
using ce_tool::Normal_map;
using vertex_descriptor = Mesh::Vertex_index;
namespace CE = CGAL::Curvature_estimation;

// CGAL 6's own estimators (CGAL::Polygon_mesh_processing), which run here only.
enum class Peer
{
  none,              // a method of the registry
  icc,               // interpolated_corrected_curvatures, with ball_edges if set
  icc_our_normals,   // the same given our default normals (estimated in the same call)
  discrete_mean,     // discrete_mean_curvatures: H only
  discrete_Gaussian, // discrete_Gaussian_curvatures: K only
};

struct Estimator
{
  std::string name;                        // identifier in benchmark names and CSV/JSON files (no spaces, no '/')
  std::string label;                       // for the report's tables and legends
  const ce_tool::Method* method = nullptr; // null for a peer
  ce_tool::Settings settings;              // given normals and the ball are set when it runs
  double ball_edges = 0;                   // > 0: a ball of this many mean edge lengths
  bool given_normals = false;              // given normals: precomputed, or exact where known
  Peer peer = Peer::none;
  bool slow = false; // timed once, not repeated: minutes (jet 1 ring and d = 4) or seconds on the 1M grid

  unsigned quantities() const;
  bool parallel() const { return method && method->parallel; }
};

// A variant of the registry's method `method`.
inline Estimator variant(const std::string& name, const std::string& label, const char* method,
                         ce_tool::Settings settings = {})
{
  Estimator e{name, label, ce_tool::find_method(method), settings};
  if (!e.method)
    throw std::logic_error(std::string("ce_bench: no method '") + method + "' in the registry");
  return e;
}

inline unsigned Estimator::quantities() const
{
  if (method)
    return method->quantities;
  return peer == Peer::discrete_mean       ? ce_tool::gives_H
         : peer == Peer::discrete_Gaussian ? ce_tool::gives_K
                                           : ce_tool::gives_all;
}

inline ce_tool::Settings with_fit_degree(int degree)
{
  ce_tool::Settings s;
  s.fit_degree = degree;
  return s;
}

inline ce_tool::Settings with_jet(int degree, int rings)
{
  ce_tool::Settings s;
  s.jet_degree = degree;
  s.rings = rings;
  return s;
}

inline Estimator with_given_normals(Estimator e)
{
  e.given_normals = true;
  return e;
}

inline Estimator in_ball(Estimator e, double edges)
{
  e.ball_edges = edges;
  return e;
}

inline Estimator timed_once(Estimator e)
{
  e.slow = true;
  return e;
}

// Our variants in report order; the default of each registry method is the one with
// nothing set, and a method without one here is added after them, as its name.
inline std::vector<Estimator> our_variants()
{
  ce_tool::Settings area_normals, order_2;
  area_normals.normal_method = CE::Vertex_normal_method::area_weighted;
  order_2.extrapolation_order = 2;
  std::vector<Estimator> v = {
    variant("paraboloid", "paraboloid (default normals)", "paraboloid"),
    variant("paraboloid_area_normals", "paraboloid (area normals)", "paraboloid", area_normals),
    with_given_normals(variant("paraboloid_given_normals", "paraboloid (given normals)", "paraboloid")),
    variant("paraboloid_d3", "paraboloid, fit degree 3", "paraboloid", with_fit_degree(3)),
    variant("paraboloid_d4", "paraboloid, fit degree 4", "paraboloid", with_fit_degree(4)),
    in_ball(variant("paraboloid_ball_2h", "paraboloid, ball radius 2 h", "paraboloid"), 2),
    in_ball(variant("paraboloid_ball_4h", "paraboloid, ball radius 4 h", "paraboloid"), 4),
    timed_once(in_ball(variant("paraboloid_ball_8h", "paraboloid, ball radius 8 h", "paraboloid"), 8)),
    variant("curve_network_1", "curve network O(h^2)", "curve-network"), // the default: order 1
    variant("curve_network_2", "curve network O(h^4)", "curve-network", order_2),
    variant("gauss_map", "Gauss map", "gauss-map"),
    variant("taubin", "Taubin", "taubin"),
    variant("chen_schmitt", "Chen-Schmitt", "chen-schmitt"),
    timed_once(variant("jet_d2_1ring", "jet d=2, 1 ring", "jet")), // the default: degree 2, 1 ring
    variant("jet_d2_2rings", "jet d=2, 2 rings", "jet", with_jet(2, 2)),
    timed_once(variant("jet_d4_3rings", "jet d=4, 3 rings", "jet", with_jet(4, 3))),
  };
  for (const ce_tool::Method& m : ce_tool::methods()) {
    const bool has_default = std::any_of(v.begin(), v.end(), [&](const Estimator& e) {
      return e.method == &m && !e.given_normals && e.ball_edges == 0 && ce_tool::given_settings(e.settings) == 0;
    });
    if (!has_default) {
      std::string name = m.name;
      std::replace(name.begin(), name.end(), '-', '_');
      v.push_back(variant(name, m.label, m.name));
    }
  }
  return v;
}

inline Estimator peer(const std::string& name, const std::string& label, Peer p, double ball_edges = 0)
{
  Estimator e;
  e.name = name;
  e.label = label;
  e.peer = p;
  return ball_edges > 0 ? timed_once(in_ball(e, ball_edges)) : e; // balls: seconds on the 1M grid
}

inline const std::vector<Estimator>& estimators()
{
  static const std::vector<Estimator> all = [] {
    std::vector<Estimator> v = our_variants();
#if CGAL_VERSION_MAJOR >= 6
    v.push_back(peer("icc", "ICC (defaults)", Peer::icc));
    v.push_back(peer("icc_ball_1h", "ICC, ball radius 1 h", Peer::icc, 1));
    v.push_back(peer("icc_ball_2h", "ICC, ball radius 2 h", Peer::icc, 2));
    v.push_back(peer("icc_our_normals", "ICC (our normals, timed)", Peer::icc_our_normals));
    v.push_back(peer("discrete_mean", "CGAL discrete H (cotangent)", Peer::discrete_mean));
    v.push_back(peer("discrete_Gaussian", "CGAL discrete K (angle defect)", Peer::discrete_Gaussian));
#endif
    return v;
  }();
  return all;
}

// The estimator of estimators() named `name`; throws if there is none.
inline const Estimator& estimator(const std::string& name)
{
  for (const Estimator& e : estimators())
    if (e.name == name)
      return e;
  throw std::logic_error("ce_bench: no estimator '" + name + "'");
}

/// The estimators the report runs over a ball of any radius (its noise section): the
/// radius is set when they run (ball_edges); `style_of` names the estimator of
/// estimators() whose line style each takes in the report's plots.
struct Ball_estimator
{
  Estimator estimator;
  std::string style_of;
};

inline const std::vector<Ball_estimator>& ball_estimators()
{
  static const std::vector<Ball_estimator> all = {
    {variant("paraboloid_ball", "paraboloid, fit degree 2", "paraboloid"), "paraboloid_ball_4h"},
    {variant("paraboloid_d3_ball", "paraboloid, fit degree 3", "paraboloid", with_fit_degree(3)), "paraboloid_d3"},
    {variant("jet_d2_ball", "jet fitting d=2", "jet"), "jet_d2_2rings"},
    {variant("gauss_map_ball", "Gauss map over the ball", "gauss-map"), "gauss_map"},
#if CGAL_VERSION_MAJOR >= 6
    {peer("icc_ball", "ICC", Peer::icc), "icc_ball_2h"},
#endif
  };
  return all;
}

/// The output maps of `np` (as ce_test::run_with_all_outputs passes them) on `mesh`, for run(); the
/// reach, which the registry's methods write and run_with_all_outputs does not ask for, into a map
/// that stays on `mesh`.
template <typename NamedParameters>
ce_tool::Outputs outputs_of(const Mesh& mesh, const NamedParameters& np)
{
  using CGAL::parameters::get_parameter;
  return {get_parameter(np, CE::internal_np::vertex_mean_curvature_map),
          get_parameter(np, CE::internal_np::vertex_Gaussian_curvature_map),
          get_parameter(np, CE::internal_np::vertex_principal_curvatures_and_directions_map),
          get_parameter(np, CE::internal_np::vertex_estimation_status_map),
          const_cast<Mesh&>(mesh).add_property_map<vertex_descriptor, double>("v:benchmark_reach").first};
}

#if CGAL_VERSION_MAJOR >= 6
namespace PMP = CGAL::Polygon_mesh_processing;

/// CGAL's interpolated corrected curvatures with the three output maps of `out` (on CGAL 6
/// our Principal_curvatures_and_directions is CGAL's) and `settings` (ball radius,
/// normals): a fresh CGAL pack, never our own parameters. With outward normals CGAL's H,
/// K and principal curvatures already follow our convention (1/r, 1/r^2 and 1/r on a
/// sphere of radius r). It writes no status.
template <typename CGALParameters>
void run_icc(const Mesh& mesh, const ce_tool::Outputs& out, const CGALParameters& settings)
{
  PMP::interpolated_corrected_curvatures(mesh, settings.vertex_mean_curvature_map(out.H)
                                                 .vertex_Gaussian_curvature_map(out.K)
                                                 .vertex_principal_curvatures_and_directions_map(out.pcd));
}

inline void run_peer(const Estimator& e, const Mesh& mesh, double h, const ce_tool::Outputs& out)
{
  switch (e.peer) {
    case Peer::icc:
      if (e.ball_edges > 0)
        run_icc(mesh, out, CGAL::parameters::ball_radius(e.ball_edges * h));
      else
        run_icc(mesh, out, CGAL::parameters::default_values());
      return;
    case Peer::icc_our_normals: {
      // Estimated here, so timed with ICC: ICC's default estimates its own normals too.
      auto normals = get(CGAL::dynamic_vertex_property_t<Kernel::Vector_3>(), mesh);
      CE::estimate_vertex_normals<CGAL::Sequential_tag>(mesh, normals);
      run_icc(mesh, out, CGAL::parameters::vertex_normal_map(normals));
      return;
    }
    case Peer::discrete_mean:
      // CGAL gives |H| (norm of the cotangent Laplacian over 4 mixed Voronoi areas): 1/r on a sphere, but unsigned.
      PMP::discrete_mean_curvatures(mesh, out.H);
      return;
    case Peer::discrete_Gaussian:
      // CGAL gives the angle defect over the mixed Voronoi area: K, 1/r^2 on a sphere.
      PMP::discrete_Gaussian_curvatures(mesh, out.K);
      return;
    case Peer::none:
      break;
  }
  throw std::logic_error("ce_bench::run_peer: not a peer");
}
#endif

/// Runs `e` on `mesh` with the outputs `out`, on `threads` threads (as ce_tool::run takes
/// them; CGAL's estimators run on one). `given_normals` is read by the estimators with
/// given normals only, `h` (the mean edge length of `mesh`) by the balls only.
inline void run(const Estimator& e, const Mesh& mesh, Normal_map given_normals, double h, const ce_tool::Outputs& out,
                int threads)
{
  if (e.method) {
    ce_tool::Settings s = e.settings;
    if (e.ball_edges > 0)
      s.ball_radius = e.ball_edges * h;
    if (e.given_normals)
      s.given_normals = given_normals;
    ce_tool::run(*e.method, mesh, s, out, threads);
    return;
  }
#if CGAL_VERSION_MAJOR >= 6
  run_peer(e, mesh, h, out);
#else
  throw std::logic_error("ce_bench::run: a peer without CGAL 6");
#endif
}

/// The estimators as benchmark/make_report.py reads them (estimators.json): in report
/// order, name, label, origin (ours, CGAL's fit behind our interface, or CGAL 6's own)
/// and whether it is slow (scripts/make_report.sh leaves those out of first_calls); and
/// the ball estimators of the noise section, with the estimator whose style each takes.
inline void write_estimators_json(std::ostream& out)
{
  const auto write = [&](const Estimator& e, const std::string& style_of, bool last) {
    // Names and labels hold no quote or backslash.
    out << "  {\"name\": \"" << e.name << "\", \"label\": \"" << e.label << "\", \"origin\": \""
        << (!e.method            ? "cgal6"
            : e.method->cgal_fit ? "cgal_fit"
                                 : "ours")
        << '"';
    if (!style_of.empty())
      out << ", \"style_of\": \"" << style_of << '"';
    if (e.slow)
      out << ", \"slow\": true";
    out << (last ? "}\n" : "},\n");
  };
  out << "{\"estimators\": [\n";
  for (const Estimator& e : estimators())
    write(e, "", &e == &estimators().back());
  out << "], \"ball_estimators\": [\n";
  for (const Ball_estimator& b : ball_estimators())
    write(b.estimator, b.style_of, &b == &ball_estimators().back());
  out << "]}\n";
}

/// The minor page faults of the process so far: a call whose temporaries the allocator
/// serves from pages the process has not touched yet faults once per page.
inline long minor_page_faults()
{
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_minflt;
}

/// The real meshes of the report (CGAL's data archive, extracted by CMake into CE_DATA_DIR).
inline const std::array<const char*, 4>& real_mesh_names()
{
  static const std::array<const char*, 4> names = {"bunny00", "armadillo", "elephant", "ChineseDragon-10kv"};
  return names;
}

/// Reads CE_DATA_DIR/meshes/<name>.off; throws with the path if it cannot.
inline Mesh read_real_mesh(const std::string& name)
{
  const std::string path = std::string(CE_DATA_DIR) + "/meshes/" + name + ".off";
  Mesh mesh;
  if (!CGAL::IO::read_polygon_mesh(path, mesh) || is_empty(mesh))
    throw std::runtime_error("cannot read the mesh " + path + " (is libcgal-demo installed?)");
  return mesh;
}

/// The speed runs' mesh `name`: grid_<n>, the n x n grid of .1(cos pi x + cos pi y) over
/// [-1, 1]^2, or a real mesh.
inline Mesh speed_input(const std::string& name)
{
  if (name.rfind("grid_", 0) == 0)
    return ce_test::to_mesh<Mesh>(
      ce_test::grid_graph_soup(ce_test::hamann_table1_functions()[8], std::stoul(name.substr(5))));
  return read_real_mesh(name);
}

} // namespace ce_bench

#endif // CE_BENCHMARK_ESTIMATORS_H
