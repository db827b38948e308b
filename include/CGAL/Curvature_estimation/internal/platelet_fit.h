// SPDX-License-Identifier: GPL-3.0-or-later
// Hamann's platelet fit at one vertex, written once for surfaces of R^3
// (FaceGraph, tangent dimension 2) and hypersurfaces of R^4 (tetrahedral
// complexes, tangent dimension 3): gather the k-ring, express it in a tangent
// frame, fit the paraboloid, widen while ill-conditioned; and the second-order
// normal that the fit uses by default.
//
// The core, Platelet_fit_core<Neighborhood>, knows nothing of meshes. A
// Neighborhood policy gives
//   ambient_dimension, Vertex, Estimate     N (3 or 4), the vertex key, the result type
//   point(v)                                the point of v in double
//   start(v), extend(), rings(), vertices(), ring_end(r)
//                                           the k-rings of v, grown one ring at a time
//   center_on_border(v)                     after start(v)
//   platelet_for_normal(method)             whether initial_normal needs the gathered 1-ring
//   initial_normal(v, method, gathered, offsets, finite, scale)
//                                           the first-order normal (any length); where
//                                           gathered, offsets are the 1-ring relative to v,
//                                           over scale, finite[i] whether offsets[i] is
//   restart_from_hyperplane                 see estimate_normal
//   estimate(status, curvature, scale)      the result from the curvature in the fit's frame
// Models: Face_graph_platelet (here) and Tetrahedral_platelet (tetrahedral_platelet_fit.h).
#ifndef CGAL_CURVATURE_ESTIMATION_INTERNAL_PLATELET_FIT_H
#define CGAL_CURVATURE_ESTIMATION_INTERNAL_PLATELET_FIT_H

