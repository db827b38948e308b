// SPDX-License-Identifier: GPL-3.0-or-later
// Every estimator of the package, with its defaults, on marching-tetrahedra meshes of three
// smooth closed surfaces (test/common/marching_tetrahedra.h: slivers, uneven valence, vertices on
// the exact surface) at 20, 40 and 80 cells per axis: the RMS and the maximum of |H - H_exact|
// over the vertices estimated, how many were not, and the observed orders between the two finest
// levels, printed for all; asserted for the estimators that converge on these meshes (and for the
// paraboloid fit's fit_degree(3) and fit_degree(4), at orders 1.8 and 2.6). The reference,
// jet fitting of degree 4 on 3 rings, runs on the two coarser levels only (it costs ten times the others).
#include <CGAL/Curvature_estimation/chen_schmitt.h>
#include <CGAL/Curvature_estimation/curve_network.h>
#include <CGAL/Curvature_estimation/gauss_map.h>
#include <CGAL/Curvature_estimation/jet_fitting.h>
#include <CGAL/Curvature_estimation/paraboloid_fitting.h>
#include <CGAL/Curvature_estimation/taubin.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <gtest/gtest.h>

#include "estimator_runs.h"
#include "marching_tetrahedra.h"
#include "test_surfaces.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
using Estimates = ce_test::Estimates<Kernel>;
namespace CE = CGAL::Curvature_estimation;
namespace params = CGAL::Curvature_estimation::parameters;

const std::size_t levels[] = {20, 40, 80};
constexpr std::size_t n_levels = sizeof(levels) / sizeof(levels[0]);

struct Estimator
{
  std::string name;
  std::function<Estimates(const Mesh&)> run;
  std::size_t measured_levels; // the first ones of `levels`
};

template <typename Run, typename Extra>
Estimator estimator(const std::string& name, Run run, const Extra& extra, std::size_t measured_levels = n_levels)
{
  return {name, [run, extra](const Mesh& mesh) { return ce_test::run_with_all_outputs<Kernel>(mesh, run, extra); },
          measured_levels};
}

const std::vector<Estimator>& estimators()
{
  const auto defaults = params::default_values();
  static const std::vector<Estimator> all = {
    estimator(
      "paraboloid_fitting", [](const Mesh& m, const auto& np) { CE::paraboloid_fitting_curvatures(m, np); }, defaults),
    estimator(
      "paraboloid d3", [](const Mesh& m, const auto& np) { CE::paraboloid_fitting_curvatures(m, np); },
      params::fit_degree(3)),
    estimator(
      "paraboloid d4", [](const Mesh& m, const auto& np) { CE::paraboloid_fitting_curvatures(m, np); },
      params::fit_degree(4)),
    estimator(
      "curve_network", [](const Mesh& m, const auto& np) { CE::curve_network_curvatures(m, np); }, defaults),
    estimator(
      "gauss_map", [](const Mesh& m, const auto& np) { CE::gauss_map_curvatures(m, np); }, defaults),
    estimator(
      "gauss_map paper", [](const Mesh& m, const auto& np) { CE::gauss_map_curvatures(m, np); },
      params::neighbor_weighting(CE::Neighbor_weighting::centroid)),
    estimator(
      "taubin", [](const Mesh& m, const auto& np) { CE::taubin_curvatures(m, np); }, defaults),
    estimator(
      "chen_schmitt", [](const Mesh& m, const auto& np) { CE::chen_schmitt_curvatures(m, np); }, defaults),
    estimator(
      "jet_fitting", [](const Mesh& m, const auto& np) { CE::jet_fitting_curvatures(m, np); }, defaults),
    estimator(
      "jet_fitting d4 3 rings", [](const Mesh& m, const auto& np) { CE::jet_fitting_curvatures(m, np); },
      params::jet_degree(4).neighborhood_rings(3), 2)};
  return all;
}

// The H errors of one estimator on one mesh, over the vertices it estimated, and how many it did not;
// the same over its vertices of status fallback, and the largest error relative to the largest
// principal curvature over the others (its own estimates).
struct Level_errors
{
  ce_test::Error_stats H, H_fallback;
  double own_relative_max = 0;
  std::size_t not_estimated = 0;
};

