// SPDX-License-Identifier: GPL-3.0-or-later
// paraboloid_fitting_curvatures() with fit_degree(3) and fit_degree(4): Taylor fits of degree 3 on 2
// rings and of degree 4 on 3 rings, with linear terms, in the frame of the area-weighted normal.
// On irregular meshes degree-2 fits are of first order; these converge at orders about 2 and 3. The
// observed orders of the interior H and K RMS between the two finest levels are asserted on Delaunay
// meshes of random points (three graph functions, three seeds) and on jittered tori: at least 1.8 for
// degree 3 and 2.6 for degree 4. The marching-tetrahedra family and the comparison with CGAL's jet
// fitting of degree 4 are in test_marching_tetrahedra_convergence. Also: the degree-4 fit is exact on
// quartic graphs, statuses, and the parameter's range.
#include <CGAL/Curvature_estimation/hypersurface_paraboloid_fitting.h>
#include <CGAL/Curvature_estimation/paraboloid_fitting.h>
#include <CGAL/Curvature_estimation/vertex_normals.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/property_map.h>

#include <gtest/gtest.h>

#include "estimator_runs.h"
#include "test_surfaces.h"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
using Estimates = ce_test::Estimates<Kernel>;
namespace CE = CGAL::Curvature_estimation;
namespace params = CGAL::Curvature_estimation::parameters;

Estimates estimate(const Mesh& mesh, int degree)
{
  return ce_test::run_with_all_outputs<Kernel>(
    mesh, [](const Mesh& m, const auto& np) { CE::paraboloid_fitting_curvatures(m, np); }, params::fit_degree(degree));
}

// The same in the frame of the given normal (0, 0, 1) at every vertex.
Estimates estimate_upward(const Mesh& mesh, int degree)
{
  const CGAL::Constant_property_map<Mesh::Vertex_index, Kernel::Vector_3> up(Kernel::Vector_3(0, 0, 1));
  return ce_test::run_with_all_outputs<Kernel>(
    mesh, [](const Mesh& m, const auto& np) { CE::paraboloid_fitting_curvatures(m, np); },
    params::fit_degree(degree).vertex_normal_map(up));
}

std::vector<char> interior(const Mesh& mesh)
{
  std::vector<char> inside;
  for (Mesh::Vertex_index v : vertices(mesh))
    inside.push_back(!CGAL::is_border(v, mesh));
  return inside;
}

const double min_order[] = {0, 0, 0, 1.8, 2.6}; // by degree

// The interior H and K RMS along a refinement: every vertex estimated, and the orders between the
// two finest levels at least min_order[degree].
struct Refinement
{
  std::string name;
  int degree;
  ce_test::Convergence H, K;
  double H_order = 0, K_order = 0;

  void add(const Mesh& mesh, const std::vector<ce_test::Exact_curvature>& exact, double h)
  {
    const Estimates e = estimate(mesh, degree);
    const std::vector<char> inside = interior(mesh);
    for (std::size_t i = 0; i < e.mean.size(); ++i)
      ASSERT_TRUE(std::isfinite(e.mean[i]) && std::isfinite(e.gaussian[i])) << name << ", vertex " << i;
    const ce_test::Curvature_errors t = ce_test::curvature_errors(e, exact, [&](std::size_t i) { return inside[i]; });
    const double H_rms = t.mean.stats().rms, K_rms = t.gaussian.stats().rms;
    const std::optional<double> H_step = H.add(h, H_rms), K_step = K.add(h, K_rms);
    std::printf("%-32s degree %d, h %.4f: interior H RMS %.3e max %.3e, K RMS %.3e", name.c_str(), degree, h, H_rms,
                t.mean.stats().max, K_rms);
    if (H_step) {
      H_order = *H_step;
      K_order = *K_step;
      std::printf(", orders H %.2f K %.2f", H_order, K_order);
    }
    std::printf("\n");
  }