#include <CGAL/Curvature_estimation/Principal_curvatures_and_directions.h>
#include <CGAL/Curvature_estimation/parameters.h>
#include <CGAL/Curvature_estimation/internal/face_average_normal.h>
#include <CGAL/Curvature_estimation/internal/neighborhood.h>
#include <CGAL/Curvature_estimation/internal/quadric_fit.h>
#include <CGAL/Curvature_estimation/internal/shape_operator.h>
#include <CGAL/Curvature_estimation/internal/surface_estimate.h>
#include <CGAL/Curvature_estimation/internal/tangent_frame.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/number_utils.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Curvature_estimation {
namespace internal {

struct Platelet_fit_settings
{
  int rings = 1;            // rings an interior vertex starts with
  int boundary_rings = 1;   // rings a boundary vertex starts with
  int max_rings = 3;        // widening stops here
  double max_condition = 1e3;
  // Whether test (b) of quadric_fit.h (whitened coordinates) may accept the
  // widest neighborhood where test (a) refuses every one; false: test (a) alone.
  bool whitened_conditioning = true;
};

// The settings from the named parameters, with the documented defaults;
// `caller` names the public function in error messages.
template <typename NamedParameters>
Platelet_fit_settings platelet_fit_settings(const NamedParameters& np, const char* caller)
{
  Platelet_fit_settings settings;
  settings.rings = parameter_or(np, internal_np::neighborhood_rings, 1);
  settings.boundary_rings = parameter_or(np, internal_np::boundary_neighborhood_rings, settings.rings);
  settings.max_rings = parameter_or(np, internal_np::max_neighborhood_rings, 3);
  settings.max_condition = parameter_or(np, internal_np::max_condition_number, 1e3);
  const std::string where = std::string(caller) + ": ";
  if (settings.rings < 1 || settings.boundary_rings < 1)
    throw std::invalid_argument(where + "neighborhood_rings and boundary_neighborhood_rings must be at least 1");
  if (settings.max_rings < settings.rings || settings.max_rings < settings.boundary_rings)
    throw std::invalid_argument(where + "max_neighborhood_rings must be at least the starting rings");
  if (!(settings.max_condition > 1))
    throw std::invalid_argument(where + "max_condition_number must be greater than 1");
  return settings;
}

// The cubic fit of a boundary normal: over at least 3 rings (with 2, an edge
// vertex of a grid has only three rows of samples, too few for cubic terms in
// the normal direction), Gaussian weights of width the mean 1-ring edge
// (the quartic remainder, largest at the far samples, otherwise leaks into the
// gradient through a one-sided stencil), and a condition threshold 1000 times
// the quadratic one (well-posed cubic stencils show about 1e4, the ones that
// are singular in the tangent plane above 1e16).
constexpr int cubic_normal_min_rings = 3;
constexpr double cubic_normal_condition_factor = 1e3;

// The unit normal of the least-squares hyperplane through `count` points: the
// eigenvector of the smallest eigenvalue of their scatter matrix, by cyclic
// Jacobi rotations (Eigen's iterative solver warns under GCC 12's -Wmaybe-uninitialized).
template <int N>
Eigen::Matrix<double, N, 1> least_squares_hyperplane_normal(const Eigen::Matrix<double, N, 1>* points,
                                                            std::size_t count)
{
  using Vector = Eigen::Matrix<double, N, 1>;
  using Square = Eigen::Matrix<double, N, N>;
  Vector mean = Vector::Zero();
  for (std::size_t i = 0; i < count; ++i)
    mean += points[i];
  mean /= double(count);
  Square scatter = Square::Zero();
  for (std::size_t i = 0; i < count; ++i)
    scatter.noalias() += (points[i] - mean) * (points[i] - mean).transpose();
  Square vectors = Square::Identity();
  for (int sweep = 0; sweep < 50; ++sweep) {
    double off = 0;
    for (int p = 0; p < N; ++p)
      for (int q = p + 1; q < N; ++q)
        off += scatter(p, q) * scatter(p, q);
    if (!(off > 1e-30 * scatter.squaredNorm()))
      break;
    for (int p = 0; p < N; ++p)
      for (int q = p + 1; q < N; ++q) {
        if (scatter(p, q) == 0)
          continue;
        const double theta = 0.5 * (scatter(q, q) - scatter(p, p)) / scatter(p, q);
        const double t = (theta >= 0 ? 1.0 : -1.0) / (std::abs(theta) + std::sqrt(theta * theta + 1));
        const double c = 1 / std::sqrt(t * t + 1), s = t * c;
        for (int k = 0; k < N; ++k) {  // scatter <- J^T scatter J, vectors <- vectors J
          const double a = scatter(k, p), b = scatter(k, q);
          scatter(k, p) = c * a - s * b;
          scatter(k, q) = s * a + c * b;
        }
        for (int k = 0; k < N; ++k) {
          const double a = scatter(p, k), b = scatter(q, k);
          scatter(p, k) = c * a - s * b;
          scatter(q, k) = s * a + c * b;
        }
        for (int k = 0; k < N; ++k) {
          const double a = vectors(k, p), b = vectors(k, q);
          vectors(k, p) = c * a - s * b;
          vectors(k, q) = s * a + c * b;
        }
      }
  }
  int smallest = 0;
  scatter.diagonal().minCoeff(&smallest);
  return vectors.col(smallest);
}

template <typename Neighborhood>
class Platelet_fit_core
{
public:
  static constexpr int N = Neighborhood::ambient_dimension;
  static constexpr int D = N - 1;
  using Vertex = typename Neighborhood::Vertex;
  using Estimate = typename Neighborhood::Estimate;
  using Vector = Eigen::Matrix<double, N, 1>;
  using Tangents = Eigen::Matrix<double, N, D>;

  // `a` and `b` construct the neighborhood: the mesh and its point map.
  template <typename A, typename B>
  Platelet_fit_core(const A& a, const B& b, const Platelet_fit_settings& settings)
    : neighborhood_(a, b), settings_(settings)
  {}

  // Hamann's fit: the paraboloid through the k-ring in the tangent frame of the
  // given `normal` (any length), widened while ill-conditioned.
  Estimate fit(Vertex v, const Vector& normal)
  {
    const double length = normal.norm();
    if (!(length > 0) || !std::isfinite(length) || !gather(v))
      return Estimate();
    return fit_curvature(normal / length);
  }

  // The same with the normal estimated by `method`.
  Estimate fit(Vertex v, Vertex_normal_method method)
  {
    Vector normal;
    if (!gather(v) || !estimate_normal(v, method, true, normal))
      return Estimate();
    return fit_curvature(normal);
  }

