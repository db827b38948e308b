// SPDX-License-Identifier: GPL-3.0-or-later
// Scale selection (`ball_radius_range`): the rule of internal/scale_selection.h on
// candidates with a known optimum; the noise estimate against the noise added; the
// selected estimate is the fixed-radius fit at the radius it reports, or the
// default; and the noisy test family against the best single radius, known from
// the exact curvature.
#include <CGAL/Curvature_estimation/internal/scale_selection.h>
#include <CGAL/Curvature_estimation/internal/scale_selector.h>
#include <CGAL/Curvature_estimation/jet_fitting.h>
#include <CGAL/Curvature_estimation/mean_edge_length.h>
#include <CGAL/Curvature_estimation/paraboloid_fitting.h>
#include <CGAL/Curvature_estimation/taubin.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <gtest/gtest.h>

#include "estimator_runs.h"
#include "noisy_meshes.h"
#include "test_surfaces.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <functional>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
using Vertex = Mesh::Vertex_index;
using Estimates = ce_test::Estimates<Kernel>;
namespace CE = CGAL::Curvature_estimation;
namespace params = CGAL::Curvature_estimation::parameters;
using CE::internal::Scale_candidate;

// Candidates at radii 2^(k/4) whose mean curvatures carry the exact bias
// beta r^order and whose variances fall as r^-(2 + 2 order) (a fit of heights
// over a disc: 1/(N r^4), N ~ r^2, at order 2).
std::vector<Scale_candidate> exact_bias_candidates(double beta, int order)
{
  std::vector<Scale_candidate> candidates;
  for (std::size_t k = 0; k <= 16; ++k) {
    const double r = std::exp2(k / 4.0);
    candidates.push_back({k, r, 0.5 + beta * std::pow(r, order), 48 / std::pow(r, 2 + 2 * order), 1.0});
  }
  return candidates;
}

TEST(LeastErrorCandidate, IsTheAnalyticOptimumOfBiasAndNoise)
{
  for (int order : {2, 4})
    for (double beta : {1e-3, 1e-2, 1e-1})
      for (double noise_variance : {1e-4, 1e-2}) {
        const auto candidates = exact_bias_candidates(beta, order);
        const auto least =
          CE::internal::least_error_candidate(candidates.data(), candidates.size(), noise_variance, order);
        // d/dr [beta^2 r^(2 order) + s^2 48 r^-(2 + 2 order)] = 0
        const double optimum =
          std::pow((1 + order) * noise_variance * 48 / (order * beta * beta), 1.0 / (4 * order + 2));
        const double expected = std::clamp(optimum, candidates.front().radius, candidates.back().radius);
        const double chosen = candidates[least.index].radius;
        EXPECT_LE(std::abs(std::log2(chosen / expected)), 0.125 + 1e-12)
          << "order " << order << " beta " << beta << " noise variance " << noise_variance;
        const double bias = beta * std::pow(chosen, order);
        EXPECT_NEAR(least.squared_error, bias * bias + noise_variance * candidates[least.index].variance,
                    1e-9 * least.squared_error);
      }
}

TEST(LeastErrorCandidate, WithoutBiasIsTheWidestBall)
{
  auto candidates = exact_bias_candidates(0, 2);
  const auto least = CE::internal::least_error_candidate(candidates.data(), candidates.size(), 1e-2, 2);
  EXPECT_EQ(least.index, candidates.size() - 1);
}

// Without bias up to 8, then mean curvatures that fall away (a ball outgrowing the
// surface, as past a torus's tube radius, but below the misfit cut): the bias
// refitted near the first choice is flat, which says nothing of the wider balls.
TEST(LeastErrorCandidate, NoneWiderThanWhereItsBiasWasFitted)
{
  auto candidates = exact_bias_candidates(0, 2);
  for (std::size_t k = 13; k < candidates.size(); ++k)
    candidates[k].mean_curvature -= 0.3 * double(k - 12);
  const auto least = CE::internal::least_error_candidate(candidates.data(), candidates.size(), 1e-2, 2);
  EXPECT_LE(candidates[least.index].radius, 8);
}

TEST(ConsideredCandidates, CleanDataAndOutgrownBalls)
{
  auto candidates = exact_bias_candidates(1e-2, 2);
  const double noise_variance = 1e-2;
  for (auto& c : candidates)
    c.residual_variance = noise_variance;
  EXPECT_EQ(CE::internal::considered_candidates(candidates.data(), candidates.size(), noise_variance),
            candidates.size());
  candidates[9].residual_variance = 101 * noise_variance;
  EXPECT_EQ(CE::internal::considered_candidates(candidates.data(), candidates.size(), noise_variance), 9u);
  candidates[0].residual_variance = 11 * noise_variance;
  EXPECT_EQ(CE::internal::considered_candidates(candidates.data(), candidates.size(), noise_variance), 0u);
  EXPECT_EQ(CE::internal::considered_candidates(candidates.data(), 0, noise_variance), 0u);
}