// The errors of one estimator on one surface at its measured levels; orders between the two finest.
struct Row
{
  std::string surface, estimator;
  std::size_t measured_levels;
  Level_errors level[n_levels];
  double h[n_levels];
  double rms_order() const
  {
    const std::size_t f = measured_levels - 1;
    return ce_test::observed_order(level[f - 1].H.rms, level[f].H.rms, h[f - 1], h[f]);
  }
  double max_order() const
  {
    const std::size_t f = measured_levels - 1;
    return ce_test::observed_order(level[f - 1].H.max, level[f].H.max, h[f - 1], h[f]);
  }
};

// Measures every estimator on the surface at every level, printing the meshes and the table.
std::vector<Row> measure(const ce_test::Implicit_surface& surface)
{
  const Eigen::Vector3d offset(0.137, 0.291, 0.413);
  std::vector<Row> rows(estimators().size());
  for (std::size_t e = 0; e < rows.size(); ++e) {
    rows[e].surface = surface.name;
    rows[e].estimator = estimators()[e].name;
    rows[e].measured_levels = estimators()[e].measured_levels;
  }
  for (std::size_t l = 0; l < n_levels; ++l) {
    const ce_test::Soup soup = ce_test::marching_tetrahedra_soup(surface, levels[l], offset);
    const auto exact = ce_test::implicit_curvatures(surface, soup);
    const Mesh mesh = ce_test::to_mesh<Mesh>(soup);
    const double h = ce_test::mean_edge_length(soup);
    std::vector<double> q = ce_test::aspect_ratios(soup);
    std::sort(q.begin(), q.end());
    std::printf("%-9s %3zu cells: %6zu vertices %6zu triangles, mean edge %.4f, aspect ratio min %.2e median %.3f\n",
                surface.name.c_str(), levels[l], soup.points.size(), soup.faces.size(), h, q.front(), q[q.size() / 2]);
    for (std::size_t e = 0; e < rows.size(); ++e) {
      if (l >= rows[e].measured_levels)
        continue;
      const Estimates est = estimators()[e].run(mesh);
      ce_test::Error_accumulator H, H_fallback;
      Level_errors& errors = rows[e].level[l];
      for (std::size_t i = 0; i < exact.size(); ++i) {
        if (!std::isfinite(est.mean[i])) {
          ++errors.not_estimated;
          continue;
        }
        H.add(exact[i].H, est.mean[i]);
        if (est.status[i] == CE::Estimation_status::fallback)
          H_fallback.add(exact[i].H, est.mean[i]);
        else
          errors.own_relative_max =
            (std::max)(errors.own_relative_max, std::abs(est.mean[i] - exact[i].H) /
                                                  (std::max)(std::abs(exact[i].k_max), std::abs(exact[i].k_min)));
      }
      errors.H = H.stats();
      errors.H_fallback = H_fallback.stats();
      rows[e].h[l] = h;
    }
  }
  std::printf("%-9s %-23s", "surface", "estimator");
  for (std::size_t level : levels)
    std::printf("  %3zu: H RMS    H max   n/e", level);
  std::printf("  order RMS  max\n");
  for (const Row& r : rows) {
    std::printf("%-9s %-23s", r.surface.c_str(), r.estimator.c_str());
    for (std::size_t l = 0; l < n_levels; ++l) {
      if (l < r.measured_levels)
        std::printf("  %10.3e %9.3e %4zu", r.level[l].H.rms, r.level[l].H.max, r.level[l].not_estimated);
      else
        std::printf("  %10s %9s %4s", "-", "-", "-");
    }
    std::printf("  %8.2f %5.2f\n", r.rms_order(), r.max_order());
  }
  return rows;
}

// The observed order of the H RMS of `estimator` is at least `min_order`; with `all_estimated`,
// it estimated every vertex at every level.
void expect_converges(const std::vector<Row>& rows, const std::string& estimator, double min_order, bool all_estimated)
{
  for (const Row& r : rows)
    if (r.estimator == estimator) {
      SCOPED_TRACE(r.surface + ", " + r.estimator);
      for (std::size_t l = 0; all_estimated && l < r.measured_levels; ++l)
        EXPECT_EQ(r.level[l].not_estimated, 0u);
      EXPECT_GE(r.rms_order(), min_order);
    }
}

