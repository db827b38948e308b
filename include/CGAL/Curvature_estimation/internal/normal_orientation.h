// SPDX-License-Identifier: GPL-3.0-or-later
// A consistent orientation of the unoriented normals of a point set: a maximum
// spanning tree of the agreement between neighbors' normals (as CGAL's
// mst_orient_normals, without reordering the points), grown in blocks in
// parallel and joined, then one side per connected part. The manual's "Point
// sets" says where it can flip.
#ifndef CGAL_CURVATURE_ESTIMATION_INTERNAL_NORMAL_ORIENTATION_H
#define CGAL_CURVATURE_ESTIMATION_INTERNAL_NORMAL_ORIENTATION_H

#include <CGAL/Curvature_estimation/internal/for_each_vertex.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <tuple>
#include <vector>

namespace CGAL {
namespace Curvature_estimation {
namespace internal {

// Per point: the part it was oriented with (no_part without a normal) and the
// confidence of its orientation in [0, 1].
struct Normal_orientation
{
  static constexpr std::uint32_t no_part = (std::numeric_limits<std::uint32_t>::max)();
  std::vector<std::uint32_t> part;
  std::vector<float> confidence;
};

// How much the orientation of q's normal follows from p's: |n_p . n_q|, less
// where the offset leaves either tangent plane (an edge across a thin part).
inline float normal_agreement(const Eigen::Vector3d& p, const Eigen::Vector3f& n_p, const Eigen::Vector3d& q,
                              const Eigen::Vector3f& n_q)
{
  const Eigen::Vector3f d = (q - p).cast<float>().normalized();
  const float leaving = d.allFinite() ? (std::max)(std::abs(n_p.dot(d)), std::abs(n_q.dot(d))) : 0.f;
  return std::abs(n_p.dot(n_q)) * (1 - leaving);
}

// Prim's front: the best edge found so far to each point not yet reached, in a
// heap indexed by point. It pops edges in the order of a queue of every edge
// listed, by largest (agreement, point, from), with one entry per point.
class Prim_front
{
public:
  struct Edge
  {
    float agreement;
    std::uint32_t point, from;
    bool operator<(const Edge& e) const
    {
      return std::tie(agreement, point, from) < std::tie(e.agreement, e.point, e.from);
    }
  };

  // The front over the points first, ..., first + points - 1.
  Prim_front(std::size_t first, std::size_t points)
      : first_(first)
      , position_(points, absent)
  {}

  bool empty() const { return heap_.empty(); }

  // Keeps the edge if it is the best yet to its point.
  void offer(const Edge& edge)
  {
    std::uint32_t at = position_[edge.point - first_];
    if (at == absent) {
      at = std::uint32_t(heap_.size());
      heap_.push_back(edge);
    } else if (heap_[at] < edge)
      heap_[at] = edge;
    else
      return;
    up(at);
  }

  Edge pop()
  {
    const Edge top = heap_.front();
    position_[top.point - first_] = absent;
    const Edge last = heap_.back();
    heap_.pop_back();
    if (!heap_.empty()) {
      place(0, last);
      down(0);
    }
    return top;
  }

private:
  static constexpr std::uint32_t absent = ~std::uint32_t(0);

  void place(std::uint32_t at, const Edge& edge)
  {
    heap_[at] = edge;
    position_[edge.point - first_] = at;
  }
  void up(std::uint32_t at)
  {
    const Edge edge = heap_[at];
    for (; at > 0 && heap_[(at - 1) / 2] < edge; at = (at - 1) / 2)
      place(at, heap_[(at - 1) / 2]);
    place(at, edge);
  }
  void down(std::uint32_t at)
  {
    const Edge edge = heap_[at];
    const std::size_t size = heap_.size();
    for (std::size_t child = 2 * std::size_t(at) + 1; child < size; child = 2 * std::size_t(at) + 1) {
      if (child + 1 < size && heap_[child] < heap_[child + 1])
        ++child;
      if (!(edge < heap_[child]))
        break;
      place(at, heap_[child]);
      at = std::uint32_t(child);
    }
    place(at, edge);
  }

