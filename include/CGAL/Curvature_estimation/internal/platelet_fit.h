// SPDX-License-Identifier: GPL-3.0-or-later
// Hamann's platelet fit at one vertex, written once for surfaces of R^3
// (FaceGraph, tangent dimension 2) and hypersurfaces of R^4 (tetrahedral
// complexes, tangent dimension 3): gather the k-ring, express it in a tangent
// frame, fit the paraboloid, widen while ill-conditioned; and the second-order
// normal that the fit uses by default. Its settings come from fit_parameters.h.
//
// The core, Platelet_fit_core<Neighborhood>, knows nothing of meshes. A
// Neighborhood policy gives
//   ambient_dimension, Vertex, Estimate     N (3 or 4), the vertex key, the result type
//   point(v)                                the point of v in double
//   start(v), extend(), rings(), vertices(), ring_end(r)
//                                           the k-rings of v, grown one ring at a time
//   grow_ball(radius, center), inside_ball(i), ball_size()
//                                           after start(v), instead of extend(): the vertices
//                                           joined to v inside the ball of that radius about
//                                           center, the point of v (see Ring_collector::grow_ball)
//   center_on_border(v)                     after start(v)
//   platelet_for_normal(method)             whether initial_normal needs the gathered 1-ring
//   initial_normal(v, method, gathered, offsets, finite, scale)
//                                           the first-order normal (any length); where
//                                           gathered, offsets are the 1-ring relative to v,
//                                           over scale, finite[i] whether offsets[i] is
//   restart_from_hyperplane                 see estimate_normal
//   estimate(status, curvature, scale)      the result from the curvature in the fit's frame
// Models: Face_graph_platelet (face_graph_platelet.h) and Tetrahedral_platelet
// (tetrahedral_platelet_fit.h).
#ifndef CGAL_CURVATURE_ESTIMATION_INTERNAL_PLATELET_FIT_H
#define CGAL_CURVATURE_ESTIMATION_INTERNAL_PLATELET_FIT_H

#include <CGAL/Curvature_estimation/Principal_curvatures_and_directions.h>
#include <CGAL/Curvature_estimation/Vertex_normal_method.h>
#include <CGAL/Curvature_estimation/internal/fit_parameters.h>
#include <CGAL/Curvature_estimation/internal/local_coordinates.h>
#include <CGAL/Curvature_estimation/internal/quadric_fit.h>
#include <CGAL/Curvature_estimation/internal/shape_operator.h>
#include <CGAL/Curvature_estimation/internal/surface_estimate.h>
#include <CGAL/Curvature_estimation/internal/symmetric_eigen.h>
#include <CGAL/Curvature_estimation/internal/tangent_frame.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Curvature_estimation {
namespace internal {

// The cubic fit of a boundary normal: over at least 3 rings (with 2, an edge
// vertex of a grid has only three rows of samples, too few for cubic terms in
// the normal direction), Gaussian weights of width the mean 1-ring edge
// (the quartic remainder, largest at the far samples, otherwise leaks into the
// gradient through a one-sided stencil), and a condition threshold 1000 times
// the quadratic one (well-posed cubic stencils show about 1e4, the ones that
// are singular in the tangent plane above 1e16).
constexpr int cubic_normal_min_rings = 3;
constexpr double cubic_normal_condition_factor = 1e3;

// The condition thresholds of the fits of fit_degree 3 and 4, over the quadratic
// one (1e5 and 1e8 by default). Measured on the Delaunay and marching-tetrahedra
// test meshes: at these values the degree-3 fit widens no Delaunay vertex and
// 4% to 7% of the marching-tetrahedra vertices (1-rings of nearly coincident
// vertices), whose wider fits have maxima 2 to 3 times smaller than their 2-ring
// fits accepted at 1e6; ten times lower widens 30% of them and triples the
// Delaunay maxima. The degree-4 fit's errors do not change between 1e7 and 1e9.
constexpr double degree_condition_factor(int degree) { return degree == 3 ? 1e2 : 1e5; }

// The condition thresholds of the fits over a ball (ball_radius), over those of
// the ring fits of the same degree. With a constant term, a ball whose vertex is
// at its edge (a corner of the domain) is one-sided for the constant and linear
// terms too. Measured: the corner balls of 2.5 steps of a jittered cube of
// tetrahedra need 1e3 to 1e4 at degree 2 (1e5 to 1e6 at 3) and were refused below;
// at the corners of Delaunay squares a ball refused at 1e3 grows, and its wider
// one-sided fit has 2.6 times the largest H error of the fit accepted at 1e4.
constexpr double ball_condition_factor = 10;

// The condition threshold of fit_in_plane_frame, over the quadratic one (1e6 by
// default). Over the 743 vertices of CGAL's data meshes where it serves, the
// median distance of its H to that of jet fitting of degree 4 on 3 rings is 2.24
// at 1e4, 2.04 at 1e5, 1.88 at 1e6, 1.80 at 1e7 and 1.78 at 1e8 (the Gauss
// map's, which serves where it is refused: 2.89), and its 90th percentile 53 to
// 57 at each; 1e6 is where the gains level off.
constexpr double plane_fit_condition_factor = 1e3;

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

