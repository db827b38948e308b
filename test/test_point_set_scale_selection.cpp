// SPDX-License-Identifier: GPL-3.0-or-later
// Scale selection on point sets (point_set_curvatures with `ball_radius_range`): random samples of an ellipsoid and
// a torus with Gaussian noise of 1%, 5% and 15% of the mean distance to the nearest neighbor, and varying from 0 to
// 15% across; interior H RMS against the best single neighbor_radius, and noise-free against the default nearest
// neighbors; the noise estimate against the noise added; the outputs and the parameters' checks.
#include <CGAL/Curvature_estimation/internal/point_set_search.h>
#include <CGAL/Curvature_estimation/point_set_curvatures.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/property_map.h>

#include <gtest/gtest.h>

#include "noisy_meshes.h"
#include "random_numbers.h"
#include "test_surfaces.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <random>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Status = CGAL::Curvature_estimation::Estimation_status;
namespace CE = CGAL::Curvature_estimation;
namespace params = CGAL::Curvature_estimation::parameters;

enum class Shape
{
  ellipsoid,
  torus
};

// A noisy sample of an exact surface: the points, their exact H (before the noise), the noise's standard deviation
// per point, and the mean distance to the nearest neighbor (after the noise).
struct Family_set
{
  std::string name;
  std::vector<Point> points;
  std::vector<double> H, sigma;
  double spacing = 0;
};

double mean_spacing(const std::vector<Point>& points)
{
  std::vector<Eigen::Vector3d> coordinates;
  for (const Point& p : points)
    coordinates.emplace_back(p.x(), p.y(), p.z());
  const CE::internal::Point_set_search search(coordinates, CGAL::Sequential_tag());
  CE::internal::Point_set_search::Found found;
  double sum = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    search.nearest(CE::internal::Point_set_search::Index(i), 1, found);
    sum += std::sqrt(found.front().first);
  }
  return sum / double(points.size());
}

// Uniformly random points (not a grid) on the ellipsoid (1, 0.8, 0.6) (uniform on the sphere, stretched) or on the
// torus (1, 0.4) (uniform by area); noise `fraction` of the mean spacing, or where negative from 0 to 0.15 across x.
Family_set family_set(Shape shape, double fraction)
{
  Family_set s;
  std::mt19937 gen(shape == Shape::ellipsoid ? 7 : 8);
  std::vector<Eigen::Vector3d> exact_points;
  if (shape == Shape::ellipsoid) {
    const double a = 1, b = 0.8, c = 0.6;
    while (exact_points.size() < 8000) {
      const double z = ce_test::uniform_symmetric(gen), phi = ce_test::uniform(gen, 0, 2 * ce_test::pi);
      const double w = std::sqrt(1 - z * z);
      exact_points.emplace_back(a * w * std::cos(phi), b * w * std::sin(phi), c * z);
      s.H.push_back(ce_test::ellipsoid_curvature(a, b, c, exact_points.back()).H);
    }
    s.name = "ellipsoid";
  } else {
    const double R = 1, r = 0.4;
    while (exact_points.size() < 12000) { // uniform by area: accept with probability (R + r cos v) / (R + r)
      const double u = ce_test::uniform(gen, 0, 2 * ce_test::pi), v = ce_test::uniform(gen, 0, 2 * ce_test::pi);
      if (ce_test::uniform(gen, 0, R + r) > R + r * std::cos(v))
        continue;
      exact_points.push_back(ce_test::torus_point(R, r, u, v));
      s.H.push_back(ce_test::torus_curvature(R, r, u, v).H);
    }
    s.name = "torus";
  }
  for (const Eigen::Vector3d& p : exact_points)
    s.points.emplace_back(p.x(), p.y(), p.z());
  const double d = mean_spacing(s.points);
  double lo = HUGE_VAL, hi = -HUGE_VAL;
  for (const Eigen::Vector3d& p : exact_points) {
    lo = (std::min)(lo, p.x());
    hi = (std::max)(hi, p.x());
  }
  for (std::size_t i = 0; i < exact_points.size(); ++i) {
    Eigen::Vector3d p = exact_points[i];
    const double f = fraction >= 0 ? fraction : 0.15 * (p.x() - lo) / (hi - lo);
    s.sigma.push_back(f * d);
    for (int k = 0; k < 3; ++k)
      p[k] += f * d * ce_test::standard_normal(gen);
    s.points[i] = Point(p.x(), p.y(), p.z());
  }
  s.spacing = mean_spacing(s.points);
  s.name += fraction < 0 ? " varying" : " " + std::to_string(static_cast<int>(std::lround(100 * fraction))) + "%";
  return s;
}

