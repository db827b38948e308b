// SPDX-License-Identifier: GPL-3.0-or-later
// The neighbors of the points of a point set: a bounding-box hierarchy over the
// points in Morton order, built once and queried from several threads: the k
// nearest, exactly, and the points within a distance, both in a canonical order.
#ifndef CGAL_CURVATURE_ESTIMATION_INTERNAL_POINT_SET_SEARCH_H
#define CGAL_CURVATURE_ESTIMATION_INTERNAL_POINT_SET_SEARCH_H

#include <CGAL/Curvature_estimation/internal/for_each_vertex.h>
#include <CGAL/tags.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/parallel_sort.h>
#endif

#include <algorithm>
#include <cstdint>
#include <limits>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Curvature_estimation {
namespace internal {

// The points are stored once, in the order of a Morton curve over their bounding
// box: an index here is a position in that order, original(i) the point's in the
// input. Each node of the hierarchy is a range of that order, a cell of the curve,
// with the box of its points; the queries read the points in place (no allocation
// but the caller's `Found`, reused). The hierarchy holds the finite points only,
// so that a non-finite point is never anyone's neighbor.
class Point_set_search
{
public:
  using Index = std::uint32_t;
  using Found = std::vector<std::pair<double, Index>>; // squared distance, index

  template <typename ConcurrencyTag>
  Point_set_search(const std::vector<Eigen::Vector3d>& points, ConcurrencyTag)
  {
    const std::vector<Key> keys = spatial_order<ConcurrencyTag>(points);
    order_.resize(points.size());
    points_.resize(points.size());
    for_each_index<ConcurrencyTag>(points.size(), [&](std::size_t i) {
      order_[i] = keys[i].second;
      points_[i] = points[keys[i].second];
    });
    while (finite_ < points_.size() && points_[finite_].allFinite()) // the non-finite points are last
      ++finite_;
    if (finite_ > 0)
      build(keys, 0, Index(finite_));
  }

  Point_set_search(const Point_set_search&) = delete;
  Point_set_search& operator=(const Point_set_search&) = delete;

  std::size_t size() const { return points_.size(); }
  std::size_t finite_size() const { return finite_; }
  const Eigen::Vector3d& point(std::size_t i) const { return points_[i]; }
  const std::vector<Eigen::Vector3d>& points() const { return points_; }
  std::size_t original(std::size_t i) const { return order_[i]; }

  // The `count` points nearest to point i, i excluded, in the order `before`;
  // fewer where the set has fewer, none where point i is not finite.
  void nearest(Index i, std::size_t count, Found& found) const
  {
    found.clear();
    if (count == 0 || i >= finite_)
      return;
    // The nearest child first, so that the bound (the count-th nearest yet) shrinks
    // early; found kept sorted by insertion (count is small).
    double bound = infinity;
    // (A box at an infinite bound, where squared distances overflow, is read while found is short.)
    const auto may_join = [&](const Node& node) { return found.size() < count || may_precede(node, found.back()); };
    visit(i, bound, may_join, [&](double d, Index j) {
      const std::pair<double, Index> candidate(d, j);
      if (found.size() < count)
        found.push_back(candidate);
      else if (before(candidate, found.back()))
        found.back() = candidate;
      else
        return;
      std::size_t m = found.size() - 1;
      for (; m > 0 && before(candidate, found[m - 1]); --m)
        found[m] = found[m - 1];
      found[m] = candidate;
      if (found.size() == count)
        bound = found.back().first;
    });
  }

  // The points within `radius` of point i, i excluded, in the order `before`.
  void within(Index i, double radius, Found& found) const
  {
    found.clear();
    if (i >= finite_)
      return;
    double bound = radius * radius;
    visit(
      i, bound, [](const Node&) { return true; }, [&](double d, Index j) { found.emplace_back(d, j); });
    std::sort(found.begin(), found.end(), [this](const auto& a, const auto& b) { return before(a, b); });
  }

private:
  // Nearer first; at equal distances by position (x, then y, then z), then by index:
  // an order that the other points of the set do not change (a tile of the set finds
  // its points' neighbors in the order the whole set does).
  bool before(const std::pair<double, Index>& a, const std::pair<double, Index>& b) const
  {
    if (a.first != b.first)
      return a.first < b.first;
    const Eigen::Vector3d &p = points_[a.second], &q = points_[b.second];
    if (p != q)
      return std::lexicographical_compare(p.data(), p.data() + 3, q.data(), q.data() + 3);
    return a.second < b.second;
  }

  static constexpr Index leaf_size = 16;
  static constexpr double infinity = std::numeric_limits<double>::infinity();

  struct Node
  {
    Eigen::Vector3d min, max;
    Index begin, end; // the points of the node
    Index second;     // the second child (the first follows the node); 0 for a leaf
  };

  // Whether a point of `node` at the distance of `worst` could come before it, by position or index
  // (a point's position is lexicographically at least its box's lower corner): the test that keeps
  // the copies of a point (a scanner's returns at the origin) from being visited by every query.
  bool may_precede(const Node& node, const std::pair<double, Index>& worst) const
  {
    const Eigen::Vector3d& w = points_[worst.second];
    if (node.min != w)
      return std::lexicographical_compare(node.min.data(), node.min.data() + 3, w.data(), w.data() + 3);
    return node.begin < worst.second;
  }

