// SPDX-License-Identifier: GPL-3.0-or-later
// The neighborhood policy that runs the fits of vertex_fitter.h at the points of
// a point set: nested sets of nearest neighbors as rings, the points within a
// distance as the ball, the least-squares plane of the first ring as the
// first-order normal.
#ifndef CGAL_CURVATURE_ESTIMATION_INTERNAL_POINT_SET_NEIGHBORHOOD_H
#define CGAL_CURVATURE_ESTIMATION_INTERNAL_POINT_SET_NEIGHBORHOOD_H

#include <CGAL/Curvature_estimation/Vertex_normal_method.h>
#include <CGAL/Curvature_estimation/internal/point_set_search.h>
#include <CGAL/Curvature_estimation/internal/shape_operator.h>
#include <CGAL/Curvature_estimation/internal/surface_estimate.h>
#include <CGAL/Curvature_estimation/internal/symmetric_eigen.h>

#include <Eigen/Core>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Curvature_estimation {
namespace internal {

// The first ring of every point, found once (a row of `stride` indices, nearest
// first, padded with `none`), and the normal of its least-squares plane.
struct Point_set_rings
{
  static constexpr Point_set_search::Index none = ~Point_set_search::Index(0);
  std::size_t stride = 0;
  std::vector<Point_set_search::Index> neighbors;
  std::vector<Eigen::Vector3f> normals; // zero where there is none
};

// Ring r is the k 2^(r-1) nearest neighbors (k = `neighbors`), or with a
// `radius` (neighbors 0) ring 1 is the points within it and the ball grows from
// it. With `rings`, the first ring and the side of the first-order normal are
// read from it; else found here, the normal with the sign that makes its largest
// coordinate positive. With k nearest as ring 1, a ball is the points within its
// radius, found once out to at least `reach` and sorted by distance, so that the
// nested balls of the scale selection share one search.
class Point_set_neighborhood
{
public:
  static constexpr int ambient_dimension = 3;
  static constexpr bool restart_from_hyperplane = false;
  using Vertex = std::size_t;
  using Estimate = Surface_estimate;
  using Index = Point_set_search::Index;

  Point_set_neighborhood(const Point_set_search& search, std::size_t neighbors, double radius,
                         const Point_set_rings* rings = nullptr, double reach = 0)
      : search_(&search)
      , k_(neighbors)
      , radius_(radius)
      , rings_(rings)
      , reach_(reach)
  {}

  const Eigen::Vector3d& point(Vertex v) const { return search_->point(v); }

  void start(Vertex v)
  {
    vertices_.assign(1, v);
    ring_ends_.assign(1, 1);
    ball_radius_ = radius_;
    ball_distances_.clear();
    inside_ = 0;
    if (rings_ != nullptr && k_ > 0) {
      const Index* row = rings_->neighbors.data() + v * rings_->stride;
      for (std::size_t i = 0; i < rings_->stride && row[i] != Point_set_rings::none; ++i)
        vertices_.push_back(row[i]);
    } else {
      if (k_ > 0)
        search_->nearest(Index(v), k_, found_);
      else
        search_->within(Index(v), radius_, found_);
      for (const auto& f : found_)
        vertices_.push_back(f.second);
    }
    ring_ends_.push_back(vertices_.size());
  }

  // The next ring: the nearest neighbors up to twice as many as gathered.
  bool extend()
  {
    const std::size_t gathered = vertices_.size();
    if (k_ > 0) {
      search_->nearest(Index(vertices_[0]), k_ << rings(), found_);
      for (const auto& f : found_)
        if (std::find(vertices_.begin(), vertices_.end(), Vertex(f.second)) == vertices_.end())
          vertices_.push_back(f.second);
    }
    ring_ends_.push_back(vertices_.size());
    return vertices_.size() > gathered;
  }

  int rings() const { return static_cast<int>(ring_ends_.size()) - 1; }
  const std::vector<Vertex>& vertices() const { return vertices_; }
  std::size_t ring_end(int r) const { return ring_ends_[r]; }
  bool center_on_border(Vertex) const { return false; }

