// SPDX-License-Identifier: GPL-3.0-or-later
// The differential of the Gauss map at a vertex: by default a least-squares fit of
// the normal's differential over the vertex's 2-ring; or, as Chen, Wu and Chi 2005
// (section 4), per-face gradients of the three normal components (eqs. 19-21),
// combined with centroid weights (eqs. 22-24) or area weights; either projected on
// a tangent frame (eq. 28).
#ifndef CGAL_CURVATURE_ESTIMATION_INTERNAL_GAUSS_MAP_DIFFERENTIAL_H
#define CGAL_CURVATURE_ESTIMATION_INTERNAL_GAUSS_MAP_DIFFERENTIAL_H

#include <CGAL/Curvature_estimation/internal/rings.h>
#include <CGAL/Curvature_estimation/internal/shape_matrix_estimate.h>
#include <CGAL/Curvature_estimation/internal/tangent_frame.h>
#include <CGAL/Curvature_estimation/internal/vertex_normal_table.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <boost/graph/graph_traits.hpp>

#include <Eigen/Core>

#include <cmath>
#include <cstddef>
#include <limits>
#include <memory>
#include <utility>
#include <vector>

namespace CGAL {
namespace Curvature_estimation {
namespace internal {

// Accumulates sum_f w_f J_f / sum_f w_f, J_f the 3x3 Jacobian of the normal on
// face f at the corner of the vertex p, of the linear interpolation of N over the
// corner (p, q_j, q_k): J_f = [N_j - N_p, N_k - N_p] Gram^-1 [q_j - p, q_k - p]^T
// (eqs. 19-21); w_f = 1 / |G_f - p|^2 (eq. 23) with `centroid_weights`, else the
// corner's doubled area |(q_j - p) x (q_k - p)|. Pure and allocation-free.
class Gauss_map_differential
{
public:
  explicit Gauss_map_differential(bool centroid_weights = true)
      : centroid_weights_(centroid_weights)
  {}

  void clear()
  {
    sum_ = infinite_sum_ = Eigen::Matrix3d::Zero();
    weight_sum_ = 0;
    infinite_count_ = 0;
  }

  // One face at p: `e_next`, `e_prev` the offsets of the face's vertices after and
  // before p, `dn_next`, `dn_prev` their normals minus p's, `centroid` the offset
  // of the face's centroid. A corner whose edges are (nearly) parallel gives no
  // gradient and is skipped. A face whose centroid is p (a non-convex polygon) has
  // an infinite weight: such faces alone then give the result.
  void add_corner(const Eigen::Vector3d& e_next, const Eigen::Vector3d& e_prev, const Eigen::Vector3d& dn_next,
                  const Eigen::Vector3d& dn_prev, const Eigen::Vector3d& centroid)
  {
    const double a = e_next.squaredNorm(), b = e_next.dot(e_prev), c = e_prev.squaredNorm();
    const double det = a * c - b * b;
    if (!(det > 1e-24 * a * c) || !std::isfinite(det))
      return;
    Eigen::Matrix<double, 3, 2> dn, edges;
    dn << dn_next, dn_prev;
    edges << e_next, e_prev;
    Eigen::Matrix2d inverse_gram;
    inverse_gram << c, -b, -b, a;
    inverse_gram /= det;
    const Eigen::Matrix3d jacobian = dn * inverse_gram * edges.transpose();
    if (!jacobian.allFinite())
      return;
    const double w = centroid_weights_ ? 1 / centroid.squaredNorm() : std::sqrt(det);
    if (std::isfinite(w)) {
      sum_ += w * jacobian;
      weight_sum_ += w;
    } else {
      infinite_sum_ += jacobian;
      ++infinite_count_;
    }
  }

  bool empty() const { return infinite_count_ == 0 && !(weight_sum_ > 0); }

  // The 3x3 differential dN (dN(u) = differential() u).
  Eigen::Matrix3d differential() const
  {
    return infinite_count_ > 0 ? Eigen::Matrix3d(infinite_sum_ / infinite_count_) : Eigen::Matrix3d(sum_ / weight_sum_);
  }

