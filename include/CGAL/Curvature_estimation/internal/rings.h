// SPDX-License-Identifier: GPL-3.0-or-later
// The rings of a vertex of a FaceGraph or of a tetrahedral complex, grown one at
// a time so that a fit can widen without gathering again, and the ball about it
// (ball.h) grown over the same connectivity.
#ifndef CGAL_CURVATURE_ESTIMATION_INTERNAL_RINGS_H
#define CGAL_CURVATURE_ESTIMATION_INTERNAL_RINGS_H

#include <CGAL/Curvature_estimation/internal/ball.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Curvature_estimation {
namespace internal {

// Calls visit(neighbors[k]) for offsets[i] <= k < offsets[i + 1]: the neighbors
// of vertex i in compressed rows, the layout of Vertex_adjacency and of
// Tetrahedral_complex_stars.
template <typename Offsets, typename Neighbors, typename Visit>
void for_each_listed_neighbor(const Offsets& offsets, const Neighbors& neighbors, std::size_t i, const Visit& visit)
{
  for (auto k = offsets[i]; k < offsets[i + 1]; ++k)
    visit(neighbors[k]);
}

// The neighbors of every vertex of a FaceGraph with index descriptors (Surface_mesh), in
// halfedge order, as 32-bit indices in compressed rows: cheaper than circulating halfedges.
struct Vertex_adjacency
{
  std::vector<std::uint32_t> offsets; // per vertex index, and one more
  std::vector<std::uint32_t> neighbors;
};

// The adjacency of `g`, or null where its vertex descriptors are not indices that fit in 32
// bits, listed in ascending order by vertices(g) (as in Surface_mesh).
template <typename FaceGraph>
std::shared_ptr<const Vertex_adjacency> vertex_adjacency(const FaceGraph& g)
{
  using vertex_descriptor = typename boost::graph_traits<FaceGraph>::vertex_descriptor;
  using halfedge_descriptor = typename boost::graph_traits<FaceGraph>::halfedge_descriptor;
  if constexpr (!std::is_convertible<vertex_descriptor, std::size_t>::value) {
    (void)g;
    return nullptr;
  } else {
    constexpr std::size_t limit = (std::numeric_limits<std::uint32_t>::max)();
    std::size_t end = 0;
    for (vertex_descriptor v : vertices(g)) {
      const std::size_t i = static_cast<std::size_t>(v);
      if (i < end)
        return nullptr;
      end = i + 1;
    }
    if (end >= limit || num_halfedges(g) > limit)
      return nullptr;
    auto adjacency = std::make_shared<Vertex_adjacency>();
    std::vector<std::uint32_t>& offsets = adjacency->offsets;
    std::vector<std::uint32_t>& neighbors = adjacency->neighbors;
    offsets.assign(end + 1, 0);
    neighbors.reserve(num_halfedges(g));
    std::size_t next = 0; // the first index whose offset is not set; those without a vertex get no neighbors
    for (vertex_descriptor v : vertices(g)) {
      const std::size_t i = static_cast<std::size_t>(v);
      for (; next <= i; ++next)
        offsets[next] = static_cast<std::uint32_t>(neighbors.size());
      const halfedge_descriptor h = halfedge(v, g);
      if (h != boost::graph_traits<FaceGraph>::null_halfedge())
        for (halfedge_descriptor incoming : halfedges_around_target(h, g))
          neighbors.push_back(static_cast<std::uint32_t>(static_cast<std::size_t>(source(incoming, g))));
    }
    offsets[end] = static_cast<std::uint32_t>(neighbors.size());
    return adjacency;
  }
}

// The buffers are reused from vertex to vertex: no allocation once they have
// reached the size of the largest neighborhood met.
template <typename FaceGraph>
class Ring_collector
{
public:
  using vertex_descriptor = typename boost::graph_traits<FaceGraph>::vertex_descriptor;
  using halfedge_descriptor = typename boost::graph_traits<FaceGraph>::halfedge_descriptor;

