// SPDX-License-Identifier: GPL-3.0-or-later
// The k-rings and balls of internal/rings.h read from a Vertex_adjacency are those of
// halfedge circulation, vertex for vertex and in the same order (the fits sum their samples in that
// order, so that their estimates stay the same to the bit): on a Delaunay mesh with a border, after
// a vertex is removed (indices with a hole, a face that is not a triangle) and with an isolated
// vertex.
#include <CGAL/Curvature_estimation/internal/rings.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/graph_traits_Polyhedron_3.h>

#include <gtest/gtest.h>

#include "test_surfaces.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
using Vertex = Mesh::Vertex_index;
namespace CEI = CGAL::Curvature_estimation::internal;

// A Delaunay mesh of 400 random points on the exponential function, less an interior vertex, plus
// an isolated one.
Mesh mesh_with_hole_and_isolated_vertex(Vertex& removed, Vertex& isolated)
{
  const ce_test::Graph_function f = ce_test::hamann_table1_functions()[7];
  Mesh mesh = ce_test::to_mesh<Mesh>(ce_test::delaunay_graph_soup(f, 400, -1, 1, 3));
  removed = Vertex(std::uint32_t(200));
  EXPECT_FALSE(mesh.is_border(removed));
  CGAL::Euler::remove_center_vertex(halfedge(removed, mesh), mesh);
  EXPECT_TRUE(mesh.is_removed(removed));
  isolated = mesh.add_vertex(Kernel::Point_3(5, 5, 5));
  return mesh;
}

std::vector<std::size_t> ring_ends(const CEI::Ring_collector<Mesh>& collector)
{
  std::vector<std::size_t> ends;
  for (int r = 0; r <= collector.rings(); ++r)
    ends.push_back(collector.ring_end(r));
  return ends;
}

TEST(VertexAdjacency, GivesTheRingsOfHalfedgeCirculation)
{
  Vertex removed, isolated;
  const Mesh mesh = mesh_with_hole_and_isolated_vertex(removed, isolated);
  const auto adjacency = CEI::vertex_adjacency(mesh);
  ASSERT_NE(adjacency, nullptr);
  for (Vertex v : {removed, isolated})
    EXPECT_EQ(adjacency->offsets[std::size_t(v) + 1], adjacency->offsets[std::size_t(v)]);
  CEI::Ring_collector<Mesh> circulating, reading;
  reading.use_adjacency(adjacency);
  std::size_t compared = 0;
  for (Vertex v : vertices(mesh)) {
    circulating.start(v, mesh);
    reading.start(v, mesh);
    for (int r = 2; r <= 4; ++r) {
      const bool more = circulating.extend(mesh);
      EXPECT_EQ(reading.extend(mesh), more) << "vertex " << v << ", ring " << r;
    }
    EXPECT_EQ(reading.vertices(), circulating.vertices()) << "vertex " << v;
    EXPECT_EQ(ring_ends(reading), ring_ends(circulating)) << "vertex " << v;
    compared += circulating.vertices().size();
  }
  EXPECT_GT(compared, 400u * 30u);
}

TEST(VertexAdjacency, GivesTheBallsOfHalfedgeCirculation)
{
  Vertex removed, isolated;
  const Mesh mesh = mesh_with_hole_and_isolated_vertex(removed, isolated);
  CEI::Ring_collector<Mesh> circulating, reading;
  reading.use_adjacency(CEI::vertex_adjacency(mesh));
  for (Vertex v : vertices(mesh)) {
    const auto squared_distance = [&](Vertex w) { return CGAL::squared_distance(mesh.point(w), mesh.point(v)); };
    circulating.start(v, mesh);
    reading.start(v, mesh);
    for (const double radius : {0.1, 0.2, 0.4}) {
      const bool more = circulating.grow_ball(mesh, radius * radius, squared_distance);
      EXPECT_EQ(reading.grow_ball(mesh, radius * radius, squared_distance), more) << "vertex " << v;
      ASSERT_EQ(reading.vertices(), circulating.vertices()) << "vertex " << v << ", radius " << radius;
      EXPECT_EQ(reading.ball_size(), circulating.ball_size());
      for (std::size_t i = 0; i < circulating.vertices().size(); ++i)
        EXPECT_EQ(reading.inside_ball(i), circulating.inside_ball(i));
    }
  }
}

// Handles that are not indices have no adjacency: their rings circulate the halfedges.
TEST(VertexAdjacency, IsNullWhereVerticesAreNotIndices)
{
  using Polyhedron = CGAL::Polyhedron_3<Kernel>;
  const Polyhedron polyhedron =
    ce_test::to_mesh<Polyhedron>(ce_test::delaunay_graph_soup(ce_test::hamann_table1_functions()[7], 50));
  EXPECT_EQ(CEI::vertex_adjacency(polyhedron), nullptr);
}

} // namespace