  void expect_orders() const
  {
    SCOPED_TRACE(name + ", degree " + std::to_string(degree));
    EXPECT_GE(H_order, min_order[degree]);
    EXPECT_GE(K_order, min_order[degree]);
  }
};

TEST(FitDegree, DelaunayMeshesConvergeAtOrdersTwoAndThree)
{
  const std::vector<ce_test::Graph_function> functions = ce_test::hamann_table1_functions();
  for (const std::size_t f : {3, 5, 8}) // paraboloid, monkey saddle, trigonometric
    for (const std::uint32_t seed : {1u, 2u, 3u})
      for (const int degree : {3, 4}) {
        Refinement r{functions[f].name + " Delaunay, seed " + std::to_string(seed), degree, {}, {}};
        for (const std::size_t points : {1000, 4000, 16000}) {
          const ce_test::Soup soup = ce_test::delaunay_graph_soup(functions[f], points, -1, 1, seed);
          r.add(ce_test::to_mesh<Mesh>(soup), ce_test::graph_curvatures(functions[f], soup),
                ce_test::mean_edge_length(soup));
        }
        r.expect_orders();
      }
}

TEST(FitDegree, JitteredToriConvergeAtOrdersTwoAndThree)
{
  for (const int degree : {3, 4}) {
    Refinement r{"torus jittered by 0.2", degree, {}, {}};
    for (const std::size_t n : {40, 80, 160}) {
      const auto torus = ce_test::sampled_torus<Mesh>(3, 1, n, n / 2, 0.2, 7);
      r.add(torus.mesh, torus.exact, ce_test::mean_edge_length(torus.soup));
    }
    r.expect_orders();
  }
}

// A quartic graph over the frame of the given normal (0, 0, 1) is fitted exactly by the degree-4 fit
// where its 3 rings are in the grid (in another frame the graph is no polynomial: see the orders
// above for the estimated normal), and not by the degree-3 fit.
TEST(FitDegree, DegreeFourIsExactOnQuarticGraphsInTheirFrame)
{
  const ce_test::Graph_function quartic{
    "quartic",
    [](double x, double y) {
      return 0.3 * x * x - 0.2 * x * y + 0.1 * y * y * y + 0.05 * x * x * x * y - 0.07 * y * y * y * y;
    },
    [](double x, double y) { return 0.6 * x - 0.2 * y + 0.15 * x * x * y; },
    [](double x, double y) { return -0.2 * x + 0.3 * y * y + 0.05 * x * x * x - 0.28 * y * y * y; },
    [](double x, double y) { return 0.6 + 0.3 * x * y; },
    [](double x, double) { return -0.2 + 0.15 * x * x; },
    [](double, double y) { return 0.6 * y - 0.84 * y * y; }};
  const ce_test::Soup soup = ce_test::grid_graph_soup(quartic, 21);
  const Mesh mesh = ce_test::to_mesh<Mesh>(soup);
  const auto exact = ce_test::graph_curvatures(quartic, soup);
  const Estimates four = estimate_upward(mesh, 4), three = estimate_upward(mesh, 3);
  const std::size_t n = 21;
  double worst_four = 0, worst_three = 0;
  for (std::size_t j = 3; j + 3 < n; ++j)
    for (std::size_t i = 3; i + 3 < n; ++i) {
      const std::size_t k = i + n * j;
      EXPECT_EQ(four.status[k], CE::Estimation_status::ok) << i << ' ' << j;
      worst_four = (std::max)(worst_four, std::abs(four.mean[k] - exact[k].H));
      worst_three = (std::max)(worst_three, std::abs(three.mean[k] - exact[k].H));
    }
  std::printf("quartic graph, 21 x 21 grid, vertices 3 rings inside: largest H error degree 4 %.2e, degree 3 %.2e\n",
              worst_four, worst_three);
  EXPECT_LE(worst_four, 1e-9);
  EXPECT_GT(worst_three, 1e3 * worst_four); // the quartic terms are there to be fitted
}