  // The rings beyond the first (and the balls) from `adjacency` (vertex_adjacency of the graph
  // passed below, shared by the copies); null: by halfedge circulation.
  void use_adjacency(std::shared_ptr<const Vertex_adjacency> adjacency) { adjacency_ = std::move(adjacency); }

  // Restarts at `center` with its 1-ring.
  void start(vertex_descriptor center, const FaceGraph& g)
  {
    if (vertices_.empty() || vertices_[0] != center)
      widest_squared_ball_ = 0;
    vertices_.clear();
    ring_ends_.clear();
    stamped_ = false;
    ball_.clear();
    vertices_.push_back(center);
    ring_ends_.push_back(1);
    center_on_border_ = false;
    has_face_.clear();
    faces_are_triangles_ = true;
    std::size_t incoming_count = 0;
    const halfedge_descriptor h = halfedge(center, g);
    if (h != boost::graph_traits<FaceGraph>::null_halfedge())
      for (halfedge_descriptor incoming : halfedges_around_target(h, g)) {
        add_if_new(source(incoming, g));
        const bool face = !is_border(incoming, g);
        has_face_.push_back(face);
        faces_are_triangles_ = faces_are_triangles_ && (!face || next(next(next(incoming, g), g), g) == incoming);
        center_on_border_ = center_on_border_ || !face || is_border(opposite(incoming, g), g);
        ++incoming_count;
      }
    ring_ends_.push_back(vertices_.size());
    one_ring_in_fan_order_ = incoming_count + 1 == vertices_.size();
  }

  // Whether the 1-ring is in the order of the incoming halfedges h_k around the
  // center, one vertex each (not so at a non-manifold vertex). Then the face of
  // h_k, where it exists, has the corner (source(h_k), center, source(h_{k+1})).
  bool one_ring_in_fan_order() const { return one_ring_in_fan_order_; }
  bool has_face(std::size_t k) const { return has_face_[k] != 0; }
  // Whether every face around the center is a triangle: then the corner normals
  // at the center are the faces' area-weighted normals.
  bool faces_are_triangles() const { return faces_are_triangles_; }

  // Whether the center has an incident border edge (found while gathering the 1-ring).
  bool center_on_border() const { return center_on_border_; }

  // Adds the next ring; returns false when it is empty (the component is exhausted).
  bool extend(const FaceGraph& g)
  {
    const std::size_t first = ring_ends_[ring_ends_.size() - 2];
    const std::size_t last = ring_ends_.back();
    // A neighbor of the last ring is on the ring before it, on it, or new.
    const std::size_t before = ring_ends_.size() >= 3 ? ring_ends_[ring_ends_.size() - 3] : 0;
    if constexpr (indexed)
      if (!stamped_)
        stamp_gathered();
    for (std::size_t i = first; i < last; ++i)
      for_each_neighbor(vertices_[i], g, [&](vertex_descriptor w) { add_if_new(w, before); });
    ring_ends_.push_back(vertices_.size());
    return ring_ends_.back() > last;
  }

  // After start(), instead of extend(): adds, as one ring after the 1-ring, the
  // vertices of the ball of squared radius `squared_radius` about the center (see
  // Ball::grow, which returns the result), by halfedge circulation.
  template <typename SquaredDistance>
  bool grow_ball(const FaceGraph& g, double squared_radius, const SquaredDistance& squared_distance)
  {
    if (!ball_.active()) {
      if constexpr (indexed)
        if (!stamped_)
          stamp_gathered();
      ring_ends_.push_back(vertices_.size());
    }
    const auto neighbors = [&](vertex_descriptor v, const auto& visit) { for_each_neighbor(v, g, visit); };
    const bool more = ball_.grow(
      vertices_, ring_ends_[1], squared_radius, neighbors, [&](vertex_descriptor w) { return reach(w); },
      squared_distance);
    ring_ends_.back() = vertices_.size();
    widest_squared_ball_ = (std::max)(widest_squared_ball_, squared_radius);
    return more;
  }

