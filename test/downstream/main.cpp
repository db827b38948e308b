// Minimal consumer of CGAL::Curvature_estimation: compiles against the public
// header and builds a tetrahedron. No C++ standard is set by the downstream
// project: C++17 must come from the target's usage requirements, and so must
// Eigen3 support (CGAL_EIGEN3_ENABLED from CGAL::Eigen3_support).
#include <CGAL/Curvature_estimation.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>

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

  Mesh mesh;
  CGAL::make_tetrahedron(Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0), Point(0, 0, 1), mesh);

  const bool ok = mesh.number_of_vertices() == 4 && mesh.number_of_faces() == 4 &&
                  CGAL::is_closed(mesh) && mesh.is_valid(false);
  return ok ? 0 : 1;
}