  // The unit normal by `method`; false where there is none.
  bool normal(Vertex v, Vertex_normal_method method, Vector& normal)
  {
    const bool gathered = neighborhood_.platelet_for_normal(method);
    if (gathered && !gather(v))
      return false;
    return estimate_normal(v, method, gathered, normal);
  }

private:
  // The 1-ring, and the local length scale (mean distance to the 1-ring) that
  // makes the fit scale invariant.
  bool gather(Vertex v)
  {
    center_ = neighborhood_.point(v);
    if (!all_finite(center_))
      return false;
    neighborhood_.start(v);
    offsets_.clear();
    offsets_.push_back(Vector::Zero());
    double length_sum = 0;
    int length_count = 0;
    const std::size_t end = neighborhood_.ring_end(1);
    for (std::size_t i = 1; i < end; ++i) {
      const Vector offset = neighborhood_.point(neighborhood_.vertices()[i]) - center_;
      offsets_.push_back(offset);
      double length = offset.norm();
      if (!(length > 1e-150 && length < 1e150))
        length = offset.stableNorm();  // no overflow or underflow for huge or tiny meshes
      if (std::isfinite(length)) {
        length_sum += length;
        ++length_count;
      }
    }
    if (length_count == 0 || !(length_sum > 0))
      return false;
    scale_ = length_sum / length_count;
    // A product is cheaper than a division and as exact to rounding, unless 1 / scale
    // overflows or is subnormal.
    inverse_scale_ = 1 / scale_;
    if (!std::isnormal(inverse_scale_))
      inverse_scale_ = 0;
    finite_.clear();
    for (Vector& offset : offsets_) {
      offset = to_scale(offset);
      finite_.push_back(all_finite(offset));
    }
    on_border_ = neighborhood_.center_on_border(v);
    curvature_rings_ = 0;
    return true;
  }

  Vector to_scale(const Vector& offset) const
  {
    return inverse_scale_ != 0 ? Vector(offset * inverse_scale_) : Vector(offset / scale_);
  }

  // x - x is 0 for finite x and NaN otherwise: one branch-free test for all
  // coefficients, cheaper than Eigen's allFinite in these per-sample checks.
  template <typename Matrix>
  static bool all_finite(const Matrix& m)
  {
    return (m - m).squaredNorm() == 0;
  }

  int start_rings() const { return on_border_ ? settings_.boundary_rings : settings_.rings; }

  // Gathers rings up to `rings`; false when the component has fewer.
  bool reach(int rings)
  {
    while (neighborhood_.rings() < rings) {
      if (!neighborhood_.extend())
        return false;
      for (std::size_t i = offsets_.size(); i < neighborhood_.vertices().size(); ++i) {
        offsets_.push_back(to_scale(neighborhood_.point(neighborhood_.vertices()[i]) - center_));
        finite_.push_back(all_finite(offsets_.back()));
      }
    }
    return true;
  }

  // Fits over the rings up to `rings`, widening up to `max_rings` until test (a)
  // of quadric_fit.h (conditioning in the scaled tangent coordinates) accepts;
  // returns the rings used, 0 if it accepts none.
  template <typename Fit>
  int fit_widening(const Vector& normal, const Tangents& tangents, int rings, int max_rings, double max_condition,
                   Fit& fit)
  {
    for (; rings <= max_rings && reach(rings); ++rings)
      if (fit_in_frame(normal, tangents, rings, max_condition, fit))
        return rings;
    return 0;
  }

  // Where test (a) accepts no neighborhood from `rings` to `max_rings`: the
  // widest of them, if test (b) of quadric_fit.h (conditioning in whitened
  // coordinates) accepts it, 0 otherwise. A neighborhood that only whitening
  // makes well-conditioned is anisotropic or uneven; over the data meshes of
  // test_cgal_data_meshes its fits agree better with a reference on the widest
  // neighborhood than on the narrowest that test (b) accepts.
  template <typename Fit>
  int fit_whitened(const Vector& normal, const Tangents& tangents, int rings, int max_rings, double max_condition,
                   Fit& fit)
  {
    if (!settings_.whitened_conditioning)
      return 0;
    int widest = 0;
    for (; rings <= max_rings && reach(rings); ++rings)
      widest = rings;
    const auto samples = [&](const auto& add) { for_each_sample<Fit>(normal, tangents, widest, add); };
    return widest != 0 && fit.solve_whitened(max_condition, samples) ? widest : 0;
  }

  // The neighborhood's first-order normal, or for quadric_fit a normal of second
  // order or better: that normal corrected by the gradient of a Taylor fit in its
  // frame (see fit_normal). `gathered`: whether gather(v) has succeeded.
  bool estimate_normal(Vertex v, Vertex_normal_method method, bool gathered, Vector& normal)
  {
    normal = neighborhood_.initial_normal(v, method, gathered, offsets_, finite_, scale_);
    if (!all_finite(normal) || !(normal.squaredNorm() > 0))
      return false;
    normal.normalize();
    if (method != Vertex_normal_method::quadric_fit)
      return true;
    if constexpr (!Neighborhood::restart_from_hyperplane)
      return fit_normal(normal);
    else {
      const Vector first = normal;
      if (fit_normal(normal))
        return true;
      // Start again from the normal of the best-fitting hyperplane through the
      // 1-ring (oriented as the first one): see Tetrahedral_platelet.
      normal = least_squares_hyperplane_normal<N>(offsets_.data(), neighborhood_.ring_end(1));
      if (normal.dot(first) < 0)
        normal = -normal;
      return all_finite(normal) && fit_normal(normal);
    }
  }

