// SPDX-License-Identifier: GPL-3.0-or-later
// Normal-curvature samples at a vertex, the common input of Taubin's tensor and
// of Chen and Schmitt's Euler fit (Chen, Wu and Chi 2005, section 3, eqs. 9-10),
// and the vertex loop both baselines share.
#ifndef CGAL_CURVATURE_ESTIMATION_INTERNAL_NORMAL_CURVATURE_SAMPLES_H
#define CGAL_CURVATURE_ESTIMATION_INTERNAL_NORMAL_CURVATURE_SAMPLES_H

#include <CGAL/Curvature_estimation/internal/estimate_at_vertices.h>
#include <CGAL/Curvature_estimation/internal/face_average_normal.h>
#include <CGAL/Curvature_estimation/internal/face_graph_neighborhood.h>
#include <CGAL/Curvature_estimation/internal/local_coordinates.h>
#include <CGAL/Curvature_estimation/internal/rings.h>
#include <CGAL/Curvature_estimation/internal/shape_matrix_estimate.h>
#include <CGAL/Curvature_estimation/internal/tangent_frame.h>
#include <CGAL/Curvature_estimation/parameters.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/number_utils.h>

#include <boost/graph/graph_traits.hpp>

#include <Eigen/Core>

#include <cmath>
#include <cstddef>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Curvature_estimation {
namespace internal {

struct Normal_curvature_sample
{
  Eigen::Vector2d direction; // unit tangent t_i in the tangent frame
  double curvature;          // k_n(t_i), in coordinates divided by the length scale
  double squared_length;     // |q_i - p|^2 in those coordinates
  double area_weight;        // sum of the areas of the faces on the edge (p, q_i); 0 beyond the 1-ring
  double centroid_weight;    // sum of 1 / |G_f - p|^2 over the faces f on the edge; 0 beyond the 1-ring
};

// Gathers the samples of one vertex; allocation-free once `samples` has grown.
template <typename FaceGraph, typename VertexPointMap>
class Normal_curvature_sampler
{
public:
  using Graph_traits = boost::graph_traits<FaceGraph>;
  using vertex_descriptor = typename Graph_traits::vertex_descriptor;
  using halfedge_descriptor = typename Graph_traits::halfedge_descriptor;
  using face_descriptor = typename Graph_traits::face_descriptor;

  Normal_curvature_sampler(const FaceGraph& g, VertexPointMap vpm)
      : local_(g, vpm)
  {}

  // Fills `samples` at `v`: one per edge with face weights (`rings == 1`), else
  // one per vertex of the rings. Returns the coordinates' length scale (the mean
  // distance to the neighbors), 0 where v has no usable neighbor.
  double sample(vertex_descriptor v, const Eigen::Vector3d& normal, const Tangent_frame& tangents, int rings,
                std::vector<Normal_curvature_sample>& samples)
  {
    samples.clear();
    if (!local_.center_on(v))
      return 0;
    const FaceGraph& g = local_.graph();
    if (rings == 1) {
      for (halfedge_descriptor h : halfedges_around_target(v, g))
        if (add_sample(local_(source(h, g)), normal, tangents, samples)) {
          add_face_weights(face(h, g), samples.back());
          add_face_weights(face(opposite(h, g), g), samples.back());
        }
    } else {
      rings_.start(v, g);
      for (int r = 1; r < rings; ++r)
        if (!rings_.extend(g))
          break;
      for (std::size_t i = 1; i < rings_.vertices().size(); ++i)
        add_sample(local_(rings_.vertices()[i]), normal, tangents, samples);
    }
    return local_.scale();
  }

private:
  // Appends the sample of the offset d = q_i - p, without face weights; false
  // (nothing appended) where d is not finite, zero or along the normal.
  static bool add_sample(const Eigen::Vector3d& d, const Eigen::Vector3d& normal, const Tangent_frame& tangents,
                         std::vector<Normal_curvature_sample>& samples)
  {
    const double d2 = d.squaredNorm();
    if (!d.allFinite() || !(d2 > 0))
      return false;
    const Eigen::Vector2d t = tangents.transpose() * d;
    const double t_norm = t.norm();
    if (!(t_norm > 0))
      return false;
    Normal_curvature_sample s;
    s.direction = t / t_norm;
    s.curvature = -2 * normal.dot(d) / d2;
    s.squared_length = d2;
    s.area_weight = 0;
    s.centroid_weight = 0;
    samples.push_back(s);
    return true;
  }

