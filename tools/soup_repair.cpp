// SPDX-License-Identifier: GPL-3.0-or-later
#include "soup_repair.h"

#include "tool_error.h"

#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>

#include <algorithm>
#include <iostream>
#include <numeric>
#include <string>
#include <tuple>

namespace ce_tool {

namespace {

namespace PMP = CGAL::Polygon_mesh_processing;

// The polygon's indices are distinct and at least three.
bool is_simple(Flat_polygons::Polygon polygon)
{
  if (polygon.size() < 3)
    return false;
  if (polygon.size() <= 8) {
    for (std::size_t i = 0; i < polygon.size(); ++i)
      for (std::size_t j = i + 1; j < polygon.size(); ++j)
        if (polygon[i] == polygon[j])
          return false;
    return true;
  }
  std::vector<std::size_t> sorted(polygon.size());
  std::copy(polygon.begin(), polygon.end(), sorted.begin());
  std::sort(sorted.begin(), sorted.end());
  return std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end();
}

// For each point, the index of the first point of the file at the same place, by
// a sort of the indices (x, then y, then z, as CGAL's Less_xyz_3: -0 and 0 are one
// place); `distinct` is the number of different places.
std::vector<std::size_t> first_at_same_place(const std::vector<Point>& points, std::size_t& distinct)
{
  std::vector<std::size_t> order(points.size());
  std::iota(order.begin(), order.end(), std::size_t(0));
  const auto less = [&](std::size_t a, std::size_t b) {
    const Point& p = points[a];
    const Point& q = points[b];
    return std::make_tuple(p.x(), p.y(), p.z()) < std::make_tuple(q.x(), q.y(), q.z());
  };
  std::stable_sort(order.begin(), order.end(), less);
  std::vector<std::size_t> first(points.size());
  distinct = 0;
  for (std::size_t k = 0; k < order.size(); ++k) {
    const bool new_place = k == 0 || less(order[k - 1], order[k]);
    first[order[k]] = new_place ? order[k] : first[order[k - 1]];
    distinct += new_place;
  }
  return first;
}

// The halfedges of a soup grouped by source vertex, each group sorted by target.
class Halfedges_by_source
{
public:
  struct Halfedge
  {
    std::size_t target, face;
  };

  explicit Halfedges_by_source(const Soup& soup) : start_(soup.points.size() + 1, 0)
  {
    const Flat_polygons& faces = soup.faces;
    for (std::size_t f = 0; f < faces.size(); ++f)
      for (std::size_t index : faces[f])
        ++start_[index + 1];
    std::partial_sum(start_.begin(), start_.end(), start_.begin());
    halfedges_.resize(start_.back());
    std::vector<std::size_t> next = start_;  // where the next halfedge of each source goes
    for (std::size_t f = 0; f < faces.size(); ++f) {
      const Flat_polygons::Polygon polygon = faces[f];
      for (std::size_t k = 0; k < polygon.size(); ++k)
        halfedges_[next[polygon[k]]++] = {polygon[(k + 1) % polygon.size()], f};
    }
    for (std::size_t v = 0; v + 1 < start_.size(); ++v)
      std::sort(begin(v), end(v), [](const Halfedge& a, const Halfedge& b) { return a.target < b.target; });
  }

  const Halfedge* begin(std::size_t v) const { return halfedges_.data() + start_[v]; }
  const Halfedge* end(std::size_t v) const { return halfedges_.data() + start_[v + 1]; }
  Halfedge* begin(std::size_t v) { return halfedges_.data() + start_[v]; }
  Halfedge* end(std::size_t v) { return halfedges_.data() + start_[v + 1]; }
  std::size_t size() const { return halfedges_.size(); }