TEST(CandidateRadii, GeometricStepsBetweenTheBounds)
{
  const auto radii = CE::internal::candidate_radii({0.5, 8});
  ASSERT_EQ(radii.size(), 17u);
  EXPECT_EQ(radii.front(), 0.5);
  EXPECT_EQ(radii.back(), 8);
  for (std::size_t k = 1; k < radii.size(); ++k)
    EXPECT_NEAR(radii[k] / radii[k - 1], std::exp2(0.25), 1e-12);
  EXPECT_EQ(CE::internal::candidate_radii({1, 1}).size(), 1u);
  EXPECT_LE(CE::internal::candidate_radii({1e-6, 1e6}).size(), 65u);
}

// One mesh of the noisy family (noisy_meshes.h) and its mean edge length after the noise.
struct Family_mesh : ce_test::Noisy_family_soup
{
  explicit Family_mesh(ce_test::Noisy_family_soup family)
      : ce_test::Noisy_family_soup(std::move(family))
      , mesh(ce_test::to_mesh<Mesh>(soup))
      , edge(CE::mean_edge_length(mesh))
  {}

  Mesh mesh;
  double edge;
};

using Shape = ce_test::Noisy_shape;

Family_mesh family_mesh(Shape shape, double fraction)
{
  return Family_mesh(ce_test::noisy_family_soup(shape, fraction));
}

struct Selection_run
{
  Estimates estimates;
  std::vector<double> radius, noise;
};

template <typename Estimator>
Selection_run run_selection(const Mesh& mesh, double min, double max, const Estimator& estimator)
{
  Mesh& m = const_cast<Mesh&>(mesh);
  auto radius = m.add_property_map<Vertex, double>("v:test_radius").first;
  auto noise = m.add_property_map<Vertex, double>("v:test_noise").first;
  Selection_run run;
  run.estimates = ce_test::run_with_all_outputs<Kernel>(
    mesh, estimator,
    params::ball_radius_range(std::make_pair(min, max)).vertex_ball_radius_map(radius).vertex_noise_map(noise));
  for (Vertex v : vertices(mesh)) {
    run.radius.push_back(radius[v]);
    run.noise.push_back(noise[v]);
  }
  m.remove_property_map(radius);
  m.remove_property_map(noise);
  return run;
}

const auto paraboloid = [](int degree) {
  return [degree](const Mesh& m, const auto& np) { CE::paraboloid_fitting_curvatures(m, np.fit_degree(degree)); };
};

double median(std::vector<double> values)
{
  std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
  return values[values.size() / 2];
}

TEST(ScaleSelection, NoiseEstimateMatchesTheNoiseAdded)
{
  for (Shape shape : {Shape::ellipsoid, Shape::torus, Shape::delaunay})
    for (double fraction : {0.01, 0.05, 0.15}) {
      const Family_mesh m = family_mesh(shape, fraction);
      const Selection_run run = run_selection(m.mesh, m.edge, 16 * m.edge, paraboloid(2));
      std::vector<double> ratios;
      for (std::size_t i = 0; i < run.noise.size(); ++i)
        if (m.interior[i]) {
          ASSERT_TRUE(std::isfinite(run.noise[i])) << m.name << " vertex " << i;
          ratios.push_back(run.noise[i] / m.sigma[i]);
        }
      EXPECT_NEAR(median(ratios), 1.0, 0.1) << m.name;
    }
}

// Where the radius reported is one of the candidate radii, the estimate is the
// fixed-radius fit at that radius, bit for bit; elsewhere it is the default's.
template <typename Estimator>
void expect_fixed_fit_at_reported_radius(const Family_mesh& m, const Estimator& estimator)
{
  const double min = m.edge, max = 16 * m.edge;
  const Selection_run run = run_selection(m.mesh, min, max, estimator);
  const Estimates defaults = ce_test::run_with_all_outputs<Kernel>(m.mesh, estimator, params::use_fallbacks(true));
  const auto radii = CE::internal::candidate_radii({min, max});
  std::map<double, Estimates> fixed;
  std::size_t selected = 0;
  for (std::size_t i = 0; i < run.radius.size(); ++i) {
    const bool candidate = std::find(radii.begin(), radii.end(), run.radius[i]) != radii.end();
    const Estimates* expected = &defaults;
    if (candidate) {
      ++selected;
      auto it = fixed.find(run.radius[i]);
      if (it == fixed.end())
        it = fixed
               .emplace(run.radius[i],
                        ce_test::run_with_all_outputs<Kernel>(m.mesh, estimator, params::ball_radius(run.radius[i])))
               .first;
      expected = &it->second;
    }
    ASSERT_EQ(run.estimates.status[i], expected->status[i]) << m.name << " vertex " << i;
    if (run.estimates.status[i] == CE::Estimation_status::not_estimable)
      continue;
    EXPECT_EQ(run.estimates.mean[i], expected->mean[i]) << m.name << " vertex " << i;
    EXPECT_EQ(run.estimates.gaussian[i], expected->gaussian[i]) << m.name << " vertex " << i;
    EXPECT_EQ(run.estimates.principal[i].min_curvature, expected->principal[i].min_curvature);
    EXPECT_EQ(run.estimates.principal[i].max_direction, expected->principal[i].max_direction);
  }
  EXPECT_GT(selected, run.radius.size() / 2) << m.name;
}

