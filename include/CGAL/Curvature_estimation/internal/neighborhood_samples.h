// SPDX-License-Identifier: GPL-3.0-or-later
// The samples of the fits at one vertex: its neighborhood gathered ring by ring
// (or in a growing ball), as offsets from the vertex scaled by a local length, and
// the samples (tangent coordinates, height, weight) of a fit in a frame.
#ifndef CGAL_CURVATURE_ESTIMATION_INTERNAL_NEIGHBORHOOD_SAMPLES_H
#define CGAL_CURVATURE_ESTIMATION_INTERNAL_NEIGHBORHOOD_SAMPLES_H

#include <CGAL/Curvature_estimation/Vertex_normal_method.h>
#include <CGAL/Curvature_estimation/internal/fit_attempts.h>
#include <CGAL/Curvature_estimation/internal/local_coordinates.h>
#include <CGAL/Curvature_estimation/internal/symmetric_eigen.h>
#include <CGAL/Curvature_estimation/internal/tangent_frame.h>
#include <CGAL/Curvature_estimation/internal/taylor_fit/pairs.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Curvature_estimation {
namespace internal {

// A Neighborhood policy (face_graph_neighborhood.h, tetrahedral_neighborhood.h) gives
//   ambient_dimension, Vertex, Estimate     N (3 or 4), the vertex key, the result type
//   point(v)                                the point of v in double
//   start(v), extend(), rings(), vertices(), ring_end(r)
//                                           the rings of v, one more at a time
//   grow_ball(radius, center), inside_ball(i), ball_size()
//                                           after start(v), instead of extend(): the ball
//   ball_joined(k)                          the place in vertices() of the k-th to join
//                                           the ball (for the scale selection)
//   center_on_border(v)                     after start(v)
//   gathers_for_normal(method)              whether initial_normal needs the gathered 1-ring
//   initial_normal(v, method, gathered, offsets, finite, scale)
//                                           the first-order normal (any length)
//   restart_from_hyperplane                 see Vertex_fitter::estimate_normal
//   set_estimate(e, status, curvature, scale) e from the curvature in the fit's frame
// The buffers are reused from vertex to vertex; nothing else is kept from one
// vertex to the next.
template <typename Neighborhood>
class Neighborhood_samples
{
public:
  static constexpr int N = Neighborhood::ambient_dimension;
  static constexpr int D = N - 1;
  using Vertex = typename Neighborhood::Vertex;
  using Vector = Eigen::Matrix<double, N, 1>;
  using Tangents = Eigen::Matrix<double, N, D>;

  struct Frame
  {
    Vector normal;
    Tangents tangents;
  };

  // The samples of a fit: in `frame`, over `rings` rings (0: the ball), with `weights`.
  struct Sampling
  {
    Frame frame;
    int rings;
    Sample_weights weights;
  };

  static Frame frame_of(const Vector& normal) { return {normal, tangent_basis<N>(normal)}; }

  explicit Neighborhood_samples(Neighborhood neighborhood)
      : neighborhood_(std::move(neighborhood))
  {}

  Neighborhood& neighborhood() { return neighborhood_; }
  double scale() const { return scale_; }
  bool on_border() const { return on_border_; }

  // The neighbors gathered, on every ring reached or (in_ball) in the last ball.
  std::size_t neighbors(bool in_ball) const
  {
    return in_ball ? ball_neighbors_ : offsets_.empty() ? 0 : offsets_.size() - 1;
  }

  // The unit first-order normal by `method` (`gathered`: whether gather(v) has succeeded).
  bool first_order_normal(Vertex v, Vertex_normal_method method, bool gathered, Vector& normal) const
  {
    normal = neighborhood_.initial_normal(v, method, gathered, offsets_, finite_, scale_);
    if (!all_finite(normal) || !(normal.squaredNorm() > 0))
      return false;
    normal.normalize();
    return true;
  }

  // `normal` normalized where given, else the first-order normal by `method`
  // (after gather(v)); false where there is none.
  bool unit_normal(Vertex v, const Vector* normal, Vertex_normal_method method, Vector& unit) const
  {
    if (normal == nullptr)
      return first_order_normal(v, method, true, unit);
    const double length = normal->norm();
    if (!(length > 0) || !std::isfinite(length))
      return false;
    unit = *normal / length;
    return true;
  }

