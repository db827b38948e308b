// SPDX-License-Identifier: GPL-3.0-or-later
// The estimation at one point of a point set (point_set_curvatures.h): the fit
// with its fallback chain and its scale selection, the loop's worker, and the
// consistently oriented first rings the fits start from.
#ifndef CGAL_CURVATURE_ESTIMATION_INTERNAL_POINT_SET_ESTIMATOR_H
#define CGAL_CURVATURE_ESTIMATION_INTERNAL_POINT_SET_ESTIMATOR_H

#include <CGAL/Curvature_estimation/Vertex_normal_method.h>
#include <CGAL/Curvature_estimation/internal/fallback_chain.h>
#include <CGAL/Curvature_estimation/internal/fit_settings.h>
#include <CGAL/Curvature_estimation/internal/for_each_vertex.h>
#include <CGAL/Curvature_estimation/internal/normal_orientation.h>
#include <CGAL/Curvature_estimation/internal/point_set_neighborhood.h>
#include <CGAL/Curvature_estimation/internal/point_set_search.h>
#include <CGAL/Curvature_estimation/internal/scale_selection.h>
#include <CGAL/Curvature_estimation/internal/scale_selector.h>
#include <CGAL/Curvature_estimation/internal/surface_estimate.h>
#include <CGAL/Curvature_estimation/internal/vertex_fitter.h>

#include <boost/iterator/counting_iterator.hpp>
#include <boost/range/iterator_range.hpp>

#include <Eigen/Core>

#include <algorithm>
#include <cstddef>
#include <optional>
#include <vector>

namespace CGAL {
namespace Curvature_estimation {
namespace internal {

// The default number_of_neighbors at fit_degree 2, 3 and 4 (the manual's "Point sets" measures the error against k).
constexpr std::size_t default_point_set_neighbors(int degree) { return degree == 2 ? 16 : degree == 3 ? 32 : 64; }

// The fit at one point with its fallback chain (see `estimate`).
class Point_set_estimator
{
public:
  Point_set_estimator(const Point_set_search& search, const Fit_settings& settings, std::size_t neighbors,
                      const Point_set_rings* rings, bool use_fallbacks)
      : fitter_(Point_set_neighborhood(search, neighbors, settings.ball_radius, rings), settings)
      , degree_two_(Point_set_neighborhood(search, neighbors, settings.ball_radius, rings), of_degree_two(settings))
      , use_fallbacks_(use_fallbacks)
  {
    if (settings.selects_radius())
      selector_.emplace(Point_set_neighborhood(search, neighbors, 0, rings, settings.radius_range.max), settings);
  }

  // The fallback chain: the fit of fit_degree; at degrees 3 and 4 the fit of degree 2.
  // Under scale selection, that estimate or the fit over the selected ball (select_estimate).
  Surface_estimate estimate(std::size_t v, const Eigen::Vector3d* given)
  {
    Surface_estimate estimate;
    estimate_with_fallbacks(
      estimate, use_fallbacks_, [&](Surface_estimate& out) { return fit(fitter_, v, given, out); },
      fallback(Tried_where::refused, [&](Surface_estimate& out) {
        return fitter_.settings().degree == 2 ? Verdict::refused : fit(degree_two_, v, given, out);
      }));
    if (selector_) {
      constexpr Vertex_normal_method method = Vertex_normal_method::quadric_fit;
      estimate = select_estimate(estimate, selector_->select(v, given, method),
                                 [&](double radius) { return fitter_.ball_estimate(v, given, method, radius); });
    }
    return estimate;
  }

private:
  using Fitter = Vertex_fitter<Point_set_neighborhood>;

  static Fit_settings of_degree_two(Fit_settings settings)
  {
    settings.degree = 2;
    return settings;
  }

