// SPDX-License-Identifier: GPL-3.0-or-later
// Wollmann's curve-network estimator on any FaceGraph: curvature of mesh curves
// through the vertex, Meusnier's and Euler's theorems, orders O(h^2) and O(h^2n).
#ifndef CGAL_CURVATURE_ESTIMATION_CURVE_NETWORK_H
#define CGAL_CURVATURE_ESTIMATION_CURVE_NETWORK_H

#include <CGAL/Curvature_estimation/Principal_curvatures_and_directions.h>
#include <CGAL/Curvature_estimation/Vertex_normal_method.h>
#include <CGAL/Curvature_estimation/internal/curve_curvature.h>
#include <CGAL/Curvature_estimation/internal/estimate_at_vertices.h>
#include <CGAL/Curvature_estimation/internal/face_average_normal.h>
#include <CGAL/Curvature_estimation/internal/face_graph_platelet.h>
#include <CGAL/Curvature_estimation/internal/local_coordinates.h>
#include <CGAL/Curvature_estimation/internal/meusnier_euler.h>
#include <CGAL/Curvature_estimation/paraboloid_fitting.h>
#include <CGAL/Curvature_estimation/parameters.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/number_utils.h>
#include <CGAL/tags.h>

#include <boost/graph/graph_traits.hpp>

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Curvature_estimation {

/// \ingroup PkgCurvatureEstimationRef
/// The curve through three points of a mesh line that `curve_network_curvatures()`
/// uses to estimate the line's curvature, tangent and principal normal (named
/// parameter `curve_model`).
enum class Curve_model : unsigned char
{
  /// The quadratic Bézier segment B with B(0), B(1/2), B(1) at the three points
  /// (Wollmann's eq. 1): the central differences B' = p2 - p0, B'' = 4 (p2 + p0 - 2 p1).
  /// Error O(h^2) for points at equal parameter steps; the only model that
  /// `extrapolation_order` greater than 1 generalises.
  bezier,
  /// The circle through the three points (Todd and McLeod 1986). Independent of
  /// the spacing of the points along the curve; error O(h^2) on parameter grids
  /// as well, with a slightly larger constant than the Bézier segment.
  circle
};

namespace internal {

// Neighbors whose tangent-plane directions make an angle of at least 150 degrees
// may form a curve through the vertex. Curves with a sharper kink (allowed with
// 120 degrees, say) mix the normal curvatures of two directions and, on jittered
// grids and Delaunay meshes, raise the RMS error of K by two orders of magnitude.
constexpr double curve_pair_max_cosine = -0.866;

// Whether a curve a - p - b is a mesh line the method can use. With a = p - h_a u_a + O(h^2),
// b = p + h_b u_b + O(h^2) (u_a, u_b unit tangent directions, <u_a, u_b> = cos(delta), delta the
// kink) and kappa_a, kappa_b the normal curvatures in the directions of a and b, the Bezier's
// central differences d1 = b - a, d2 = 4 (a + b - 2p) give, through Meusnier's theorem, to leading
// order in h
//   kappa_est = 2 [h_a^2 kappa_a + h_b^2 kappa_b - (h_b^2 - h_a^2)(h_b^2 kappa_b - h_a^2 kappa_a) / L^2] / L^2,
//   L^2 = |b - a|^2 = h_a^2 + h_b^2 + 2 h_a h_b cos(delta):
// on a straight line with uneven steps, kappa (1 - s^2) with s = (h_a - h_b) / (h_a + h_b) (the
// first-order terms of the two sides no longer cancel); with even steps and a kink, the mean of
// kappa_a and kappa_b times 1 + tan^2(delta / 2), and a kink also mixes two directions (and,
// through the normal's error, the geodesic curvature). The circle model has no s^2 term but a
// first-order one of size s h kappa'. Both relative errors are O(1): they vanish under refinement
// only if s and delta do, as on a parameter grid of a smooth surface, where they are O(h), and not
// on meshes without mesh lines (Delaunay triangulations of scattered points, marching cubes or
// tetrahedra), where the curve network is order 0. The curve's irregularity
//   s^2 + tan^2(delta / 2) = s^2 + (1 + c) / (1 - c),  c = <u_a, u_b> = -cos(delta),
// bounds the magnitude of both leading relative errors; `a` and `b` are the neighbors' offsets
// from p, `cosine` the cosine of their angle in the tangent plane (at most
// curve_pair_max_cosine, so the division is safe).
inline double curve_irregularity(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double cosine)
{
  const double length_a = a.norm(), length_b = b.norm();
  const double s = (length_a - length_b) / (length_a + length_b);
  return s * s + (1 + cosine) / (1 - cosine);
}

// Default of `max_curve_irregularity`: a vertex with a curve of higher irregularity falls back.
// Measured: the largest irregularity on the parameter grids of the tests is 0.012 (the 40 x 20
// torus grid; it is O(h), 0.003 at 80 x 40) and on icospheres 0.031 (next to the valence-5
// vertices, at every level); 0.04 keeps all of these. On marching-tetrahedra meshes the median is
// 0.25 and on Delaunay meshes of random points 0.11: 0.04 keeps about 9% and 4% of their vertices,
// whose error is bounded by a fraction of the curvature (at most 5.4% measured), not by h, while the
// others converge through the fallback: no fixed threshold makes the estimate converge on such meshes
// (see the manual), and lower ones would send the icospheres' vertices next to valence 5 to it.
constexpr double default_max_curve_irregularity = 0.04;

// The estimator at one vertex; one copy per thread (buffers reused, no allocation
// per vertex once warmed up).
template <typename FaceGraph, typename VertexPointMap>
class Curve_network_estimator
{
public:
  using vertex_descriptor = typename boost::graph_traits<FaceGraph>::vertex_descriptor;
  using halfedge_descriptor = typename boost::graph_traits<FaceGraph>::halfedge_descriptor;

  Curve_network_estimator(const FaceGraph& g, VertexPointMap vpm, Curve_model model, int order, double max_irregularity)
      : g_(&g)
      , vpm_(vpm)
      , model_(model)
      , order_(order)
      , max_irregularity_(max_irregularity)
      , fallback_(g, vpm, Fit_parameters{Platelet_fit_settings(), Vertex_normal_method::quadric_fit})
  {}

  // The estimate at `v`; `given_normal` is the user's normal (any length), or
  // null for the default (the normal of the curves' tangents).
  Surface_estimate estimate(vertex_descriptor v, const Eigen::Vector3d* given_normal)
  {
    Eigen::Vector3d given = Eigen::Vector3d::Zero();
    if (given_normal != nullptr) {
      const double length = given_normal->norm();
      if (!(length > 0) || !std::isfinite(length))
        return Surface_estimate();
      given = *given_normal / length;
    }
    center_ = point_in_double(vpm_, v);
    if (!center_.allFinite() || !gather_one_ring(v))
      return Surface_estimate();

    // Orientation of the tangent plane in which neighbors are paired, and of
    // the normal computed from the tangents: the given normal, else the faces'.
    Eigen::Vector3d orientation = given;
    if (given_normal == nullptr) {
      orientation = face_average_normal(v, *g_, vpm_, Vertex_normal_method::area_weighted);
      const double length = orientation.norm();
      if (!(length > 0) || !std::isfinite(length))
        return fall_back(v, given_normal, given);
      orientation /= length;
    }

    pair_neighbors(orientation);
    if (pairs_.size() < 3 || !curves_are_mesh_lines())
      return fall_back(v, given_normal, given);

    // One curve per pair, at the highest order the mesh lines allow up to order_.
    tangents_.clear();
    curvature_vectors_.clear();
    bool reduced = false;
    for (const std::pair<std::size_t, std::size_t>& pair : pairs_) {
      int available = 0;
      const Curve_estimate curve = line_curve(v, pair.first, pair.second, available);
      if (!curve.valid)
        continue;
      reduced = reduced || available < order_;
      tangents_.push_back(curve.tangent);
      curvature_vectors_.push_back(curve.curvature_vector);
    }
    if (tangents_.size() < 3)
      return fall_back(v, given_normal, given);

    Eigen::Vector3d normal = given;
    if (given_normal == nullptr && !normal_from_tangents(tangents_.data(), tangents_.size(), orientation, normal))
      return fall_back(v, given_normal, given);

    normal_curvatures_.clear();
    for (const Eigen::Vector3d& vector : curvature_vectors_)
      normal_curvatures_.push_back(meusnier_normal_curvature(vector, normal));
    const Euler_solution euler = euler_fit(tangents_.data(), normal_curvatures_.data(), tangents_.size(), normal);
    if (!euler.valid)
      return fall_back(v, given_normal, given);

    return Surface_estimate::from_principal(reduced ? Estimation_status::widened : Estimation_status::ok,
                                            euler.max_curvature / scale_, euler.min_curvature / scale_,
                                            euler.max_direction, euler.min_direction, normal);
  }

private:
  // Fewer than three curves, a curve that is no mesh line, no normal, or an ill-conditioned Euler system:
  // paraboloid_fitting_curvatures() with its defaults (its own fallback included), with the same
  // normal if one was given.
  Surface_estimate fall_back(vertex_descriptor v, const Eigen::Vector3d* given_normal, const Eigen::Vector3d& given)
  {
    return as_fallback(fallback_.estimate(v, given_normal != nullptr ? &given : nullptr));
  }

  // The distinct neighbors of `v` with finite points, in the order of the
  // halfedges around `v`, and the length scale (their mean distance).
  bool gather_one_ring(vertex_descriptor v)
  {
    ring_.clear();
    offsets_.clear();
    const halfedge_descriptor h = halfedge(v, *g_);
    if (h == boost::graph_traits<FaceGraph>::null_halfedge())
      return false;
    double length_sum = 0;
    for (halfedge_descriptor incoming : halfedges_around_target(h, *g_)) {
      const vertex_descriptor w = source(incoming, *g_);
      if (w == v || std::find(ring_.begin(), ring_.end(), w) != ring_.end())
        continue;
      const Eigen::Vector3d offset = point_in_double(vpm_, w) - center_;
      const double length = safe_norm(offset);
      if (!offset.allFinite() || !(length > 0) || !std::isfinite(length))
        continue;
      ring_.push_back(w);
      offsets_.push_back(offset);
      length_sum += length;
    }
    if (ring_.empty() || !(length_sum > 0))
      return false;
    scale_ = length_sum / double(ring_.size());
    return true;
  }

  // Greedy pairing: of all pairs of neighbors whose directions in the tangent
  // plane are at least 150 degrees apart, the most nearly opposite first, each
  // neighbor in one pair at most.
  void pair_neighbors(const Eigen::Vector3d& normal)
  {
    directions_.clear();
    for (const Eigen::Vector3d& offset : offsets_) {
      Eigen::Vector3d d = offset - offset.dot(normal) * normal;
      const double length = d.norm();
      directions_.push_back(length > 0 ? Eigen::Vector3d(d / length) : Eigen::Vector3d(Eigen::Vector3d::Zero()));
    }
    candidates_.clear();
    for (std::size_t i = 0; i < directions_.size(); ++i)
      for (std::size_t j = i + 1; j < directions_.size(); ++j) {
        const double cosine = directions_[i].dot(directions_[j]);
        if (cosine <= curve_pair_max_cosine)
          candidates_.push_back({cosine, {i, j}});
      }
    // Ties in the order (i, j) of generation, as a stable sort would leave them:
    // std::stable_sort allocates a buffer at every call.
    std::sort(candidates_.begin(), candidates_.end(), [](const Candidate& a, const Candidate& b) {
      return a.first < b.first || (a.first == b.first && a.second < b.second);
    });
    used_.assign(directions_.size(), 0);
    pairs_.clear();
    for (const Candidate& c : candidates_)
      if (!used_[c.second.first] && !used_[c.second.second]) {
        used_[c.second.first] = used_[c.second.second] = 1;
        pairs_.push_back(c.second);
      }
  }

  // Every curve of pairs_ has an irregularity of at most max_irregularity_.
  bool curves_are_mesh_lines() const
  {
    for (const std::pair<std::size_t, std::size_t>& pair : pairs_)
      if (!(curve_irregularity(offsets_[pair.first], offsets_[pair.second],
                               directions_[pair.first].dot(directions_[pair.second])) <= max_irregularity_))
        return false;
    return true;
  }

  // The neighbor of `at` straight across from `from`: the third of its six
  // neighbors counted around it from `from`, if `at` is an interior vertex of
  // valence 6 (of a grid triangulation, the next vertex on the grid line).
  bool continue_straight(vertex_descriptor from, vertex_descriptor at, vertex_descriptor& next) const
  {
    const halfedge_descriptor h = halfedge(at, *g_);
    if (h == boost::graph_traits<FaceGraph>::null_halfedge())
      return false;
    std::array<vertex_descriptor, 6> around;
    std::size_t count = 0;
    for (halfedge_descriptor incoming : halfedges_around_target(h, *g_)) {
      if (count == 6 || is_border(incoming, *g_) || is_border(opposite(incoming, *g_), *g_))
        return false;
      around[count++] = source(incoming, *g_);
    }
    if (count != 6)
      return false;
    for (std::size_t k = 0; k < 6; ++k)
      if (around[k] == from) {
        next = around[(k + 3) % 6];
        return true;
      }
    return false;
  }

  // The points of the line through ring_[before] - v - ring_[after], continued
  // up to order_ - 1 more steps each way (scaled, relative to v); `available` is
  // the order used: the fewest steps either way. Stops at a boundary, at a vertex
  // of other valence, at a non-finite point, and if the line closes on itself.
  Curve_estimate line_curve(vertex_descriptor v, std::size_t before, std::size_t after, int& available)
  {
    int counts[2] = {0, 0};
    const std::size_t sides[2] = {before, after};
    for (int side = 0; side < 2; ++side) {
      Eigen::Vector3d* points = side == 0 ? before_.data() : after_.data();
      vertex_descriptor previous = v, current = ring_[sides[side]];
      points[0] = offsets_[sides[side]] / scale_;
      counts[side] = 1;
      while (counts[side] < order_) {
        vertex_descriptor next;
        if (!continue_straight(previous, current, next) || next == v)
          break;
        const Eigen::Vector3d point = (point_in_double(vpm_, next) - center_) / scale_;
        if (!point.allFinite())
          break;
        points[counts[side]++] = point;
        previous = current;
        current = next;
      }
    }
    available = (std::min)(counts[0], counts[1]);
    if (model_ == Curve_model::circle)
      return circle_curve_curvature(before_[0], Eigen::Vector3d::Zero(), after_[0]);
    return extrapolated_curve_curvature(before_.data(), Eigen::Vector3d::Zero(), after_.data(), available);
  }

  using Candidate = std::pair<double, std::pair<std::size_t, std::size_t>>;

  const FaceGraph* g_;
  VertexPointMap vpm_;
  Curve_model model_;
  int order_;
  double max_irregularity_;
  Paraboloid_estimator<FaceGraph, VertexPointMap> fallback_;
  Eigen::Vector3d center_ = Eigen::Vector3d::Zero();
  double scale_ = 1;
  std::vector<vertex_descriptor> ring_;
  std::vector<Eigen::Vector3d> offsets_, directions_;
  std::vector<Candidate> candidates_;
  std::vector<char> used_;
  std::vector<std::pair<std::size_t, std::size_t>> pairs_;
  std::array<Eigen::Vector3d, max_extrapolation_order> before_, after_;
  std::vector<Eigen::Vector3d> tangents_, curvature_vectors_;
  std::vector<double> normal_curvatures_;
};

} // namespace internal

/// \ingroup PkgCurvatureEstimationRef
///
/// Estimates principal curvatures and directions, mean and Gaussian curvature at
/// every vertex of a triangle mesh by Wollmann's curve network (Wollmann 2000):
/// the curvature, tangent and principal normal of mesh curves through the vertex
/// are estimated from three points each (or 2n + 1 points, see below); Meusnier's
/// theorem turns them into normal curvatures k_n = -kappa <h, N> (h the curve's
/// principal normal, N the surface normal; the sign is the package's, positive
/// where the surface bends away from N); Euler's theorem, solved exactly for three
/// curves and by least squares for more, gives the principal curvatures and
/// directions.
///
/// **Curves.** The 1-ring neighbors are projected to the tangent plane of the
/// area-weighted normal (or of the given normal) and paired greedily, the most
/// nearly opposite pair first, among the pairs at least 150 degrees apart; each
/// pair and the vertex make one curve. On a grid triangulation (valence 6) these
/// are exactly the two parameter lines and the diagonal, the paper's setting. A
/// vertex of valence 7 or more may have more than three curves (least squares).
///
/// **Order O(h^2n).** With `extrapolation_order(n)`, n = 1..4, each curve takes the
/// points at ±h, ..., ±nh along its mesh line, continued straight through interior
/// vertices of valence 6 (the vertex three neighbors round from the one the line
/// came from), and combines them with the paper's even/odd coefficients
/// (`internal::extrapolation_coefficients()`), which cancel the Taylor terms up to
/// order 2n of the first and second derivatives: the curvature and tangent are
/// then O(h^2n) on a parameter grid. Where a line cannot be continued n steps both
/// ways (it meets the boundary or a vertex of valence other than 6), that curve
/// uses the highest order available on both sides. The points must be at equal
/// parameter steps for the high order to show: on irregular meshes the O(h^2n)
/// combination is no better than n = 1.
///
/// **Normals.** Without a `vertex_normal_map`, the normal is the paper's: the
/// normal of the plane of the estimated curve tangents (their least-squares plane
/// when there are more than two), oriented like the area-weighted face normal.
/// It is as accurate as the tangents, O(h^2n); a second-order normal (such as the
/// package's quadric-fit normal) would cap every order at O(h^2), since a mesh
/// curve generally has geodesic curvature, which a tilted normal mixes into
/// Meusnier's theorem at first order. With a `vertex_normal_map` the given normals
/// are used for the pairing and in Meusnier's theorem.
///
/// **Status and fallback.** `Estimation_status::ok`: at least three curves, each at
/// the requested order. `Estimation_status::widened`: some curve had to use a lower
/// order (only possible for n > 1, within n - 1 rings of the boundary or of a vertex
/// of valence other than 6). `Estimation_status::fallback`: the curve network does
/// not exist at the vertex, or its curves are no mesh lines:
/// fewer than three pairs of opposite neighbors (boundary vertices; interior
/// vertices of valence 5 or less; on irregular meshes, every vertex without three
/// pairs of neighbors at least 150 degrees apart); a curve whose irregularity
/// s^2 + tan^2(delta/2) is above `max_curve_irregularity` (0.04), with
/// s = (|a - p| - |b - p|) / (|a - p| + |b - p|) the asymmetry of its two edges and
/// delta its kink in the tangent plane (the deviation from 180 degrees); no normal
/// from the tangents; or directions too close for Euler's system (condition number
/// above 20). The irregularity is the size of the curve estimate's leading relative
/// error (a factor 1 - s^2 from the uneven steps, 1 + tan^2(delta/2) from the kink),
/// which does not vanish under refinement unless s and delta do: on parameter grids
/// of smooth surfaces they are O(h) (at most 0.012 on the grids of the tests, 0.031
/// on icospheres), on marching-cubes or marching-tetrahedra meshes and Delaunay
/// triangulations of scattered points they are not (median 0.25 and 0.11), and
/// there the curve network without this test does not converge (order 0, errors of
/// H up to 400 at slivers, for curvatures of order 1). With the test about 90% of the
/// vertices of such meshes and 65% of those of grids jittered by 0.2 of the step
/// fall back, and the estimate converges, mostly as the fallback's: do not use the
/// curve network on such meshes. In every case of
/// `fallback` the estimate is Hamann's paraboloid fit
/// (`paraboloid_fitting_curvatures()` with its defaults and the given normal if
/// any), which widens its neighborhood as it needs and has a fallback of its own
/// (the Gauss map, without a given normal). `Estimation_status::not_estimable`:
/// isolated vertex, non-finite point, all neighbors coincident, or the fallback
/// failed too; every output is NaN.
///
/// **Conventions.** A sphere with outward normals has `max_curvature == min_curvature
/// == 1/r`; `max_curvature >= min_curvature`; the directions are unit, tangent and
/// orthogonal; H is the mean of the principal curvatures, K their product. The
/// computation is in coordinates scaled by the mean 1-ring edge length, so scaling
/// the mesh by s scales the curvatures by 1/s, to rounding.
///
/// Only the outputs whose maps are passed are written; passing none does nothing.
///
/// \ceConcurrencyTag
/// \tparam FaceGraph a model of `FaceGraph` (the curves need triangles; other
///         faces are accepted and only change which vertices neighbor each other).
/// \tparam NamedParameters a sequence of named parameters, built with the functions of
/// `CGAL::Curvature_estimation::parameters`
///
/// \param g the mesh
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \ceSurfaceInputParameters
///   \cgalParamNBegin{vertex_normal_map}
///     \cgalParamDescription{normals at the vertices, trusted as given (they need not be unit)}
///     \cgalParamType{a model of `ReadablePropertyMap` with `boost::graph_traits<FaceGraph>::%vertex_descriptor`
///                    as key type and `GT::Vector_3` as value type}
///     \cgalParamDefault{the normal of the plane of the curves' tangents, oriented like the faces}
///   \cgalParamNEnd
///   \cgalParamNBegin{curve_model}
///     \cgalParamDescription{the curve through three points of a mesh line}
///     \cgalParamType{`CGAL::Curvature_estimation::Curve_model`}
///     \cgalParamDefault{`Curve_model::bezier`}
///   \cgalParamNEnd
///   \cgalParamNBegin{extrapolation_order}
///     \cgalParamDescription{n: the curves use the points at ±h ... ±nh along the mesh lines, error O(h^2n)
///                           on parameter grids; n > 1 requires `Curve_model::bezier`}
///     \cgalParamType{`int`, from 1 to 4}
///     \cgalParamDefault{`1`}
///   \cgalParamNEnd
///   \cgalParamNBegin{max_curve_irregularity}
///     \cgalParamDescription{a vertex falls back to the paraboloid fit if one of its curves has an
///                           irregularity s^2 + tan^2(delta/2) above this (see "Status and fallback");
///                           `std::numeric_limits<double>::infinity()` gives Wollmann's method at every
///                           vertex with three curves}
///     \cgalParamType{`double`, at least 0}
///     \cgalParamDefault{`0.04`}
///   \cgalParamNEnd
///   \ceSurfaceOutputParameters{K = k1 k2, see "Status and fallback" above}
/// \cgalNamedParamsEnd
///
/// \throws std::invalid_argument if `extrapolation_order` is not in 1..4, or is
///         greater than 1 with `Curve_model::circle`, if `max_curve_irregularity` is
///         negative or NaN, or if `ball_radius` is given
///         (neighborhoods are set in rings).
template <typename ConcurrencyTag = CGAL::Sequential_tag, typename FaceGraph,
          typename NamedParameters = parameters::Default_named_parameters>
void curve_network_curvatures(const FaceGraph& g, const NamedParameters& np = parameters::default_values())
{
  internal::reject_ball_radius<NamedParameters>("curve_network_curvatures");
  const Curve_model model = internal::parameter_or(np, internal_np::curve_model, Curve_model::bezier);
  const int order = internal::parameter_or(np, internal_np::extrapolation_order, 1);
  if (order < 1 || order > internal::max_extrapolation_order)
    throw std::invalid_argument("curve_network_curvatures: extrapolation_order must be in 1.." +
                                std::to_string(internal::max_extrapolation_order));
  if (order > 1 && model != Curve_model::bezier)
    throw std::invalid_argument(
      "curve_network_curvatures: extrapolation_order greater than 1 requires Curve_model::bezier");
  const double max_irregularity =
    internal::parameter_or(np, internal_np::max_curve_irregularity, internal::default_max_curve_irregularity);
  if (!(max_irregularity >= 0))
    throw std::invalid_argument("curve_network_curvatures: max_curve_irregularity must be at least 0");

  internal::estimate_surface_curvatures<ConcurrencyTag>(g, np, [&](const auto& vpm) {
    return internal::Curve_network_estimator<FaceGraph, std::decay_t<decltype(vpm)>>(g, vpm, model, order,
                                                                                     max_irregularity);
  });
}

} // namespace Curvature_estimation
} // namespace CGAL

#endif // CGAL_CURVATURE_ESTIMATION_CURVE_NETWORK_H
