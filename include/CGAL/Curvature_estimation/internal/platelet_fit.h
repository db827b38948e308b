// Hamann's platelet fit at one vertex of a FaceGraph: gather the k-ring, express
// it in a tangent frame, fit the paraboloid, widen while ill-conditioned; and the
// second-order normal that the fit uses by default.
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
};

// The settings from the named parameters, with the documented defaults;
// `caller` names the public function in error messages.
template <typename NamedParameters>
Platelet_fit_settings platelet_fit_settings(const NamedParameters& np, const char* caller)
{
  using ::CGAL::parameters::choose_parameter;
  using ::CGAL::parameters::get_parameter;
  Platelet_fit_settings settings;
  settings.rings = choose_parameter(get_parameter(np, internal_np::neighborhood_rings), 1);
  settings.boundary_rings = choose_parameter(get_parameter(np, internal_np::boundary_neighborhood_rings), settings.rings);
  settings.max_rings = choose_parameter(get_parameter(np, internal_np::max_neighborhood_rings), 3);
  settings.max_condition = choose_parameter(get_parameter(np, internal_np::max_condition_number), 1e3);
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
// gradient through a one-sided stencil), and a condition threshold 100 times
// the quadratic one (well-posed cubic stencils show about 1e4, the ones that
// are singular in the tangent plane above 1e16).
constexpr int cubic_normal_min_rings = 3;
constexpr double cubic_normal_condition_factor = 1e3;


template <typename FaceGraph, typename VertexPointMap>
class Platelet_fitter
{
public:
  using vertex_descriptor = typename boost::graph_traits<FaceGraph>::vertex_descriptor;

  Platelet_fitter(const FaceGraph& g, VertexPointMap vpm, const Platelet_fit_settings& settings)
    : g_(&g), vpm_(vpm), settings_(settings)
  {}

  // Hamann's fit: the paraboloid through the k-ring in the tangent frame of the
  // given `normal` (any length), widened while ill-conditioned.
  Surface_estimate fit(vertex_descriptor v, const Eigen::Vector3d& normal)
  {
    const double length = normal.norm();
    if (!(length > 0) || !std::isfinite(length) || !gather(v))
      return Surface_estimate();
    return fit_curvature(normal / length);
  }

  // The same with the normal estimated by `method`.
  Surface_estimate fit(vertex_descriptor v, Vertex_normal_method method)
  {
    Eigen::Vector3d normal;
    if (!gather(v) || !estimate_normal(v, method, normal))
      return Surface_estimate();
    return fit_curvature(normal);
  }

  // The unit normal by `method`; false where there is none.
  bool normal(vertex_descriptor v, Vertex_normal_method method, Eigen::Vector3d& normal)
  {
    // Face averages need no neighbourhood.
    if (method == Vertex_normal_method::quadric_fit && !gather(v))
      return false;
    return estimate_normal(v, method, normal);
  }

private:
  // The 1-ring, and the local length scale (mean distance to the 1-ring) that
  // makes the fit scale invariant.
  bool gather(vertex_descriptor v)
  {
    center_ = point_in_double(vpm_, v);
    if (!center_.allFinite())
      return false;
    rings_.start(v, *g_);
    offsets_.clear();
    offsets_.push_back(Eigen::Vector3d::Zero());
    double length_sum = 0;
    int length_count = 0;
    for (std::size_t i = 1; i < rings_.ring_end(1); ++i) {
      const Eigen::Vector3d offset = point_in_double(vpm_, rings_.vertices()[i]) - center_;
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
    for (Eigen::Vector3d& offset : offsets_)
      offset /= scale_;
    on_border_ = rings_.center_on_border();
    return true;
  }

  int start_rings() const { return on_border_ ? settings_.boundary_rings : settings_.rings; }

  // Gathers rings up to `rings`; false when the component has fewer.
  bool reach(int rings)
  {
    while (rings_.rings() < rings) {
      if (!rings_.extend(*g_))
        return false;
      for (std::size_t i = offsets_.size(); i < rings_.vertices().size(); ++i)
        offsets_.push_back((point_in_double(vpm_, rings_.vertices()[i]) - center_) / scale_);
    }
    return true;
  }

  // Fits over the rings up to `rings`, widening up to `max_rings` until the
  // normal equations are well-conditioned; returns the rings used, 0 on failure.
  using Tangents = Eigen::Matrix<double, 3, 2>;

  template <typename Fit>
  int fit_widening(const Eigen::Vector3d& normal, const Tangents& tangents, int rings, int max_rings,
                   double max_condition, Fit& fit)
  {
    for (; rings <= max_rings && reach(rings); ++rings)
      if (fit_in_frame(normal, tangents, rings, max_condition, fit))
        return rings;
    return 0;
  }

  // A face average, or for quadric_fit a normal of second order or better: the
  // area-weighted normal corrected by the gradient of a Taylor fit in its frame.
  // A symmetric interior stencil cancels the odd terms, so the degree-2 fit over
  // the starting rings suffices there; a one-sided boundary stencil does not, and
  // a boundary vertex fits the cubic terms too, falling back to degree 2 where
  // that is ill-conditioned up to the widest ring.
  bool estimate_normal(vertex_descriptor v, Vertex_normal_method method, Eigen::Vector3d& normal)
  {
    const bool fitted = method == Vertex_normal_method::quadric_fit;
    normal = fitted ? corner_normal_sum(v) : face_average_normal(v, *g_, vpm_, method);
    if (!normal.allFinite() || !(normal.squaredNorm() > 0))
      return false;
    normal.normalize();
    return !fitted || fit_normal(normal);
  }

  // The sum of the faces' corner normals at the center, from the gathered 1-ring:
  // the area-weighted normal on a triangle mesh, without walking the faces again.
  Eigen::Vector3d corner_normal_sum(vertex_descriptor v) const
  {
    if (!rings_.one_ring_in_fan_order())
      return face_average_normal(v, *g_, vpm_, Vertex_normal_method::area_weighted);
    const std::size_t valence = rings_.ring_end(1) - 1;
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (std::size_t k = 0; k < valence; ++k) {
      const Eigen::Vector3d& previous = offsets_[1 + k];
      const Eigen::Vector3d& next = offsets_[1 + (k + 1) % valence];
      if (rings_.has_face(k) && previous.allFinite() && next.allFinite())
        sum += next.cross(previous);
    }
    return sum;
  }

  bool fit_normal(Eigen::Vector3d& normal)
  {
    const Tangents tangents = tangent_basis<3>(normal);
    if (on_border_) {
      const int rings = (std::max)(cubic_normal_min_rings, start_rings());
      Taylor_fit<2, 1, 3> cubic;
      if (fit_widening(normal, tangents, rings, (std::max)(rings, settings_.max_rings),
                       cubic_normal_condition_factor * settings_.max_condition, cubic) != 0)
        return correct_normal(normal, tangents, cubic.gradient());
    }
    Taylor_fit<2, 1, 2> quadratic;
    return fit_widening(normal, tangents, start_rings(), settings_.max_rings, settings_.max_condition, quadratic) != 0 &&
           correct_normal(normal, tangents, quadratic.gradient());
  }

  static bool correct_normal(Eigen::Vector3d& normal, const Tangents& tangents, const Eigen::Vector2d& gradient)
  {
    normal = (normal - tangents * gradient).normalized();
    return normal.allFinite();
  }

  Surface_estimate fit_curvature(const Eigen::Vector3d& normal)
  {
    Surface_estimate result;
    const Tangents tangents = tangent_basis<3>(normal);
    Taylor_fit<2, 2, 2> fit;
    const int rings = fit_widening(normal, tangents, start_rings(), settings_.max_rings, settings_.max_condition, fit);
    if (rings == 0)
      return result;
    const Graph_curvature<3> curvature = graph_curvature<3>(fit.hessian(), fit.gradient(), tangents, normal);
    if (!curvature.curvatures.allFinite() || !curvature.directions.allFinite())
      return result;
    return Surface_estimate::from_principal(rings > 1 ? Estimation_status::widened : Estimation_status::ok,
                                            curvature.curvatures[0] / scale_, curvature.curvatures[1] / scale_,
                                            curvature.directions.col(0), curvature.directions.col(1), normal);
  }

  // Samples weighted by a Gaussian of width the mean 1-ring edge in the cubic
  // fit only (see cubic_normal_min_rings); Hamann's fit is unweighted.
  template <typename Fit>
  bool fit_in_frame(const Eigen::Vector3d& normal, const Tangents& tangents, int rings, double max_condition,
                    Fit& fit) const
  {
    constexpr bool weighted = Fit::unknowns > Taylor_fit<2, 1, 2>::unknowns;
    fit.clear();
    for (std::size_t i = 1; i < rings_.ring_end(rings); ++i) {
      const Eigen::Vector3d& q = offsets_[i];
      if (q.allFinite())
        fit.add(tangents.transpose() * q, normal.dot(q), weighted ? std::exp(-q.squaredNorm()) : 1.0);
    }
    return fit.solve(max_condition);
  }

  const FaceGraph* g_;
  VertexPointMap vpm_;
  Platelet_fit_settings settings_;
  Ring_collector<FaceGraph> rings_;
  std::vector<Eigen::Vector3d> offsets_;  // scaled p_w - p_v, aligned with rings_.vertices()
  Eigen::Vector3d center_ = Eigen::Vector3d::Zero();
  double scale_ = 1;
  bool on_border_ = false;
};

} // namespace internal
} // namespace Curvature_estimation
} // namespace CGAL

#endif // CGAL_CURVATURE_ESTIMATION_INTERNAL_PLATELET_FIT_H