struct Outputs
{
  std::vector<double> H, radius, noise;
  std::vector<Status> status;
};

// point_set_curvatures over `s` with the named parameters `extra`, and the selection's outputs where `selects`.
template <bool selects = false, typename Extra>
Outputs run(const Family_set& s, const Extra& extra)
{
  const std::size_t n = s.points.size();
  std::vector<std::size_t> indices(n);
  std::iota(indices.begin(), indices.end(), std::size_t(0));
  Outputs r;
  r.H.resize(n);
  r.status.resize(n);
  const auto np = extra.point_map(CGAL::make_property_map(s.points))
                    .vertex_mean_curvature_map(CGAL::make_property_map(r.H))
                    .vertex_estimation_status_map(CGAL::make_property_map(r.status));
  if constexpr (selects) {
    r.radius.resize(n);
    r.noise.resize(n);
    CE::point_set_curvatures(
      indices,
      np.vertex_ball_radius_map(CGAL::make_property_map(r.radius)).vertex_noise_map(CGAL::make_property_map(r.noise)));
  } else
    CE::point_set_curvatures(indices, np);
  return r;
}

// The range of the tool's --radius auto on point sets: 2 to 32 mean spacings (the balls of 1 to 16 mean edges
// of a mesh hold about as many points).
Outputs selection(const Family_set& s)
{
  return run<true>(s, params::ball_radius_range(std::make_pair(2 * s.spacing, 32 * s.spacing)));
}

// H RMS over every point (both surfaces are closed: every point is interior); infinite where one is not estimated.
double rms(const Family_set& s, const std::vector<double>& H)
{
  double sum = 0;
  for (std::size_t i = 0; i < H.size(); ++i)
    sum += (H[i] - s.H[i]) * (H[i] - s.H[i]);
  const double e = std::sqrt(sum / double(H.size()));
  return std::isfinite(e) ? e : HUGE_VAL;
}

double median(std::vector<double> values)
{
  std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
  return values[values.size() / 2];
}

TEST(PointSetScaleSelection, NoiseEstimateMatchesTheNoiseAdded)
{
  for (Shape shape : {Shape::ellipsoid, Shape::torus})
    for (double fraction : {0.01, 0.05, 0.15}) {
      const Family_set s = family_set(shape, fraction);
      const Outputs r = selection(s);
      std::vector<double> ratios;
      for (std::size_t i = 0; i < r.noise.size(); ++i) {
        ASSERT_TRUE(std::isfinite(r.noise[i])) << s.name << " point " << i;
        ratios.push_back(r.noise[i] / s.sigma[i]);
      }
      std::printf("%-14s estimated noise / true noise: median %.3f\n", s.name.c_str(), median(ratios));
      EXPECT_NEAR(median(ratios), 1.0, 0.1) << s.name;
    }
}

// The radius reported is one of the candidate radii (the estimate over that ball) or the largest distance to the
// default nearest neighbors, and there the estimate is the default's, bit for bit.
TEST(PointSetScaleSelection, ReportsTheBallOrKeepsTheDefault)
{
  const Family_set s = family_set(Shape::ellipsoid, 0.05);
  const Outputs r = selection(s);
  const Outputs defaults = run(s, params::default_values());
  const auto radii = CE::internal::candidate_radii({2 * s.spacing, 32 * s.spacing});
  std::size_t selected = 0, kept = 0;
  for (std::size_t i = 0; i < r.H.size(); ++i) {
    ASSERT_NE(r.status[i], Status::not_estimable) << i;
    if (std::find(radii.begin(), radii.end(), r.radius[i]) != radii.end()) {
      ++selected;
      continue;
    }
    ++kept;
    EXPECT_EQ(r.H[i], defaults.H[i]) << i;
    EXPECT_EQ(r.status[i], defaults.status[i]) << i;
    EXPECT_GT(r.radius[i], s.spacing) << i;
    EXPECT_LT(r.radius[i], 10 * s.spacing) << i; // 16 neighbors: about 4.5 spacings
  }
  EXPECT_GT(selected, r.H.size() / 2);
  std::printf("5%% noise: %zu points of a selected ball, %zu of the default neighbors\n", selected, kept);
}