  // The squared radius of the widest ball grown about `center` since it became the
  // center, in grow_ball's units; 0 for another center or where none was grown.
  double widest_squared_ball(vertex_descriptor center) const
  {
    return !vertices_.empty() && vertices_[0] == center ? widest_squared_ball_ : 0;
  }

  // After grow_ball: whether vertices()[i] is in the ball, their number, and the
  // place in vertices() of the k-th to join it.
  bool inside_ball(std::size_t i) const { return ball_.inside(i); }
  std::size_t ball_size() const { return ball_.size(); }
  std::size_t ball_joined(std::size_t k) const { return ball_.joined(k); }

  // Number of rings gathered (1 after start()).
  int rings() const { return static_cast<int>(ring_ends_.size()) - 1; }

  // The center is vertices()[0]; ring r (r >= 1) is [ring_end(r - 1), ring_end(r)).
  const std::vector<vertex_descriptor>& vertices() const { return vertices_; }
  std::size_t ring_end(int r) const { return ring_ends_[r]; }

private:
  template <typename Visit>
  void for_each_neighbor(vertex_descriptor v, const FaceGraph& g, const Visit& visit) const
  {
    if constexpr (indexed)
      if (adjacency_) {
        for_each_listed_neighbor(adjacency_->offsets, adjacency_->neighbors, static_cast<std::size_t>(v),
                                 [&](std::uint32_t w) { visit(vertex_descriptor(w)); });
        return;
      }
    const halfedge_descriptor h = halfedge(v, g);
    if (h != boost::graph_traits<FaceGraph>::null_halfedge())
      for (halfedge_descriptor incoming : halfedges_around_target(h, g))
        visit(source(incoming, g));
  }

  // Where a vertex descriptor is an index, the rings beyond the first find the
  // vertices gathered since the last start by their stamp in stamps_ (kept from
  // vertex to vertex). Elsewhere, and on the 1-ring (whose stamps would cost more
  // memory traffic than the search), a linear search of vertices_ from `from` on
  // (the 1-ring of a non-manifold vertex may repeat a neighbor).
  void add_if_new(vertex_descriptor w, std::size_t from = 0)
  {
    if constexpr (indexed)
      if (stamped_) {
        if (stamp(w))
          vertices_.push_back(w);
        return;
      }
    const vertex_descriptor* const end = vertices_.data() + vertices_.size();
    for (const vertex_descriptor* it = vertices_.data() + from; it != end; ++it)
      if (*it == w)
        return;
    vertices_.push_back(w);
  }

  // Marks w as reached by the ball; false where it was already (gathered, or
  // met outside the ball).
  bool reach(vertex_descriptor w)
  {
    if constexpr (indexed)
      return stamp(w);
    else {
      for (const vertex_descriptor& u : vertices_)
        if (u == w)
          return false;
      return !ball_.met_outside(w);
    }
  }

  // A new stamp on the vertices gathered so far: the first extend or grow_ball since start.
  void stamp_gathered()
  {
    if (++stamp_ == 0) { // wrapped around: no stamp is current
      std::fill(stamps_.begin(), stamps_.end(), 0);
      stamp_ = 1;
    }
    for (vertex_descriptor w : vertices_)
      stamp(w);
    stamped_ = true;
  }

  // Stamps w; false where it was already.
  bool stamp(vertex_descriptor w)
  {
    const std::size_t i = static_cast<std::size_t>(w);
    if (i >= stamps_.size())
      stamps_.resize(i + i / 2 + 1, 0);
    if (stamps_[i] == stamp_)
      return false;
    stamps_[i] = stamp_;
    return true;
  }