// estimate_vertex_normals with fit_degree d: the area-weighted normal corrected by the gradient of the
// degree-d fit, an error of order h^d where the fit's gradient is (a degree-d fit leaves the terms of
// degree d + 1 in its gradient through an uneven stencil). The observed order of the interior normal's
// RMS angle error between the two finest Delaunay meshes: at least 1.8, 2.7 and 3.5 for d = 2, 3, 4.
TEST(FitDegree, NormalsOfDegreeDConvergeAtOrderD)
{
  const std::vector<ce_test::Graph_function> functions = ce_test::hamann_table1_functions();
  const double min_normal_order[] = {0, 0, 1.8, 2.7, 3.5};
  for (const std::size_t f : {5, 8}) // monkey saddle, trigonometric
    for (const int degree : {2, 3, 4}) {
      ce_test::Convergence angles;
      double order = 0;
      for (const std::size_t points : {1000, 4000, 16000}) {
        const ce_test::Soup soup = ce_test::delaunay_graph_soup(functions[f], points, -1, 1, 1);
        const Mesh mesh = ce_test::to_mesh<Mesh>(soup);
        const auto exact = ce_test::graph_curvatures(functions[f], soup);
        std::vector<Kernel::Vector_3> normals(num_vertices(mesh));
        CE::estimate_vertex_normals(mesh, CGAL::make_property_map(normals), params::fit_degree(degree));
        const std::vector<char> inside = interior(mesh);
        double sum = 0;
        std::size_t count = 0;
        for (std::size_t i = 0; i < normals.size(); ++i) {
          const Eigen::Vector3d n(normals[i].x(), normals[i].y(), normals[i].z());
          ASSERT_TRUE(std::isfinite(n.squaredNorm())) << functions[f].name << ", vertex " << i;
          if (!inside[i])
            continue;
          const double angle = std::atan2(n.cross(exact[i].normal).norm(), n.dot(exact[i].normal));
          sum += angle * angle;
          ++count;
        }
        const double rms = std::sqrt(sum / count);
        const std::optional<double> step = angles.add(ce_test::mean_edge_length(soup), rms);
        std::printf("%-22s Delaunay, %5zu points, normal of degree %d: interior RMS angle %.3e",
                    functions[f].name.c_str(), points, degree, rms);
        if (step) {
          order = *step;
          std::printf(", order %.2f", order);
        }
        std::printf("\n");
      }
      EXPECT_GE(order, min_normal_order[degree]) << functions[f].name << ", degree " << degree;
    }
  std::vector<Kernel::Vector_3> normals(25);
  EXPECT_THROW(CE::estimate_vertex_normals(ce_test::to_mesh<Mesh>(ce_test::grid_graph_soup(functions[3], 5)),
                                           CGAL::make_property_map(normals), params::fit_degree(5)),
               std::invalid_argument);
}

TEST(FitDegree, OutOfRangeIsRefused)
{
  const Mesh mesh = ce_test::to_mesh<Mesh>(ce_test::grid_graph_soup(ce_test::hamann_table1_functions()[3], 5));
  for (const int degree : {1, 5})
    EXPECT_THROW(CE::paraboloid_fitting_curvatures(mesh, params::fit_degree(degree)), std::invalid_argument) << degree;
  // Hypersurfaces: degrees 2 and 3 (a trivariate quartic fit has 34 unknowns).
  CE::Indexed_tetrahedral_mesh<Eigen::Vector4d> tetrahedra;
  EXPECT_THROW(CE::hypersurface_paraboloid_fitting_curvatures(tetrahedra, params::fit_degree(4)),
               std::invalid_argument);
  EXPECT_NO_THROW(CE::hypersurface_paraboloid_fitting_curvatures(tetrahedra, params::fit_degree(3)));
}

} // namespace