  static Verdict fit(Fitter& fitter, std::size_t v, const Eigen::Vector3d* given, Surface_estimate& out)
  {
    const Vertex_fit r =
      given != nullptr ? fitter.fit(v, *given, out) : fitter.fit(v, Vertex_normal_method::quadric_fit, out);
    if (out.status != Estimation_status::not_estimable)
      return Verdict::accepted;
    return r.neighbors < std::size_t(Intercept_fit<2, 2>::unknowns) ? Verdict::hopeless : Verdict::refused;
  }

  Fitter fitter_;
  Fitter degree_two_;
  bool use_fallbacks_;
  std::optional<Scale_selector<Point_set_neighborhood>> selector_; // under scale selection
};

// The loop's worker (for_each_vertex): the given normals read by `keys(i)`.
template <bool given, typename NormalMap, typename Keys>
struct Point_set_worker
{
  Point_set_estimator estimator;
  NormalMap normals;
  const Keys* keys;
  Eigen::Vector3d load(std::size_t i) const { return load_given_normal<given>(normals, (*keys)(i)); }
  Surface_estimate compute(std::size_t i, const Eigen::Vector3d& normal)
  {
    return estimator.estimate(i, given ? &normal : nullptr);
  }
};

// The estimate seen from the other side: what the opposite normal gives.
inline Surface_estimate flipped(const Surface_estimate& e)
{
  return Surface_estimate::from_principal(e.status, -e.min_curvature, -e.max_curvature, e.min_direction,
                                          e.max_direction, -e.normal);
}

// The first ring of every point and the normal of its least-squares plane,
// oriented consistently (see orient_normals); rows of `stride` neighbors.
template <typename ConcurrencyTag>
Normal_orientation oriented_rings(const Point_set_search& search, std::size_t neighbors, double radius,
                                  std::size_t stride, Point_set_rings& rings)
{
  const std::size_t n = search.size();
  rings.stride = stride;
  rings.neighbors.assign(n * stride, Point_set_rings::none);
  rings.normals.assign(n, Eigen::Vector3f::Zero());
  struct Worker
  {
    Point_set_neighborhood neighborhood;
    Point_set_rings* rings;
    std::vector<Eigen::Vector3d> offsets;
    char load(std::size_t) const { return 0; }
    char compute(std::size_t v, char)
    {
      if (!neighborhood.point(v).allFinite())
        return 0;
      neighborhood.start(v);
      const auto& gathered = neighborhood.vertices(); // v, then its neighbors nearest first
      offsets.clear();
      for (std::size_t i = 0; i < gathered.size(); ++i)
        offsets.push_back(neighborhood.point(gathered[i]) - neighborhood.point(v));
      const std::size_t row = (std::min)(rings->stride, gathered.size() - 1);
      for (std::size_t i = 0; i < row; ++i)
        rings->neighbors[v * rings->stride + i] = Point_set_search::Index(gathered[i + 1]);
      const Eigen::Vector3d normal = Point_set_neighborhood::plane_normal(offsets.data(), offsets.size());
      if (offsets.size() >= 3 && normal.allFinite())
        rings->normals[v] = normal.cast<float>();
      return 0;
    }
  };
  const auto indices =
    boost::make_iterator_range(boost::counting_iterator<std::size_t>(0), boost::counting_iterator<std::size_t>(n));
  for_each_vertex<ConcurrencyTag, true>(indices, Worker{Point_set_neighborhood(search, neighbors, radius), &rings, {}},
                                        [](std::size_t, char) {});
  return orient_normals<ConcurrencyTag>(search.points(), rings.normals, [&](std::size_t i, const auto& visit) {
    for (std::size_t k = 0; k < stride; ++k) {
      const Point_set_search::Index j = rings.neighbors[i * stride + k];
      if (j == Point_set_rings::none)
        break;
      visit(j);
    }
  });
}
} // namespace internal
} // namespace Curvature_estimation
} // namespace CGAL

#endif // CGAL_CURVATURE_ESTIMATION_INTERNAL_POINT_SET_ESTIMATOR_H
