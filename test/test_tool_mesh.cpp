// SPDX-License-Identifier: GPL-3.0-or-later
// The tool's mesh of a polygon soup (tools/soup_repair.h, build_mesh) against
// CGAL's: halfedge for halfedge the connectivity that polygon_soup_to_polygon_mesh
// gives the soup (after orient_polygon_soup where the soup needs it), so that the
// estimates, which gather neighbors from halfedge(v) on, are CGAL's mesh's to the bit.
#include "marching_tetrahedra.h"
#include "soup_repair.h"
#include "test_surfaces.h"

#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <random>
#include <vector>

namespace {

using ce_tool::Mesh;
using Polygons = std::vector<std::vector<std::size_t>>;

ce_tool::Soup tool_soup(const std::vector<ce_tool::Point>& points, const Polygons& polygons)
{
  ce_tool::Soup soup;
  soup.points = points;
  soup.faces.append(polygons);
  return soup;
}

std::vector<ce_tool::Point> points_of(const ce_test::Soup& s)
{
  std::vector<ce_tool::Point> points;
  for (const Eigen::Vector3d& p : s.points)
    points.emplace_back(p.x(), p.y(), p.z());
  return points;
}

Polygons polygons_of(const ce_test::Soup& s)
{
  Polygons polygons;
  for (const auto& f : s.faces)
    polygons.push_back({f[0], f[1], f[2]});
  return polygons;
}

// The faces in a shuffled order, each from a shuffled start (the same polygon).
Polygons shuffled(Polygons polygons, unsigned seed)
{
  std::mt19937 random(seed);
  std::shuffle(polygons.begin(), polygons.end(), random);
  for (std::vector<std::size_t>& polygon : polygons)
    std::rotate(polygon.begin(), polygon.begin() + std::ptrdiff_t(random() % polygon.size()), polygon.end());
  return polygons;
}

// Expects build_mesh to give CGAL's mesh of the soup: PMP's orientation where
// `orient` (the soup's points are then unchanged: no vertex is split here), then
// polygon_soup_to_polygon_mesh.
void expect_cgal_mesh(const std::vector<ce_tool::Point>& points, const Polygons& polygons, bool orient = false)
{
  std::vector<Mesh::Vertex_index> file_to_mesh;
  const Mesh ours = ce_tool::build_mesh(tool_soup(points, polygons), file_to_mesh);

  std::vector<ce_tool::Point> cgal_points = points;
  Polygons cgal_polygons = polygons;
  if (orient) {
    ASSERT_TRUE(CGAL::Polygon_mesh_processing::orient_polygon_soup(cgal_points, cgal_polygons));
  }
  ASSERT_EQ(cgal_points.size(), points.size());
  Mesh cgal;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(cgal_points, cgal_polygons, cgal);

  ASSERT_TRUE(ours.is_valid(false));
  ASSERT_EQ(ours.number_of_vertices(), cgal.number_of_vertices());
  ASSERT_EQ(ours.number_of_halfedges(), cgal.number_of_halfedges());
  ASSERT_EQ(ours.number_of_faces(), cgal.number_of_faces());
  ASSERT_EQ(file_to_mesh.size(), points.size());
  std::size_t differences = 0;
  for (std::size_t i = 0; i < points.size(); ++i)
    differences += file_to_mesh[i] != Mesh::Vertex_index(Mesh::size_type(i));
  for (Mesh::Vertex_index v : cgal.vertices())
    differences += ours.halfedge(v) != cgal.halfedge(v) || ours.point(v) != cgal.point(v);
  for (Mesh::Face_index f : cgal.faces())
    differences += ours.halfedge(f) != cgal.halfedge(f);
  for (Mesh::Halfedge_index h : cgal.halfedges())
    differences += ours.target(h) != cgal.target(h) || ours.next(h) != cgal.next(h) || ours.prev(h) != cgal.prev(h) ||
                   ours.face(h) != cgal.face(h);
  EXPECT_EQ(differences, 0u) << "of " << points.size() << " vertices, " << polygons.size() << " faces";
}

TEST(ToolMesh, GridWithBorderInTheFileOrderAndShuffled)
{
  const ce_test::Soup grid = ce_test::grid_graph_soup(ce_test::hamann_table1_functions()[0], 12);
  expect_cgal_mesh(points_of(grid), polygons_of(grid));
  for (unsigned seed = 1; seed <= 5; ++seed)
    expect_cgal_mesh(points_of(grid), shuffled(polygons_of(grid), seed));
}

TEST(ToolMesh, ClosedSurfacesShuffled)
{
  for (const ce_test::Soup& s : {ce_test::sphere_soup(1.0, 3), ce_test::torus_soup(3.0, 1.0, 24, 10),
                                 ce_test::marching_tetrahedra_soup(ce_test::gaussian_blobs(), 10)})
  {
    expect_cgal_mesh(points_of(s), polygons_of(s));
    for (unsigned seed = 1; seed <= 3; ++seed)
      expect_cgal_mesh(points_of(s), shuffled(polygons_of(s), seed));
  }
}

// Quadrilaterals and triangles on a 9 x 9 grid of points with three holes (no two
// borders meet at a vertex), and a second component with a pentagon.
TEST(ToolMesh, MixedPolygonsHolesAndComponents)
{
  constexpr std::size_t n = 9;
  std::vector<ce_tool::Point> points;
  for (std::size_t j = 0; j < n; ++j)
    for (std::size_t i = 0; i < n; ++i)
      points.emplace_back(double(i), double(j), 0.1 * double(i * j % 5));
  const auto at = [](std::size_t i, std::size_t j) { return j * n + i; };
  Polygons polygons;
  for (std::size_t j = 0; j + 1 < n; ++j) {
    for (std::size_t i = 0; i + 1 < n; ++i) {
      if ((i == 2 && j == 2) || (i == 5 && j == 4) || (i == 2 && j == 6))
        continue; // holes
      const std::size_t a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1), d = at(i, j + 1);
      switch ((i + 2 * j) % 3) {
        case 0:
          polygons.push_back({a, b, c, d});
          break;
        case 1:
          polygons.push_back({a, b, c});
          polygons.push_back({a, c, d});
          break;
        default:
          polygons.push_back({b, c, d});
          polygons.push_back({b, d, a});
          break;
      }
    }
  }
  // A pentagon and a triangle on one of its edges, beside the grid.
  const std::size_t first = points.size();
  for (int k = 0; k < 6; ++k)
    points.emplace_back(20.0 + std::cos(1.2566 * k), std::sin(1.2566 * k), 0.05 * k);
  polygons.push_back({first, first + 1, first + 2, first + 3, first + 4});
  polygons.push_back({first + 1, first, first + 5});

  expect_cgal_mesh(points, polygons);
  for (unsigned seed = 1; seed <= 5; ++seed)
    expect_cgal_mesh(points, shuffled(polygons, seed));
}

// Faces that the soup repair reorients (CGAL's orientation is taken where it is
// well defined): then CGAL's mesh of the reoriented soup.
TEST(ToolMesh, ReorientedFaces)
{
  const ce_test::Soup grid = ce_test::grid_graph_soup(ce_test::hamann_table1_functions()[2], 10);
  Polygons polygons = polygons_of(grid);
  for (std::size_t f : {std::size_t(0), std::size_t(37), std::size_t(90), polygons.size() - 1})
    std::reverse(polygons[f].begin(), polygons[f].end());
  expect_cgal_mesh(points_of(grid), polygons, true);
  const ce_test::Soup sphere = ce_test::sphere_soup(1.0, 2);
  Polygons closed = shuffled(polygons_of(sphere), 7);
  for (std::size_t f = 0; f < closed.size(); f += 9)
    std::reverse(closed[f].begin(), closed[f].end());
  expect_cgal_mesh(points_of(sphere), closed, true);
}

} // namespace