  // The normal of the least-squares hyperplane of the vertex and its 1-ring.
  Vector one_ring_hyperplane_normal() const
  {
    return least_squares_hyperplane_normal<N>(offsets_.data(), neighborhood_.ring_end(1));
  }

  // Calls add(x, height, weight) for each finite sample: the vertex too where the
  // fit has an intercept (the others pass through it), over the rings or in the ball.
  template <typename Fit, typename Add>
  CGAL_CURVATURE_ESTIMATION_INLINE void for_each_sample(const Sampling& sampling, const Add& add) const
  {
    const Eigen::Matrix<double, D, N> to_tangent = sampling.frame.tangents.transpose();
    const Vector& normal = sampling.frame.normal;
    if (sampling.rings == 0) {
      for (std::size_t i = 0; i < offsets_.size(); ++i) {
        const Vector& q = offsets_[i];
        if (finite_[i] && neighborhood_.inside_ball(i)) {
          const double falloff = 1 - q.squaredNorm() / ball_squared_radius_;
          add(tangent_coordinates(to_tangent, q), normal.dot(q),
              sampling.weights == Sample_weights::smooth ? falloff * falloff : 1.0);
        }
      }
      return;
    }
    const std::size_t end = neighborhood_.ring_end(sampling.rings); // hoisted: add writes memory
    const auto ring_samples = [&](const auto& weight) {
      for (std::size_t i = Fit::constant_term ? 0 : 1; i < end; ++i) {
        const Vector& q = offsets_[i];
        if (finite_[i])
          add(tangent_coordinates(to_tangent, q), normal.dot(q), weight(q));
      }
    };
    if (sampling.weights == Sample_weights::gaussian)
      ring_samples([](const Vector& q) { return std::exp(-q.squaredNorm()); });
    else
      ring_samples([](const Vector&) { return 1.0; });
  }

  // Calls add(x, height) for each finite sample of the ball, in the frame, from
  // the `first`-th to join it on; returns the number that have joined.
  template <typename Add>
  std::size_t for_each_joined_sample(const Frame& frame, std::size_t first, const Add& add) const
  {
    const Eigen::Matrix<double, D, N> to_tangent = frame.tangents.transpose();
    const std::size_t size = neighborhood_.ball_size();
    for (std::size_t k = first; k < size; ++k) {
      const std::size_t i = neighborhood_.ball_joined(k);
      if (finite_[i])
        add(tangent_coordinates(to_tangent, offsets_[i]), frame.normal.dot(offsets_[i]));
    }
    return size;
  }

  // The largest distance from the vertex to a finite sample of its 1-ring, in units of scale().
  double one_ring_radius() const
  {
    double squared = 0;
    for (std::size_t i = 1; i < neighborhood_.ring_end(1); ++i)
      if (finite_[i])
        squared = (std::max)(squared, offsets_[i].squaredNorm());
    return std::sqrt(squared);
  }

  // A q for A = T^T, as Eigen's product sums it; in R^3 by columns, one assignment per
  // column (Eigen's assignment of the whole sum is a call per sample; two scalar rows
  // stall the packed reads of x).
  static CGAL_CURVATURE_ESTIMATION_INLINE Eigen::Matrix<double, D, 1>
  tangent_coordinates(const Eigen::Matrix<double, D, N>& A, const Vector& q)
  {
    if constexpr (N == 3) {
      Eigen::Matrix<double, D, 1> x = A.col(0) * q[0];
      x += A.col(1) * q[1];
      x += A.col(2) * q[2];
      return x;
    } else
      return A * q;
  }

  // The frame of the least-squares plane of the vertex and its rings up to
  // `rings`, oriented as frame.normal; false where it is not determined.
  bool plane_frame(int rings, Frame& frame) const
  {
    Vector plane = least_squares_hyperplane_normal<N>(offsets_.data(), neighborhood_.ring_end(rings));
    if (!all_finite(plane))
      return false;
    if (plane.dot(frame.normal) < 0)
      plane = -plane;
    frame = frame_of(plane);
    return true;
  }