  // The first halfedge from `source` to `target`, or null.
  const Halfedge* find(std::size_t source, std::size_t target) const
  {
    const Halfedge* h = std::lower_bound(begin(source), end(source), target,
                                         [](const Halfedge& a, std::size_t t) { return a.target < t; });
    return h != end(source) && h->target == target ? h : nullptr;
  }

private:
  std::vector<std::size_t> start_;
  std::vector<Halfedge> halfedges_;
};

std::size_t position(Flat_polygons::Polygon polygon, std::size_t v)
{
  return std::size_t(std::find(polygon.begin(), polygon.end(), v) - polygon.begin());
}

// The index that follows (step 1) or precedes (step -1) `v` in the polygon.
std::size_t neighbour_in(Flat_polygons::Polygon polygon, std::size_t v, int step)
{
  const std::size_t n = polygon.size();
  return polygon[(position(polygon, v) + n + std::size_t(step)) % n];
}

// True if g is f backwards: one polygon in two orientations (both hold v).
bool is_reversed(Flat_polygons::Polygon f, Flat_polygons::Polygon g, std::size_t v)
{
  const std::size_t n = f.size();
  if (g.size() != n)
    return false;
  const std::size_t i = position(f, v), j = position(g, v);
  for (std::size_t k = 1; k < n; ++k)
    if (f[(i + n - k) % n] != g[(j + k) % n])
      return false;
  return true;
}

// True if CGAL's soup repair and orientation would change nothing in the soup:
// no two points at one place, polygons of three or more distinct indices, every
// point in a polygon, no polygon twice, every edge in one polygon or in two of
// opposite orientations, and the polygons around each vertex one fan. `edges` is
// then the mesh's number of edges.
bool is_a_polygon_mesh_as_it_is(const Soup& soup, std::size_t& edges)
{
  const Flat_polygons& faces = soup.faces;
  for (std::size_t f = 0; f < faces.size(); ++f)
    if (!is_simple(faces[f]))
      return false;
  std::size_t distinct = 0;
  first_at_same_place(soup.points, distinct);
  if (distinct != soup.points.size())
    return false;

  const Halfedges_by_source halfedges(soup);
  std::size_t boundary = 0;
  for (std::size_t v = 0; v < soup.points.size(); ++v) {
    if (halfedges.begin(v) == halfedges.end(v))
      return false;  // an isolated point
    std::size_t fan_starts = 0;
    const Halfedges_by_source::Halfedge* start = halfedges.begin(v);
    for (auto h = halfedges.begin(v); h != halfedges.end(v); ++h) {
      if (h + 1 != halfedges.end(v) && h[1].target == h->target)
        return false;  // an edge twice in one orientation
      const auto* opposite = halfedges.find(h->target, v);
      if (!opposite) {
        ++boundary;
      } else if (v < h->target && is_reversed(faces[h->face], faces[opposite->face], v)) {
        return false;  // a polygon twice, in opposite orientations
      }
      if (!halfedges.find(v, neighbour_in(faces[h->face], v, -1))) {
        ++fan_starts;  // the polygon before h around v is missing: a fan starts at h
        start = h;
      }
    }
    if (fan_starts > 1)
      return false;
    // Around v from the fan's start: the polygon across h's edge, then v's halfedge in it.
    std::size_t visited = 1;
    for (const auto* h = start;; ++visited) {
      const auto* opposite = halfedges.find(h->target, v);
      if (!opposite)
        break;
      h = halfedges.find(v, neighbour_in(faces[opposite->face], v, 1));
      if (h == start)
        break;
    }
    if (visited != std::size_t(halfedges.end(v) - halfedges.begin(v)))
      return false;  // several fans
  }
  edges = (halfedges.size() + boundary) / 2;
  return true;
}

// The mesh of a soup that is a polygon mesh, as CGAL's polygon_soup_to_polygon_mesh
// makes it (a vertex per point in order, then the faces in order by Euler::add_face):
// mesh index = soup index.
template <typename Polygons>
Mesh polygon_mesh(const std::vector<Point>& points, const Polygons& polygons, std::size_t edges)
{
  Mesh mesh;
  mesh.reserve(Mesh::size_type(points.size()), Mesh::size_type(edges), Mesh::size_type(polygons.size()));
  for (const Point& p : points)
    mesh.add_vertex(p);
  std::vector<V> face;
  for (std::size_t f = 0; f < polygons.size(); ++f) {
    face.clear();
    for (std::size_t index : polygons[f])
      face.push_back(V(Mesh::size_type(index)));
    CGAL::Euler::add_face(face, mesh);
  }
  return mesh;
}

// CGAL's repair_polygon_soup and orient_polygon_soup, step by step as
// repair_polygon_soup takes them (CGAL 5.5), with file_to_mesh kept by index
// through the steps that renumber the points; one note on stderr of what changed.
Mesh repaired_mesh(const Soup& soup, std::vector<V>& file_to_mesh)
{
  const std::size_t file_points = soup.points.size();
  // Duplicate points merged: numbered by their first occurrence, as CGAL numbers them.
  std::size_t distinct = 0;
  const std::vector<std::size_t> first = first_at_same_place(soup.points, distinct);
  std::vector<std::size_t> merged_index(file_points);
  std::vector<Point> points;
  points.reserve(distinct);
  for (std::size_t i = 0; i < file_points; ++i) {
    if (first[i] == i) {
      merged_index[i] = points.size();
      points.push_back(soup.points[i]);
    } else {
      merged_index[i] = merged_index[first[i]];
    }
  }
  std::vector<std::vector<std::size_t>> polygons(soup.faces.size());
  for (std::size_t f = 0; f < polygons.size(); ++f)
    for (std::size_t index : soup.faces[f])
      polygons[f].push_back(merged_index[index]);

  {
    Silence_cerr silence;
    PMP::internal::simplify_polygons_in_polygon_soup<Kernel>(points, polygons);
    PMP::internal::split_pinched_polygons_in_polygon_soup<Kernel>(points, polygons);
    PMP::internal::remove_invalid_polygons_in_polygon_soup(points, polygons);
    PMP::merge_duplicate_polygons_in_polygon_soup(points, polygons);
    // Isolated points removed from the merged points' indices: kept[r] is the merged
    // index of the point the repaired soup has at r.
    std::vector<std::size_t> kept(points.size());
    std::iota(kept.begin(), kept.end(), std::size_t(0));
    PMP::remove_isolated_points_in_polygon_soup(kept, polygons);
    std::vector<std::size_t> repaired_index(points.size(), file_points);
    std::vector<Point> used;
    used.reserve(kept.size());
    for (std::size_t r = 0; r < kept.size(); ++r) {
      repaired_index[kept[r]] = r;
      used.push_back(points[kept[r]]);
    }
    points.swap(used);
    for (std::size_t& index : merged_index)
      index = repaired_index[index];
  }
  std::vector<std::string> notes;
  const std::size_t distinct_used = points.size();
  const std::size_t faces_kept = polygons.size();
  if (distinct < file_points)
    notes.push_back("merged " + std::to_string(file_points - distinct) + " duplicate points");
  if (faces_kept < soup.faces.size())
    notes.push_back("dropped " + std::to_string(soup.faces.size() - faces_kept) +
                    " degenerate or duplicate faces");

  const std::vector<std::vector<std::size_t>> before_orientation = polygons;
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
    std::size_t halfedges = 0;
    for (const auto& polygon : polygons)
      halfedges += polygon.size();
    mesh = polygon_mesh(points, polygons, halfedges);
  }

  // A file's vertex is the mesh's vertex of its repaired index (the first copy of a
  // vertex that the orientation split), or none if its point is in no kept face.
  file_to_mesh.assign(file_points, V());
  std::size_t unused = 0;
  for (std::size_t i = 0; i < file_points; ++i) {
    if (merged_index[i] < distinct_used)
      file_to_mesh[i] = V(Mesh::size_type(merged_index[i]));
    else
      ++unused;
  }
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

} // namespace

Mesh build_mesh(const Soup& soup, std::vector<V>& file_to_mesh)
{
  std::size_t edges = 0;
  if (!is_a_polygon_mesh_as_it_is(soup, edges))
    return repaired_mesh(soup, file_to_mesh);
  file_to_mesh.resize(soup.points.size());
  for (std::size_t i = 0; i < file_to_mesh.size(); ++i)
    file_to_mesh[i] = V(Mesh::size_type(i));
  return polygon_mesh(soup.points, soup.faces, edges);
}

} // namespace ce_tool
