// SPDX-License-Identifier: GPL-3.0-or-later
#include "soup_repair.h"

#include "tool_error.h"

#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>

#include <algorithm>
#include <cstdint>
#include <iostream>
#include <limits>
#include <numeric>
#include <optional>
#include <string>
#include <tuple>

namespace ce_tool {

namespace {

namespace PMP = CGAL::Polygon_mesh_processing;

using Polygons = std::vector<std::vector<std::size_t>>;

// The polygon's indices are distinct and at least three.
template <typename Polygon>
bool is_simple(const Polygon& polygon)
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

template <typename Polygon_range>
bool all_simple(const Polygon_range& polygons)
{
  for (std::size_t f = 0; f < polygons.size(); ++f)
    if (!is_simple(polygons[f]))
      return false;
  return true;
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

template <typename Polygon>
std::size_t position(const Polygon& polygon, std::size_t v)
{
  return std::size_t(std::find(polygon.begin(), polygon.end(), v) - polygon.begin());
}

// The index that follows (step 1) or precedes (step -1) `v` in the polygon.
template <typename Polygon>
std::size_t neighbor_in(const Polygon& polygon, std::size_t v, int step)
{
  const std::size_t n = polygon.size();
  return polygon[(position(polygon, v) + n + std::size_t(step)) % n];
}

// True if g is f, from another start (direction 1) or backwards (direction -1):
// one polygon twice, in the same or in opposite orientations (both hold v).
template <typename Polygon>
bool is_same_polygon(const Polygon& f, const Polygon& g, std::size_t v, int direction)
{
  const std::size_t n = f.size();
  if (g.size() != n)
    return false;
  const std::size_t i = position(f, v), j = position(g, v);
  for (std::size_t k = 1; k < n; ++k)
    if (f[(i + k * (n + std::size_t(direction))) % n] != g[(j + k) % n])
      return false;
  return true;
}

// The halfedges of simple polygons on `points` points, grouped by source vertex,
// each group sorted by target. 32-bit indices (half the memory, and the mesh's
// own indices are 32-bit).
class Halfedges_by_source
{
public:
  struct Halfedge
  {
    std::uint32_t target, face;
  };

  template <typename Polygon_range>
  Halfedges_by_source(std::size_t points, const Polygon_range& polygons)
      : start_(points + 1, 0)
  {
    if (points > std::numeric_limits<std::uint32_t>::max() ||
        polygons.size() > std::numeric_limits<std::uint32_t>::max())
      fail("the mesh has more vertices or faces than CGAL::Surface_mesh can index");
    for (std::size_t f = 0; f < polygons.size(); ++f)
      for (std::size_t index : polygons[f])
        ++start_[index + 1];
    std::partial_sum(start_.begin(), start_.end(), start_.begin());
    halfedges_.resize(start_.back());
    std::vector<std::size_t> next = start_; // where the next halfedge of each source goes
    for (std::size_t f = 0; f < polygons.size(); ++f) {
      const auto& polygon = polygons[f];
      for (std::size_t k = 0; k < polygon.size(); ++k)
        halfedges_[next[polygon[k]]++] = {std::uint32_t(polygon[(k + 1) % polygon.size()]), std::uint32_t(f)};
    }
    for (std::size_t v = 0; v < points; ++v)
      std::sort(halfedges_.begin() + std::ptrdiff_t(start_[v]), halfedges_.begin() + std::ptrdiff_t(start_[v + 1]),
                [](const Halfedge& a, const Halfedge& b) { return a.target < b.target; });
  }

  std::size_t points() const { return start_.size() - 1; }
  std::size_t size() const { return halfedges_.size(); }
  const Halfedge* begin(std::size_t v) const { return halfedges_.data() + start_[v]; }
  const Halfedge* end(std::size_t v) const { return halfedges_.data() + start_[v + 1]; }

  // The halfedges from `source` to `target`: by a linear scan where a vertex has
  // few (as most have), where it beats a binary search's mispredicted branches.
  std::pair<const Halfedge*, const Halfedge*> between(std::size_t source, std::size_t target) const
  {
    const Halfedge* first = begin(source);
    const Halfedge* const last = end(source);
    if (last - first > 16)
      return std::equal_range(first, last, Halfedge{std::uint32_t(target), 0},
                              [](const Halfedge& a, const Halfedge& b) { return a.target < b.target; });
    while (first != last && first->target < target)
      ++first;
    const Halfedge* past = first;
    while (past != last && past->target == target)
      ++past;
    return {first, past};
  }

  // The first halfedge from `source` to `target`, or null.
  const Halfedge* find(std::size_t source, std::size_t target) const
  {
    const auto [first, last] = between(source, target);
    return first != last ? first : nullptr;
  }

private:
  std::vector<std::size_t> start_;
  std::vector<Halfedge> halfedges_;
};

// What stands between simple polygons and a polygon mesh with a vertex per point.
struct Topology
{
  bool directed_edges_unique = true; // no edge twice in one orientation
  bool one_fan_per_vertex = true;    // (if the above) the polygons around each vertex are one fan
  bool isolated_points = false;      // a point in no polygon
  bool duplicate_polygons = false;   // a polygon twice, in either orientation

  bool polygon_mesh() const { return directed_edges_unique && one_fan_per_vertex; }
};

template <typename Polygon_range>
Topology topology(const Halfedges_by_source& halfedges, const Polygon_range& polygons)
{
  Topology t;
  for (std::size_t v = 0; v < halfedges.points(); ++v) {
    if (halfedges.begin(v) == halfedges.end(v)) {
      t.isolated_points = true;
      continue;
    }
    // Polygons on one edge are compared pairwise; more than a few are taken for
    // duplicates, which leaves the decision to CGAL's merge (a pairwise comparison
    // of thousands of polygons on one edge would take long).
    const std::ptrdiff_t few = 8;
    for (auto h = halfedges.begin(v); h != halfedges.end(v);) {
      const auto [same, same_last] = halfedges.between(v, h->target);
      const auto [opposite, opposite_last] = halfedges.between(h->target, v);
      t.directed_edges_unique &= same_last - same == 1;
      if (same_last - same > few || opposite_last - opposite > few) {
        t.duplicate_polygons = true;
      } else {
        for (auto f = same; f != same_last; ++f) {
          for (auto g = f + 1; g != same_last; ++g)
            t.duplicate_polygons |= is_same_polygon(polygons[f->face], polygons[g->face], v, 1);
          if (v < h->target)
            for (auto g = opposite; g != opposite_last; ++g)
              t.duplicate_polygons |= is_same_polygon(polygons[f->face], polygons[g->face], v, -1);
        }
      }
      h = same_last;
    }
    if (!t.directed_edges_unique)
      continue; // a fan is not well defined
    std::size_t fan_starts = 0;
    const Halfedges_by_source::Halfedge* start = halfedges.begin(v);
    for (auto h = halfedges.begin(v); h != halfedges.end(v); ++h) {
      if (!halfedges.find(v, neighbor_in(polygons[h->face], v, -1))) {
        ++fan_starts; // the polygon before h around v is missing: a fan starts at h
        start = h;
      }
    }
    // Around v from the fan's start: the polygon across h's edge, then v's halfedge in it.
    std::size_t visited = 1;
    for (const auto* h = start;; ++visited) {
      const auto* opposite = halfedges.find(h->target, v);
      if (!opposite)
        break;
      h = halfedges.find(v, neighbor_in(polygons[opposite->face], v, 1));
      if (h == start)
        break;
    }
    if (fan_starts > 1 || visited != std::size_t(halfedges.end(v) - halfedges.begin(v)))
      t.one_fan_per_vertex = false;
  }
  return t;
}

// Reverses the polygons that CGAL's orient_polygon_soup reverses where it is well
// defined: every edge in at most two polygons, and each connected component
// orientable; the component (across edges of two polygons) takes the orientation
// of its first polygon. Returns the polygons reversed, or false (and changes
// nothing) where it is not well defined.
bool orient_as_cgal(const Halfedges_by_source& halfedges, Polygons& polygons, std::vector<std::size_t>& reversed)
{
  std::vector<signed char> parity(polygons.size(), -1);
  std::vector<std::size_t> stack;
  for (std::size_t root = 0; root < polygons.size(); ++root) {
    if (parity[root] >= 0)
      continue;
    parity[root] = 0;
    stack.push_back(root);
    while (!stack.empty()) {
      const std::size_t f = stack.back();
      stack.pop_back();
      const std::vector<std::size_t>& polygon = polygons[f];
      for (std::size_t k = 0; k < polygon.size(); ++k) {
        const std::size_t u = polygon[k], v = polygon[(k + 1) % polygon.size()];
        const auto [same_first, same_last] = halfedges.between(u, v);
        const auto [opposite_first, opposite_last] = halfedges.between(v, u);
        const std::size_t same = std::size_t(same_last - same_first);
        const std::size_t opposite = std::size_t(opposite_last - opposite_first);
        if (same + opposite > 2)
          return false; // a non-manifold edge
        if (same + opposite == 1)
          continue; // a boundary edge
        const std::size_t g =
          same == 2 ? (same_first->face == f ? same_first[1].face : same_first->face) : opposite_first->face;
        const auto p = static_cast<signed char>(parity[f] ^ (same == 2));
        if (parity[g] < 0) {
          parity[g] = p;
          stack.push_back(g);
        } else if (parity[g] != p) {
          return false; // a non-orientable component
        }
      }
    }
  }
  reversed.clear();
  for (std::size_t f = 0; f < polygons.size(); ++f)
    if (parity[f] == 1) {
      std::reverse(polygons[f].begin(), polygons[f].end());
      reversed.push_back(f);
    }
  return true;
}

// The mesh of a soup that is a polygon mesh (as topology() finds it), with the
// connectivity that CGAL's polygon_soup_to_polygon_mesh gives it (a vertex per
// point in order, then the faces in order by Euler::add_face), set directly:
// add_face searches and relinks halfedges face by face, about 190 ns a triangle
// on a 1M-vertex grid. What add_face leaves, for such a soup:
// - an edge per pair of opposite halfedges, numbered in the order in which the
//   faces first meet it; its first halfedge is the one that face has;
// - halfedge(f): the halfedge of f into its first vertex;
// - halfedge(v): the border halfedge into v if v is on a border, else the halfedge
//   into v of the last face around v (add_face points v at its border halfedge
//   into v after each face around v; the last face makes that halfedge inner).
// Mesh index = soup index. The halfedges are looked up once, per corner of the
// polygons (corner c: the halfedge from its vertex to the next of its polygon),
// and `halfedges` (those of `polygons`) is freed before the mesh takes its memory.
template <typename Polygon_range>
Mesh polygon_mesh(const std::vector<Point>& points, const Polygon_range& polygons,
                  std::optional<Halfedges_by_source>& halfedges)
{
  using H = Mesh::Halfedge_index;
  // 32-bit corner numbers, as the mesh's halfedge indices are.
  using Corner = Mesh::size_type;
  const Corner none = std::numeric_limits<Corner>::max();
  std::vector<Corner> first_corner(polygons.size() + 1, 0);
  for (std::size_t f = 0; f < polygons.size(); ++f) {
    if (polygons[f].size() >= std::size_t(none / 2 - first_corner[f]))
      fail("the mesh has more halfedges than CGAL::Surface_mesh can index");
    first_corner[f + 1] = first_corner[f] + Corner(polygons[f].size());
  }
  // The opposite corner of each corner, or `none` on a border; then (below) the
  // corner's mesh halfedge in its place. An edge is new where its first corner is.
  std::vector<Corner> corner(first_corner.back());
  Corner edges = 0;
  for (std::size_t f = 0; f < polygons.size(); ++f) {
    const auto& polygon = polygons[f];
    for (std::size_t k = 0; k < polygon.size(); ++k) {
      const std::size_t u = polygon[k], w = polygon[(k + 1) % polygon.size()];
      const Corner c = first_corner[f] + Corner(k);
      const Halfedges_by_source::Halfedge* opposite = halfedges->find(w, u);
      corner[c] = opposite ? first_corner[opposite->face] + Corner(position(polygons[opposite->face], w)) : none;
      edges += corner[c] == none || corner[c] > c;
    }
  }
  halfedges.reset();

  // Every element at once (add_edge and add_face grow every property array by one).
  Mesh mesh;
  mesh.resize(Mesh::size_type(points.size()), edges, Mesh::size_type(polygons.size()));
  for (std::size_t v = 0; v < points.size(); ++v)
    mesh.point(V(Mesh::size_type(v))) = points[v];
  std::vector<H> border_out(points.size()), border_in(points.size());
  Corner next_edge = 0;
  for (std::size_t f = 0; f < polygons.size(); ++f) {
    const auto& polygon = polygons[f];
    const Mesh::Face_index face{Mesh::size_type(f)};
    for (std::size_t k = 0; k < polygon.size(); ++k) {
      const Corner c = first_corner[f] + Corner(k), opposite = corner[c];
      const V u{Mesh::size_type(polygon[k])}, w{Mesh::size_type(polygon[(k + 1) % polygon.size()])};
      H h;
      if (opposite != none && opposite < c) {
        h = mesh.opposite(H(corner[opposite]));
      } else {
        h = H(2 * next_edge++);
        mesh.set_target(h, w);
        mesh.set_target(mesh.opposite(h), u);
        if (opposite == none)
          border_out[std::size_t(w)] = border_in[std::size_t(u)] = mesh.opposite(h);
      }
      corner[c] = Corner(h);
      mesh.set_face(h, face);
      mesh.set_halfedge(w, h);
    }
    for (std::size_t k = 0; k < polygon.size(); ++k)
      mesh.set_next(H(corner[first_corner[f] + k]), H(corner[first_corner[f] + (k + 1) % polygon.size()]));
    mesh.set_halfedge(face, H(corner[first_corner[f + 1] - 1]));
  }
  for (std::size_t v = 0; v < points.size(); ++v) {
    const H border = border_in[v];
    if (border != H()) {
      mesh.set_next(border, border_out[std::size_t(mesh.target(border))]);
      mesh.set_halfedge(V(Mesh::size_type(v)), border);
    }
  }
  return mesh;
}

// CGAL's repair_polygon_soup and orient_polygon_soup, step by step as
// repair_polygon_soup takes them (CGAL 5.5), each skipped where the soup shows it
// would change nothing, with file_to_mesh kept by index through the steps that
// renumber the points; one note on `notes_out` of what changed.
Mesh repaired_mesh(const Soup& soup, std::vector<V>& file_to_mesh, std::ostream& notes_out)
{
  const std::size_t file_points = soup.points.size();
  // Duplicate points merged: numbered by their first occurrence, as CGAL numbers them.
  std::size_t distinct = 0;
  std::vector<std::size_t> merged_index(file_points);
  std::vector<Point> points;
  {
    const std::vector<std::size_t> first = first_at_same_place(soup.points, distinct);
    points.reserve(distinct);
    for (std::size_t i = 0; i < file_points; ++i) {
      if (first[i] == i) {
        merged_index[i] = points.size();
        points.push_back(soup.points[i]);
      } else {
        merged_index[i] = merged_index[first[i]];
      }
    }
  }
  Polygons polygons(soup.faces.size());
  for (std::size_t f = 0; f < polygons.size(); ++f) {
    polygons[f].reserve(soup.faces[f].size());
    for (std::size_t index : soup.faces[f])
      polygons[f].push_back(merged_index[index]);
  }

  if (!all_simple(polygons)) {
    // CGAL-internal: repair_polygon_soup would merge points and polygons again (1M-vertex grid: 1.9x the tool's time).
    Silence_cerr silence;
    PMP::internal::simplify_polygons_in_polygon_soup<Kernel>(points, polygons);
    PMP::internal::split_pinched_polygons_in_polygon_soup<Kernel>(points, polygons);
    PMP::internal::remove_invalid_polygons_in_polygon_soup(points, polygons);
  }
  // Isolated points removed from the merged points' indices: kept[r] is the merged
  // index of the point the repaired soup has at r. Before the duplicate polygons are
  // merged, unlike in repair_polygon_soup: merging them leaves no point isolated, and
  // renumbering the points changes no polygon's duplicates, so the order is the same.
  {
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

  // The halfedges and topology of the polygons as they are (the old ones freed first).
  std::optional<Halfedges_by_source> halfedges;
  Topology t;
  const auto analyse = [&] {
    halfedges.reset();
    halfedges.emplace(points.size(), polygons);
    t = topology(*halfedges, polygons);
  };
  analyse();
  if (t.duplicate_polygons) {
    {
      Silence_cerr silence;
      PMP::merge_duplicate_polygons_in_polygon_soup(points, polygons);
    }
    analyse();
  }

  std::vector<std::string> notes;
  const std::size_t distinct_used = points.size();
  const std::size_t faces_kept = polygons.size();
  if (distinct < file_points)
    notes.push_back("merged " + std::to_string(file_points - distinct) + " duplicate points");
  if (faces_kept < soup.faces.size())
    notes.push_back("dropped " + std::to_string(soup.faces.size() - faces_kept) + " degenerate or duplicate faces");

  std::size_t reoriented = 0;
  bool oriented = true;
  if (!t.polygon_mesh()) {
    std::vector<std::size_t> reversed;
    if (orient_as_cgal(*halfedges, polygons, reversed)) {
      analyse();
      if (!t.polygon_mesh()) // CGAL would split vertices too: undone, and left to CGAL
        for (std::size_t f : reversed)
          std::reverse(polygons[f].begin(), polygons[f].end());
      reoriented = reversed.size();
    }
    if (!t.polygon_mesh()) {
      halfedges.reset();
      const Polygons before_orientation = polygons;
      {
        Silence_cerr silence;
        oriented = PMP::orient_polygon_soup(points, polygons);
      }
      reoriented = 0;
      for (std::size_t f = 0; f < polygons.size() && f < before_orientation.size(); ++f)
        reoriented += polygons[f] != before_orientation[f];
      analyse();
    }
  }
  if (reoriented > 0)
    notes.push_back("re-oriented " + std::to_string(reoriented) + " faces");
  if (points.size() > distinct_used)
    notes.push_back("duplicated " + std::to_string(points.size() - distinct_used) + " non-manifold vertices");
  if (!oriented && points.size() == distinct_used)
    notes.push_back("could not orient every face consistently");

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
  merged_index = std::vector<std::size_t>();

  Mesh mesh;
  if (!polygons.empty()) {
    if (!t.polygon_mesh())
      fail("the faces cannot be made into a polygon mesh, even after repair");
    // Flat, as the file's soup is, before the mesh is built: a vector per
    // polygon takes twice the memory (peak on a 1M-vertex OFF with a flipped face:
    // 410 bytes per vertex, 362 so).
    Flat_polygons flat;
    flat.append(polygons);
    polygons = Polygons();
    mesh = polygon_mesh(points, flat, halfedges);
  }

  if (!notes.empty()) {
    std::string line = "curvature: note: repaired the input:";
    for (std::size_t i = 0; i < notes.size(); ++i)
      line += (i ? ", " : " ") + notes[i];
    notes_out << line << '\n';
  }
  if (unused > 0)
    notes_out << "curvature: note: " << unused << " of the file's vertices are in no face; their rows are 'failed'\n";
  return mesh;
}

} // namespace

Mesh build_mesh(const Soup& soup, std::vector<V>& file_to_mesh, std::ostream& notes)
{
  // The direct path: a soup that CGAL's repair and orientation would not change.
  std::size_t distinct = 0;
  if (all_simple(soup.faces)) {
    first_at_same_place(soup.points, distinct);
    if (distinct == soup.points.size()) {
      std::optional<Halfedges_by_source> halfedges(std::in_place, soup.points.size(), soup.faces);
      const Topology t = topology(*halfedges, soup.faces);
      if (t.polygon_mesh() && !t.isolated_points && !t.duplicate_polygons) {
        file_to_mesh.resize(soup.points.size());
        for (std::size_t i = 0; i < file_to_mesh.size(); ++i)
          file_to_mesh[i] = V(Mesh::size_type(i));
        return polygon_mesh(soup.points, soup.faces, halfedges);
      }
    }
  }
  return repaired_mesh(soup, file_to_mesh, notes);
}

} // namespace ce_tool