  // A symmetric interior stencil cancels the odd terms, so the degree-2 fit over
  // the starting rings suffices there; a one-sided boundary stencil does not, and
  // a boundary vertex fits the cubic terms too, falling back to degree 2 where
  // that is ill-conditioned up to the widest ring.
  bool fit_normal(Vector& normal)
  {
    const Tangents tangents = tangent_basis<N>(normal);
    const int cubic_rings = (std::max)(cubic_normal_min_rings, start_rings());
    const int cubic_max_rings = (std::max)(cubic_rings, settings_.max_rings);
    const double cubic_condition = cubic_normal_condition_factor * settings_.max_condition;
    if (on_border_) {
      Taylor_fit<D, 1, 3> cubic;
      if (fit_widening(normal, tangents, cubic_rings, cubic_max_rings, cubic_condition, cubic) != 0)
        return correct_normal(normal, tangents, cubic.gradient());
    }
    Taylor_fit<D, 1, 2> quadratic;
    if (fit_widening(normal, tangents, start_rings(), settings_.max_rings, settings_.max_condition, quadratic) != 0)
      return correct_normal(normal, tangents, quadratic.gradient());
    // Test (b), in the same order, where test (a) accepts neither fit.
    if (on_border_) {
      Taylor_fit<D, 1, 3> cubic;
      curvature_rings_ = fit_whitened(normal, tangents, cubic_rings, cubic_max_rings, cubic_condition, cubic);
      if (curvature_rings_ != 0)
        return correct_normal(normal, tangents, cubic.gradient());
    }
    curvature_rings_ =
      fit_whitened(normal, tangents, start_rings(), settings_.max_rings, settings_.max_condition, quadratic);
    return curvature_rings_ != 0 && correct_normal(normal, tangents, quadratic.gradient());
  }

  static bool correct_normal(Vector& normal, const Tangents& tangents, const Eigen::Matrix<double, D, 1>& gradient)
  {
    normal = (normal - tangents * gradient).normalized();
    return all_finite(normal);
  }

  Estimate fit_curvature(const Vector& normal)
  {
    const Tangents tangents = tangent_basis<N>(normal);
    Taylor_fit<D, 2, 2> fit;
    const int first = curvature_rings_ != 0 ? (std::min)(curvature_rings_, settings_.max_rings) : start_rings();
    int rings = fit_widening(normal, tangents, first, settings_.max_rings, settings_.max_condition, fit);
    if (rings == 0)
      rings = fit_whitened(normal, tangents, first, settings_.max_rings, settings_.max_condition, fit);
    if (rings == 0)
      return Estimate();
    const Graph_curvature<N> curvature = graph_curvature<N>(fit.hessian(), fit.gradient(), tangents, normal);
    if (!all_finite(curvature.curvatures) || !all_finite(curvature.directions))
      return Estimate();
    return Neighborhood::estimate(rings > 1 ? Estimation_status::widened : Estimation_status::ok, curvature, scale_);
  }

  template <typename Fit>
  bool fit_in_frame(const Vector& normal, const Tangents& tangents, int rings, double max_condition, Fit& fit) const
  {
    fit.clear();
    for_each_sample<Fit>(normal, tangents, rings, [&](const auto& x, double height, double weight) {
      fit.add(x, height, weight);
    });
    return fit.solve(max_condition);
  }

  // Calls add(x, height, weight) for each sample of the rings up to `rings` in
  // the frame: samples weighted by a Gaussian of width the mean 1-ring edge in
  // the cubic fit only (see cubic_normal_min_rings); Hamann's fit is unweighted.
  template <typename Fit, typename Add>
  void for_each_sample(const Vector& normal, const Tangents& tangents, int rings, const Add& add) const
  {
    constexpr bool weighted = Fit::unknowns > Taylor_fit<D, 1, 2>::unknowns;
    const Eigen::Matrix<double, D, N> to_tangent = tangents.transpose();
    const std::size_t end = neighborhood_.ring_end(rings);  // hoisted: add writes memory
    for (std::size_t i = 1; i < end; ++i) {
      const Vector& q = offsets_[i];
      if (finite_[i])
        add(Eigen::Matrix<double, D, 1>(to_tangent * q), normal.dot(q), weighted ? std::exp(-q.squaredNorm()) : 1.0);
    }
  }