  Platelet_fit_core(Neighborhood neighborhood, const Platelet_fit_settings& settings)
      : neighborhood_(std::move(neighborhood))
      , settings_(settings)
  {}

  // Hamann's fit: the paraboloid through the k-ring in the tangent frame of the
  // given `normal` (any length), widened while ill-conditioned; with a fit degree
  // of 3 or 4, that fit (see fit_of_degree) in the same frame, and Hamann's fit,
  // status fallback, where it is not determined up to the widest ring.
  Estimate fit(Vertex v, const Vector& normal)
  {
    const double length = normal.norm();
    if (!(length > 0) || !std::isfinite(length) || !gather(v))
      return Estimate();
    if (in_ball())
      return fit_in_ball(normal / length);
    if (settings_.degree == 2)
      return fit_curvature(normal / length);
    const Estimate estimate = fit_of_degree(normal / length, false);
    return estimate.status != Estimation_status::not_estimable ? estimate : as_fallback(fit_curvature(normal / length));
  }

  // The same with the normal estimated by `method`. With the quadric_fit normal,
  // at an interior vertex, the curvature fit keeps the linear terms: the normal's
  // remaining error then tilts the fitted gradient instead of leaking, through an
  // uneven stencil, into the curvatures (on marching-tetrahedra and Delaunay meshes
  // Hamann's fit had maximum errors 3 to 9 times larger). See fit_curvature for its
  // widening and its quartic term. Where the linear terms are not determined on any
  // ring, and at boundary vertices (whose one-sided stencils make them less
  // accurate than Hamann's fit in the cubic normal's frame), Hamann's fit.
  // With a fit degree of 3 or 4, that fit in the frame of the first-order normal;
  // where it is not determined up to the widest ring (the one-sided corners of
  // tetrahedral grids), the degree-2 fit, status fallback.
  Estimate fit(Vertex v, Vertex_normal_method method)
  {
    if (!gather(v))
      return Estimate();
    if (settings_.degree == 2 && !in_ball())
      return fit_of_degree_two(v, method);
    Vector normal;
    if (!first_order_normal(v, method, true, normal))
      return Estimate();
    if (in_ball())
      return fit_in_ball(normal);
    const Estimate estimate = fit_of_degree(normal, true);
    return estimate.status != Estimation_status::not_estimable ? estimate : as_fallback(fit_of_degree_two(v, method));
  }

