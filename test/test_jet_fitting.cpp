// SPDX-License-Identifier: GPL-3.0-or-later
// jet_fitting_curvatures: CGAL's jet fitting behind this package's interface.
#include <CGAL/Curvature_estimation/jet_fitting.h>
#include <CGAL/Curvature_estimation/paraboloid_fitting.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <gtest/gtest.h>

#include "estimator_runs.h"
#include "test_surfaces.h"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <vector>

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
using Estimates = ce_test::Estimates<Kernel>;
using CGAL::Curvature_estimation::Estimation_status;
namespace CE = CGAL::Curvature_estimation;
namespace params = CGAL::Curvature_estimation::parameters;

template <typename ConcurrencyTag = CGAL::Sequential_tag, typename Extra>
Estimates estimate(const Mesh& mesh, const Extra& extra)
{
  return ce_test::run_with_all_outputs<Kernel>(
    mesh, [](const Mesh& m, const auto& np) { CE::jet_fitting_curvatures<ConcurrencyTag>(m, np); }, extra);
}

std::vector<bool> border_flags(const Mesh& mesh)
{
  std::vector<bool> border;
  for (Mesh::Vertex_index v : vertices(mesh))
    border.push_back(static_cast<bool>(CGAL::is_border(v, mesh)));
  return border;
}

TEST(Jet_fitting, SphereHasPositiveCurvatureOneOverRadiusAndConverges)
{
  const double radius = 2.0;
  double previous = std::numeric_limits<double>::infinity();
  for (unsigned level = 2; level <= 4; ++level) {
    const ce_test::Soup soup = ce_test::sphere_soup(radius, level);
    const Estimates e = estimate(ce_test::to_mesh<Mesh>(soup), params::default_values());
    ce_test::Error_accumulator mean_error;
    for (std::size_t i = 0; i < e.mean.size(); ++i) {
      ASSERT_NE(e.status[i], Estimation_status::not_estimable);
      EXPECT_GT(e.principal[i].min_curvature, 0); // outward normals: positive
      EXPECT_GE(e.principal[i].max_curvature, e.principal[i].min_curvature);
      mean_error.add(1 / radius, e.mean[i]);
    }
    std::printf("jet d=2, icosphere level %u: H RMS error %.2e\n", level, mean_error.stats().rms);
    EXPECT_LT(mean_error.stats().rms, 0.6 * previous);
    previous = mean_error.stats().rms;
  }
}

TEST(Jet_fitting, TiltedPlaneHasZeroCurvature)
{
  const ce_test::Graph_function plane = ce_test::hamann_table1_functions()[0];
  const Estimates e = estimate(ce_test::to_mesh<Mesh>(ce_test::jittered_grid_graph_soup(plane, 15, -1, 1, 0.2, 3)),
                               params::default_values());
  for (std::size_t i = 0; i < e.mean.size(); ++i) {
    ASSERT_NE(e.status[i], Estimation_status::not_estimable);
    EXPECT_LT(std::abs(e.principal[i].max_curvature), 1e-9);
    EXPECT_LT(std::abs(e.principal[i].min_curvature), 1e-9);
  }
}

TEST(Jet_fitting, WideningOnTheConditionNumberRemovesTheGridBoundaryGarbage)
{
  // At a grid boundary the 3-ring has the 15 points a degree-4 jet needs, but
  // they lie on four rows: too few for a quartic across them, the system is
  // (nearly) singular. Without the condition test those fits are accepted.
  const ce_test::Graph_function f = ce_test::hamann_table1_functions()[8];
  const ce_test::Soup soup = ce_test::grid_graph_soup(f, 31);
  const Mesh mesh = ce_test::to_mesh<Mesh>(soup);
  const auto exact = ce_test::graph_curvatures(f, soup);
  const std::vector<bool> border = border_flags(mesh);
  const auto on_border = [&](std::size_t i) { return bool(border[i]); };

  // 3-ring fits only, accepted whatever their condition; compared where the
  // 3-ring has enough points.
  const auto degree4 = params::jet_degree(4).monge_degree(4).neighborhood_rings(3);
  const Estimates accepted_all = estimate(mesh, degree4.max_condition_number(1e300).max_neighborhood_rings(3));
  const Estimates widened = estimate(mesh, degree4);
  std::size_t not_estimable = 0;
  for (std::size_t i = 0; i < widened.status.size(); ++i)
    not_estimable += widened.status[i] == Estimation_status::not_estimable;
  const auto fitted_on_border = [&](std::size_t i) {
    return on_border(i) && accepted_all.status[i] != Estimation_status::not_estimable &&
           widened.status[i] != Estimation_status::not_estimable;
  };
  const double garbage = ce_test::curvature_errors(accepted_all, exact, fitted_on_border).mean.stats().max;
  const double fixed = ce_test::curvature_errors(widened, exact, fitted_on_border).mean.stats().max;
  std::printf("jet d=4 on the boundary of a 31x31 grid: max H error %.3g without the condition test, %.3g with it "
              "(%zu vertices not estimable with it)\n",
              garbage, fixed, not_estimable);
  EXPECT_GT(garbage, 10 * fixed);
  EXPECT_LT(fixed, 0.1);
}

