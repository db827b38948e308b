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
#include <CGAL/Curvature_estimation/internal/fallback_chain.h>
#include <CGAL/Curvature_estimation/internal/local_coordinates.h>
#include <CGAL/Curvature_estimation/internal/mesh_lines.h>
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

// The estimator at one vertex; one copy per thread (buffers reused, no allocation
// per vertex once warmed up).
template <typename FaceGraph, typename VertexPointMap>
class Curve_network_estimator
{
public:
  using vertex_descriptor = typename boost::graph_traits<FaceGraph>::vertex_descriptor;
  using halfedge_descriptor = typename boost::graph_traits<FaceGraph>::halfedge_descriptor;

  Curve_network_estimator(const FaceGraph& g, VertexPointMap vpm, Curve_model model, int order, double max_irregularity,
                          bool use_fallbacks = true)
      : g_(&g)
      , vpm_(vpm)
      , model_(model)
      , order_(order)
      , max_irregularity_(max_irregularity)
      , use_fallbacks_(use_fallbacks)
      , paraboloid_(g, vpm, Fit_parameters{Fit_settings(), Vertex_normal_method::quadric_fit})
  {}

  // The fallback chain: the curve network; where it has too few curves, no normal or an
  // ill-conditioned Euler system, the paraboloid fit with its defaults and the same given
  // normal. `given_normal`: the user's (any length), or null (the curves' tangents' normal).
  Surface_estimate estimate(vertex_descriptor v, const Eigen::Vector3d* given_normal)
  {
    Eigen::Vector3d given = Eigen::Vector3d::Zero();
    if (given_normal != nullptr) {
      const double length = given_normal->norm();
      if (!(length > 0) || !std::isfinite(length))
        return Surface_estimate();
      given = *given_normal / length;
    }
    const Eigen::Vector3d* unit = given_normal != nullptr ? &given : nullptr;
    Surface_estimate estimate;
    estimate_with_fallbacks(
      estimate, use_fallbacks_, [&](Surface_estimate& out) { return curve_network_fit(v, unit, out); },
      fallback(Tried_where::refused,
               [&](Surface_estimate& out) { return final_estimate(out, paraboloid_.estimate(v, unit)); }));
    return estimate;
  }

private:
  // The estimate from the curves through `v`, refused where they are not enough
  // (see estimate), hopeless where `v` has no finite point or 1-ring.
  Verdict curve_network_fit(vertex_descriptor v, const Eigen::Vector3d* given_normal, Surface_estimate& out)
  {
    center_ = point_in_double(vpm_, v);
    if (!center_.allFinite() || !gather_one_ring(v))
      return Verdict::hopeless;

    // Orientation of the tangent plane in which neighbors are paired, and of
    // the normal computed from the tangents: the given normal, else the faces'.
    Eigen::Vector3d orientation = given_normal != nullptr ? *given_normal : Eigen::Vector3d::Zero();
    if (given_normal == nullptr) {
      orientation = face_average_normal(v, *g_, vpm_, Vertex_normal_method::area_weighted);
      const double length = orientation.norm();
      if (!(length > 0) || !std::isfinite(length))
        return Verdict::refused;
      orientation /= length;
    }

    pair_neighbors(orientation);
    if (pairs_.size() < 3 || !curves_are_mesh_lines())
      return Verdict::refused;

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
      return Verdict::refused;

    Eigen::Vector3d normal = orientation;
    if (given_normal == nullptr && !normal_from_tangents(tangents_.data(), tangents_.size(), orientation, normal))
      return Verdict::refused;

    normal_curvatures_.clear();
    for (const Eigen::Vector3d& vector : curvature_vectors_)
      normal_curvatures_.push_back(meusnier_normal_curvature(vector, normal));
    const Euler_solution euler = euler_fit(tangents_.data(), normal_curvatures_.data(), tangents_.size(), normal);
    if (!euler.valid)
      return Verdict::refused;

    out.set_principal(reduced ? Estimation_status::widened : Estimation_status::ok, euler.max_curvature / scale_,
                      euler.min_curvature / scale_, euler.max_direction, euler.min_direction, normal);
    return Verdict::accepted;
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

  // The points of the line through ring_[before] - v - ring_[after], continued up to order_ - 1
  // steps each way (scaled, relative to v); `available`: the fewest steps either way. Stops at a
  // boundary, a vertex of other valence, a non-finite point, or where the line closes.
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
        if (!next_on_mesh_line(previous, current, *g_, next) || next == v)
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
  bool use_fallbacks_;
  Paraboloid_estimator<FaceGraph, VertexPointMap> paraboloid_;
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
/// estimates principal curvatures and directions, mean and Gaussian curvature at every vertex of a
/// triangle mesh by Wollmann's curve network (Wollmann 2000): the 1-ring neighbors, projected to the
/// tangent plane, are paired into curves through the vertex (the most nearly opposite pair first, at
/// least 150 degrees apart); each curve's curvature, tangent and principal normal come from three points
/// (or from 2n + 1 points along straight mesh lines with `extrapolation_order(n)`, error O(h^2n) on
/// parameter grids); Meusnier's theorem gives normal curvatures and Euler's theorem, fitted to them, the
/// principal curvatures and directions. Without a `vertex_normal_map` the normal is that of the plane of
/// the curves' tangents, oriented like the faces.
///
/// Statuses: `ok`: three curves or more, each at the requested order; `widened`: some curve used a lower
/// order (near the boundary or a vertex of valence other than 6); `fallback`: fewer than three curves, a
/// curve that is no mesh line (irregularity s^2 + tan^2(delta/2) above `max_curve_irregularity`, s the
/// asymmetry of its two edges, delta its kink), no normal, or an ill-conditioned Euler system: the estimate
/// is then that of `paraboloid_fitting_curvatures()` with its defaults and the given normal, if any;
/// `not_estimable`: an isolated vertex, a non-finite point, all neighbors coincident, or the fallback failed
/// too (NaN). Curve networks need mesh lines: on meshes without them (Delaunay triangulations, marching
/// cubes) most vertices fall back; see the User Manual, "Curve network".
///
/// Conventions: as `paraboloid_fitting_curvatures()`. Only the outputs whose maps are passed are written.
///
/// \ceSurfaceEstimatorParameters
///
/// \cgalNamedParamsBegin
///   \ceSurfaceInputParameters
///   \cgalParamNBegin{vertex_normal_map}
///     \cgalParamDescription{normals at the vertices, trusted as given}
///     \cgalParamDefault{the normal of the plane of the curves' tangents, oriented like the faces}
///   \cgalParamNEnd
///   \cgalParamNBegin{curve_model}
///     \cgalParamDescription{the curve through three points of a mesh line (`Curve_model`)}
///     \cgalParamDefault{`Curve_model::bezier`}
///   \cgalParamNEnd
///   \cgalParamNBegin{extrapolation_order}
///     \cgalParamDescription{n, 1 to 4: the points at ±h ... ±nh along the mesh lines; n > 1 needs the Bézier model}
///     \cgalParamDefault{`1`}
///   \cgalParamNEnd
///   \cgalParamNBegin{max_curve_irregularity}
///     \cgalParamDescription{a vertex falls back if one of its curves is more irregular than this (at least 0;
///                           infinity gives Wollmann's method at every vertex with three curves)}
///     \cgalParamDefault{`0.04`}
///   \cgalParamNEnd
///   \ceUseFallbacksParameter
///   \ceSurfaceOutputParameters{K = k1 k2, see the statuses above}
/// \cgalNamedParamsEnd
///
/// \throws std::invalid_argument if `extrapolation_order` is not in 1..4, or is greater than 1 with
///         `Curve_model::circle`, if `max_curve_irregularity` is negative or NaN, or if `ball_radius` is given.
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
  const bool use_fallbacks = internal::parameter_or(np, internal_np::use_fallbacks, true);

  internal::estimate_surface_curvatures<ConcurrencyTag>(g, np, [&](const auto& vpm) {
    return internal::Curve_network_estimator<FaceGraph, std::decay_t<decltype(vpm)>>(g, vpm, model, order,
                                                                                     max_irregularity, use_fallbacks);
  });
}

} // namespace Curvature_estimation
} // namespace CGAL

#endif // CGAL_CURVATURE_ESTIMATION_CURVE_NETWORK_H