// The Gauss map's default (the least-squares differential over the 2-ring, quadric_fit normals)
// estimates every vertex, its H RMS falls at every refinement, at order 0.5 at least between the two
// finest levels, and at the finest level it is below the mean edge length h (in the surfaces'
// units, where the curvatures are of order 1): the normals are second order (measured on this
// family, their RMS angle error is about h^2), the fit divides their errors by the stencil's
// extent, about h, and its truncation error is O(h) with a constant of the order of the curvature's
// gradient, so the error is C h with C of order 1 (measured 0.5 to 0.8).
void expect_gauss_map_converges(const std::vector<Row>& rows)
{
  expect_converges(rows, "gauss_map", 0.5, true);
  for (const Row& r : rows)
    if (r.estimator == "gauss_map") {
      SCOPED_TRACE(r.surface + ", " + r.estimator);
      for (std::size_t l = 1; l < r.measured_levels; ++l)
        EXPECT_LT(r.level[l].H.rms, r.level[l - 1].H.rms) << l;
      EXPECT_LT(r.level[r.measured_levels - 1].H.rms, r.h[r.measured_levels - 1]);
    }
}

// The curve network cannot converge on these meshes by construction: a curve a - p - b whose edges
// are uneven or kinked (irregularity s^2 + tan^2(delta/2), see curve_network.h) has a relative error of
// about its irregularity, which does not fall with h. It says so per vertex: about 91% of the vertices
// here have such a curve and are status fallback, with the paraboloid fit's values, whose RMS converges at
// order 0.5 at least (measured 0.98 to 1.04); the others keep their curves (irregularity at most 0.04),
// with an error bounded by a fraction of the curvature rather than by h: the irregularity's 4% plus the
// three-point curve's own O(h) error, measured at most 5.4% of the largest principal curvature, asserted
// at most 10%. Their share keeps the whole at order 0.26 to 0.69 (printed), and lower as h shrinks.
void expect_curve_network_says_where_it_falls_back(const std::vector<Row>& rows)
{
  for (const Row& r : rows)
    if (r.estimator == "curve_network") {
      SCOPED_TRACE(r.surface + ", " + r.estimator);
      const std::size_t f = n_levels - 1;
      const double order =
        ce_test::observed_order(r.level[f - 1].H_fallback.rms, r.level[f].H_fallback.rms, r.h[f - 1], r.h[f]);
      std::printf("%-9s curve network: fallback vertices' H RMS", r.surface.c_str());
      for (std::size_t l = 0; l < n_levels; ++l)
        std::printf(" %.3e (%zu)", r.level[l].H_fallback.rms, r.level[l].H_fallback.count);
      std::printf(", order %.2f; own estimates' largest |H error| / max |k|", order);
      for (std::size_t l = 0; l < n_levels; ++l)
        std::printf(" %.3f", r.level[l].own_relative_max);
      std::printf("\n");
      for (std::size_t l = 0; l < n_levels; ++l) {
        EXPECT_EQ(r.level[l].not_estimated, 0u);
        EXPECT_LE(r.level[l].own_relative_max, 0.1) << levels[l] << " cells";
      }
      EXPECT_GE(order, 0.5);
    }
}

// The estimators that converge on this family: the paraboloid fit, jet fitting (degree 2) and the
// Gauss map at first order, jet fitting of degree 4 at third order, the curve network at order 0.5 (about
// 90% of its vertices are the paraboloid fit's, status fallback: their curves are no mesh lines) and
// Chen-Schmitt's default (the 2-ring, weights |q - p|^2) at first order. Not asserted (printed only): the
// Gauss map with the paper's per-face centroid weights, whose errors do not fall steadily (the slivers' and
// the tiny vertex clusters' per-face gradients divide the normals' errors by lengths far below h), and
// Taubin's, order 0. Chen-Schmitt's paper fit (unweighted, 1-ring) does not converge either.
void expect_convergent_ones_converge(const std::vector<Row>& rows)
{
  expect_converges(rows, "paraboloid_fitting", 0.5, false);
  expect_converges(rows, "jet_fitting", 0.5, true);
  expect_converges(rows, "jet_fitting d4 3 rings", 2.0, true);
  expect_converges(rows, "paraboloid d3", 1.8, true);
  expect_converges(rows, "paraboloid d4", 2.6, true);
  expect_converges(rows, "chen_schmitt", 0.5, true);
  expect_gauss_map_converges(rows);
  expect_curve_network_says_where_it_falls_back(rows);
}