  // a_ij = <e_i, dN(e_j)> in the frame (eq. 28); with outward normals a sphere of
  // radius r gives I / r, the package's sign (the paper's H = -trace/2 is for the
  // opposite normal).
  Eigen::Matrix2d shape_matrix(const Tangent_frame& tangents) const
  {
    return tangents.transpose() * differential() * tangents;
  }

private:
  Eigen::Matrix3d sum_ = Eigen::Matrix3d::Zero(), infinite_sum_ = Eigen::Matrix3d::Zero();
  double weight_sum_ = 0;
  int infinite_count_ = 0;
  bool centroid_weights_ = true;
};

// The least-squares differential of the normal at p in the tangent frame T of p's
// normal: the 2x2 A minimising sum_i |T^T (N_i - N_p) - A T^T (q_i - p)|^2 over the
// neighbors q_i, all at once and unweighted (a neighbor nearly coincident with p
// weighs as its squared distance): A = B M^-1, M = sum x_i x_i^T, B = sum d_i x_i^T,
// x_i = T^T (q_i - p), d_i = T^T (N_i - N_p). Exact for exact normals of a sphere.
// Pure and allocation-free.
class Gauss_map_least_squares
{
public:
  void clear() { moments_ = products_ = Eigen::Matrix2d::Zero(); }

  void add(const Tangent_frame& tangents, const Eigen::Vector3d& offset, const Eigen::Vector3d& normal_difference)
  {
    const Eigen::Vector2d x = tangents.transpose() * offset, d = tangents.transpose() * normal_difference;
    if (!x.allFinite() || !d.allFinite())
      return;
    moments_ += x * x.transpose();
    products_ += d * x.transpose();
  }

  // False when the projected neighbors lie on a line through p (or there are
  // none). B M^-1 does not change under a linear change of tangent coordinates, so
  // only a singular M is refused: det M / tr(M)^2 below 1e-12 (1/4 when isotropic).
  bool determined() const
  {
    const double trace = moments_.trace();
    return trace > 0 && std::isfinite(trace) && moments_.determinant() > 1e-12 * trace * trace;
  }

  Eigen::Matrix2d shape_matrix() const { return products_ * moments_.inverse(); }

private:
  Eigen::Matrix2d moments_ = Eigen::Matrix2d::Zero(), products_ = Eigen::Matrix2d::Zero();
};

// How Gauss_map_estimator combines the normals around a vertex.
enum class Gauss_map_differential_method : unsigned char
{
  least_squares_2_ring,   // Gauss_map_least_squares over the vertices of the 2-ring (the default)
  face_centroid_weighted, // Gauss_map_differential, centroid weights: Chen, Wu and Chi's
  face_area_weighted      // Gauss_map_differential, area weights
};

// The rings of the least squares of least_squares_2_ring.
constexpr int gauss_map_rings = 2;

// A shared Vertex_normal_table as the normals of Gauss_map_estimator.
template <typename FaceGraph>
struct Shared_vertex_normals
{
  std::shared_ptr<const Vertex_normal_table<FaceGraph>> table;

  bool find(typename boost::graph_traits<FaceGraph>::vertex_descriptor u, Eigen::Vector3d& n) const
  {
    return table->find(u, n);
  }
  double reach(typename boost::graph_traits<FaceGraph>::vertex_descriptor u) const { return table->reach(u); }
};

// The Gauss-map estimate at one vertex of a FaceGraph (faces: any polygons;
// border halfedges are skipped, so boundary vertices use the faces they have),
// with the unit normals of `Normals`: find(u, n), false where u has none
// (Shared_vertex_normals, or normals computed on demand). The least squares are
// over the 2-ring (the manual says why).
template <typename FaceGraph, typename VertexPointMap, typename Normals = Shared_vertex_normals<FaceGraph>>
class Gauss_map_estimator
{
public:
  using vertex_descriptor = typename boost::graph_traits<FaceGraph>::vertex_descriptor;
  using halfedge_descriptor = typename boost::graph_traits<FaceGraph>::halfedge_descriptor;

  // The normals are those of `Normals`.
  static constexpr bool uses_given_normals = false;

  // With a `ball_radius` (> 0, least_squares_2_ring only), the least squares are
  // over the ball of that radius instead of the 2-ring (see ball_least_squares).
  Gauss_map_estimator(const FaceGraph& g, VertexPointMap vpm, Normals normals,
                      Gauss_map_differential_method method = Gauss_map_differential_method::least_squares_2_ring,
                      double ball_radius = 0)
      : local_(g, vpm)
      , normals_(std::move(normals))
      , method_(method)
      , differential_(method == Gauss_map_differential_method::face_centroid_weighted)
      , ball_radius_(ball_radius)
  {}

