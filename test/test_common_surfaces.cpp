// SPDX-License-Identifier: GPL-3.0-or-later
// Tests of the shared test utilities (test/common/test_surfaces.h) against independent facts:
// closed-form curvatures of known surfaces, finite differences, Rodrigues' formula, Eigen's
// generalized eigensolver, and the topology/orientation of the generated meshes.

#include "marching_tetrahedra.h"
#include "test_surfaces.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/graph_traits_Polyhedron_3.h>
#include <CGAL/boost/graph/helpers.h>

#include <Eigen/Eigenvalues>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>
#include <vector>

namespace {

using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
using Surface_mesh = CGAL::Surface_mesh<Epick::Point_3>;
using Polyhedron = CGAL::Polyhedron_3<Epick>;
using ce_test::Diagonal;
using ce_test::Exact_curvature;
using ce_test::Graph_function;
using ce_test::Soup;

const Graph_function& fn(int index) // 1-based, as in Hamann's table
{
  static const std::vector<Graph_function> fs = ce_test::hamann_table1_functions();
  return fs.at(static_cast<std::size_t>(index - 1));
}

// Sample points inside [-1,1]^2 (away from the grid lines of symmetric cases).
const std::vector<Eigen::Vector2d>& sample_points()
{
  static const std::vector<Eigen::Vector2d> pts = {{0.0, 0.0},    {0.3, -0.7},  {-0.81, 0.44}, {0.95, 0.95},
                                                   {-0.5, -0.25}, {0.12, 0.66}, {-1.0, 1.0},   {0.7, -0.05}};
  return pts;
}

double parallel_abs_cos(const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{
  return std::abs(a.normalized().dot(b.normalized()));
}

// ---------------------------------------------------------------------------
// The function table
// ---------------------------------------------------------------------------

TEST(HamannTable, NineFunctionsAndRows)
{
  const auto fs = ce_test::hamann_table1_functions();
  const auto rows = ce_test::hamann_table1_published();
  ASSERT_EQ(fs.size(), 9u);
  ASSERT_EQ(rows.size(), 9u);
  const char* names[] = {"plane",         "cylinder", "sphere",      "paraboloid",   "hyperboloid",
                         "monkey_saddle", "cubic",    "exponential", "trigonometric"};
  for (std::size_t i = 0; i < 9; ++i)
    EXPECT_EQ(fs[i].name, names[i]);
  EXPECT_EQ(rows[0].k1, 0.0);
  EXPECT_EQ(rows[0].K, 0.0);
  EXPECT_DOUBLE_EQ(rows[3].k1, 0.003073);
  EXPECT_DOUBLE_EQ(rows[5].K, 0.007247);
  EXPECT_DOUBLE_EQ(rows[8].k2, 0.002821);
  // Spot values of the formulas.
  EXPECT_DOUBLE_EQ(fn(1).f(0.5, 0.25), 0.15);
  EXPECT_DOUBLE_EQ(fn(2).f(1.0, 0.3), 1.0);
  EXPECT_DOUBLE_EQ(fn(3).f(0.0, 0.0), 2.0);
  EXPECT_DOUBLE_EQ(fn(6).f(1.0, 1.0), 0.2 * (1.0 - 3.0));
  EXPECT_DOUBLE_EQ(fn(7).f(1.0, 1.0), 0.15 * (1.0 + 2.0 - 1.0 + 2.0));
  EXPECT_DOUBLE_EQ(fn(8).f(0.0, 0.0), 1.0);
  EXPECT_NEAR(fn(9).f(1.0, 0.0), 0.0, 1e-15);
}

TEST(HamannTable, AnalyticDerivativesMatchFiniteDifferences)
{
  const double h1 = 1e-5; // first derivatives: O(h^2) + O(eps/h) ~ 1e-10
  const double h2 = 1e-4; // second difference of f: O(h^2) + O(eps/h^2) ~ 1e-8
  for (const auto& g : ce_test::hamann_table1_functions())
    for (const auto& p : sample_points()) {
      const double x = 0.9 * p.x(), y = 0.9 * p.y(); // keep the stencils inside the domain
      SCOPED_TRACE(g.name + " at (" + std::to_string(x) + ", " + std::to_string(y) + ")");
      const double fx = (g.f(x + h1, y) - g.f(x - h1, y)) / (2 * h1);
      const double fy = (g.f(x, y + h1) - g.f(x, y - h1)) / (2 * h1);
      EXPECT_NEAR(g.fx(x, y), fx, 1e-6);
      EXPECT_NEAR(g.fy(x, y), fy, 1e-6);
      // second derivatives as differences of the analytic first ones ...
      EXPECT_NEAR(g.fxx(x, y), (g.fx(x + h1, y) - g.fx(x - h1, y)) / (2 * h1), 1e-6);
      EXPECT_NEAR(g.fyy(x, y), (g.fy(x, y + h1) - g.fy(x, y - h1)) / (2 * h1), 1e-6);
      EXPECT_NEAR(g.fxy(x, y), (g.fx(x, y + h1) - g.fx(x, y - h1)) / (2 * h1), 1e-6);
      EXPECT_NEAR(g.fxy(x, y), (g.fy(x + h1, y) - g.fy(x - h1, y)) / (2 * h1), 1e-6);
      // ... and as second differences of f itself.
      const double f0 = g.f(x, y);
      EXPECT_NEAR(g.fxx(x, y), (g.f(x + h2, y) - 2 * f0 + g.f(x - h2, y)) / (h2 * h2), 1e-6);
      EXPECT_NEAR(g.fyy(x, y), (g.f(x, y + h2) - 2 * f0 + g.f(x, y - h2)) / (h2 * h2), 1e-6);
      EXPECT_NEAR(
        g.fxy(x, y),
        (g.f(x + h2, y + h2) - g.f(x + h2, y - h2) - g.f(x - h2, y + h2) + g.f(x - h2, y - h2)) / (4 * h2 * h2), 1e-6);
    }
}

// ---------------------------------------------------------------------------
// Exact curvature of graphs
// ---------------------------------------------------------------------------

TEST(GraphCurvature, SphereAtOrigin)
{
  const Exact_curvature c = ce_test::graph_curvature(fn(3), 0.0, 0.0);
  EXPECT_DOUBLE_EQ(c.k_max, 0.5);
  EXPECT_DOUBLE_EQ(c.k_min, 0.5);
  EXPECT_DOUBLE_EQ(c.H, 0.5);
  EXPECT_DOUBLE_EQ(c.K, 0.25);
  EXPECT_NEAR((c.normal - Eigen::Vector3d::UnitZ()).norm(), 0.0, 1e-15);
}

TEST(GraphCurvature, SphereEverywhere)
{
  for (const auto& p : sample_points()) {
    const Exact_curvature c = ce_test::graph_curvature(fn(3), p.x(), p.y());
    EXPECT_NEAR(c.k_max, 0.5, 1e-12);
    EXPECT_NEAR(c.k_min, 0.5, 1e-12);
    EXPECT_NEAR(c.H, 0.5, 1e-12);
    EXPECT_NEAR(c.K, 0.25, 1e-12);
    // upward normal of the upper hemisphere = outward = radial
    const Eigen::Vector3d q(p.x(), p.y(), fn(3).f(p.x(), p.y()));
    EXPECT_NEAR((c.normal - q / 2.0).norm(), 0.0, 1e-12);
  }
}

TEST(GraphCurvature, Cylinder)
{
  // z = sqrt(2 - x^2): a cylinder of radius sqrt(2) with axis along y, upward normal = outward.
  for (const auto& p : sample_points()) {
    const Exact_curvature c = ce_test::graph_curvature(fn(2), p.x(), p.y());
    EXPECT_NEAR(c.k_max, 1.0 / std::sqrt(2.0), 1e-12);
    EXPECT_NEAR(c.k_min, 0.0, 1e-12);
    EXPECT_NEAR(c.K, 0.0, 1e-12);
    EXPECT_NEAR(c.H, 0.5 / std::sqrt(2.0), 1e-12);
    EXPECT_NEAR(std::abs(c.d_min.y()), 1.0, 1e-12); // along the axis
    EXPECT_NEAR(c.d_max.y(), 0.0, 1e-12);           // around the axis: perpendicular to y
    const Eigen::Vector3d radial = Eigen::Vector3d(p.x(), 0.0, fn(2).f(p.x(), p.y())) / std::sqrt(2.0);
    EXPECT_NEAR((c.normal - radial).norm(), 0.0, 1e-12);
    EXPECT_NEAR(c.d_max.dot(radial), 0.0, 1e-12);
  }
}

TEST(GraphCurvature, ParaboloidAndHyperboloidAtOrigin)
{
  // Opening upward, the paraboloid is concave seen from its upward normal: k = -0.8.
  const Exact_curvature p = ce_test::graph_curvature(fn(4), 0.0, 0.0);
  EXPECT_DOUBLE_EQ(p.k_max, -0.8);
  EXPECT_DOUBLE_EQ(p.k_min, -0.8);
  // z = .4(x^2 - y^2): k = -0.8 along x, +0.8 along y.
  const Exact_curvature h = ce_test::graph_curvature(fn(5), 0.0, 0.0);
  EXPECT_DOUBLE_EQ(h.k_max, 0.8);
  EXPECT_DOUBLE_EQ(h.k_min, -0.8);
  EXPECT_NEAR(std::abs(h.d_max.y()), 1.0, 1e-15);
  EXPECT_NEAR(std::abs(h.d_min.x()), 1.0, 1e-15);
  // Plane: flat, tilted normal.
  const Exact_curvature pl = ce_test::graph_curvature(fn(1), 0.3, 0.4);
  EXPECT_EQ(pl.k_max, 0.0);
  EXPECT_EQ(pl.k_min, 0.0);
  EXPECT_NEAR((pl.normal - Eigen::Vector3d(-0.2, -0.2, 1.0).normalized()).norm(), 0.0, 1e-15);
}

void expect_frame_invariants(const Exact_curvature& c, double tol)
{
  EXPECT_GE(c.k_max, c.k_min);
  EXPECT_NEAR(c.K, c.k_max * c.k_min, tol * (1.0 + std::abs(c.K)));
  EXPECT_NEAR(c.H, 0.5 * (c.k_max + c.k_min), tol * (1.0 + std::abs(c.H)));
  EXPECT_NEAR(c.normal.norm(), 1.0, tol);
  EXPECT_NEAR(c.d_max.norm(), 1.0, tol);
  EXPECT_NEAR(c.d_min.norm(), 1.0, tol);
  EXPECT_NEAR(c.d_max.dot(c.d_min), 0.0, tol);
  EXPECT_NEAR(c.d_max.dot(c.normal), 0.0, tol);
  EXPECT_NEAR(c.d_min.dot(c.normal), 0.0, tol);
  EXPECT_NEAR((c.d_max.cross(c.d_min) - c.normal).norm(), 0.0, tol);
}

TEST(GraphCurvature, InvariantsForEveryFunction)
{
  for (const auto& g : ce_test::hamann_table1_functions())
    for (const auto& p : sample_points()) {
      SCOPED_TRACE(g.name);
      const Exact_curvature c = ce_test::graph_curvature(g, p.x(), p.y());
      expect_frame_invariants(c, 1e-12);
      const double fx = g.fx(p.x(), p.y()), fy = g.fy(p.x(), p.y());
      EXPECT_NEAR((c.normal - Eigen::Vector3d(-fx, -fy, 1.0).normalized()).norm(), 0.0, 1e-14);
    }
}

TEST(GraphCurvature, MatchesGeneralizedEigenproblem)
{
  // Independent computation: (-Hess/l) a = k G a with Eigen's generalized solver,
  // direction a.x x_u + a.y x_v.
  for (const auto& g : ce_test::hamann_table1_functions())
    for (const auto& p : sample_points()) {
      SCOPED_TRACE(g.name);
      const double x = p.x(), y = p.y();
      const double fx = g.fx(x, y), fy = g.fy(x, y), l = std::sqrt(1 + fx * fx + fy * fy);
      Eigen::Matrix2d A, B;
      A << -g.fxx(x, y) / l, -g.fxy(x, y) / l, -g.fxy(x, y) / l, -g.fyy(x, y) / l;
      B << 1 + fx * fx, fx * fy, fx * fy, 1 + fy * fy;
      Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::Matrix2d> es(A, B);
      ASSERT_EQ(es.info(), Eigen::Success);
      const Exact_curvature c = ce_test::graph_curvature(g, x, y);
      EXPECT_NEAR(c.k_min, es.eigenvalues()(0), 1e-12);
      EXPECT_NEAR(c.k_max, es.eigenvalues()(1), 1e-12);
      // -(1/l) Hess G^{-1} has the same eigenvalues
      const Eigen::Matrix2d W = A * B.inverse();
      EXPECT_NEAR(W.trace(), 2 * c.H, 1e-12);
      EXPECT_NEAR(W.determinant(), c.K, 1e-12);
      if (c.k_max - c.k_min > 1e-6) { // directions are defined away from umbilics
        const Eigen::Vector2d a = es.eigenvectors().col(1), b = es.eigenvectors().col(0);
        const Eigen::Vector3d xu(1, 0, fx), xv(0, 1, fy);
        EXPECT_NEAR(parallel_abs_cos(a.x() * xu + a.y() * xv, c.d_max), 1.0, 1e-10);
        EXPECT_NEAR(parallel_abs_cos(b.x() * xu + b.y() * xv, c.d_min), 1.0, 1e-10);
      }
    }
}

TEST(GraphCurvature, RodriguesFormulaByFiniteDifferences)
{
  // Along a principal direction t, the derivative of the normal field is dn(t) = k t in the
  // library's convention (sphere, outward normal: n = p/r, dn = dp/r). The parameter
  // coordinates of a tangent vector t are (t.x, t.y).
  auto normal = [](const Graph_function& g, double x, double y) {
    return Eigen::Vector3d(-g.fx(x, y), -g.fy(x, y), 1.0).normalized();
  };
  const double eps = 1e-6;
  for (const auto& g : ce_test::hamann_table1_functions())
    for (const auto& p : sample_points()) {
      SCOPED_TRACE(g.name);
      const double x = 0.9 * p.x(), y = 0.9 * p.y();
      const Exact_curvature c = ce_test::graph_curvature(g, x, y);
      for (int k = 0; k < 2; ++k) {
        const Eigen::Vector3d t = (k == 0) ? c.d_max : c.d_min;
        const double kappa = (k == 0) ? c.k_max : c.k_min;
        const Eigen::Vector3d dn =
          (normal(g, x + eps * t.x(), y + eps * t.y()) - normal(g, x - eps * t.x(), y - eps * t.y())) / (2 * eps);
        EXPECT_NEAR((dn - kappa * t).norm(), 0.0, 1e-8);
      }
    }
}

// ---------------------------------------------------------------------------
// Closed surfaces: exact curvature
// ---------------------------------------------------------------------------

TEST(ClosedSurfaces, TorusCurvature)
{
  const double R = 3.0, r = 1.0;
  const Exact_curvature outer = ce_test::torus_curvature(R, r, 0.4, 0.0);
  EXPECT_DOUBLE_EQ(outer.k_max, 1.0);
  EXPECT_DOUBLE_EQ(outer.k_min, 1.0 / (R + r));
  const Exact_curvature inner = ce_test::torus_curvature(R, r, 0.4, ce_test::pi);
  EXPECT_DOUBLE_EQ(inner.k_min, -1.0 / (R - r));
  const Exact_curvature top = ce_test::torus_curvature(R, r, 0.4, ce_test::pi / 2);
  EXPECT_NEAR(top.k_min, 0.0, 1e-15);
  // Rodrigues by finite differences on the parametrization; outward normal = (p - c)/r,
  // c the centre of the tube.
  auto normal = [&](double u, double v) {
    const Eigen::Vector3d centre(R * std::cos(u), R * std::sin(u), 0.0);
    return Eigen::Vector3d((ce_test::torus_point(R, r, u, v) - centre) / r);
  };
  const double eps = 1e-6;
  for (double u : {0.0, 0.7, 2.5, -1.9})
    for (double v : {0.0, 0.5, 1.9, 3.0, -2.2}) {
      const Exact_curvature c = ce_test::torus_curvature(R, r, u, v);
      expect_frame_invariants(c, 1e-12);
      EXPECT_NEAR((c.normal - normal(u, v)).norm(), 0.0, 1e-12);
      const Exact_curvature c2 = ce_test::torus_curvature_at(R, r, ce_test::torus_point(R, r, u, v));
      EXPECT_NEAR(c2.k_min, c.k_min, 1e-12);
      EXPECT_NEAR((c2.normal - c.normal).norm(), 0.0, 1e-12);
      for (int d = 0; d < 2; ++d) {
        const double du = d == 0 ? 0.0 : eps, dv = d == 0 ? eps : 0.0; // d = 0: x_v (tube), 1: x_u
        const Eigen::Vector3d dp =
          ce_test::torus_point(R, r, u + du, v + dv) - ce_test::torus_point(R, r, u - du, v - dv);
        const Eigen::Vector3d dn = normal(u + du, v + dv) - normal(u - du, v - dv);
        const double kappa = d == 0 ? c.k_max : c.k_min;
        EXPECT_NEAR((dn - kappa * dp).norm() / dp.norm(), 0.0, 1e-8);
        EXPECT_NEAR(parallel_abs_cos(dp, d == 0 ? c.d_max : c.d_min), 1.0, 1e-10);
      }
    }
}

TEST(ClosedSurfaces, SphereCurvature)
{
  const Exact_curvature c = ce_test::sphere_curvature(2.0, Eigen::Vector3d(0.3, -1.2, 0.9));
  EXPECT_DOUBLE_EQ(c.k_max, 0.5);
  EXPECT_DOUBLE_EQ(c.k_min, 0.5);
  EXPECT_DOUBLE_EQ(c.K, 0.25);
  expect_frame_invariants(c, 1e-12);
  EXPECT_NEAR((c.normal - Eigen::Vector3d(0.3, -1.2, 0.9).normalized()).norm(), 0.0, 1e-15);
}

// ---------------------------------------------------------------------------
// Mesh helpers
// ---------------------------------------------------------------------------

template <class Mesh>
long euler_characteristic(const Mesh& m)
{
  return static_cast<long>(num_vertices(m)) - static_cast<long>(num_edges(m)) + static_cast<long>(num_faces(m));
}

template <class Mesh>
void expect_soup_order(const Mesh& m, const Soup& s)
{
  ASSERT_EQ(static_cast<std::size_t>(num_vertices(m)), s.points.size());
  const auto vs = ce_test::soup_order_vertices(m);
  const auto vpm = get(CGAL::vertex_point, m);
  std::size_t i = 0;
  for (auto v : vertices(m)) {
    ASSERT_TRUE(vs[i] == v);
    const auto& p = get(vpm, v);
    ASSERT_EQ(p.x(), s.points[i].x()) << "vertex " << i;
    ASSERT_EQ(p.y(), s.points[i].y()) << "vertex " << i;
    ASSERT_EQ(p.z(), s.points[i].z()) << "vertex " << i;
    ++i;
  }
}

// Length of the border projected to the xy-plane; checks that each border edge lies on one side of [lo,hi]^2.
template <class Mesh>
double border_length_on_square(const Mesh& m, double lo, double hi)
{
  const auto vpm = get(CGAL::vertex_point, m);
  double length = 0.0;
  for (auto h : halfedges(m)) {
    if (!CGAL::is_border(h, m))
      continue;
    const auto& a = get(vpm, source(h, m));
    const auto& b = get(vpm, target(h, m));
    const bool same_side = (a.x() == lo && b.x() == lo) || (a.x() == hi && b.x() == hi) ||
                           (a.y() == lo && b.y() == lo) || (a.y() == hi && b.y() == hi);
    EXPECT_TRUE(same_side) << "border edge (" << a << ") - (" << b << ") is not on the square";
    length += std::hypot(b.x() - a.x(), b.y() - a.y()); // in the xy-plane
  }
  return length;
}

template <class Mesh>
void check_graph_mesh(const Soup& s, double lo, double hi)
{
  const Mesh m = ce_test::to_mesh<Mesh>(s);
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(m));
  EXPECT_EQ(euler_characteristic(m), 1);
  EXPECT_EQ(static_cast<std::size_t>(num_faces(m)), s.faces.size());
  expect_soup_order(m, s);
  EXPECT_NEAR(border_length_on_square(m, lo, hi), 4 * (hi - lo), 1e-12);
}

// The soup as a Surface_mesh and as a Polyhedron_3: closed, of Euler characteristic `euler`, in soup order.
void check_closed_meshes(const Soup& s, long euler)
{
  const Surface_mesh sm = ce_test::to_mesh<Surface_mesh>(s);
  const Polyhedron ph = ce_test::to_mesh<Polyhedron>(s);
  EXPECT_EQ(euler_characteristic(sm), euler);
  EXPECT_EQ(euler_characteristic(ph), euler);
  EXPECT_TRUE(CGAL::is_closed(sm));
  EXPECT_TRUE(CGAL::is_closed(ph));
  expect_soup_order(sm, s);
  expect_soup_order(ph, s);
}

void expect_ccw_and_covering(const Soup& s, double lo, double hi)
{
  double area = 0.0;
  for (std::size_t f = 0; f < s.faces.size(); ++f) {
    const double a = ce_test::signed_area_xy(s, f);
    EXPECT_GT(a, 0.0) << "face " << f;
    area += a;
  }
  EXPECT_NEAR(area, (hi - lo) * (hi - lo), 1e-12);
}

TEST(GridSoup, HamannGridLayout)
{
  const std::size_t n = 51;
  for (Diagonal d : {Diagonal::main, Diagonal::anti}) {
    const Soup s = ce_test::grid_graph_soup(fn(7), n, -1.0, 1.0, d);
    ASSERT_EQ(s.points.size(), n * n);
    ASSERT_EQ(s.params.size(), n * n);
    ASSERT_EQ(s.faces.size(), 2 * (n - 1) * (n - 1));
    for (std::size_t j = 0; j < n; ++j)
      for (std::size_t i = 0; i < n; ++i) {
        const Eigen::Vector3d& p = s.points[i + n * j];
        ASSERT_EQ(p.x(), -1.0 + static_cast<double>(i) / 25.0); // Hamann's (x_i, y_j)
        ASSERT_EQ(p.y(), -1.0 + static_cast<double>(j) / 25.0);
        ASSERT_EQ(p.z(), fn(7).f(p.x(), p.y()));
      }
    expect_ccw_and_covering(s, -1.0, 1.0);
  }
}

TEST(GridSoup, Diagonals)
{
  const std::size_t n = 4;
  const Soup m = ce_test::grid_graph_soup(fn(4), n, -1.0, 1.0, Diagonal::main);
  const Soup a = ce_test::grid_graph_soup(fn(4), n, -1.0, 1.0, Diagonal::anti);
  const std::array<std::size_t, 3> m0 = {0, 1, n + 1}, m1 = {0, n + 1, n};
  const std::array<std::size_t, 3> a0 = {0, 1, n}, a1 = {1, n + 1, n};
  EXPECT_EQ(m.faces[0], m0);
  EXPECT_EQ(m.faces[1], m1);
  EXPECT_EQ(a.faces[0], a0);
  EXPECT_EQ(a.faces[1], a1);
  // every face of the main split has a (i,j)-(i+1,j+1) edge, of the anti split an (i+1,j)-(i,j+1) edge
  auto has_edge = [](const std::array<std::size_t, 3>& f, std::size_t p, std::size_t q) {
    std::set<std::size_t> s(f.begin(), f.end());
    return s.count(p) && s.count(q);
  };
  for (std::size_t k = 0; k < m.faces.size(); ++k) {
    const std::size_t quad = k / 2, i = quad % (n - 1), j = quad / (n - 1);
    EXPECT_TRUE(has_edge(m.faces[k], i + n * j, i + 1 + n * (j + 1)));
    EXPECT_TRUE(has_edge(a.faces[k], i + 1 + n * j, i + n * (j + 1)));
  }
}

TEST(GridSoup, MeshesKeepSoupOrder)
{
  for (Diagonal d : {Diagonal::main, Diagonal::anti}) {
    const Soup s = ce_test::grid_graph_soup(fn(8), 9, -1.0, 1.0, d);
    check_graph_mesh<Surface_mesh>(s, -1.0, 1.0);
    check_graph_mesh<Polyhedron>(s, -1.0, 1.0);
  }
}

TEST(JitteredGrid, DeterministicAndValid)
{
  const std::size_t n = 21;
  const double lo = -1.0, hi = 1.0, jf = 0.2, h = (hi - lo) / (n - 1);
  const Soup a = ce_test::jittered_grid_graph_soup(fn(9), n, lo, hi, jf, 42);
  const Soup b = ce_test::jittered_grid_graph_soup(fn(9), n, lo, hi, jf, 42);
  const Soup c = ce_test::jittered_grid_graph_soup(fn(9), n, lo, hi, jf, 43);
  const Soup g = ce_test::grid_graph_soup(fn(9), n, lo, hi, Diagonal::anti);
  ASSERT_EQ(a.points.size(), n * n);
  ASSERT_EQ(a.faces, g.faces);
  bool differs = false, moved = false;
  for (std::size_t k = 0; k < a.points.size(); ++k) {
    ASSERT_EQ(a.points[k], b.points[k]); // bitwise identical
    differs = differs || (a.points[k] != c.points[k]);
    moved = moved || (a.points[k] != g.points[k]);
    const std::size_t i = k % n, j = k / n;
    const Eigen::Vector3d& p = a.points[k];
    const Eigen::Vector3d& q = g.points[k];
    EXPECT_EQ(p.z(), fn(9).f(p.x(), p.y()));
    EXPECT_EQ(a.params[k], Eigen::Vector2d(p.x(), p.y()));
    EXPECT_LE(std::abs(p.x() - q.x()), jf * h * (1 + 1e-12));
    EXPECT_LE(std::abs(p.y() - q.y()), jf * h * (1 + 1e-12));
    if (i == 0 || i + 1 == n) {
      EXPECT_EQ(p.x(), q.x()); // on a side x = lo/hi: stays there
    }
    if (j == 0 || j + 1 == n) {
      EXPECT_EQ(p.y(), q.y());
    }
  }
  EXPECT_TRUE(differs);
  EXPECT_TRUE(moved);
  expect_ccw_and_covering(a, lo, hi);
  check_graph_mesh<Surface_mesh>(a, lo, hi);
  check_graph_mesh<Polyhedron>(a, lo, hi);
  EXPECT_THROW(ce_test::jittered_grid_graph_soup(fn(9), n, lo, hi, 0.3, 1), std::invalid_argument);
}

TEST(JitteredGrid, OwnUniformGenerator)
{
  std::mt19937 gen(5489u);
  double lo = 1.0, hi = 0.0, sum = 0.0;
  const int N = 20000;
  for (int k = 0; k < N; ++k) {
    const double u = ce_test::uniform01(gen);
    ASSERT_GE(u, 0.0);
    ASSERT_LT(u, 1.0);
    lo = std::min(lo, u);
    hi = std::max(hi, u);
    sum += u;
  }
  EXPECT_LT(lo, 1e-3);
  EXPECT_GT(hi, 1 - 1e-3);
  EXPECT_NEAR(sum / N, 0.5, 0.01);
  // The standard fixes mt19937's raw sequence; so the first value is fixed too.
  std::mt19937 g2(5489u);
  const double first = ce_test::uniform01(g2);
  std::mt19937 g3(5489u);
  const std::uint32_t r0 = static_cast<std::uint32_t>(g3()), r1 = static_cast<std::uint32_t>(g3());
  EXPECT_EQ(first, ((r0 >> 5) * 67108864.0 + (r1 >> 6)) / 9007199254740992.0);
  EXPECT_EQ(r0, 3499211612u); // first output of the default-seeded mt19937
}

TEST(DelaunaySoup, ValidSquareDeterministic)
{
  const double lo = -1.0, hi = 1.0;
  const std::size_t n = 400;
  const Soup s = ce_test::delaunay_graph_soup(fn(6), n, lo, hi, 7);
  const Soup t = ce_test::delaunay_graph_soup(fn(6), n, lo, hi, 7);
  ASSERT_EQ(s.points.size(), n);
  ASSERT_EQ(s.points, t.points);
  ASSERT_EQ(s.faces, t.faces);
  for (const auto& p : s.points) {
    EXPECT_GE(p.x(), lo);
    EXPECT_LE(p.x(), hi);
    EXPECT_GE(p.y(), lo);
    EXPECT_LE(p.y(), hi);
    EXPECT_EQ(p.z(), fn(6).f(p.x(), p.y()));
  }
  // corners first
  EXPECT_EQ(s.points[0], Eigen::Vector3d(lo, lo, fn(6).f(lo, lo)));
  EXPECT_EQ(s.points[2], Eigen::Vector3d(hi, hi, fn(6).f(hi, hi)));
  expect_ccw_and_covering(s, lo, hi);
  check_graph_mesh<Surface_mesh>(s, lo, hi);
  check_graph_mesh<Polyhedron>(s, lo, hi);
  // Euler for a disk triangulation with V vertices and B border vertices: F = 2V - B - 2.
  const std::size_t side = static_cast<std::size_t>(std::lround(std::sqrt(double(n))));
  const std::size_t border_vertices = 4 * (side - 1);
  EXPECT_EQ(s.faces.size(), 2 * n - border_vertices - 2);
  const Soup other = ce_test::delaunay_graph_soup(fn(6), n, lo, hi, 8);
  EXPECT_NE(other.points, s.points);
  // a small and an odd-sized case
  const Soup small = ce_test::delaunay_graph_soup(fn(6), 9, 0.0, 2.0, 3);
  EXPECT_EQ(small.points.size(), 9u);
  expect_ccw_and_covering(small, 0.0, 2.0);
  const Soup odd = ce_test::delaunay_graph_soup(fn(6), 1000, 0.0, 2.0, 3);
  EXPECT_EQ(odd.points.size(), 1000u);
  expect_ccw_and_covering(odd, 0.0, 2.0);
}

TEST(Icosphere, TopologyOrientationRadius)
{
  const double radius = 1.7;
  for (unsigned sub : {0u, 1u, 3u}) {
    const Soup s = ce_test::sphere_soup(radius, sub);
    const std::size_t f = 20u << (2 * sub);
    ASSERT_EQ(s.faces.size(), f);
    ASSERT_EQ(s.points.size(), f / 2 + 2);
    for (const auto& p : s.points)
      EXPECT_NEAR(p.norm(), radius, 1e-13);
    for (const auto& t : s.faces) {
      const Eigen::Vector3d n = (s.points[t[1]] - s.points[t[0]]).cross(s.points[t[2]] - s.points[t[0]]);
      EXPECT_GT(n.dot(s.points[t[0]] + s.points[t[1]] + s.points[t[2]]), 0.0);
    }
    const double vol = ce_test::signed_volume(s);
    EXPECT_GT(vol, 0.0);
    EXPECT_LT(vol, 4.0 / 3.0 * ce_test::pi * radius * radius * radius);
    check_closed_meshes(s, 2);
  }
  const Soup fine = ce_test::sphere_soup(radius, 4);
  EXPECT_NEAR(ce_test::signed_volume(fine), 4.0 / 3.0 * ce_test::pi * std::pow(radius, 3), 0.01 * std::pow(radius, 3));
}

TEST(TorusSoup, TopologyOrientationExactness)
{
  const double R = 2.0, r = 0.5;
  for (double jitter : {0.0, 0.2}) {
    const Soup s = ce_test::torus_soup(R, r, 40, 20, jitter, 11);
    ASSERT_EQ(s.points.size(), 800u);
    ASSERT_EQ(s.faces.size(), 1600u);
    for (std::size_t k = 0; k < s.points.size(); ++k) {
      const Eigen::Vector3d& p = s.points[k];
      EXPECT_NEAR(std::hypot(std::hypot(p.x(), p.y()) - R, p.z()), r, 1e-14); // on the torus
      EXPECT_NEAR((p - ce_test::torus_point(R, r, s.params[k].x(), s.params[k].y())).norm(), 0.0, 1e-15);
    }
    for (const auto& t : s.faces) { // faces agree with the exact outward normal
      const Eigen::Vector3d n = (s.points[t[1]] - s.points[t[0]]).cross(s.points[t[2]] - s.points[t[0]]);
      const Eigen::Vector3d c = (s.points[t[0]] + s.points[t[1]] + s.points[t[2]]) / 3.0;
      EXPECT_GT(n.dot(ce_test::torus_curvature_at(R, r, c).normal), 0.0);
    }
    // inscribed polyhedron: a little less than the exact volume 2 pi^2 R r^2
    const double exact_volume = 2 * ce_test::pi * ce_test::pi * R * r * r;
    EXPECT_LT(ce_test::signed_volume(s), exact_volume);
    EXPECT_GT(ce_test::signed_volume(s), 0.95 * exact_volume);
    check_closed_meshes(s, 0);
    const auto exact = ce_test::torus_curvatures(R, r, s);
    ASSERT_EQ(exact.size(), s.points.size());
    EXPECT_DOUBLE_EQ(exact[0].k_max, 1.0 / r);
  }
  const Soup a = ce_test::torus_soup(R, r, 12, 8, 0.2, 3), b = ce_test::torus_soup(R, r, 12, 8, 0.2, 3);
  EXPECT_EQ(a.points, b.points);
}

TEST(Soup, PerVertexExactValues)
{
  const Soup s = ce_test::grid_graph_soup(fn(3), 5, -1.0, 1.0);
  const auto ex = ce_test::graph_curvatures(fn(3), s);
  ASSERT_EQ(ex.size(), 25u);
  for (const auto& c : ex)
    EXPECT_NEAR(c.k_min, 0.5, 1e-12);
  const auto sp = ce_test::sphere_curvatures(3.0, ce_test::sphere_soup(3.0, 1));
  ASSERT_EQ(sp.size(), 42u);
  EXPECT_DOUBLE_EQ(sp[5].H, 1.0 / 3.0);
  EXPECT_NEAR(ce_test::mean_edge_length(ce_test::grid_graph_soup(fn(1), 3, 0.0, 2.0, Diagonal::main)),
              (12 * std::sqrt(1 + 0.04) + 4 * std::sqrt(2 + 0.16)) / 16.0, 1e-14);
}

// ---------------------------------------------------------------------------
// Marching tetrahedra of implicit surfaces
// ---------------------------------------------------------------------------

// Every directed edge of the soup once, and its reverse once: closed, manifold along edges,
// consistently oriented.
void expect_each_edge_in_two_opposite_faces(const Soup& s)
{
  std::map<std::pair<std::size_t, std::size_t>, int> directed;
  for (const auto& t : s.faces)
    for (int k = 0; k < 3; ++k)
      ++directed[{t[k], t[(k + 1) % 3]}];
  for (const auto& e : directed) {
    ASSERT_EQ(e.second, 1) << "edge " << e.first.first << "-" << e.first.second;
    const auto reverse = directed.find({e.first.second, e.first.first});
    ASSERT_TRUE(reverse != directed.end()) << "edge " << e.first.first << "-" << e.first.second;
  }
}

const Eigen::Vector3d grid_offset(0.137, 0.291, 0.413);

TEST(MarchingTetrahedra, ClosedManifoldOnTheSurface)
{
  const double R = 1.0, r = 0.4;
  struct Case
  {
    ce_test::Implicit_surface surface;
    long euler;
    double volume;
  };
  const Case cases[] = {{ce_test::implicit_ellipsoid(1.0, 0.8, 0.6), 2, 4.0 / 3.0 * ce_test::pi * 1.0 * 0.8 * 0.6},
                        {ce_test::implicit_torus(R, r), 0, 2.0 * ce_test::pi * ce_test::pi * R * r * r},
                        {ce_test::gaussian_blobs(), 2, 0.0}};
  for (const Case& c : cases)
    for (std::size_t cells : {24u, 48u})
      for (const Eigen::Vector3d& offset : {Eigen::Vector3d(Eigen::Vector3d::Zero()), grid_offset}) {
        SCOPED_TRACE(c.surface.name + " on " + std::to_string(cells) + " cells");
        const Soup s = ce_test::marching_tetrahedra_soup(c.surface, cells, offset);
        ASSERT_GT(s.faces.size(), 100u);
        expect_each_edge_in_two_opposite_faces(s);
        check_closed_meshes(s, c.euler);
        Surface_mesh sm = ce_test::to_mesh<Surface_mesh>(s);
        auto component = sm.add_property_map<Surface_mesh::Face_index, std::size_t>("f:component").first;
        EXPECT_EQ(CGAL::Polygon_mesh_processing::connected_components(sm, component), 1u);
        std::set<std::array<double, 3>> distinct;
        for (const auto& p : s.points)
          distinct.insert({p.x(), p.y(), p.z()});
        EXPECT_EQ(distinct.size(), s.points.size()); // no two vertices coincide
        for (const auto& p : s.points) {
          EXPECT_LE(std::abs(c.surface.value(p)) / c.surface.gradient(p).norm(), 1e-12 * c.surface.half_width);
        }
        // outward, and close to the enclosed volume (second order in the cell size)
        const double volume = ce_test::signed_volume(s);
        EXPECT_GT(volume, 0.0);
        if (c.volume > 0.0) {
          EXPECT_NEAR(volume, c.volume, 0.02 * c.volume);
        }
      }
}

TEST(MarchingTetrahedra, ExactCurvature)
{
  const double a = 1.0, b = 0.8, c = 0.6, R = 1.0, r = 0.4;
  const ce_test::Implicit_surface ellipsoid = ce_test::implicit_ellipsoid(a, b, c);
  const Soup e = ce_test::marching_tetrahedra_soup(ellipsoid, 24, grid_offset);
  const auto exact_e = ce_test::implicit_curvatures(ellipsoid, e);
  ASSERT_EQ(exact_e.size(), e.points.size());
  for (std::size_t i = 0; i < e.points.size(); i += 37) {
    const Eigen::Vector3d& p = e.points[i];
    const Exact_curvature ref = ce_test::ellipsoid_curvature(a, b, c, p);
    EXPECT_NEAR(exact_e[i].k_max, ref.k_max, 1e-12);
    EXPECT_NEAR(exact_e[i].k_min, ref.k_min, 1e-12);
    // the closed form K = 1 / (a b c)^2 / (x^2/a^4 + y^2/b^4 + z^2/c^4)^2
    const double w = p.x() * p.x() / std::pow(a, 4) + p.y() * p.y() / std::pow(b, 4) + p.z() * p.z() / std::pow(c, 4);
    EXPECT_NEAR(exact_e[i].K, 1.0 / (a * a * b * b * c * c * w * w), 1e-12);
    EXPECT_GT(exact_e[i].normal.dot(p), 0.0);
  }
  const ce_test::Implicit_surface torus = ce_test::implicit_torus(R, r);
  const Soup t = ce_test::marching_tetrahedra_soup(torus, 24, grid_offset);
  const auto exact_t = ce_test::implicit_curvatures(torus, t);
  for (std::size_t i = 0; i < t.points.size(); i += 37) {
    const Exact_curvature ref = ce_test::torus_curvature_at(R, r, t.points[i]);
    EXPECT_NEAR(exact_t[i].k_max, ref.k_max, 1e-11);
    EXPECT_NEAR(exact_t[i].k_min, ref.k_min, 1e-11);
    EXPECT_NEAR((exact_t[i].normal - ref.normal).norm(), 0.0, 1e-11);
  }
  // The blobs: the analytic gradient and Hessian against central differences.
  const ce_test::Implicit_surface blobs = ce_test::gaussian_blobs();
  const double eps = 1e-5;
  for (const Eigen::Vector3d& p :
       {Eigen::Vector3d(0.1, 0.2, -0.3), Eigen::Vector3d(-0.7, 0.05, 0.4), Eigen::Vector3d(0.5, -0.6, 0.2)})
  {
    const Eigen::Vector3d g = blobs.gradient(p);
    const Eigen::Matrix3d H = blobs.hessian(p);
    for (int d = 0; d < 3; ++d) {
      const Eigen::Vector3d step = eps * Eigen::Vector3d::Unit(d);
      EXPECT_NEAR(g(d), (blobs.value(p + step) - blobs.value(p - step)) / (2 * eps), 1e-9);
      EXPECT_NEAR((H.col(d) - (blobs.gradient(p + step) - blobs.gradient(p - step)) / (2 * eps)).norm(), 0.0, 1e-8);
    }
  }
}

TEST(MarchingTetrahedra, HasSlivers)
{
  for (const ce_test::Implicit_surface& s :
       {ce_test::implicit_ellipsoid(1.0, 0.8, 0.6), ce_test::implicit_torus(1.0, 0.4), ce_test::gaussian_blobs()})
  {
    SCOPED_TRACE(s.name);
    std::vector<double> q = ce_test::aspect_ratios(ce_test::marching_tetrahedra_soup(s, 48, grid_offset));
    std::sort(q.begin(), q.end());
    EXPECT_GT(q.front(), 0.0); // no triangle of zero area: nothing needed merging or dropping
    EXPECT_LT(q.front(), 1e-3);
    EXPECT_GT(q[q.size() / 2], 0.3); // most triangles are fair
  }
}

// ---------------------------------------------------------------------------
// Statistics
// ---------------------------------------------------------------------------

TEST(Statistics, AccumulatorAndOrder)
{
  ce_test::Error_accumulator acc;
  EXPECT_EQ(acc.stats().count, 0u);
  EXPECT_EQ(acc.stats().rms, 0.0);
  acc.add(3.0);
  acc.add(1.0, -3.0); // error -4
  const ce_test::Error_stats s = acc.stats();
  EXPECT_EQ(s.count, 2u);
  EXPECT_DOUBLE_EQ(s.rms, std::sqrt(12.5));
  EXPECT_DOUBLE_EQ(s.max, 4.0);
  acc.add(std::nan(""));
  EXPECT_TRUE(std::isnan(acc.stats().rms));
  EXPECT_TRUE(std::isnan(acc.stats().max));
  EXPECT_EQ(acc.stats().count, 3u);
  acc.clear();
  EXPECT_EQ(acc.stats().count, 0u);
  EXPECT_DOUBLE_EQ(ce_test::observed_order(4e-2, 1e-2, 0.2, 0.1), 2.0);
  EXPECT_NEAR(ce_test::observed_order(3.0 * std::pow(0.3, 1.5), 3.0 * std::pow(0.07, 1.5), 0.3, 0.07), 1.5, 1e-12);
}

} // namespace