// The row of `estimator`, or nullptr.
const Row* find_row(const std::vector<Row>& rows, const std::string& estimator)
{
  for (const Row& r : rows)
    if (r.estimator == estimator)
      return &r;
  return nullptr;
}

// The default paraboloid fit has no outliers where jet fitting (its defaults) has none: at every
// level its H RMS and maximum error are at most 5% above jet fitting's. Measured: RMS 0.42 to 0.57
// times jet's, maxima 0.23 to 0.75 times. Before the widened fit took the cubic terms, the vertices
// whose 1-ring has near-coincident neighbors (three directions left) were fitted by a paraboloid over
// the 2-ring, and the torus at 20 cells had 1.35 times jet's RMS and 1.7 times its maximum.
void expect_paraboloid_no_worse_than_jet(const std::vector<Row>& rows)
{
  const Row* paraboloid = find_row(rows, "paraboloid_fitting");
  const Row* jet = find_row(rows, "jet_fitting");
  ASSERT_TRUE(paraboloid != nullptr && jet != nullptr);
  SCOPED_TRACE(paraboloid->surface);
  for (std::size_t l = 0; l < n_levels; ++l) {
    EXPECT_LE(paraboloid->level[l].H.rms, 1.05 * jet->level[l].H.rms) << levels[l] << " cells";
    EXPECT_LE(paraboloid->level[l].H.max, 1.05 * jet->level[l].H.max) << levels[l] << " cells";
  }
}

// fit_degree(4) against CGAL's jet fitting of degree 4 on 3 rings, at the levels where that runs: the
// H RMS at most 1.5 times jet's and the maximum at most 2 times (measured: RMS 0.58 to 0.83 times,
// maxima 0.32 to 1.25 times). The torus at 20 cells, whose 3 rings span 70% of the tube's radius, had
// 2.5 times jet's maximum when the fit's frame was always the area-weighted normal's (see
// fit_rings_of_degree in platelet_fit.h).
void expect_degree_four_near_jet_degree_four(const std::vector<Row>& rows)
{
  const Row* ours = find_row(rows, "paraboloid d4");
  const Row* jet = find_row(rows, "jet_fitting d4 3 rings");
  ASSERT_TRUE(ours != nullptr && jet != nullptr);
  SCOPED_TRACE(ours->surface);
  for (std::size_t l = 0; l < jet->measured_levels; ++l) {
    std::printf("%-9s %3zu cells: fit_degree(4) / jet d4 on 3 rings: H RMS %.2f, max %.2f\n", ours->surface.c_str(),
                levels[l], ours->level[l].H.rms / jet->level[l].H.rms, ours->level[l].H.max / jet->level[l].H.max);
    EXPECT_LE(ours->level[l].H.rms, 1.5 * jet->level[l].H.rms) << levels[l] << " cells";
    EXPECT_LE(ours->level[l].H.max, 2.0 * jet->level[l].H.max) << levels[l] << " cells";
  }
}

TEST(MarchingTetrahedraConvergence, Ellipsoid)
{
  const std::vector<Row> rows = measure(ce_test::implicit_ellipsoid(1.0, 0.8, 0.6));
  expect_convergent_ones_converge(rows);
  expect_paraboloid_no_worse_than_jet(rows);
  expect_degree_four_near_jet_degree_four(rows);
}

TEST(MarchingTetrahedraConvergence, Torus)
{
  const std::vector<Row> rows = measure(ce_test::implicit_torus(1.0, 0.4));
  expect_convergent_ones_converge(rows);
  expect_paraboloid_no_worse_than_jet(rows);
  expect_degree_four_near_jet_degree_four(rows);
}

TEST(MarchingTetrahedraConvergence, Blobs)
{
  const std::vector<Row> rows = measure(ce_test::gaussian_blobs());
  expect_convergent_ones_converge(rows);
  expect_paraboloid_no_worse_than_jet(rows);
  expect_degree_four_near_jet_degree_four(rows);
}

} // namespace
