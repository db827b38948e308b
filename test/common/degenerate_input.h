// SPDX-License-Identifier: GPL-3.0-or-later
// Bad input shared by the estimators' tests: a small graph mesh with a vertex in no face
// and a vertex with a NaN coordinate, and the GoogleTest checks of the outputs there.
#ifndef CE_TEST_COMMON_DEGENERATE_INPUT_H
#define CE_TEST_COMMON_DEGENERATE_INPUT_H

#include <CGAL/Curvature_estimation/Principal_curvatures_and_directions.h>

#include <gtest/gtest.h>

#include "estimator_runs.h"
#include "test_surfaces.h"

#include <cmath>
#include <limits>

namespace ce_test {

template <typename Mesh>
struct Mesh_with_bad_vertices
{
  Mesh mesh;
  typename Mesh::Vertex_index isolated, broken;
};

// The 11 x 11 grid of Hamann's paraboloid as a CGAL::Surface_mesh, plus `isolated`, a
// vertex at (5, 5, 5) in no face, and `broken`, the grid's centre moved to (NaN, 0, 0).
template <typename Mesh>
Mesh_with_bad_vertices<Mesh> grid_with_isolated_and_nan_vertex()
{
  using Point = typename Mesh::Point;
  using Vertex = typename Mesh::Vertex_index;
  Mesh_with_bad_vertices<Mesh> m{to_mesh<Mesh>(grid_graph_soup(hamann_table1_functions()[3], 11)), {}, {}};
  m.isolated = m.mesh.add_vertex(Point(5, 5, 5));
  m.broken = Vertex(static_cast<typename Mesh::size_type>(5 + 11 * 5));
  m.mesh.point(m.broken) = Point(std::numeric_limits<double>::quiet_NaN(), 0, 0);
  return m;
}

// The outputs at a vertex that cannot be estimated: its status says so, the values are NaN.
template <typename Kernel, typename Vertex>
void expect_not_estimable(const Estimates<Kernel>& e, Vertex v)
{
  using CGAL::Curvature_estimation::Estimation_status;
  EXPECT_EQ(e.status[v], Estimation_status::not_estimable) << v;
  EXPECT_TRUE(std::isnan(e.principal[v].max_curvature) && std::isnan(e.principal[v].min_curvature));
  EXPECT_TRUE(std::isnan(e.mean[v]) && std::isnan(e.gaussian[v]));
  EXPECT_TRUE(std::isnan(e.principal[v].max_direction.x()));
}

// The neighbors of `v` are estimated, finite.
template <typename Kernel, typename Mesh>
void expect_neighbors_estimated(const Estimates<Kernel>& e, const Mesh& mesh, typename Mesh::Vertex_index v)
{
  using CGAL::Curvature_estimation::Estimation_status;
  for (typename Mesh::Vertex_index w : vertices_around_target(halfedge(v, mesh), mesh)) {
    EXPECT_NE(e.status[w], Estimation_status::not_estimable) << w;
    EXPECT_TRUE(std::isfinite(e.mean[w])) << w;
  }
}

} // namespace ce_test

#endif // CE_TEST_COMMON_DEGENERATE_INPUT_H