  std::size_t first_;
  std::vector<Edge> heap_;
  std::vector<std::uint32_t> position_; // in heap_, of the points listed and not reached
};

// Orients `normals` (unit, or zero where a point has none) over the graph in
// which `neighbors(i, visit)` calls visit(j) for the neighbors j of i. The
// trees grow in blocks of consecutive points, on several threads; the parts
// they leave are joined after, so that the result does not depend on the
// number of threads.
template <typename ConcurrencyTag, typename Neighbors>
Normal_orientation orient_normals(const std::vector<Eigen::Vector3d>& points, std::vector<Eigen::Vector3f>& normals,
                                  const Neighbors& neighbors)
{
  const std::size_t n = points.size();
  const auto has_normal = [&](std::size_t i) { return normals[i].squaredNorm() > 0; };
  Normal_orientation result;
  result.part.assign(n, Normal_orientation::no_part);
  result.confidence.assign(n, 0.f);
  std::vector<std::uint32_t>& part = result.part;
  std::vector<float>& confidence = result.confidence;

  // Prim from each point of a block not yet reached, over the edges within the
  // block listed from reached points; parts numbered within the block, then in
  // the order of their first point.
  constexpr std::size_t block_size = std::size_t(1) << 16;
  const std::size_t blocks = (n + block_size - 1) / block_size;
  std::vector<std::uint32_t> first_part(blocks + 1, 0);
  for_each_index<ConcurrencyTag>(blocks, [&](std::size_t b) {
    const std::size_t begin = b * block_size, end = (std::min)(n, begin + block_size);
    Prim_front front(begin, end - begin);
    std::uint32_t parts = 0;
    for (std::size_t seed = begin; seed < end; ++seed) {
      if (part[seed] != Normal_orientation::no_part || !has_normal(seed))
        continue;
      front.offer({1.f, std::uint32_t(seed), std::uint32_t(seed)});
      while (!front.empty()) {
        const Prim_front::Edge edge = front.pop();
        const std::uint32_t i = edge.point, from = edge.from;
        if (normals[i].dot(normals[from]) < 0)
          normals[i] = -normals[i];
        part[i] = parts;
        confidence[i] = (std::min)(edge.agreement, i == from ? 1.f : confidence[from]);
        neighbors(i, [&](std::uint32_t j) {
          if (j >= begin && j < end && part[j] == Normal_orientation::no_part && has_normal(j))
            front.offer({normal_agreement(points[i], normals[i], points[j], normals[j]), j, i});
        });
      }
      ++parts;
    }
    first_part[b + 1] = parts;
  });
  for (std::size_t b = 0; b < blocks; ++b)
    first_part[b + 1] += first_part[b];
  const std::uint32_t parts = first_part[blocks];
  for_each_index<ConcurrencyTag>(n, [&](std::size_t i) {
    if (part[i] != Normal_orientation::no_part)
      part[i] += first_part[i / block_size];
  });

  // Parts joined by the edges between blocks and those listed from their far side
  // only: by decreasing agreement, a union-find that keeps each part's flip
  // relative to its root. Of the edges between two parts, only the strongest can
  // join them: each block keeps those.
  using Edge = std::tuple<float, std::uint32_t, std::uint32_t>; // agreement, point, neighbor
  const auto stronger = [](const Edge& a, const Edge& b) {
    return std::make_tuple(-std::get<0>(a), std::get<1>(a), std::get<2>(a)) <
           std::make_tuple(-std::get<0>(b), std::get<1>(b), std::get<2>(b));
  };
  const auto parts_of = [&](const Edge& e) {
    const std::uint32_t p = part[std::get<1>(e)], q = part[std::get<2>(e)];
    return std::make_pair((std::min)(p, q), (std::max)(p, q));
  };
  std::vector<std::vector<Edge>> block_joins(blocks);
  for_each_index<ConcurrencyTag>(blocks, [&](std::size_t b) {
    std::vector<Edge> edges;
    for (std::size_t i = b * block_size; i < (std::min)(n, (b + 1) * block_size); ++i)
      if (part[i] != Normal_orientation::no_part)
        neighbors(i, [&](std::uint32_t j) {
          if (part[j] != Normal_orientation::no_part && part[j] != part[i])
            edges.emplace_back(normal_agreement(points[i], normals[i], points[j], normals[j]), std::uint32_t(i), j);
        });
    std::sort(edges.begin(), edges.end(), [&](const Edge& a, const Edge& c) {
      return parts_of(a) != parts_of(c) ? parts_of(a) < parts_of(c) : stronger(a, c);
    });
    const auto end =
      std::unique(edges.begin(), edges.end(), [&](const Edge& a, const Edge& c) { return parts_of(a) == parts_of(c); });
    block_joins[b].assign(edges.begin(), end);
  });
  std::vector<Edge> joins;
  for (std::vector<Edge>& edges : block_joins) {
    joins.insert(joins.end(), edges.begin(), edges.end());
    std::vector<Edge>().swap(edges);
  }
  std::sort(joins.begin(), joins.end(), stronger);
  std::vector<std::uint32_t> root(parts);
  std::vector<char> flip(parts, 0); // relative to root[], before compression: to the root
  std::vector<float> join_agreement(parts, 1.f);
  for (std::uint32_t c = 0; c < parts; ++c)
    root[c] = c;
  const auto find = [&](std::uint32_t c) {
    char parity = 0;
    std::uint32_t r = c;
    while (root[r] != r) {
      parity ^= flip[r];
      r = root[r];
    }
    return std::make_pair(r, parity);
  };
  for (const auto& [agreement, i, j] : joins) {
    const auto [ri, pi] = find(part[i]);
    const auto [rj, pj] = find(part[j]);
    if (ri == rj)
      continue;
    const std::uint32_t child = (std::max)(ri, rj), parent = (std::min)(ri, rj);
    root[child] = parent;
    flip[child] = char(pi ^ pj ^ (normals[i].dot(normals[j]) < 0 ? 1 : 0));
    join_agreement[child] = agreement;
  }

  // One side per joined part: the one whose normals point away from its centroid
  // on the whole (outward on a closed surface).
  std::vector<Eigen::Vector3d> centroid(parts, Eigen::Vector3d::Zero());
  std::vector<double> count(parts, 0), side(parts, 0), spread(parts, 0);
  std::vector<std::uint32_t> final_part(parts);
  std::vector<char> final_flip(parts);
  std::vector<float> weakest_join(parts);
  std::vector<std::uint32_t> number(parts, Normal_orientation::no_part); // of the roots, from 0
  std::uint32_t joined = 0;
  for (std::uint32_t c = 0; c < parts; ++c) {
    const auto [r, parity] = find(c);
    if (number[r] == Normal_orientation::no_part)
      number[r] = joined++;
    final_part[c] = number[r];
    final_flip[c] = parity;
    float weakest = 1.f;
    for (std::uint32_t k = c; root[k] != k; k = root[k])
      weakest = (std::min)(weakest, join_agreement[k]);
    weakest_join[c] = weakest;
  }
  for_each_index<ConcurrencyTag>(n, [&](std::size_t i) {
    if (part[i] != Normal_orientation::no_part) {
      const std::uint32_t c = part[i];
      if (final_flip[c])
        normals[i] = -normals[i];
      confidence[i] = (std::min)(confidence[i], weakest_join[c]);
      part[i] = final_part[c];
    }
  });
  for (std::size_t i = 0; i < n; ++i)
    if (part[i] != Normal_orientation::no_part) {
      centroid[part[i]] += points[i];
      count[part[i]] += 1;
    }
  for (std::size_t i = 0; i < n; ++i)
    if (part[i] != Normal_orientation::no_part) {
      const double s = normals[i].cast<double>().dot(points[i] - centroid[part[i]] / count[part[i]]);
      side[part[i]] += s;
      spread[part[i]] += std::abs(s);
    }
  for_each_index<ConcurrencyTag>(n, [&](std::size_t i) {
    if (part[i] != Normal_orientation::no_part) {
      const std::uint32_t c = part[i];
      if (side[c] < 0)
        normals[i] = -normals[i];
      const double certainty = spread[c] > 0 ? std::abs(side[c]) / spread[c] : 0;
      confidence[i] = (std::min)(confidence[i], float(certainty));
    }
  });
  return result;
}

} // namespace internal
} // namespace Curvature_estimation
} // namespace CGAL

#endif // CGAL_CURVATURE_ESTIMATION_INTERNAL_NORMAL_ORIENTATION_H
