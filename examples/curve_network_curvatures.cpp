// SPDX-License-Identifier: GPL-3.0-or-later
// Estimates curvature on a mesh file with Wollmann's curve network and prints a
// summary. Without an argument it reads the Stanford bunny shipped by Debian's
// libcgal-demo package.
//
//   curve_network_curvatures [mesh.off|.ply|.obj|.stl] [extrapolation order 1..4]
#include <CGAL/Curvature_estimation/curve_network.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <algorithm>
#include <cstdlib>
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
  const int order = argc > 2 ? std::atoi(argv[2]) : 1;
  Mesh mesh;
  if (!CGAL::IO::read_polygon_mesh(path, mesh) || is_empty(mesh)) {
    std::cerr << "error: cannot read a non-empty polygon mesh from '" << path << "'\n";
    return 1;
  }

  auto mean = mesh.add_property_map<vertex_descriptor, double>("v:mean_curvature").first;
  auto gaussian = mesh.add_property_map<vertex_descriptor, double>("v:Gaussian_curvature").first;
  auto status = mesh.add_property_map<vertex_descriptor, CE::Estimation_status>("v:status").first;

  try {
    CE::curve_network_curvatures<CGAL::Parallel_if_available_tag>(mesh, CE::parameters::vertex_mean_curvature_map(mean)
                                                                          .vertex_Gaussian_curvature_map(gaussian)
                                                                          .vertex_estimation_status_map(status)
                                                                          .curve_model(CE::Curve_model::bezier)
                                                                          .extrapolation_order(order));
  } catch (const std::invalid_argument& e) {
    std::cerr << "error: " << e.what() << '\n';
    return 1;
  }

  std::vector<double> H, K;
  std::size_t ok = 0, widened = 0, fallback = 0, failed = 0;
  for (vertex_descriptor v : vertices(mesh)) {
    switch (status[v]) {
      case CE::Estimation_status::ok:
        ++ok;
        break;
      case CE::Estimation_status::widened:
        ++widened;
        break;
      case CE::Estimation_status::fallback:
        ++fallback;
        break;
      default:
        ++failed;
        continue;
    }
    H.push_back(mean[v]);
    K.push_back(gaussian[v]);
  }
  std::sort(H.begin(), H.end());
  std::sort(K.begin(), K.end());

  std::cout << "mesh: " << path << " (" << num_vertices(mesh) << " vertices)\n"
            << "estimator: curve network (Wollmann), Bezier curves, extrapolation order " << order << '\n'
            << "curve network at the requested order: " << ok << ", lower order: " << widened
            << ", paraboloid-fit fallback (no curve network, or no mesh lines): " << fallback
            << ", not estimable: " << failed << '\n';
  if (!H.empty())
    std::cout << "median H " << H[H.size() / 2] << ", median K " << K[K.size() / 2] << '\n';
  return 0;
}
