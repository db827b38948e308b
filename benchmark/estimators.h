// The estimators the benchmark report compares, and the inputs it times, in one
// place: the speed benchmark (bench_estimators.cpp) and the accuracy runner
// (accuracy_runner.cpp) both iterate over `estimators()`, so that a variant added
// here shows up in every table and plot of benchmark/REPORT.md under the same name.
#ifndef CE_BENCHMARK_ESTIMATORS_H
#define CE_BENCHMARK_ESTIMATORS_H

#include <CGAL/Curvature_estimation.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <array>
#include <stdexcept>
#include <string>

namespace ce_bench {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
using vertex_descriptor = Mesh::Vertex_index;
using Normal_map = Mesh::Property_map<vertex_descriptor, Kernel::Vector_3>;
namespace CE = CGAL::Curvature_estimation;

enum class Estimator
{
  paraboloid,                // default (quadric-fit) normals
  paraboloid_area_normals,   // area-weighted face-average normals
  paraboloid_given_normals,  // normals passed in a vertex_normal_map
  curve_network_1,           // extrapolation_order(1): O(h^2)
  curve_network_2,           // extrapolation_order(2): O(h^4) on parameter grids
  gauss_map,
  taubin,
  chen_schmitt,
  jet_d2_1ring,
  jet_d2_2rings,
  jet_d4_3rings
};

struct Estimator_info
{
  Estimator id;
  const char* name;  // identifier in benchmark names and CSV/JSON files (no spaces, no '/')
  const char* label; // for the report's tables and legends
};

inline const std::array<Estimator_info, 11>& estimators()
{
  static const std::array<Estimator_info, 11> all = {{
    {Estimator::paraboloid, "paraboloid", "paraboloid (default normals)"},
    {Estimator::paraboloid_area_normals, "paraboloid_area_normals", "paraboloid (area normals)"},
    {Estimator::paraboloid_given_normals, "paraboloid_given_normals", "paraboloid (given normals)"},
    {Estimator::curve_network_1, "curve_network_1", "curve network O(h^2)"},
    {Estimator::curve_network_2, "curve_network_2", "curve network O(h^4)"},
    {Estimator::gauss_map, "gauss_map", "Gauss map"},
    {Estimator::taubin, "taubin", "Taubin"},
    {Estimator::chen_schmitt, "chen_schmitt", "Chen-Schmitt"},
    {Estimator::jet_d2_1ring, "jet_d2_1ring", "jet d=2, 1 ring"},
    {Estimator::jet_d2_2rings, "jet_d2_2rings", "jet d=2, 2 rings"},
    {Estimator::jet_d4_3rings, "jet_d4_3rings", "jet d=4, 3 rings"},
  }};
  return all;
}

inline bool is_jet(Estimator e)
{
  return e == Estimator::jet_d2_1ring || e == Estimator::jet_d2_2rings || e == Estimator::jet_d4_3rings;
}

/// Runs estimator `e` on `mesh` with the outputs (and any other parameters) of `np`.
/// `given_normals` is read by `paraboloid_given_normals` only.
template <typename ConcurrencyTag, typename NamedParameters>
void run(Estimator e, const Mesh& mesh, Normal_map given_normals, const NamedParameters& np)
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