  // The fit of jet fitting (degree 2) for the vertices where fit(v, quadric_fit)
  // finds none, or whitened_at_border() (see Paraboloid_estimator): the quadratic
  // Taylor polynomial with a constant term and linear terms, unweighted, over the
  // vertex and its rings in the frame of their least-squares plane (oriented as
  // the first-order normal), from the starting rings, widened while test (a)
  // refuses it at plane_fit_condition_factor times max_condition (no test (b), as
  // in jet fitting: with it, the median distance below over these vertices is the
  // same, 1.34 times jet fitting's on hand.off instead of 1.00, 0.98 on anchor.off
  // instead of 1.05, and within 1% on the other meshes); the curvatures are those
  // of the fitted graph. Status fallback; not_estimable where no ring gives one.
  // Over the vertices of CGAL's data meshes where fit(v, quadric_fit) finds none
  // (743), its median distance to jet fitting of degree 4 is 1.88, the Gauss
  // map's 2.89 (test_cgal_data_meshes).
  Estimate fit_in_plane_frame(Vertex v)
  {
    Vector normal;
    if (!gather(v) || !first_order_normal(v, Vertex_normal_method::quadric_fit, true, normal))
      return Estimate();
    const double max_condition = plane_fit_condition_factor * settings_.max_condition;
    for (int rings = start_rings(); rings <= settings_.max_rings && reach(rings); ++rings) {
      const std::size_t end = neighborhood_.ring_end(rings);
      Vector plane = least_squares_hyperplane_normal<N>(offsets_.data(), end);
      if (!all_finite(plane))
        continue;
      if (plane.dot(normal) < 0)
        plane = -plane;
      const Tangents tangents = tangent_basis<N>(plane);
      const Eigen::Matrix<double, D, N> to_tangent = tangents.transpose();
      Taylor_fit<D, 0, 2> fit;
      for (std::size_t i = 0; i < end; ++i)
        if (finite_[i])
          fit.add(Eigen::Matrix<double, D, 1>(to_tangent * offsets_[i]), plane.dot(offsets_[i]));
      if (!fit.solve(max_condition))
        continue;
      const Graph_curvature<N> curvature = graph_curvature<N>(fit.hessian(), fit.gradient(), tangents, plane);
      if (all_finite(curvature.curvatures) && all_finite(curvature.directions))
        return Neighborhood::estimate(Estimation_status::fallback, curvature, scale_);
    }
    return Estimate();
  }

  // The neighbors gathered by the last fit or normal, on every ring it reached
  // (0 where its vertex had no finite point); in a ball, those inside it.
  std::size_t neighbors() const { return in_ball() ? ball_neighbors_ : offsets_.empty() ? 0 : offsets_.size() - 1; }

  // Whether the last fit(v, method) of fit_degree 2 over rings was Hamann's fit at
  // a boundary vertex that only test (b) accepted, for its normal or for itself.
  bool whitened_at_border() const { return settings_.degree == 2 && !in_ball() && on_border_ && whitened_; }

  // The unit normal by `method`; false where there is none. With quadric_fit and
  // a fit degree of 3 or 4, the first-order normal corrected by the gradient of
  // that fit (see fit_of_degree), or where it is not determined up to the widest
  // ring, by the degree-2 fit's; in a ball, by the gradient of the fit in the ball.
  bool normal(Vertex v, Vertex_normal_method method, Vector& normal)
  {
    const bool gathered = neighborhood_.platelet_for_normal(method);
    if (gathered && !gather(v))
      return false;
    if (method == Vertex_normal_method::quadric_fit && in_ball()) {
      if (!first_order_normal(v, method, gathered, normal))
        return false;
      return with_fit_of_degree<0>([&](auto& fit) {
        return fit_ball(normal, fit) != 0 && correct_normal(normal, tangent_basis<N>(normal), fit.gradient());
      });
    }
    if (method == Vertex_normal_method::quadric_fit && settings_.degree != 2) {
      if (!first_order_normal(v, method, gathered, normal))
        return false;
      Tangents tangents = tangent_basis<N>(normal);
      const bool corrected = with_fit_of_degree<1>([&](auto& fit) {
        return fit_rings_of_degree(normal, tangents, true, fit) != 0 &&
               correct_normal(normal, tangents, fit.gradient());
      });
      if (corrected)
        return true;
    }
    return estimate_normal(v, method, gathered, normal);
  }

private:
  // fit(v, method) with fit_degree 2, after gather(v).
  Estimate fit_of_degree_two(Vertex v, Vertex_normal_method method)
  {
    Vector normal;
    if (!estimate_normal(v, method, true, normal))
      return Estimate();
    if (method == Vertex_normal_method::quadric_fit && !on_border_) {
      const Estimate estimate = fit_curvature<Taylor_fit<D, 1, 2>>(normal);
      if (estimate.status != Estimation_status::not_estimable)
        return estimate;
    }
    return fit_curvature(normal);
  }

