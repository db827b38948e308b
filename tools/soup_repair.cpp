// SPDX-License-Identifier: GPL-3.0-or-later
#include "soup_repair.h"

#include "tool_error.h"

#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>

#include <iostream>
#include <map>
#include <string>
#include <tuple>

namespace ce_tool {

namespace {

namespace PMP = CGAL::Polygon_mesh_processing;

struct Point_less
{
  bool operator()(const Point& a, const Point& b) const
  {
    return std::make_tuple(a.x(), a.y(), a.z()) < std::make_tuple(b.x(), b.y(), b.z());
  }
};

} // namespace

Mesh build_mesh(const Soup& soup, std::vector<V>& file_to_mesh)
{
  std::vector<Point> points = soup.points;
  std::vector<Polygon> polygons = soup.polygons;
  {
    Silence_cerr silence;
    PMP::repair_polygon_soup(points, polygons);
  }
  std::vector<std::string> notes;
  const std::size_t distinct_used = points.size();
  const std::size_t faces_kept = polygons.size();
  if (faces_kept < soup.polygons.size())
    notes.push_back("dropped " + std::to_string(soup.polygons.size() - faces_kept) +
                    " degenerate or duplicate faces");

  const std::vector<Polygon> before_orientation = polygons;
  bool oriented = true;
  {
    Silence_cerr silence;
    oriented = PMP::orient_polygon_soup(points, polygons);
  }
  std::size_t reoriented = 0;
  for (std::size_t f = 0; f < polygons.size() && f < before_orientation.size(); ++f)
    reoriented += polygons[f] != before_orientation[f];
  if (reoriented > 0)
    notes.push_back("re-oriented " + std::to_string(reoriented) + " faces");
  if (points.size() > distinct_used)
    notes.push_back("duplicated " + std::to_string(points.size() - distinct_used) + " non-manifold vertices");
  if (!oriented && points.size() == distinct_used)
    notes.push_back("could not orient every face consistently");

  Mesh mesh;
  if (!polygons.empty()) {
    if (!PMP::is_polygon_soup_a_polygon_mesh(polygons))
      fail("the faces cannot be made into a polygon mesh, even after repair");
    PMP::polygon_soup_to_polygon_mesh(points, polygons, mesh);
  }

  std::map<Point, V, Point_less> by_point;
  for (V v : vertices(mesh))
    by_point.emplace(mesh.point(v), v);  // the first copy of a split vertex wins
  file_to_mesh.assign(soup.points.size(), V());
  std::size_t merged = 0, unused = 0;
  std::map<Point, std::size_t, Point_less> first_file_index;
  for (std::size_t i = 0; i < soup.points.size(); ++i) {
    if (!first_file_index.emplace(soup.points[i], i).second)
      ++merged;
    auto it = by_point.find(soup.points[i]);
    if (it != by_point.end())
      file_to_mesh[i] = it->second;
    else
      ++unused;
  }
  if (merged > 0)
    notes.insert(notes.begin(), "merged " + std::to_string(merged) + " duplicate points");
  if (!notes.empty()) {
    std::string line = "curvature: note: repaired the input:";
    for (std::size_t i = 0; i < notes.size(); ++i)
      line += (i ? ", " : " ") + notes[i];
    std::cerr << line << '\n';
  }
  if (unused > 0)
    std::cerr << "curvature: note: " << unused << " of the file's vertices are in no face; their rows are 'failed'\n";
  return mesh;
}

} // namespace ce_tool