  // After start(v) with a radius: the ball is every point within `radius`, the
  // first ring first (nothing joins points: the other side of a thin part is taken).
  // With k nearest: the points within `radius`, appended after the rings nearest
  // first (ring 1 is no ball: its points are in the ball only as appended).
  bool grow_ball(double radius, const Eigen::Vector3d&)
  {
    if (k_ == 0) {
      if (radius > ball_radius_) {
        search_->within(Index(vertices_[0]), radius, found_);
        const double inner = ball_radius_ * ball_radius_;
        for (const auto& f : found_)
          if (f.first > inner)
            vertices_.push_back(f.second);
        ball_radius_ = radius;
      }
      return vertices_.size() < search_->finite_size();
    }
    if (ball_distances_.empty() && inside_ == 0)
      ball_begin_ = vertices_.size();
    if (radius > ball_radius_) {
      const double reach = (std::max)(radius, reach_);
      search_->within(Index(vertices_[0]), reach, found_);
      const double inner = ball_distances_.empty() ? -1 : ball_radius_ * ball_radius_;
      for (const auto& f : found_)
        if (f.first > inner) {
          vertices_.push_back(f.second);
          ball_distances_.push_back(f.first);
        }
      ball_radius_ = reach;
    }
    while (inside_ < ball_distances_.size() && ball_distances_[inside_] <= radius * radius)
      ++inside_;
    return 1 + inside_ < search_->finite_size();
  }
  bool inside_ball(std::size_t i) const { return k_ == 0 || i == 0 || (i >= ball_begin_ && i - ball_begin_ < inside_); }
  std::size_t ball_size() const { return k_ == 0 ? vertices_.size() : 1 + inside_; }
  // With k nearest: the k-th point to join the ball, nearest first.
  std::size_t ball_joined(std::size_t k) const { return k == 0 ? 0 : ball_begin_ + k - 1; }

  static bool gathers_for_normal(Vertex_normal_method) { return true; }

  Eigen::Vector3d initial_normal(Vertex v, Vertex_normal_method, bool, const std::vector<Eigen::Vector3d>& offsets,
                                 const std::vector<char>&, double) const
  {
    if (rings_ == nullptr)
      return plane_normal(offsets.data(), ring_end(1));
    // The oriented normal is stored in floats: it gives the side only, so that
    // the fit's frame does not depend on the orientation.
    const Eigen::Vector3d oriented = rings_->normals[v].cast<double>();
    if (oriented.isZero())
      return oriented;
    const Eigen::Vector3d normal = plane_normal(offsets.data(), ring_end(1));
    return normal.dot(oriented) < 0 ? Eigen::Vector3d(-normal) : normal;
  }

  // The normal of the least-squares plane of `count` points, its largest coordinate positive.
  static Eigen::Vector3d plane_normal(const Eigen::Vector3d* points, std::size_t count)
  {
    const Eigen::Vector3d normal = least_squares_hyperplane_normal<3>(points, count);
    int k = 0;
    normal.cwiseAbs().maxCoeff(&k);
    return normal[k] < 0 ? Eigen::Vector3d(-normal) : normal;
  }

  static void set_estimate(Surface_estimate& e, Estimation_status status, const Graph_curvature<3>& curvature,
                           double scale)
  {
    set_surface_estimate(e, status, curvature, scale);
  }

private:
  const Point_set_search* search_;
  std::size_t k_;
  double radius_;
  const Point_set_rings* rings_;
  double reach_;
  std::vector<Vertex> vertices_;
  std::vector<std::size_t> ring_ends_;
  Point_set_search::Found found_;
  double ball_radius_ = 0;                  // the radius searched
  std::vector<double> ball_distances_;      // with k nearest: the squared distances of the points appended
  std::size_t ball_begin_ = 0, inside_ = 0; // where they begin, how many are inside the ball
};

} // namespace internal
} // namespace Curvature_estimation
} // namespace CGAL

#endif // CGAL_CURVATURE_ESTIMATION_INTERNAL_POINT_SET_NEIGHBORHOOD_H