TEST(PointSetScaleSelection, ParametersAreChecked)
{
  const Family_set s = family_set(Shape::ellipsoid, 0.05);
  const double d = s.spacing;
  using Pair = std::pair<double, double>;
  std::vector<double> radius(s.points.size());
  EXPECT_THROW(run(s, params::ball_radius_range(Pair(0, d))), std::invalid_argument);
  EXPECT_THROW(run(s, params::ball_radius_range(Pair(2 * d, d))), std::invalid_argument);
  EXPECT_THROW(run(s, params::ball_radius_range(Pair(d, HUGE_VAL))), std::invalid_argument);
  EXPECT_THROW(run(s, params::ball_radius_range(Pair(d, 2 * d)).neighbor_radius(4 * d)), std::invalid_argument);
  EXPECT_THROW(run(s, params::ball_radius_range(Pair(d, 2 * d)).ball_radius(4 * d)), std::invalid_argument);
  EXPECT_THROW(run(s, params::vertex_ball_radius_map(CGAL::make_property_map(radius))), std::invalid_argument);
  EXPECT_NO_THROW(run(s, params::ball_radius_range(Pair(d, 2 * d)).number_of_neighbors(24)));
}

// Too few points for any ball: every estimate is the default's, NaN where that is.
TEST(PointSetScaleSelection, TinySetsAndNonFinitePoints)
{
  Family_set s;
  for (int i = 0; i < 5; ++i)
    s.points.emplace_back(i, i * i, 0.5 * i);
  s.points.emplace_back(HUGE_VAL, 0, 0);
  s.H.assign(s.points.size(), 0);
  const Outputs r = run<true>(s, params::ball_radius_range(std::make_pair(0.5, 8.0)));
  for (std::size_t i = 0; i < r.H.size(); ++i) {
    EXPECT_EQ(r.status[i], Status::not_estimable) << i;
    EXPECT_TRUE(std::isnan(r.H[i])) << i;
  }
}

// Interior H RMS of the selection, of the best single neighbor_radius of 2 to 32 mean spacings (in steps of
// 2^(1/2)) and of the default 16 nearest neighbors.
struct Family_result
{
  double selected, best_fixed, best_radius, default_fit;
};

Family_result family_result(const Family_set& s)
{
  Family_result r;
  r.selected = rms(s, selection(s).H);
  r.default_fit = rms(s, run(s, params::default_values()).H);
  r.best_fixed = HUGE_VAL;
  for (int k = 2; k <= 10; ++k) {
    const double radius = std::exp2(k / 2.0);
    const double e = rms(s, run(s, params::neighbor_radius(radius * s.spacing)).H);
    if (e < r.best_fixed) {
      r.best_fixed = e;
      r.best_radius = radius;
    }
  }
  std::printf("%-14s selected %.4f, best fixed %.4f at %.2f spacings (ratio %.2f), default %.4f (ratio %.2f)\n",
              s.name.c_str(), r.selected, r.best_fixed, r.best_radius, r.selected / r.best_fixed, r.default_fit,
              r.selected / r.default_fit);
  return r;
}

TEST(PointSetScaleSelection, RecognisesCleanSets)
{
  for (Shape shape : {Shape::ellipsoid, Shape::torus}) {
    const Family_result r = family_result(family_set(shape, 0));
    EXPECT_LE(r.selected, 1.1 * r.default_fit);
  }
}

// The target, 1.25 times the best single radius.
TEST(PointSetScaleSelection, UniformNoiseNearTheBestSingleRadius)
{
  for (Shape shape : {Shape::ellipsoid, Shape::torus})
    for (double fraction : {0.01, 0.05, 0.15}) {
      const Family_result r = family_result(family_set(shape, fraction));
      EXPECT_LE(r.selected, 1.25 * r.best_fixed);
    }
}

// Where the noise varies from 0 to 15% across the set, the 0.8 times the best single radius holds on the
// ellipsoid; on the torus a choice per vertex still beats every single radius, but not by that much (on meshes an
// oracle that knows the exact curvature and the noise's distribution gets 0.94 there: the manual, "Choosing the
// radius per vertex").
TEST(PointSetScaleSelection, VaryingNoiseBelowTheBestSingleRadius)
{
  for (Shape shape : {Shape::ellipsoid, Shape::torus}) {
    const Family_result r = family_result(family_set(shape, -1));
    EXPECT_LE(r.selected, (shape == Shape::torus ? 1.0 : 0.8) * r.best_fixed);
  }
}

} // namespace
