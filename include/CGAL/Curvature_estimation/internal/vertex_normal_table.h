// SPDX-License-Identifier: GPL-3.0-or-later
// The unit normals of a mesh's vertices, computed once and read by the Gauss map's
// differential at each vertex's neighbors.
#ifndef CGAL_CURVATURE_ESTIMATION_INTERNAL_VERTEX_NORMAL_TABLE_H
#define CGAL_CURVATURE_ESTIMATION_INTERNAL_VERTEX_NORMAL_TABLE_H

#include <CGAL/Surface_mesh/Surface_mesh_fwd.h>

#include <boost/functional/hash.hpp>
#include <boost/graph/graph_traits.hpp>

#include <Eigen/Core>

#include <cstddef>
#include <limits>
#include <type_traits>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Curvature_estimation {
namespace internal {

// Unit vertex normals addressed by vertex, with the reach of each (how far from
// its vertex the balls it was fitted over reach, 0 for none), filled on the
// calling thread and then only read by the worker threads. A vertex without a
// normal holds NaNs. On a Surface_mesh a vector by vertex index (one allocation);
// on other graphs a hash map (a node per vertex; concurrent `find` on a const
// std::unordered_map is safe).
template <typename FaceGraph>
class Vertex_normal_table
{
  using vertex_descriptor = typename boost::graph_traits<FaceGraph>::vertex_descriptor;

  template <typename Graph>
  struct Is_surface_mesh : std::false_type
  {};
  template <typename P>
  struct Is_surface_mesh<CGAL::Surface_mesh<P>> : std::true_type
  {};
  static constexpr bool by_index = Is_surface_mesh<FaceGraph>::value;

public:
  struct Entry
  {
    Eigen::Vector3d normal = Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
    double reach = 0;
  };

  explicit Vertex_normal_table(const FaceGraph& g)
  {
    if constexpr (by_index) // indices of removed, not yet collected vertices included
      entries_.assign(g.number_of_vertices() + g.number_of_removed_vertices(), Entry());
    else
      entries_.reserve(num_vertices(g));
  }

  void set(vertex_descriptor v, const Entry& e)
  {
    if constexpr (by_index)
      entries_[std::size_t(v)] = e;
    else
      entries_[v] = e;
  }

  // The unit normal of `u`; false where it has none.
  bool find(vertex_descriptor u, Eigen::Vector3d& n) const
  {
    const Entry* e = entry(u);
    if (e == nullptr)
      return false;
    n = e->normal;
    return n.allFinite();
  }

  double reach(vertex_descriptor u) const
  {
    const Entry* e = entry(u);
    return e != nullptr ? e->reach : 0;
  }

private:
  const Entry* entry(vertex_descriptor u) const
  {
    if constexpr (by_index)
      return &entries_[std::size_t(u)];
    else {
      const auto it = entries_.find(u);
      return it != entries_.end() ? &it->second : nullptr;
    }
  }

  std::conditional_t<by_index, std::vector<Entry>,
                     std::unordered_map<vertex_descriptor, Entry, boost::hash<vertex_descriptor>>>
    entries_;
};

} // namespace internal
} // namespace Curvature_estimation
} // namespace CGAL

#endif // CGAL_CURVATURE_ESTIMATION_INTERNAL_VERTEX_NORMAL_TABLE_H
