// SPDX-License-Identifier: GPL-3.0-or-later
// The estimators the benchmark report compares, and the inputs it times, in one
// place: the speed benchmark (bench_estimators.cpp) and the accuracy runner
// (accuracy_runner.cpp) both iterate over `estimators()`, so that a variant added
// here shows up in every table and plot of benchmark/REPORT.md under the same name.
// Configured against CGAL 6 or later, the list also holds CGAL's own curvature
// estimators (interpolated corrected curvatures, the discrete operators).
#ifndef CE_BENCHMARK_ESTIMATORS_H
#define CE_BENCHMARK_ESTIMATORS_H

#include <CGAL/Curvature_estimation.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/version.h>

#if CGAL_VERSION_MAJOR >= 6
#include <CGAL/Polygon_mesh_processing/curvature.h>
#include <CGAL/Polygon_mesh_processing/interpolated_corrected_curvatures.h>
#endif

#include <array>
#include <stdexcept>
#include <string>
#include <vector>

namespace ce_bench {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
using vertex_descriptor = Mesh::Vertex_index;
using Normal_map = Mesh::Property_map<vertex_descriptor, Kernel::Vector_3>;
namespace CE = CGAL::Curvature_estimation;

enum class Estimator
{
  paraboloid,               // default (quadric-fit) normals
  paraboloid_area_normals,  // area-weighted face-average normals
  paraboloid_given_normals, // normals passed in a vertex_normal_map
  paraboloid_d3,            // fit_degree(3): cubic Taylor fit over 2 rings
  paraboloid_d4,            // fit_degree(4): quartic Taylor fit over 3 rings
  paraboloid_ball_2h,       // ball_radius of 2 mean edge lengths
  paraboloid_ball_4h,       // ... 4
  paraboloid_ball_8h,       // ... 8
  curve_network_1,          // extrapolation_order(1): O(h^2)
  curve_network_2,          // extrapolation_order(2): O(h^4) on parameter grids
  gauss_map,
  taubin,
  chen_schmitt,
  jet_d2_1ring,
  jet_d2_2rings,
  jet_d4_3rings,
#if CGAL_VERSION_MAJOR >= 6
  icc,               // CGAL::Polygon_mesh_processing::interpolated_corrected_curvatures, its defaults
  icc_ball_1h,       // the same with ball_radius = 1 mean edge length
  icc_ball_2h,       // the same with ball_radius = 2 mean edge lengths
  icc_our_normals,   // the same given our default normals (estimated in the same call)
  discrete_mean,     // CGAL::Polygon_mesh_processing::discrete_mean_curvatures: H only
  discrete_Gaussian, // CGAL::Polygon_mesh_processing::discrete_Gaussian_curvatures: K only
#endif
};

/// The quantities an estimator gives (a bit set); the others are neither measured nor reported.
enum Quantities : unsigned
{
  gives_principal = 1, // k_max, k_min and the principal directions
  gives_H = 2,
  gives_K = 4,
  gives_all = gives_principal | gives_H | gives_K
};

struct Estimator_info
{
  Estimator id;
  const char* name;  // identifier in benchmark names and CSV/JSON files (no spaces, no '/')
  const char* label; // for the report's tables and legends
  unsigned quantities = gives_all;
  bool parallel = true; // has a parallel version (CGAL::Parallel_tag); CGAL 6's estimators have none
};

inline const std::vector<Estimator_info>& estimators()
{
  static const std::vector<Estimator_info> all = {
    {Estimator::paraboloid, "paraboloid", "paraboloid (default normals)"},
    {Estimator::paraboloid_area_normals, "paraboloid_area_normals", "paraboloid (area normals)"},
    {Estimator::paraboloid_given_normals, "paraboloid_given_normals", "paraboloid (given normals)"},
    {Estimator::paraboloid_d3, "paraboloid_d3", "paraboloid, fit degree 3"},
    {Estimator::paraboloid_d4, "paraboloid_d4", "paraboloid, fit degree 4"},
    {Estimator::paraboloid_ball_2h, "paraboloid_ball_2h", "paraboloid, ball radius 2 h"},
    {Estimator::paraboloid_ball_4h, "paraboloid_ball_4h", "paraboloid, ball radius 4 h"},
    {Estimator::paraboloid_ball_8h, "paraboloid_ball_8h", "paraboloid, ball radius 8 h"},
    {Estimator::curve_network_1, "curve_network_1", "curve network O(h^2)"},
    {Estimator::curve_network_2, "curve_network_2", "curve network O(h^4)"},
    {Estimator::gauss_map, "gauss_map", "Gauss map"},
    {Estimator::taubin, "taubin", "Taubin"},
    {Estimator::chen_schmitt, "chen_schmitt", "Chen-Schmitt"},
    {Estimator::jet_d2_1ring, "jet_d2_1ring", "jet d=2, 1 ring"},
    {Estimator::jet_d2_2rings, "jet_d2_2rings", "jet d=2, 2 rings"},
    {Estimator::jet_d4_3rings, "jet_d4_3rings", "jet d=4, 3 rings"},
#if CGAL_VERSION_MAJOR >= 6
    {Estimator::icc, "icc", "ICC (defaults)", gives_all, false},
    {Estimator::icc_ball_1h, "icc_ball_1h", "ICC, ball radius 1 h", gives_all, false},
    {Estimator::icc_ball_2h, "icc_ball_2h", "ICC, ball radius 2 h", gives_all, false},
    {Estimator::icc_our_normals, "icc_our_normals", "ICC (our normals, timed)", gives_all, false},
    {Estimator::discrete_mean, "discrete_mean", "CGAL discrete H (cotangent)", gives_H, false},
    {Estimator::discrete_Gaussian, "discrete_Gaussian", "CGAL discrete K (angle defect)", gives_K, false},
#endif
  };
  return all;
}

#if CGAL_VERSION_MAJOR >= 6
namespace PMP = CGAL::Polygon_mesh_processing;

// The output maps of `np`, which must hold them (the benchmark always asks for all three).
template <typename NamedParameters>
auto mean_curvature_map(const NamedParameters& np)
{
  return CGAL::parameters::get_parameter(np, CE::internal_np::vertex_mean_curvature_map);
}
template <typename NamedParameters>
auto Gaussian_curvature_map(const NamedParameters& np)
{
  return CGAL::parameters::get_parameter(np, CE::internal_np::vertex_Gaussian_curvature_map);
}

/// CGAL's interpolated corrected curvatures with the three output maps of `np` (on CGAL 6
/// our Principal_curvatures_and_directions is CGAL's) and `settings` (ball radius,
/// normals): a fresh CGAL pack, never our own parameters. With outward normals CGAL's H,
/// K and principal curvatures already follow our convention (1/r, 1/r^2 and 1/r on a
/// sphere of radius r).
template <typename NamedParameters, typename CGALParameters>
void run_icc(const Mesh& mesh, const NamedParameters& np, const CGALParameters& settings)
{
  PMP::interpolated_corrected_curvatures(
    mesh, settings.vertex_mean_curvature_map(mean_curvature_map(np))
            .vertex_Gaussian_curvature_map(Gaussian_curvature_map(np))
            .vertex_principal_curvatures_and_directions_map(
              CGAL::parameters::get_parameter(np, CE::internal_np::vertex_principal_curvatures_and_directions_map)));
}
#endif

/// The estimators the report runs over a ball of any radius (its noise section).
enum class Ball_estimator
{
  paraboloid,    // paraboloid_fitting_curvatures, default fit_degree (2)
  paraboloid_d3, // ... fit_degree(3)
  jet_d2,        // jet_fitting_curvatures, jet_degree(2)
  gauss_map,     // gauss_map_curvatures
#if CGAL_VERSION_MAJOR >= 6
  icc, // CGAL::Polygon_mesh_processing::interpolated_corrected_curvatures
#endif
};

struct Ball_estimator_info
{
  Ball_estimator id;
  const char* name; // identifier in CSV files, as Estimator_info::name
};

inline const std::vector<Ball_estimator_info>& ball_estimators()
{
  static const std::vector<Ball_estimator_info> all = {
    {Ball_estimator::paraboloid, "paraboloid_ball"},
    {Ball_estimator::paraboloid_d3, "paraboloid_d3_ball"},
    {Ball_estimator::jet_d2, "jet_d2_ball"},
    {Ball_estimator::gauss_map, "gauss_map_ball"},
#if CGAL_VERSION_MAJOR >= 6
    {Ball_estimator::icc, "icc_ball"},
#endif
  };
  return all;
}

/// Runs estimator `e` on `mesh` over the ball of radius `radius` (mesh units) with the
/// outputs (and any other parameters) of `np`.
template <typename ConcurrencyTag, typename NamedParameters>
void run_in_ball(Ball_estimator e, const Mesh& mesh, double radius, const NamedParameters& np)
{
  switch (e) {
    case Ball_estimator::paraboloid:
      CE::paraboloid_fitting_curvatures<ConcurrencyTag>(mesh, np.ball_radius(radius));
      return;
    case Ball_estimator::paraboloid_d3:
      CE::paraboloid_fitting_curvatures<ConcurrencyTag>(mesh, np.ball_radius(radius).fit_degree(3));
      return;
    case Ball_estimator::jet_d2:
      CE::jet_fitting_curvatures<ConcurrencyTag>(mesh, np.ball_radius(radius).jet_degree(2));
      return;
    case Ball_estimator::gauss_map:
      CE::gauss_map_curvatures<ConcurrencyTag>(mesh, np.ball_radius(radius));
      return;
#if CGAL_VERSION_MAJOR >= 6
    case Ball_estimator::icc:
      run_icc(mesh, np, CGAL::parameters::ball_radius(radius));
      return;
#endif
  }
  throw std::logic_error("ce_bench::run_in_ball: unknown estimator");
}

/// Runs estimator `e` on `mesh` with the outputs (and any other parameters) of `np`.
/// `given_normals` is read by `paraboloid_given_normals` only, `h` (the mean edge
/// length of `mesh`) by the ball radii only.
template <typename ConcurrencyTag, typename NamedParameters>
void run(Estimator e, const Mesh& mesh, Normal_map given_normals, double h, const NamedParameters& np)
{
  switch (e) {
    case Estimator::paraboloid:
      CE::paraboloid_fitting_curvatures<ConcurrencyTag>(mesh, np);
      return;
    case Estimator::paraboloid_area_normals:
      CE::paraboloid_fitting_curvatures<ConcurrencyTag>(
        mesh, np.vertex_normal_method(CE::Vertex_normal_method::area_weighted));
      return;
    case Estimator::paraboloid_given_normals:
      CE::paraboloid_fitting_curvatures<ConcurrencyTag>(mesh, np.vertex_normal_map(given_normals));
      return;
    case Estimator::paraboloid_d3:
      CE::paraboloid_fitting_curvatures<ConcurrencyTag>(mesh, np.fit_degree(3));
      return;
    case Estimator::paraboloid_d4:
      CE::paraboloid_fitting_curvatures<ConcurrencyTag>(mesh, np.fit_degree(4));
      return;
    case Estimator::paraboloid_ball_2h:
      run_in_ball<ConcurrencyTag>(Ball_estimator::paraboloid, mesh, 2 * h, np);
      return;
    case Estimator::paraboloid_ball_4h:
      run_in_ball<ConcurrencyTag>(Ball_estimator::paraboloid, mesh, 4 * h, np);
      return;
    case Estimator::paraboloid_ball_8h:
      run_in_ball<ConcurrencyTag>(Ball_estimator::paraboloid, mesh, 8 * h, np);
      return;
    case Estimator::curve_network_1:
      CE::curve_network_curvatures<ConcurrencyTag>(mesh, np.extrapolation_order(1));
      return;
    case Estimator::curve_network_2:
      CE::curve_network_curvatures<ConcurrencyTag>(mesh, np.extrapolation_order(2));
      return;
    case Estimator::gauss_map:
      CE::gauss_map_curvatures<ConcurrencyTag>(mesh, np);
      return;
    case Estimator::taubin:
      CE::taubin_curvatures<ConcurrencyTag>(mesh, np);
      return;
    case Estimator::chen_schmitt:
      CE::chen_schmitt_curvatures<ConcurrencyTag>(mesh, np);
      return;
    case Estimator::jet_d2_1ring:
      CE::jet_fitting_curvatures<ConcurrencyTag>(mesh, np.jet_degree(2).neighborhood_rings(1));
      return;
    case Estimator::jet_d2_2rings:
      CE::jet_fitting_curvatures<ConcurrencyTag>(mesh, np.jet_degree(2).neighborhood_rings(2));
      return;
    case Estimator::jet_d4_3rings:
      CE::jet_fitting_curvatures<ConcurrencyTag>(mesh, np.jet_degree(4).neighborhood_rings(3));
      return;
#if CGAL_VERSION_MAJOR >= 6
    case Estimator::icc:
      run_icc(mesh, np, CGAL::parameters::default_values());
      return;
    case Estimator::icc_ball_1h:
      run_in_ball<ConcurrencyTag>(Ball_estimator::icc, mesh, h, np);
      return;
    case Estimator::icc_ball_2h:
      run_in_ball<ConcurrencyTag>(Ball_estimator::icc, mesh, 2 * h, np);
      return;
    case Estimator::icc_our_normals: {
      // Estimated here, so timed with ICC: ICC's default estimates its own normals too.
      auto normals = get(CGAL::dynamic_vertex_property_t<Kernel::Vector_3>(), mesh);
      CE::estimate_vertex_normals<ConcurrencyTag>(mesh, normals);
      run_icc(mesh, np, CGAL::parameters::vertex_normal_map(normals));
      return;
    }
    case Estimator::discrete_mean:
      // CGAL gives |H| (norm of the cotangent Laplacian over 4 mixed Voronoi areas): 1/r on a sphere, but unsigned.
      PMP::discrete_mean_curvatures(mesh, mean_curvature_map(np));
      return;
    case Estimator::discrete_Gaussian:
      // CGAL gives the angle defect over the mixed Voronoi area: K, 1/r^2 on a sphere.
      PMP::discrete_Gaussian_curvatures(mesh, Gaussian_curvature_map(np));
      return;
#endif
  }
  throw std::logic_error("ce_bench::run: unknown estimator");
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

} // namespace ce_bench

#endif // CE_BENCHMARK_ESTIMATORS_H