  // The 1-ring of `v`, and the local length scale that makes the fit scale
  // invariant: `ball_radius` where positive, else the mean distance to the 1-ring.
  bool gather(Vertex v, double ball_radius)
  {
    offsets_.clear();
    ball_neighbors_ = 0;
    exhausted_ = false;
    center_ = neighborhood_.point(v);
    if (!all_finite(center_))
      return false;
    neighborhood_.start(v);
    const std::size_t end = neighborhood_.ring_end(1);
    offsets_.resize(end);
    offsets_[0] = Vector::Zero();
    double length_sum = 0;
    int length_count = 0;
    for (std::size_t i = 1; i < end; ++i) {
      const Vector offset = neighborhood_.point(neighborhood_.vertices()[i]) - center_;
      offsets_[i] = offset;
      const double length = safe_norm(offset);
      if (std::isfinite(length)) {
        length_sum += length;
        ++length_count;
      }
    }
    if (length_count == 0 || !(length_sum > 0))
      return false;
    scale_ = ball_radius > 0 ? ball_radius : length_sum / length_count;
    // A product is cheaper than a division, unless 1 / scale overflows or is subnormal.
    inverse_scale_ = 1 / scale_;
    if (!std::isnormal(inverse_scale_))
      inverse_scale_ = 0;
    finite_.resize(end);
    for (std::size_t i = 0; i < end; ++i) {
      offsets_[i] = to_scale(offsets_[i]);
      finite_[i] = all_finite(offsets_[i]);
    }
    on_border_ = neighborhood_.center_on_border(v);
    return true;
  }

  // Gathers rings up to `rings`; false when the component has fewer, on every
  // call (the collector counts the empty ring it met last).
  CGAL_CURVATURE_ESTIMATION_INLINE bool reach(int rings)
  {
    while (!exhausted_ && neighborhood_.rings() < rings) {
      exhausted_ = !neighborhood_.extend();
      if (!exhausted_)
        append_offsets();
    }
    return exhausted_ ? rings < neighborhood_.rings() : true;
  }

  // Grows the ball to `radius` (in units of the ball radius); false when no
  // vertex joined to it is left outside.
  bool reach_ball(double radius)
  {
    const bool more = neighborhood_.grow_ball(radius * scale_, center_);
    append_offsets();
    ball_neighbors_ = neighborhood_.ball_size() - 1;
    ball_squared_radius_ = radius * radius;
    return more;
  }

  // x - x is 0 for finite x, NaN otherwise: cheaper than Eigen's allFinite per sample.
  template <typename Matrix>
  static bool all_finite(const Matrix& m)
  {
    return (m - m).squaredNorm() == 0;
  }

private:
  // The scaled offsets of the vertices gathered since the last call, and whether each is finite.
  void append_offsets()
  {
    const auto& vertices = neighborhood_.vertices();
    const std::size_t first = offsets_.size();
    offsets_.resize(vertices.size());
    finite_.resize(vertices.size());
    for (std::size_t i = first; i < vertices.size(); ++i) {
      offsets_[i] = to_scale(neighborhood_.point(vertices[i]) - center_);
      finite_[i] = all_finite(offsets_[i]);
    }
  }

  Vector to_scale(const Vector& offset) const
  {
    return inverse_scale_ != 0 ? Vector(offset * inverse_scale_) : Vector(offset / scale_);
  }

  Neighborhood neighborhood_;
  std::vector<Vector> offsets_; // scaled p_w - p_v, aligned with neighborhood_.vertices()
  std::vector<char> finite_;    // whether each offset is finite
  Vector center_ = Vector::Zero();
  double scale_ = 1;
  double inverse_scale_ = 1; // 1 / scale_, or 0 where that is not a normal number
  bool on_border_ = false;
  bool exhausted_ = false;         // whether the rings met an empty one
  std::size_t ball_neighbors_ = 0; // in the ball of the last ball fit, the vertex excluded
  double ball_squared_radius_ = 1; // its squared radius, in units of scale_
};

} // namespace internal
} // namespace Curvature_estimation
} // namespace CGAL

#endif // CGAL_CURVATURE_ESTIMATION_INTERNAL_NEIGHBORHOOD_SAMPLES_H
