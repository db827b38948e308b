// SPDX-License-Identifier: GPL-3.0-or-later
// The neighbors of the points of a point set: CGAL's kd-tree over their indices,
// built once and queried from several threads: the k nearest, exactly, and the
// points within a distance.
#ifndef CGAL_CURVATURE_ESTIMATION_INTERNAL_POINT_SET_SEARCH_H
#define CGAL_CURVATURE_ESTIMATION_INTERNAL_POINT_SET_SEARCH_H

#include <CGAL/Euclidean_distance.h>
#include <CGAL/Fuzzy_sphere.h>
#include <CGAL/Kd_tree.h>
#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Simple_cartesian.h>

#include <boost/function_output_iterator.hpp>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

namespace CGAL {
namespace Curvature_estimation {
namespace internal {

// The points are stored once, in the order of a Morton curve over their bounding
// box (queries in that order find their neighbors in the cache): an index here is
// a position in that order, original(i) the point's in the input. The tree holds
// the finite points only, so that a non-finite point is never anyone's neighbor.
class Point_set_search
{
public:
  using Index = std::uint32_t;
  using Kernel = CGAL::Simple_cartesian<double>;
  using Found = std::vector<std::pair<double, Index>>; // squared distance, index

  template <typename ConcurrencyTag>
  Point_set_search(const std::vector<Eigen::Vector3d>& points, ConcurrencyTag)
      : order_(spatial_order(points))
      , tree_(Splitter(), Traits{&points_})
      , distance_(Traits{&points_})
  {
    points_.reserve(points.size());
    for (Index i : order_)
      points_.push_back(points[i]);
    for (std::size_t i = 0; i < points_.size(); ++i)
      if (points_[i].allFinite()) {
        tree_.insert(Index(i));
        ++finite_;
      }
    tree_.template build<ConcurrencyTag>();
  }

  Point_set_search(const Point_set_search&) = delete;
  Point_set_search& operator=(const Point_set_search&) = delete;

  std::size_t size() const { return points_.size(); }
  std::size_t finite_size() const { return finite_; }
  const Eigen::Vector3d& point(std::size_t i) const { return points_[i]; }
  const std::vector<Eigen::Vector3d>& points() const { return points_; }
  std::size_t original(std::size_t i) const { return order_[i]; }

  // The `count` points nearest to point i, i excluded, nearest first and ties by
  // index; fewer where the set has fewer.
  void nearest(Index i, std::size_t count, Found& found) const
  {
    found.clear();
    const Search search(tree_, i, static_cast<unsigned>(count + 1), 0, true, distance_);
    for (const auto& neighbor : search)
      if (neighbor.first != i)
        found.emplace_back(neighbor.second, neighbor.first);
    if (found.size() > count)
      found.resize(count);
    std::sort(found.begin(), found.end());
  }

  // The points within `radius` of point i, i excluded, in no order.
  void within(Index i, double radius, Found& found) const
  {
    found.clear();
    tree_.search(boost::make_function_output_iterator(Add{&points_, i, &found}), Sphere(i, radius, 0, tree_.traits()));
  }

private:
  // CGAL's search traits over the indices of points_, whose coordinates are read in
  // place: Search_traits_adapter over a map that returns points by value copies each
  // point it reads to the heap (two allocations a point visited, most of a query's time).
  struct Traits
  {
    using Dimension = CGAL::Dimension_tag<3>;
    using FT = double;
    using Point_d = Index;
    using Cartesian_const_iterator_d = const double*;
    using Iso_box_d = Kernel::Iso_cuboid_3; // for the concept: no box queries here
    struct Construct_cartesian_const_iterator_d
    {
      using result_type = const double*;
      const std::vector<Eigen::Vector3d>* points;
      const double* operator()(Index i) const { return (*points)[i].data(); }
      const double* operator()(Index i, int) const { return (*points)[i].data() + 3; }
    };
    const std::vector<Eigen::Vector3d>* points = nullptr;
    Construct_cartesian_const_iterator_d construct_cartesian_const_iterator_d_object() const { return {points}; }
  };
  using Splitter = CGAL::Sliding_midpoint<Traits>;
  using Distance = CGAL::Euclidean_distance<Traits>;
  using Tree = CGAL::Kd_tree<Traits, Splitter, CGAL::Tag_true, CGAL::Tag_true>;
  using Search = CGAL::Orthogonal_k_neighbor_search<Traits, Distance, Splitter, Tree>;
  using Sphere = CGAL::Fuzzy_sphere<Traits>;

  struct Add // assignable, as an output iterator's function must be
  {
    const std::vector<Eigen::Vector3d>* points;
    Index center;
    Found* found;
    void operator()(Index j) const
    {
      if (j != center)
        found->emplace_back(((*points)[j] - (*points)[center]).squaredNorm(), j);
    }
  };

  static std::vector<Index> spatial_order(const std::vector<Eigen::Vector3d>& points)
  {
    Eigen::AlignedBox3d box;
    for (const Eigen::Vector3d& p : points)
      if (p.allFinite())
        box.extend(p);
    const Eigen::Vector3d scale =
      (double(1 << 21) - 1) * (box.sizes().array() > 0).select(box.sizes().cwiseInverse(), 0);
    std::vector<std::pair<std::uint64_t, Index>> keys(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) {
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
    }
    std::sort(keys.begin(), keys.end());
    std::vector<Index> order(points.size());
    for (std::size_t i = 0; i < points.size(); ++i)
      order[i] = keys[i].second;
    return order;
  }

  std::vector<Index> order_;
  std::vector<Eigen::Vector3d> points_;
  Tree tree_;
  Distance distance_;
  std::size_t finite_ = 0;
};

} // namespace internal
} // namespace Curvature_estimation
} // namespace CGAL

#endif // CGAL_CURVATURE_ESTIMATION_INTERNAL_POINT_SET_SEARCH_H