  // The 1-ring, and the local length scale (mean distance to the 1-ring) that
  // makes the fit scale invariant.
  bool gather(Vertex v)
  {
    offsets_.clear();
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
    // In a ball, its radius: the ball is the unit ball.
    scale_ = in_ball() ? settings_.ball_radius : length_sum / length_count;
    // A product is cheaper than a division and as exact to rounding, unless 1 / scale
    // overflows or is subnormal.
    inverse_scale_ = 1 / scale_;
    if (!std::isnormal(inverse_scale_))
      inverse_scale_ = 0;
    finite_.resize(end);
    for (std::size_t i = 0; i < end; ++i) {
      offsets_[i] = to_scale(offsets_[i]);
      finite_[i] = all_finite(offsets_[i]);
    }
    on_border_ = neighborhood_.center_on_border(v);
    whitened_ = false;
    curvature_rings_ = 0;
    ball_neighbors_ = 0;
    return true;
  }

  bool in_ball() const { return settings_.ball_radius > 0; }

  // The fits over the ball of radius ball_radius: the
  // Taylor polynomial of fit_degree with a constant term (the vertex is a sample,
  // not a point the fit must pass through: its noise would enter the curvature
  // divided by the squared radius) and linear terms, unweighted (or smooth_weights), in the frame of
  // `normal` (first order); the curvatures are those of the fitted graph, whose
  // gradient takes the frame's tilt (fitting again in the frame of the corrected
  // normal changed the H RMS on the noisy and noise-free test ellipsoids and
  // Delaunay meshes by at most 4%, and cost a second fit). The ball grows as
  // fit_in_growing_ball says, while test (a) and then (b) refuse the fit; status
  // widened where it grew.
  Estimate fit_in_ball(const Vector& normal)
  {
    const Tangents tangents = tangent_basis<N>(normal);
    return with_fit_of_degree<0>([&](auto& fit) {
      const int growths = fit_ball(normal, fit);
      return growths != 0 ? curvature_estimate(normal, tangents, growths, 1, fit) : Estimate();
    });
  }

  // The fit of fit_in_ball, accepted in the frame of `normal`: 1 plus the number of
  // times the ball grew, 0 where no ball is accepted.
  template <typename Fit>
  int fit_ball(const Vector& normal, Fit& fit)
  {
    const double max_condition = ball_condition_factor *
                                 (settings_.degree == 2 ? 1 : degree_condition_factor(settings_.degree)) *
                                 settings_.max_condition;
    const Tangents tangents = tangent_basis<N>(normal);
    const auto accepted = [&] {
      if (fit_in_frame(normal, tangents, 0, max_condition, fit))
        return true;
      const auto samples = [&](const auto& add) { for_each_sample<Fit>(normal, tangents, 0, add); };
      return settings_.whitened_conditioning && fit.solve_whitened(max_condition, samples);
    };
    return fit_in_growing_ball(
      1.0, Fit::unknowns, [&](double radius) { return reach_ball(radius); }, [&] { return neighborhood_.ball_size(); },
      accepted);
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

  // Gathers rings up to `rings`; false when the component has fewer, on every
  // call (the collector counts the empty ring it met last).
  bool reach(int rings)
  {
    while (!exhausted_ && neighborhood_.rings() < rings) {
      exhausted_ = !neighborhood_.extend();
      if (!exhausted_)
        append_offsets();
    }
    return exhausted_ ? rings < neighborhood_.rings() : true;
  }

  // The scaled offsets of the vertices gathered since the last call, and whether
  // each is finite (sized once: a push_back per vertex was not inlined).
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
    const bool accepted = widest != 0 && fit.solve_whitened(max_condition, samples);
    whitened_ = whitened_ || accepted;
    return accepted ? widest : 0;
  }

