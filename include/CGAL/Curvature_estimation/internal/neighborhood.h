// k-ring neighbourhoods of a vertex of a FaceGraph, grown one ring at a time so
// that an estimator can widen its stencil without gathering it again.
#ifndef CGAL_CURVATURE_ESTIMATION_INTERNAL_NEIGHBORHOOD_H
#define CGAL_CURVATURE_ESTIMATION_INTERNAL_NEIGHBORHOOD_H

#include <CGAL/boost/graph/iterator.h>

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Curvature_estimation {
namespace internal {

// The buffers are reused from vertex to vertex: no allocation once they have
// reached the size of the largest neighbourhood met.
template <typename FaceGraph>
class Ring_collector
{
public:
  using vertex_descriptor = typename boost::graph_traits<FaceGraph>::vertex_descriptor;
  using halfedge_descriptor = typename boost::graph_traits<FaceGraph>::halfedge_descriptor;

  // Restarts at `center` with its 1-ring.
  void start(vertex_descriptor center, const FaceGraph& g)
  {
    vertices_.clear();
    ring_ends_.clear();
    vertices_.push_back(center);
    ring_ends_.push_back(1);
    const halfedge_descriptor h = halfedge(center, g);
    if (h != boost::graph_traits<FaceGraph>::null_halfedge())
      for (halfedge_descriptor incoming : halfedges_around_target(h, g))
        add_if_new(source(incoming, g));
    ring_ends_.push_back(vertices_.size());
  }

  // Adds the next ring; returns false when it is empty (the component is exhausted).
  bool extend(const FaceGraph& g)
  {
    const std::size_t first = ring_ends_[ring_ends_.size() - 2];
    const std::size_t last = ring_ends_.back();
    for (std::size_t i = first; i < last; ++i) {
      const halfedge_descriptor h = halfedge(vertices_[i], g);
      for (halfedge_descriptor incoming : halfedges_around_target(h, g))
        add_if_new(source(incoming, g));
    }
    ring_ends_.push_back(vertices_.size());
    return ring_ends_.back() > last;
  }

  // Number of rings gathered (1 after start()).
  int rings() const { return static_cast<int>(ring_ends_.size()) - 1; }

  // The center is vertices()[0]; ring r (r >= 1) is [ring_end(r - 1), ring_end(r)).
  const std::vector<vertex_descriptor>& vertices() const { return vertices_; }
  std::size_t ring_end(int r) const { return ring_ends_[r]; }

private:
  // A linear search: neighbourhoods hold tens of vertices, and the 1-ring of a
  // non-manifold vertex may repeat a neighbour.
  void add_if_new(vertex_descriptor w)
  {
    if (std::find(vertices_.begin(), vertices_.end(), w) == vertices_.end())
      vertices_.push_back(w);
  }

  std::vector<vertex_descriptor> vertices_;
  std::vector<std::size_t> ring_ends_;
};

} // namespace internal
} // namespace Curvature_estimation
} // namespace CGAL

#endif // CGAL_CURVATURE_ESTIMATION_INTERNAL_NEIGHBORHOOD_H
