// SPDX-License-Identifier: GPL-3.0-or-later
// The default paraboloid fit against CGAL's jet fitting (jet_fitting_curvatures() with its defaults:
// degree 2, the 1-ring widened as needed) on Delaunay meshes of random points: the eight curved graph
// functions of Hamann's Table 1, three seeds, 1,000, 4,000 and 16,000 points. Over the interior
// vertices, the default's H RMS and maximum error are at most 5% above jet fitting's at every level:
// no outliers where jet fitting has none. On the sphere and the cylinder the default's error is of
// fourth order (the curvature's own quartic term, quadric_fit.h), where both fits
// were of second order and the default's RMS was 1.13 to 1.26 times jet's.
#include <CGAL/Curvature_estimation/jet_fitting.h>
#include <CGAL/Curvature_estimation/paraboloid_fitting.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <gtest/gtest.h>

#include "estimator_runs.h"
#include "test_surfaces.h"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <vector>

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
using Estimates = ce_test::Estimates<Kernel>;
namespace CE = CGAL::Curvature_estimation;
namespace params = CGAL::Curvature_estimation::parameters;

// The H errors over the interior vertices (the boundary is one-sided for both fits, and jet fitting
// has no second-order boundary normal).
ce_test::Error_stats interior_H_errors(const Mesh& mesh, const Estimates& e,
                                       const std::vector<ce_test::Exact_curvature>& exact)
{
  ce_test::Error_accumulator H;
  std::size_t i = 0;
  for (Mesh::Vertex_index v : vertices(mesh)) {
    if (!CGAL::is_border(v, mesh))
      H.add(exact[i].H, e.mean[i]);
    ++i;
  }
  return H.stats();
}

TEST(DelaunayAgainstJetFitting, DefaultHasNoLargerRmsOrMaximumAtAnyLevel)
{
  const std::vector<ce_test::Graph_function> functions = ce_test::hamann_table1_functions();
  for (std::size_t f = 1; f < functions.size(); ++f) // 0 is the plane
    for (const std::uint32_t seed : {1u, 2u, 3u})
      for (const std::size_t points : {1000, 4000, 16000}) {
        const ce_test::Soup soup = ce_test::delaunay_graph_soup(functions[f], points, -1, 1, seed);
        const Mesh mesh = ce_test::to_mesh<Mesh>(soup);
        const auto exact = ce_test::graph_curvatures(functions[f], soup);
        const ce_test::Error_stats ours =
          interior_H_errors(mesh,
                            ce_test::run_with_all_outputs<Kernel>(
                              mesh, [](const Mesh& m, const auto& np) { CE::paraboloid_fitting_curvatures(m, np); },
                              params::default_values()),
                            exact);
        const ce_test::Error_stats jet = interior_H_errors(
          mesh,
          ce_test::run_with_all_outputs<Kernel>(
            mesh, [](const Mesh& m, const auto& np) { CE::jet_fitting_curvatures(m, np); }, params::default_values()),
          exact);
        std::printf("%-12s seed %u %5zu points: H RMS %.3e (jet %.3e, ratio %.2f), max %.3e (jet %.3e, ratio %.2f)\n",
                    functions[f].name.c_str(), seed, points, ours.rms, jet.rms, ours.rms / jet.rms, ours.max, jet.max,
                    ours.max / jet.max);
        SCOPED_TRACE(functions[f].name + ", seed " + std::to_string(seed) + ", " + std::to_string(points) + " points");
        EXPECT_LE(ours.rms, 1.05 * jet.rms);
        EXPECT_LE(ours.max, 1.05 * jet.max);
        // Spheres and cylinders: fourth order, where jet fitting is of second order (measured: RMS
        // 1e-3 to 1e-5 times jet's, maxima 3e-3 to 1e-4 times).
        if (functions[f].name == "sphere" || functions[f].name == "cylinder") {
          EXPECT_LE(ours.rms, 1e-2 * jet.rms);
          EXPECT_LE(ours.max, 1e-2 * jet.max);
        }
      }
}

} // namespace