  Neighborhood neighborhood_;
  Platelet_fit_settings settings_;
  std::vector<Vector> offsets_;  // scaled p_w - p_v, aligned with neighborhood_.vertices()
  std::vector<char> finite_;     // whether each offset is finite
  Vector center_ = Vector::Zero();
  double scale_ = 1;
  double inverse_scale_ = 1;     // 1 / scale_, or 0 where that is not a normal number
  bool on_border_ = false;
  // Where the normal fit needed test (b), the curvature fit starts on the rings
  // that gave the normal (the widest; the narrower ones failed test (a) for the
  // normal). 0: it starts on the settings' rings.
  int curvature_rings_ = 0;
};

// The neighborhood policy of a FaceGraph: k-rings by halfedge circulation, the
// area-weighted normal (or another face average) as the first-order normal.
template <typename FaceGraph, typename VertexPointMap>
class Face_graph_platelet
{
public:
  static constexpr int ambient_dimension = 3;
  static constexpr bool restart_from_hyperplane = false;
  using Vertex = typename boost::graph_traits<FaceGraph>::vertex_descriptor;
  using Estimate = Surface_estimate;

  Face_graph_platelet(const FaceGraph& g, VertexPointMap vpm) : g_(&g), vpm_(vpm) {}

  Eigen::Vector3d point(Vertex v) const { return point_in_double(vpm_, v); }
  void start(Vertex v) { rings_.start(v, *g_); }
  bool extend() { return rings_.extend(*g_); }
  int rings() const { return rings_.rings(); }
  const std::vector<Vertex>& vertices() const { return rings_.vertices(); }
  std::size_t ring_end(int r) const { return rings_.ring_end(r); }
  bool center_on_border(Vertex) const { return rings_.center_on_border(); }

  // Face averages need no neighborhood.
  static bool platelet_for_normal(Vertex_normal_method method) { return method == Vertex_normal_method::quadric_fit; }

  // The area-weighted normal from the gathered 1-ring for quadric_fit, and for
  // area_weighted where the 1-ring is gathered and its faces are triangles (the same
  // normal, without walking the faces again); else the face average by `method`.
  Eigen::Vector3d initial_normal(Vertex v, Vertex_normal_method method, bool gathered,
                                 const std::vector<Eigen::Vector3d>& offsets, const std::vector<char>& finite,
                                 double) const
  {
    const bool from_ring = method == Vertex_normal_method::quadric_fit ||
                           (gathered && method == Vertex_normal_method::area_weighted && rings_.faces_are_triangles());
    return from_ring ? corner_normal_sum(v, offsets, finite) : face_average_normal(v, *g_, vpm_, method);
  }

  static Surface_estimate estimate(Estimation_status status, const Graph_curvature<3>& curvature, double scale)
  {
    return Surface_estimate::from_principal(status, curvature.curvatures[0] / scale, curvature.curvatures[1] / scale,
                                            curvature.directions.col(0), curvature.directions.col(1),
                                            curvature.normal);
  }

private:
  // The sum of the faces' corner normals at the center, from the gathered 1-ring:
  // the area-weighted normal on a triangle mesh, without walking the faces again.
  Eigen::Vector3d corner_normal_sum(Vertex v, const std::vector<Eigen::Vector3d>& offsets,
                                    const std::vector<char>& finite) const
  {
    if (!rings_.one_ring_in_fan_order())
      return face_average_normal(v, *g_, vpm_, Vertex_normal_method::area_weighted);
    const std::size_t valence = rings_.ring_end(1) - 1;
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (std::size_t k = 0; k < valence; ++k) {
      const std::size_t next = k + 1 < valence ? k + 2 : 1;
      if (rings_.has_face(k) && finite[1 + k] && finite[next])
        sum += offsets[next].cross(offsets[1 + k]);
    }
    return sum;
  }

  const FaceGraph* g_;
  VertexPointMap vpm_;
  Ring_collector<FaceGraph> rings_;
};

template <typename FaceGraph, typename VertexPointMap>
using Platelet_fitter = Platelet_fit_core<Face_graph_platelet<FaceGraph, VertexPointMap>>;

} // namespace internal
} // namespace Curvature_estimation
} // namespace CGAL

#endif // CGAL_CURVATURE_ESTIMATION_INTERNAL_PLATELET_FIT_H