  static constexpr bool indexed = std::is_convertible<vertex_descriptor, std::size_t>::value;
  std::shared_ptr<const Vertex_adjacency> adjacency_;
  std::vector<std::uint32_t> stamps_;
  std::uint32_t stamp_ = 0;
  bool stamped_ = false; // whether the gathered vertices carry stamp_ (indexed only)
  std::vector<vertex_descriptor> vertices_;
  std::vector<std::size_t> ring_ends_;
  std::vector<char> has_face_; // per incoming halfedge of the center
  Ball<vertex_descriptor> ball_;
  double widest_squared_ball_ = 0; // since the center changed
  bool center_on_border_ = false;
  bool one_ring_in_fan_order_ = false;
  bool faces_are_triangles_ = false;
};

// The rings over the neighbors of Tetrahedral_complex_stars, one at a time. A
// stamp per vertex (allocated on first use, so that copying an unused collector
// is cheap) replaces the surface collector's linear search: tetrahedral rings
// hold hundreds of vertices.
class Tetrahedral_ring_collector
{
public:
  template <typename Stars>
  void start(std::size_t center, const Stars& stars)
  {
    if (stamps_.size() != stars.size()) {
      stamps_.assign(stars.size(), 0);
      stamp_ = 0;
    }
    if (++stamp_ == 0) {
      std::fill(stamps_.begin(), stamps_.end(), 0);
      stamp_ = 1;
    }
    vertices_.clear();
    ring_ends_.clear();
    ball_.clear();
    vertices_.push_back(center);
    stamps_[center] = stamp_;
    ring_ends_.push_back(1);
    add_neighbors(center, stars);
    ring_ends_.push_back(vertices_.size());
  }

  // Adds the next ring; returns false when it is empty (the component is exhausted).
  template <typename Stars>
  bool extend(const Stars& stars)
  {
    const std::size_t first = ring_ends_[ring_ends_.size() - 2];
    const std::size_t last = ring_ends_.back();
    for (std::size_t i = first; i < last; ++i)
      add_neighbors(vertices_[i], stars);
    ring_ends_.push_back(vertices_.size());
    return ring_ends_.back() > last;
  }

  // After start(), instead of extend(): the ball of Ring_collector::grow_ball.
  template <typename Stars, typename SquaredDistance>
  bool grow_ball(const Stars& stars, double squared_radius, const SquaredDistance& squared_distance)
  {
    if (!ball_.active())
      ring_ends_.push_back(vertices_.size());
    const auto neighbors = [&](std::size_t v, const auto& visit) {
      for_each_listed_neighbor(stars.neighbor_offsets, stars.neighbors, v, visit);
    };
    const auto reach = [&](std::size_t w) {
      if (stamps_[w] == stamp_)
        return false;
      stamps_[w] = stamp_;
      return true;
    };
    const bool more = ball_.grow(vertices_, ring_ends_[1], squared_radius, neighbors, reach, squared_distance);
    ring_ends_.back() = vertices_.size();
    return more;
  }
  bool inside_ball(std::size_t i) const { return ball_.inside(i); }
  std::size_t ball_size() const { return ball_.size(); }

  int rings() const { return static_cast<int>(ring_ends_.size()) - 1; }
  const std::vector<std::size_t>& vertices() const { return vertices_; }
  std::size_t ring_end(int r) const { return ring_ends_[r]; }

private:
  template <typename Stars>
  void add_neighbors(std::size_t v, const Stars& stars)
  {
    for_each_listed_neighbor(stars.neighbor_offsets, stars.neighbors, v, [&](std::size_t w) {
      if (stamps_[w] != stamp_) {
        stamps_[w] = stamp_;
        vertices_.push_back(w);
      }
    });
  }

  std::vector<unsigned> stamps_;
  unsigned stamp_ = 0;
  std::vector<std::size_t> vertices_;
  std::vector<std::size_t> ring_ends_;
  Ball<std::size_t> ball_;
};

} // namespace internal
} // namespace Curvature_estimation
} // namespace CGAL

#endif // CGAL_CURVATURE_ESTIMATION_INTERNAL_RINGS_H