TEST(Jet_fitting, OnAnIrregularMeshDegreeTwoIsFirstOrderAndDegreeFourHigher)
{
  const double R = 3, r = 1;
  // Jittered in the parameter domain: no symmetric stencil cancels the odd terms.
  double previous_d2 = 0, previous_d4 = 0;
  for (int n : {60, 120, 240}) {
    const auto [soup, mesh, exact] = ce_test::sampled_torus<Mesh>(R, r, n, n / 2, 0.2, 5);
    const double d2 = ce_test::curvature_errors(estimate(mesh, params::default_values()), exact).mean.stats().rms;
    const double d4 =
      ce_test::curvature_errors(estimate(mesh, params::jet_degree(4).monge_degree(4).neighborhood_rings(3)), exact)
        .mean.stats()
        .rms;
    std::printf("jet on a jittered %dx%d torus: H RMS %.2e (d=2, 1-ring), %.2e (d=4, 3-ring)\n", n, n / 2, d2, d4);
    if (previous_d2 > 0) {
      // Halving the spacing: order log2 of the error ratio.
      EXPECT_GT(std::log2(previous_d2 / d2), 0.8);
      EXPECT_GT(std::log2(previous_d4 / d4), 2.5);
    }
    previous_d2 = d2;
    previous_d4 = d4;
  }
}

TEST(Jet_fitting, BadInputAndParameters)
{
  Mesh mesh = ce_test::to_mesh<Mesh>(ce_test::sphere_soup(1, 2));
  const Mesh::Vertex_index isolated = mesh.add_vertex(Kernel::Point_3(5, 5, 5));
  const Estimates e = estimate(mesh, params::default_values());
  EXPECT_EQ(e.status[isolated], Estimation_status::not_estimable);
  EXPECT_TRUE(std::isnan(e.mean[isolated]) && std::isnan(e.gaussian[isolated]));

  EXPECT_THROW(CE::jet_fitting_curvatures(mesh, params::jet_degree(5)), std::invalid_argument);
  EXPECT_THROW(CE::jet_fitting_curvatures(mesh, params::jet_degree(2).monge_degree(3)), std::invalid_argument);
  EXPECT_THROW(CE::jet_fitting_curvatures(mesh, params::neighborhood_rings(0)), std::invalid_argument);
  EXPECT_THROW(CE::jet_fitting_curvatures(mesh, params::max_condition_number(1.0)), std::invalid_argument);
}

// A thick-walled pipe of single bands of triangles, as CGAL's data pipe.off: at some of its
// vertices (24 of 48 when this test was written) CGAL's condition number exceeds 1e3 on every
// ring up to the fourth; the estimate there is the paraboloid fit's with its defaults, status
// fallback, and every vertex is estimated.
TEST(Jet_fitting, WhereCgalsFitIsIllConditionedOnEveryRingItFallsBackToTheParaboloidFit)
{
  const Mesh mesh = ce_test::to_mesh<Mesh>(ce_test::pipe_soup(0.17, 0.31, 1.0, 12));
  const Estimates jet = estimate(mesh, params::default_values());
  const Estimates paraboloid = ce_test::run_with_all_outputs<Kernel>(
    mesh, [](const Mesh& m, const auto& np) { CE::paraboloid_fitting_curvatures(m, np); }, params::default_values());
  std::size_t fallbacks = 0;
  for (std::size_t i = 0; i < jet.status.size(); ++i) {
    SCOPED_TRACE(i);
    ASSERT_NE(jet.status[i], Estimation_status::not_estimable);
    if (jet.status[i] != Estimation_status::fallback)
      continue;
    ++fallbacks;
    EXPECT_NEAR(jet.principal[i].max_curvature, paraboloid.principal[i].max_curvature, 1e-12);
    EXPECT_NEAR(jet.principal[i].min_curvature, paraboloid.principal[i].min_curvature, 1e-12);
    EXPECT_NEAR(jet.mean[i], paraboloid.mean[i], 1e-12);
  }
  EXPECT_GT(fallbacks, 0u);
}

// use_fallbacks(false): the vertices the paraboloid fit served are not estimable,
// the others unchanged to the bit.
TEST(Jet_fitting, WithoutFallbacksTheirVerticesAreNotEstimable)
{
  const Mesh mesh = ce_test::to_mesh<Mesh>(ce_test::pipe_soup(0.17, 0.31, 1.0, 12));
  const ce_test::Fallback_counts counts = ce_test::compare_without_fallbacks(
    estimate(mesh, params::default_values()), estimate(mesh, params::use_fallbacks(false)));
  EXPECT_GT(counts.not_estimable, 0u);
  EXPECT_EQ(counts.own, 0u);
}

#ifdef CGAL_LINKED_WITH_TBB
TEST(Jet_fitting, SequentialAndParallelAreIdentical)
{
  const Mesh mesh =
    ce_test::to_mesh<Mesh>(ce_test::jittered_grid_graph_soup(ce_test::hamann_table1_functions()[7], 60, -1, 1, 0.2, 9));
  const Estimates sequential = estimate<CGAL::Sequential_tag>(mesh, params::default_values());
  const Estimates parallel = estimate<CGAL::Parallel_tag>(mesh, params::default_values());
  for (std::size_t i = 0; i < sequential.status.size(); ++i) {
    ASSERT_EQ(sequential.status[i], parallel.status[i]);
    ASSERT_EQ(std::memcmp(&sequential.principal[i], &parallel.principal[i], sizeof(sequential.principal[i])), 0) << i;
  }
}
#endif

} // namespace