  // One formula for the points and the boxes, so that a box is never farther than its points.
  static double squared_distance(const Eigen::Vector3d& p, const Eigen::Vector3d& q)
  {
    const double x = p[0] - q[0], y = p[1] - q[1], z = p[2] - q[2];
    return x * x + y * y + z * z;
  }
  static double box_distance(const Node& node, const Eigen::Vector3d& q)
  {
    return squared_distance(q, q.cwiseMax(node.min).cwiseMin(node.max));
  }

  // Calls offer(squared distance, j) for the points j other than i within `bound`
  // of point i (which offer may lower), the nodes' nearer child first; a node whose
  // box is at `bound` only where at_bound(node).
  template <typename AtBound, typename Offer>
  void visit(Index i, const double& bound, const AtBound& at_bound, const Offer& offer) const
  {
    const Eigen::Vector3d& q = points_[i];
    struct Pending
    {
      double distance;
      Index node;
    };
    Pending stack[128]; // the depth is at most 63 bits of code and 32 halvings
    int size = 0;
    stack[size++] = {0., 0};
    while (size > 0) {
      const Pending pending = stack[--size];
      const Node& node = nodes_[pending.node];
      if (pending.distance > bound || (pending.distance == bound && !at_bound(node)))
        continue;
      if (node.second == 0) {
        for (Index j = node.begin; j < node.end; ++j) {
          const double d = squared_distance(points_[j], q);
          if (d <= bound && j != i)
            offer(d, j);
        }
        continue;
      }
      const Pending first{box_distance(nodes_[pending.node + 1], q), pending.node + 1},
        second{box_distance(nodes_[node.second], q), node.second};
      stack[size++] = first.distance <= second.distance ? second : first;
      stack[size++] = first.distance <= second.distance ? first : second;
    }
  }

  using Key = std::pair<std::uint64_t, Index>; // Morton code, index in the input

  // The node of points [begin, end), split where their Morton codes' highest differing
  // bit changes (at the middle where the codes are equal), so that its children's
  // boxes are cells of the curve and seldom overlap.
  Index build(const std::vector<Key>& keys, Index begin, Index end)
  {
    const Index n = Index(nodes_.size());
    nodes_.push_back({points_[begin], points_[begin], begin, end, 0});
    if (end - begin <= leaf_size) {
      for (Index j = begin + 1; j < end; ++j) {
        nodes_[n].min = nodes_[n].min.cwiseMin(points_[j]);
        nodes_[n].max = nodes_[n].max.cwiseMax(points_[j]);
      }
      return n;
    }
    const std::uint64_t first = keys[begin].first, last = keys[end - 1].first;
    Index middle = begin + (end - begin) / 2;
    if (first != last) {
      std::uint64_t bit = std::uint64_t(1) << 63;
      while ((first & bit) == (last & bit))
        bit >>= 1;
      middle = Index(std::partition_point(keys.begin() + begin, keys.begin() + end,
                                          [bit](const Key& key) { return (key.first & bit) == 0; }) -
                     keys.begin());
    }
    build(keys, begin, middle);
    const Index second = build(keys, middle, end);
    nodes_[n].second = second;
    nodes_[n].min = nodes_[n + 1].min.cwiseMin(nodes_[second].min);
    nodes_[n].max = nodes_[n + 1].max.cwiseMax(nodes_[second].max);
    return n;
  }

  // The points' Morton codes over their bounding box, sorted.
  template <typename ConcurrencyTag>
  static std::vector<Key> spatial_order(const std::vector<Eigen::Vector3d>& points)
  {
    Eigen::AlignedBox3d box;
    for (const Eigen::Vector3d& p : points)
      if (p.allFinite())
        box.extend(p);
    const Eigen::Vector3d scale =
      (double(1 << 21) - 1) * (box.sizes().array() > 0).select(box.sizes().cwiseInverse(), 0);
    std::vector<Key> keys(points.size());
    for_each_index<ConcurrencyTag>(points.size(), [&](std::size_t i) {
      std::uint64_t key = ~std::uint64_t(0); // the non-finite points last
      if (points[i].allFinite()) {
        key = 0;
        const Eigen::Vector3d q = (points[i] - box.min()).cwiseProduct(scale);
        std::uint64_t cell[3]; // in range also where the box's extent overflows (q infinite or NaN)
        for (int c = 0; c < 3; ++c)
          cell[c] = q[c] > 0 ? std::uint64_t((std::min)(q[c], double(1 << 21) - 1)) : 0;
        for (int bit = 20; bit >= 0; --bit)
          for (int c = 0; c < 3; ++c)
            key = (key << 1) | ((cell[c] >> bit) & 1);
      }
      keys[i] = {key, Index(i)};
    });
#ifdef CGAL_LINKED_WITH_TBB
    if (std::is_same<ConcurrencyTag, CGAL::Parallel_tag>::value)
      tbb::parallel_sort(keys.begin(), keys.end());
    else
#endif
      std::sort(keys.begin(), keys.end());
    return keys;
  }

  std::vector<Index> order_;
  std::vector<Eigen::Vector3d> points_;
  std::vector<Node> nodes_;
  std::size_t finite_ = 0;
};

} // namespace internal
} // namespace Curvature_estimation
} // namespace CGAL

#endif // CGAL_CURVATURE_ESTIMATION_INTERNAL_POINT_SET_SEARCH_H
