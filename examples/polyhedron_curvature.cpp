// SPDX-License-Identifier: GPL-3.0-or-later
// Principal curvatures on a CGAL::Polyhedron_3, with the outputs in
// std::map-backed property maps (Polyhedron_3 has no vertex index of its own).
//
//   polyhedron_curvature [mesh.off]
#include <CGAL/Curvature_estimation.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/graph_traits_Polyhedron_3.h>

#include <boost/property_map/property_map.hpp>

#include <iostream>
#include <map>
#include <string>

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Polyhedron = CGAL::Polyhedron_3<Kernel>;
using vertex_descriptor = boost::graph_traits<Polyhedron>::vertex_descriptor;
namespace CE = CGAL::Curvature_estimation;

int main(int argc, char** argv)
{
  const std::string path = argc > 1 ? argv[1] : std::string(CE_DATA_DIR) + "/meshes/bunny00.off";
  Polyhedron polyhedron;
  if (!CGAL::IO::read_polygon_mesh(path, polyhedron) || is_empty(polyhedron)) {
    std::cerr << "error: cannot read a non-empty polygon mesh from '" << path << "'\n";
    return 1;
  }

  std::map<vertex_descriptor, CE::Principal_curvatures_and_directions<Kernel>> principal;
  std::map<vertex_descriptor, CE::Estimation_status> status;
  CE::paraboloid_fitting_curvatures(
    polyhedron,
    CE::parameters::vertex_principal_curvatures_and_directions_map(boost::make_assoc_property_map(principal))
      .vertex_estimation_status_map(boost::make_assoc_property_map(status)));

  // The first few vertices, as a user would inspect them.
  int shown = 0;
  for (vertex_descriptor v : vertices(polyhedron)) {
    const auto& pc = principal[v];
    std::cout << "vertex " << v->point() << ": k_max " << pc.max_curvature << " along (" << pc.max_direction
              << "), k_min " << pc.min_curvature << " along (" << pc.min_direction << "), " << status[v] << '\n';
    if (++shown == 5)
      break;
  }
  std::cout << num_vertices(polyhedron) << " vertices estimated\n";
  return 0;
}