TEST(ScaleSelection, IsTheFixedFitAtTheRadiusItReports)
{
  const Family_mesh m = family_mesh(Shape::ellipsoid, 0.05);
  for (int degree : {2, 3, 4})
    expect_fixed_fit_at_reported_radius(m, paraboloid(degree));
  expect_fixed_fit_at_reported_radius(m,
                                      [](const Mesh& mesh, const auto& np) { CE::jet_fitting_curvatures(mesh, np); });
}

TEST(ScaleSelection, ParametersAreChecked)
{
  const Family_mesh m = family_mesh(Shape::ellipsoid, 0.05);
  const auto h = m.edge;
  using Pair = std::pair<double, double>;
  EXPECT_THROW(CE::paraboloid_fitting_curvatures(m.mesh, params::ball_radius_range(Pair(0, h))), std::invalid_argument);
  EXPECT_THROW(CE::paraboloid_fitting_curvatures(m.mesh, params::ball_radius_range(Pair(2 * h, h))),
               std::invalid_argument);
  EXPECT_THROW(CE::paraboloid_fitting_curvatures(m.mesh, params::ball_radius_range(Pair(h, HUGE_VAL))),
               std::invalid_argument);
  EXPECT_THROW(CE::paraboloid_fitting_curvatures(m.mesh, params::ball_radius_range(Pair(h, 2 * h)).ball_radius(h)),
               std::invalid_argument);
  Mesh& mesh = const_cast<Mesh&>(m.mesh);
  auto radius = mesh.add_property_map<Vertex, double>("v:radius").first;
  EXPECT_THROW(CE::paraboloid_fitting_curvatures(m.mesh, params::vertex_ball_radius_map(radius)),
               std::invalid_argument);
  EXPECT_THROW(CE::taubin_curvatures(m.mesh, params::ball_radius_range(Pair(h, 2 * h))), std::invalid_argument);
  mesh.remove_property_map(radius);
}

// The noisy family against the best single radius of 1 to 16 mean edges (in
// steps of 2^(1/2)) and, noise-free, against the default 1-ring fit: interior H RMS.
struct Family_result
{
  double selected, best_fixed, best_radius, default_fit;
};

Family_result family_result(const Family_mesh& m, int degree)
{
  Family_result r;
  r.selected = interior_rms(m, run_selection(m.mesh, m.edge, 16 * m.edge, paraboloid(degree)).estimates.mean);
  r.default_fit = interior_rms(
    m, ce_test::run_with_all_outputs<Kernel>(m.mesh, paraboloid(degree), params::use_fallbacks(true)).mean);
  r.best_fixed = HUGE_VAL;
  for (const double radius : ce_test::noisy_family_radii_in_edges()) {
    const double e = interior_rms(
      m, ce_test::run_with_all_outputs<Kernel>(m.mesh, paraboloid(degree), params::ball_radius(radius * m.edge)).mean);
    if (e < r.best_fixed) {
      r.best_fixed = e;
      r.best_radius = radius;
    }
  }
  std::printf("%-18s degree %d: selected %.4f, best fixed %.4f at %.2f edges (ratio %.2f), default %.4f (ratio %.2f)\n",
              m.name.c_str(), degree, r.selected, r.best_fixed, r.best_radius, r.selected / r.best_fixed, r.default_fit,
              r.selected / r.default_fit);
  return r;
}

TEST(ScaleSelection, RecognisesCleanMeshes)
{
  for (Shape shape : {Shape::ellipsoid, Shape::torus, Shape::delaunay}) {
    const Family_result r = family_result(family_mesh(shape, 0), 2);
    EXPECT_LE(r.selected, 1.1 * r.default_fit);
  }
}

// The target, 1.25 times the best single radius.
TEST(ScaleSelection, UniformNoiseNearTheBestSingleRadius)
{
  for (Shape shape : {Shape::ellipsoid, Shape::torus, Shape::delaunay})
    for (double fraction : {0.01, 0.05, 0.15}) {
      const Family_result r = family_result(family_mesh(shape, fraction), 2);
      EXPECT_LE(r.selected, 1.25 * r.best_fixed);
    }
}

// Where the noise varies from 0 to 15% across the mesh, the 0.8 times the best
// single radius holds on the ellipsoid, and a choice per vertex beats every single
// radius on the Delaunay mesh. On the torus and the Delaunay mesh 0.8 is out of reach
// of an oracle that knows the exact curvature and the noise's distribution (0.94 and
// 0.90: benchmark/scale_selection_oracle, the manual); on the torus the uniform
// target holds.
TEST(ScaleSelection, VaryingNoiseBelowTheBestSingleRadius)
{
  for (Shape shape : {Shape::ellipsoid, Shape::torus, Shape::delaunay}) {
    const Family_result r = family_result(family_mesh(shape, -1), 2);
    EXPECT_LE(r.selected, (shape == Shape::ellipsoid ? 0.8 : shape == Shape::torus ? 1.25 : 1.0) * r.best_fixed);
  }
}

} // namespace
