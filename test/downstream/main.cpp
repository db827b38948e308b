// SPDX-License-Identifier: GPL-3.0-or-later
// Minimal consumer of CGAL::Curvature_estimation: compiles against the public
// header and estimates curvature on an icosahedron. No C++ standard is set by the downstream
// project: C++17 must come from the target's usage requirements, and so must
// Eigen3 support (CGAL_EIGEN3_ENABLED from CGAL::Eigen3_support).
#include <CGAL/Curvature_estimation.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/generators.h>

#if __cplusplus < 201703L
#error "CGAL::Curvature_estimation must propagate C++17"
#endif
#ifndef CGAL_EIGEN3_ENABLED
#error "CGAL::Curvature_estimation must propagate CGAL::Eigen3_support"
#endif

int main()
{
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Point = K::Point_3;
  using Mesh = CGAL::Surface_mesh<Point>;

  namespace CE = CGAL::Curvature_estimation;

  Mesh mesh;
  CGAL::make_icosahedron(mesh, Point(0, 0, 0), 2.0);
  auto mean = mesh.add_property_map<Mesh::Vertex_index, double>("v:H").first;
  auto status = mesh.add_property_map<Mesh::Vertex_index, CE::Estimation_status>("v:status").first;
  CE::paraboloid_fitting_curvatures(
    mesh, CE::parameters::vertex_mean_curvature_map(mean).vertex_estimation_status_map(status));

  // Every vertex of a convex closed surface with outward faces has H > 0.
  for (Mesh::Vertex_index v : vertices(mesh))
    if (status[v] == CE::Estimation_status::not_estimable || !(mean[v] > 0))
      return 1;
  return mesh.number_of_vertices() == 12 ? 0 : 1;
}