  // The estimate, whose reach is that of the ball of the least squares and of the balls of the
  // normals read, from v.
  Surface_estimate estimate(vertex_descriptor v, const Eigen::Vector3d*)
  {
    reach_ = 0;
    center_ = v;
    Surface_estimate e = estimate_at(v);
    const double ball = rings_.widest_squared_ball(v);
    e.reach = ball > 0 ? (std::max)(reach_, std::sqrt(ball) * local_.scale()) : reach_;
    return e;
  }

private:
  Surface_estimate estimate_at(vertex_descriptor v)
  {
    Eigen::Vector3d normal;
    if (!lookup(v, normal) || !local_.center_on(v))
      return Surface_estimate();
    const FaceGraph& g = local_.graph();

    const Tangent_frame tangents = tangent_basis<3>(normal);
    if (method_ == Gauss_map_differential_method::least_squares_2_ring) {
      rings_.start(v, g);
      if (ball_radius_ > 0)
        return ball_least_squares(tangents, normal);
      for (int ring = 1; ring < gauss_map_rings; ++ring)
        rings_.extend(g);
      if (!fit_least_squares(tangents, normal, false))
        return Surface_estimate();
      return shape_estimate_from_matrix(least_squares_.shape_matrix(), tangents, normal, local_.scale(), true);
    }

    differential_.clear();
    for (halfedge_descriptor h : halfedges_around_target(v, g)) {
      if (is_border(h, g))
        continue;
      // Around the face from h (target v): the next vertex, the centroid, and the
      // previous vertex, source(h).
      const vertex_descriptor next_vertex = target(next(h, g), g), previous_vertex = source(h, g);
      Eigen::Vector3d vertex_sum = Eigen::Vector3d::Zero();
      int n = 0;
      for (halfedge_descriptor k : halfedges_around_face(h, g)) {
        vertex_sum += local_(target(k, g));
        ++n;
      }
      Eigen::Vector3d next_normal, previous_normal;
      if (!vertex_sum.allFinite() || !lookup(next_vertex, next_normal) || !lookup(previous_vertex, previous_normal))
        continue;
      differential_.add_corner(local_(next_vertex), local_(previous_vertex), next_normal - normal,
                               previous_normal - normal, vertex_sum / n);
    }
    if (differential_.empty())
      return Surface_estimate();
    return shape_estimate_from_matrix(differential_.shape_matrix(tangents), tangents, normal, local_.scale(), true);
  }

  // The normal of u, whose reach (of its balls, if any) from the vertex estimated at joins reach_.
  bool lookup(vertex_descriptor u, Eigen::Vector3d& n)
  {
    const bool found = normals_.find(u, n);
    const double reach = normals_.reach(u);
    if (reach > 0) // local_ is centered on center_ once its own normal is found
      reach_ = (std::max)(reach_, (u == center_ ? 0 : local_(u).norm() * local_.scale()) + reach);
    return found;
  }

  // Gauss_map_least_squares over the vertices gathered by rings_ (in the ball
  // only, with `in_ball`); whether it is determined.
  bool fit_least_squares(const Tangent_frame& tangents, const Eigen::Vector3d& normal, bool in_ball)
  {
    least_squares_.clear();
    const std::vector<vertex_descriptor>& neighbors = rings_.vertices();
    Eigen::Vector3d neighbor_normal;
    for (std::size_t i = 1; i < neighbors.size(); ++i)
      if ((!in_ball || rings_.inside_ball(i)) && lookup(neighbors[i], neighbor_normal))
        least_squares_.add(tangents, local_(neighbors[i]), neighbor_normal - normal);
    return least_squares_.determined();
  }

  // The least squares over the ball of radius ball_radius_, grown as
  // fit_in_growing_ball says (to at least twice the 3 vertices that determine the
  // differential, then while it is not determined); status widened where it grew.
  Surface_estimate ball_least_squares(const Tangent_frame& tangents, const Eigen::Vector3d& normal)
  {
    const FaceGraph& g = local_.graph();
    const int growths = fit_in_growing_ball(
      ball_radius_ / local_.scale(), 3,
      [&](double radius) {
        return rings_.grow_ball(g, radius * radius, [&](vertex_descriptor w) { return local_(w).squaredNorm(); });
      },
      [&] { return rings_.ball_size(); }, [&] { return fit_least_squares(tangents, normal, true); });
    if (growths == 0)
      return Surface_estimate();
    Surface_estimate e =
      shape_estimate_from_matrix(least_squares_.shape_matrix(), tangents, normal, local_.scale(), true);
    if (growths > 1 && e.status == Estimation_status::ok)
      e.status = Estimation_status::widened;
    return e;
  }

  Vertex_local_coordinates<FaceGraph, VertexPointMap> local_;
  Normals normals_;
  Gauss_map_differential_method method_;
  Gauss_map_differential differential_;
  Gauss_map_least_squares least_squares_;
  Ring_collector<FaceGraph> rings_;
  double ball_radius_ = 0;
  vertex_descriptor center_{}; // the vertex estimated at
  double reach_ = 0;           // of the normals read there
};

} // namespace internal
} // namespace Curvature_estimation
} // namespace CGAL

#endif // CGAL_CURVATURE_ESTIMATION_INTERNAL_GAUSS_MAP_DIFFERENTIAL_H
