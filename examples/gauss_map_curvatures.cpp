// SPDX-License-Identifier: GPL-3.0-or-later
// Estimates curvature on a mesh file with the Gauss-map method of Chen, Wu and
// Chi and with its two baselines (Taubin, Chen-Schmitt), and compares the
// median |H| of the three. Without an argument it reads the Stanford bunny
// shipped by Debian's libcgal-demo package.
//
//   gauss_map_curvatures [mesh.off|.ply|.obj|.stl]
#include <CGAL/Curvature_estimation/chen_schmitt.h>
#include <CGAL/Curvature_estimation/gauss_map.h>
#include <CGAL/Curvature_estimation/taubin.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
using vertex_descriptor = Mesh::Vertex_index;
namespace CE = CGAL::Curvature_estimation;

int main(int argc, char** argv)
{
  const std::string path = argc > 1 ? argv[1] : std::string(CE_DATA_DIR) + "/meshes/bunny00.off";
  Mesh mesh;
  if (!CGAL::IO::read_polygon_mesh(path, mesh) || is_empty(mesh)) {
    std::cerr << "error: cannot read a non-empty polygon mesh from '" << path << "'\n";
    return 1;
  }
  auto H = mesh.add_property_map<vertex_descriptor, double>("v:mean_curvature").first;
  auto status = mesh.add_property_map<vertex_descriptor, CE::Estimation_status>("v:status").first;
  const auto outputs = CE::parameters::vertex_mean_curvature_map(H).vertex_estimation_status_map(status);

  // Median |H| over the vertices that could be estimated.
  auto report = [&](const char* name) {
    std::vector<double> values;
    for (vertex_descriptor v : vertices(mesh))
      if (status[v] != CE::Estimation_status::not_estimable)
        values.push_back(std::abs(H[v]));
    std::cout << name << ": ";
    if (values.empty()) {
      std::cout << "no estimate\n";
      return;
    }
    std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
    std::cout << "median |H| " << values[values.size() / 2] << " (" << num_vertices(mesh) - values.size()
              << " vertices not estimable)\n";
  };

  std::cout << "mesh: " << path << ", " << num_vertices(mesh) << " vertices\n";
  // Default normals: a second-order quadric fit (see the documentation of each function).
  CE::gauss_map_curvatures<CGAL::Parallel_if_available_tag>(mesh, outputs);
  report("Gauss map (Chen-Wu-Chi)");
  CE::taubin_curvatures<CGAL::Parallel_if_available_tag>(mesh, outputs);
  report("Taubin, area weights   ");
  CE::taubin_curvatures<CGAL::Parallel_if_available_tag>(mesh,
                                                         outputs.neighbor_weighting(CE::Neighbor_weighting::centroid));
  report("Taubin, centroid       ");
  CE::chen_schmitt_curvatures<CGAL::Parallel_if_available_tag>(mesh, outputs);
  report("Chen-Schmitt           ");
  return 0;
}