  // Area and centroid weight of face f (any polygon: Newell's area, the mean of
  // the vertices), in the scaled coordinates; degenerate or non-finite faces add nothing.
  void add_face_weights(face_descriptor f, Normal_curvature_sample& s) const
  {
    if (f == Graph_traits::null_face())
      return;
    const FaceGraph& g = local_.graph();
    const Face_walk walk = walk_face(halfedge(f, g), g, [this](vertex_descriptor u) { return local_(u); });
    const double area = 0.5 * walk.newell.norm();
    const double centroid_weight = 1 / (walk.vertex_sum / walk.size).squaredNorm();
    if (!std::isfinite(area) || !(area > 0) || !std::isfinite(centroid_weight))
      return;
    s.area_weight += area;
    s.centroid_weight += centroid_weight;
  }

  Vertex_local_coordinates<FaceGraph, VertexPointMap> local_;
  Ring_collector<FaceGraph> rings_;
};

// The local estimator of the estimators built on normal-curvature samples:
// `solve(samples, shape)` turns the samples of the vertex's `rings`-ring into its
// shape matrix (false: not estimable). The normal is the given one, else estimated by `method`.
template <typename FaceGraph, typename VertexPointMap, typename Solve>
struct Normal_curvature_sample_estimator
{
  using vertex_descriptor = typename boost::graph_traits<FaceGraph>::vertex_descriptor;

  Surface_fitter<FaceGraph, VertexPointMap> fitter;
  Normal_curvature_sampler<FaceGraph, VertexPointMap> sampler;
  Vertex_normal_method method;
  int rings;
  Solve solve;
  std::vector<Normal_curvature_sample> samples;

  Surface_estimate estimate(vertex_descriptor v, const Eigen::Vector3d* given)
  {
    Eigen::Vector3d normal;
    if (given != nullptr) {
      if (!given->allFinite() || !(given->norm() > 0))
        return Surface_estimate();
      normal = given->normalized();
    } else if (!fitter.normal(v, method, normal)) {
      return Surface_estimate();
    }
    const Tangent_frame tangents = tangent_basis<3>(normal);
    const double scale = sampler.sample(v, normal, tangents, rings, samples);
    Eigen::Matrix2d shape;
    if (!(scale > 0) || !solve(samples, shape))
      return Surface_estimate();
    return shape_estimate_from_matrix(shape, tangents, normal, scale, false);
  }
};

// Taubin's and Chen and Schmitt's estimators, which differ by `solve` (see
// Normal_curvature_sample_estimator) and by the `rings` they sample; `caller`
// names the public function in errors.
template <typename ConcurrencyTag, typename FaceGraph, typename NamedParameters, typename Solve>
void normal_curvature_sample_curvatures(const FaceGraph& g, const NamedParameters& np, const char* caller, int rings,
                                        Solve solve)
{
  const Fit_parameters fit = fit_parameters(np, caller);
  estimate_surface_curvatures<ConcurrencyTag>(g, np, [&](const auto& vpm) {
    using VPM = std::decay_t<decltype(vpm)>;
    return Normal_curvature_sample_estimator<FaceGraph, VPM, Solve>{
      Surface_fitter<FaceGraph, VPM>(g, vpm, fit.settings),
      Normal_curvature_sampler<FaceGraph, VPM>(g, vpm),
      fit.normal_method,
      rings,
      solve,
      {}};
  });
}

} // namespace internal
} // namespace Curvature_estimation
} // namespace CGAL

#endif // CGAL_CURVATURE_ESTIMATION_INTERNAL_NORMAL_CURVATURE_SAMPLES_H
