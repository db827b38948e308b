// SPDX-License-Identifier: GPL-3.0-or-later
// Estimates curvature on a mesh file with Hamann's paraboloid fit and prints a
// summary of every output: the median H, the signs of K, the principal curvatures
// and directions at the most curved vertex, the status counts. Without an
// argument it reads the Stanford bunny shipped by Debian's libcgal-demo package.
//
//   curvature_summary [mesh.off|.ply|.obj|.stl]
#include <CGAL/Curvature_estimation.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <algorithm>
#include <chrono>
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

  auto mean = mesh.add_property_map<vertex_descriptor, double>("v:mean_curvature").first;
  auto gaussian = mesh.add_property_map<vertex_descriptor, double>("v:Gaussian_curvature").first;
  auto principal = mesh
                     .add_property_map<vertex_descriptor, CE::Principal_curvatures_and_directions<Kernel>>(
                       "v:principal_curvatures_and_directions")
                     .first;
  auto status = mesh.add_property_map<vertex_descriptor, CE::Estimation_status>("v:status").first;

  const auto start = std::chrono::steady_clock::now();
  CE::paraboloid_fitting_curvatures<CGAL::Parallel_if_available_tag>(
    mesh, CE::parameters::vertex_mean_curvature_map(mean)
            .vertex_Gaussian_curvature_map(gaussian)
            .vertex_principal_curvatures_and_directions_map(principal)
            .vertex_estimation_status_map(status));
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  std::vector<double> H;
  std::size_t elliptic = 0, hyperbolic = 0, widened = 0, failed = 0;
  vertex_descriptor most_curved;
  double largest = -1;
  for (vertex_descriptor v : vertices(mesh)) {
    if (status[v] == CE::Estimation_status::not_estimable) {
      ++failed;
      continue;
    }
    widened += status[v] == CE::Estimation_status::widened;
    H.push_back(mean[v]);
    elliptic += gaussian[v] > 0;
    hyperbolic += gaussian[v] < 0;
    const double k = std::max(std::abs(principal[v].max_curvature), std::abs(principal[v].min_curvature));
    if (k > largest) {
      largest = k;
      most_curved = v;
    }
  }

  std::cout << "mesh: " << path << '\n'
            << "vertices: " << num_vertices(mesh) << ", faces: " << num_faces(mesh) << '\n'
            << "estimator: paraboloid fitting (Hamann), normals from a quadric fit\n"
            << "time: " << seconds * 1e3 << " ms (" << seconds * 1e9 / num_vertices(mesh) << " ns per vertex)\n"
            << "widened neighborhoods: " << widened << ", not estimable: " << failed << '\n';
  if (H.empty())
    return 0;
  std::nth_element(H.begin(), H.begin() + H.size() / 2, H.end());
  const CE::Principal_curvatures_and_directions<Kernel>& pc = principal[most_curved];
  std::cout << "median mean curvature H: " << H[H.size() / 2] << '\n'
            << "Gaussian curvature K > 0 (elliptic) at " << elliptic << " vertices, K < 0 (hyperbolic) at "
            << hyperbolic << '\n'
            << "most curved vertex, at " << mesh.point(most_curved) << ": principal curvatures " << pc.max_curvature
            << " and " << pc.min_curvature << ", principal directions (" << pc.max_direction << ") and ("
            << pc.min_direction << ")\n";
  return 0;
}