  // The neighborhood's first-order normal, or for quadric_fit a normal of second
  // order or better: that normal corrected by the gradient of a Taylor fit in its
  // frame (see fit_normal). `gathered`: whether gather(v) has succeeded.
  bool estimate_normal(Vertex v, Vertex_normal_method method, bool gathered, Vector& normal)
  {
    if (!first_order_normal(v, method, gathered, normal))
      return false;
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

  // The neighborhood's first-order normal (for quadric_fit the area-weighted one), unit.
  bool first_order_normal(Vertex v, Vertex_normal_method method, bool gathered, Vector& normal)
  {
    normal = neighborhood_.initial_normal(v, method, gathered, offsets_, finite_, scale_);
    if (!all_finite(normal) || !(normal.squaredNorm() > 0))
      return false;
    normal.normalize();
    return true;
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

  // The curvature fit in the frame of `normal`: Hamann's paraboloid by default, or
  // a Taylor fit with linear terms (Fit = Taylor_fit<D, 1, 2>), which:
  //  - where test (a) refuses the starting rings, is widened with the cubic terms
  //    too (weighted as the cubic normal fit, see cubic_normal_min_rings) before it
  //    is widened as it is: a degree-2 fit over a wider neighborhood has an error
  //    that grows as the square of its radius, and the cubic terms take out the
  //    first order of it. On marching-tetrahedra meshes, whose vertices with
  //    near-coincident neighbors (a 1-ring of three directions) are widened, this
  //    lowers the largest H error 2 to 4 times (test MarchingTetrahedraConvergence);
  //  - on surfaces, is fitted again with the heights less the curvature's own
  //    quartic term (quadric_fit.h), which makes it of fourth order on spheres and
  //    cylinders. Not on hypersurfaces: they are the graphs of trivariate fields,
  //    whose natural exact case is a quadratic field, which the fit is exact on at
  //    its interior vertices and the correction, made for spheres, would not be.
  // Hamann's fit stays the paper's.
  template <typename Fit = Taylor_fit<D, 2, 2>>
  Estimate fit_curvature(const Vector& normal)
  {
    const Tangents tangents = tangent_basis<N>(normal);
    const int first = curvature_rings_ != 0 ? (std::min)(curvature_rings_, settings_.max_rings) : start_rings();
    Fit fit;
    if constexpr (Fit::linear_terms) {
      if (fit_widening(normal, tangents, first, first, settings_.max_condition, fit) != 0)
        return curvature_estimate(normal, tangents, first, 1, fit);
      Taylor_fit<D, 1, 3> cubic;
      const int rings = fit_widening(normal, tangents, first + 1, settings_.max_rings,
                                     cubic_normal_condition_factor * settings_.max_condition, cubic);
      if (rings != 0)
        return curvature_estimate(normal, tangents, rings, 1, cubic);
    }
    int rings = fit_widening(normal, tangents, first, settings_.max_rings, settings_.max_condition, fit);
    if (rings == 0)
      rings = fit_whitened(normal, tangents, first, settings_.max_rings, settings_.max_condition, fit);
    if (rings == 0)
      return Estimate();
    return curvature_estimate(normal, tangents, rings, 1, fit);
  }

  // fit_degree 3 or 4: the Taylor fit of that degree with linear terms in the frame
  // of `normal` (a first-order normal is enough: the fitted gradient corrects it to
  // the fit's order), unweighted, over degree - 1 rings at least (the starting
  // rings if more), widened while test (a) refuses, up to max_neighborhood_rings or
  // one ring more; test (b) on the widest where (a) accepts none. Where `normal`
  // is estimated, the degree-4 fit is first tried in another frame (see
  // fit_rings_of_degree). Degree 4 is for surfaces only (a hypersurface's quartic
  // fit has 34 unknowns).
  Estimate fit_of_degree(Vector normal, bool estimated_normal)
  {
    Tangents tangents = tangent_basis<N>(normal);
    return with_fit_of_degree<1>([&](auto& fit) {
      const int rings = fit_rings_of_degree(normal, tangents, estimated_normal, fit);
      return rings != 0 ? curvature_estimate(normal, tangents, rings, first_rings_of_degree(fit), fit) : Estimate();
    });
  }

  // use(fit) with a Taylor fit of the settings' degree with the terms of orders
  // FirstOrder to the degree: 1 for the ring fits of fit_degree 3 and 4, 0 (a
  // constant term too) for the ball fits of every degree.
  template <int FirstOrder, typename Use>
  auto with_fit_of_degree(const Use& use)
  {
    if constexpr (D == 2)
      if (settings_.degree == 4) {
        Taylor_fit<D, FirstOrder, 4> fit;
        return use(fit);
      }
    if (FirstOrder == 1 || settings_.degree == 3) {
      Taylor_fit<D, FirstOrder, 3> fit;
      return use(fit);
    }
    Taylor_fit<D, FirstOrder, 2> fit;
    return use(fit);
  }

  template <typename Fit>
  int first_rings_of_degree(const Fit&) const
  {
    return (std::max)(start_rings(), Fit::last_order - 1);
  }

  // The rings of the accepted fit of fit_of_degree, 0 where there is none, and its
  // frame in `normal` and `tangents`.
  //
  // Where the normal is estimated, the degree-4 fit is first fitted over the rings
  // it starts on in the frame of their least-squares plane (with the vertex;
  // oriented as `normal`), as jet fitting does, and kept where test (a) accepts it.
  // Three rings are wide enough to be lopsided and curved: a frame that leaves the
  // far samples steep spoils a quartic graph there, even the exact normal's.
  // Measured on the marching-tetrahedra family (20, 40 and 80 cells): H RMS and
  // maxima at most 4% above those in the frame of the area-weighted normal, and
  // on the torus at 20 cells a maximum 2 times smaller (0.170 against 0.337; at
  // one vertex 0.03, where the exact normal's frame gives 1.1). At a crease the
  // plane is tilted and the fit in it ill-conditioned: the fits in the normal's
  // frame follow, as before (the plane alone made the fallbacks over CGAL's data
  // meshes 4,416 instead of 2,444; with them they are 2,398). At degree 3, over 2
  // rings, the plane gained at most 16% on the maxima elsewhere and made that
  // torus's RMS 11% and largest error 2.5 times larger, so degree 3 keeps the
  // normal's frame.
  template <typename Fit>
  int fit_rings_of_degree(Vector& normal, Tangents& tangents, bool estimated_normal, Fit& fit)
  {
    const int first = first_rings_of_degree(fit);
    const int widest = (std::max)(settings_.max_rings, first + 1);
    const double max_condition = degree_condition_factor(Fit::last_order) * settings_.max_condition;
    if (Fit::last_order == 4 && estimated_normal && reach(first)) {
      Vector plane = least_squares_hyperplane_normal<N>(offsets_.data(), neighborhood_.ring_end(first));
      if (all_finite(plane)) {
        if (plane.dot(normal) < 0)
          plane = -plane;
        const Tangents plane_tangents = tangent_basis<N>(plane);
        if (fit_in_frame(plane, plane_tangents, first, max_condition, fit)) {
          normal = plane;
          tangents = plane_tangents;
          return first;
        }
      }
    }
    const int rings = fit_widening(normal, tangents, first, widest, max_condition, fit);
    return rings != 0 ? rings : fit_whitened(normal, tangents, first, widest, max_condition, fit);
  }

  // The estimate from an accepted fit over `rings` rings (status widened where
  // that is more than `asked`); on surfaces, a fit with linear terms and no
  // quartic ones is first solved again without the curvature's quartic term:
  // from its moments where they reach the degree that takes (quadric_fit.h),
  // else sample by sample.
  template <typename Fit>
  Estimate curvature_estimate(const Vector& normal, const Tangents& tangents, int rings, int asked, Fit& fit) const
  {
    if constexpr (Fit::quartic_moments)
      fit.subtract_curvature_quartic();
    else if constexpr (D == 2 && Fit::linear_terms && Fit::last_order < 4) {
      const Eigen::Matrix<double, D, D> first_hessian = fit.hessian();
      fit.solve_again([&](const auto& add) {
        for_each_sample<Fit>(normal, tangents, rings, [&](const auto& x, double height, double weight) {
          add(x, height - curvature_quartic<D>(first_hessian, x), weight);
        });
      });
    }
    const Graph_curvature<N> curvature = graph_curvature<N>(fit.hessian(), fit.gradient(), tangents, normal);
    if (!all_finite(curvature.curvatures) || !all_finite(curvature.directions))
      return Estimate();
    return Neighborhood::estimate(rings > asked ? Estimation_status::widened : Estimation_status::ok, curvature,
                                  scale_);
  }

  template <typename Fit>
  bool fit_in_frame(const Vector& normal, const Tangents& tangents, int rings, double max_condition, Fit& fit) const
  {
    fit.clear();
    for_each_sample<Fit>(normal, tangents, rings,
                         [&](const auto& x, double height, double weight) { fit.add(x, height, weight); });
    return fit.solve(max_condition);
  }

  // Calls add(x, height, weight) for each sample of the rings up to `rings` in
  // the frame: samples weighted by a Gaussian of width the mean 1-ring edge in the
  // cubic fits of fit_degree 2 only (see cubic_normal_min_rings); Hamann's fit and
  // the fits of fit_degree 3 and 4, over the rings their degree needs, are unweighted.
  // The fits with a constant term are those over a ball (rings ignored): its
  // samples, the vertex too, unweighted or with Neighbor_weighting::smooth.
  template <typename Fit, typename Add>
  void for_each_sample(const Vector& normal, const Tangents& tangents, int rings, const Add& add) const
  {
    const Eigen::Matrix<double, D, N> to_tangent = tangents.transpose();
    if constexpr (Fit::constant_term) {
      for (std::size_t i = 0; i < offsets_.size(); ++i) {
        const Vector& q = offsets_[i];
        if (finite_[i] && neighborhood_.inside_ball(i)) {
          const double falloff = 1 - q.squaredNorm() / ball_squared_radius_;
          add(Eigen::Matrix<double, D, 1>(to_tangent * q), normal.dot(q),
              settings_.smooth_weights ? falloff * falloff : 1.0);
        }
      }
      return;
    }
    const bool weighted = settings_.degree == 2 && Fit::unknowns > Taylor_fit<D, 1, 2>::unknowns;
    const std::size_t end = neighborhood_.ring_end(rings); // hoisted: add writes memory
    for (std::size_t i = 1; i < end; ++i) {
      const Vector& q = offsets_[i];
      if (finite_[i])
        add(Eigen::Matrix<double, D, 1>(to_tangent * q), normal.dot(q), weighted ? std::exp(-q.squaredNorm()) : 1.0);
    }
  }

  Neighborhood neighborhood_;
  Platelet_fit_settings settings_;
  std::vector<Vector> offsets_; // scaled p_w - p_v, aligned with neighborhood_.vertices()
  std::vector<char> finite_;    // whether each offset is finite
  Vector center_ = Vector::Zero();
  double scale_ = 1;
  double inverse_scale_ = 1; // 1 / scale_, or 0 where that is not a normal number
  bool on_border_ = false;
  bool exhausted_ = false; // whether the rings met an empty one
  bool whitened_ = false;  // whether test (b) accepted a fit since gather(v)
  // Where the normal fit needed test (b), the curvature fit starts on the rings
  // that gave the normal (the widest; the narrower ones failed test (a) for the
  // normal). 0: it starts on the settings' rings.
  int curvature_rings_ = 0;
  std::size_t ball_neighbors_ = 0; // in the ball of the last fit in a ball, the vertex excluded
  double ball_squared_radius_ = 1; // its squared radius, in units of scale_
};

} // namespace internal
} // namespace Curvature_estimation
} // namespace CGAL

#endif // CGAL_CURVATURE_ESTIMATION_INTERNAL_PLATELET_FIT_H
