// SPDX-License-Identifier: GPL-3.0-or-later
// Hamann's paraboloid fitting on tetrahedral hypersurfaces of R^4 (thesis §4.3):
// the reproduction of Table 4.2, convergence, invariance, complex-type independence.
#include <CGAL/Curvature_estimation/Tetrahedral_complex_traits.h>
#include <CGAL/Curvature_estimation/hypersurface_paraboloid_fitting.h>

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Epick_d.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Random.h>
#include <CGAL/property_map.h>

#include <Eigen/Dense>

#include <gtest/gtest.h>

#include "kuhn_grid.h"
#include "noisy_meshes.h"
#include "test_surfaces.h"

#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <map>
#include <optional>
#include <random>
#include <vector>

namespace {

namespace CE = CGAL::Curvature_estimation;
using Point4 = std::array<double, 4>;
using Mesh = CE::Indexed_tetrahedral_mesh<Point4>;
using Principal = CE::Hypersurface_principal_curvatures_and_directions<Point4>;
using Status = CE::Estimation_status;
using ce_test::Kuhn_diagonal;

// A trivariate function with its gradient and Hessian.
struct Function
{
  const char* name;
  std::function<double(const Eigen::Vector3d&)> f;
  std::function<Eigen::Vector3d(const Eigen::Vector3d&)> gradient;
  std::function<Eigen::Matrix3d(const Eigen::Vector3d&)> hessian;
  double thesis_H, thesis_K; // Table 4.2
};

std::vector<Function> table_functions()
{
  const double pi = 3.14159265358979323846;
  std::vector<Function> fs;
  fs.push_back({"1 linear .2(x+y+z)", [](const Eigen::Vector3d& p) { return 0.2 * p.sum(); },
                [](const Eigen::Vector3d&) { return Eigen::Vector3d(0.2, 0.2, 0.2); },
                [](const Eigen::Vector3d&) { return Eigen::Matrix3d::Zero().eval(); }, 0, 0});
  fs.push_back({"2 .4(x2+y2+z2)", [](const Eigen::Vector3d& p) { return 0.4 * p.squaredNorm(); },
                [](const Eigen::Vector3d& p) { return (0.8 * p).eval(); },
                [](const Eigen::Vector3d&) { return (0.8 * Eigen::Matrix3d::Identity()).eval(); }, .002950, .002597});
  fs.push_back({"3 .4(x2-y2-z2)",
                [](const Eigen::Vector3d& p) { return 0.4 * (p.x() * p.x() - p.y() * p.y() - p.z() * p.z()); },
                [](const Eigen::Vector3d& p) { return Eigen::Vector3d(0.8 * p.x(), -0.8 * p.y(), -0.8 * p.z()); },
                [](const Eigen::Vector3d&) { return Eigen::Vector3d(0.8, -0.8, -0.8).asDiagonal().toDenseMatrix(); },
                .001115, .002216});
  fs.push_back({"4 cubic",
                [](const Eigen::Vector3d& p) {
                  const double x = p.x(), y = p.y(), z = p.z();
                  return 0.15 * (x * x * x + 2 * x * x * y - x * z * z + 2 * y * y);
                },
                [](const Eigen::Vector3d& p) {
                  const double x = p.x(), y = p.y(), z = p.z();
                  return Eigen::Vector3d(0.15 * (3 * x * x + 4 * x * y - z * z), 0.15 * (2 * x * x + 4 * y),
                                         0.15 * (-2 * x * z));
                },
                [](const Eigen::Vector3d& p) {
                  const double x = p.x(), y = p.y(), z = p.z();
                  Eigen::Matrix3d h;
                  h << 6 * x + 4 * y, 4 * x, -2 * z, 4 * x, 4, 0, -2 * z, 0, -2 * x;
                  return (0.15 * h).eval();
                },
                .002545, .001207});
  fs.push_back({"5 exp", [](const Eigen::Vector3d& p) { return std::exp(-0.5 * p.squaredNorm()); },
                [](const Eigen::Vector3d& p) { return (-std::exp(-0.5 * p.squaredNorm()) * p).eval(); },
                [](const Eigen::Vector3d& p) {
                  return (std::exp(-0.5 * p.squaredNorm()) * (p * p.transpose() - Eigen::Matrix3d::Identity())).eval();
                },
                .006349, .002802});
  fs.push_back({"6 trig",
                [pi](const Eigen::Vector3d& p) {
                  return 0.1 * (std::cos(pi * p.x()) + std::cos(pi * p.y()) + std::cos(pi * p.z()));
                },
                [pi](const Eigen::Vector3d& p) {
                  return Eigen::Vector3d(-0.1 * pi * std::sin(pi * p.x()), -0.1 * pi * std::sin(pi * p.y()),
                                         -0.1 * pi * std::sin(pi * p.z()));
                },
                [pi](const Eigen::Vector3d& p) {
                  return Eigen::Vector3d(-0.1 * pi * pi * std::cos(pi * p.x()), -0.1 * pi * pi * std::cos(pi * p.y()),
                                         -0.1 * pi * pi * std::cos(pi * p.z()))
                    .asDiagonal()
                    .toDenseMatrix();
                },
                .003269, .009065});
  return fs;
}

// Exact curvatures of the graph with the upward normal (-grad f, 1)/l, in the
// package's convention (positive where the graph bends away from the normal):
// the negated eigenvalues of G^-1/2 Hess G^-1/2 / l, decreasing.
Eigen::Vector3d exact_curvatures(const Function& fn, const Eigen::Vector3d& p)
{
  const Eigen::Vector3d g = fn.gradient(p);
  const Eigen::Matrix3d metric = Eigen::Matrix3d::Identity() + g * g.transpose();
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> m(metric);
  const Eigen::Matrix3d inv_sqrt = m.operatorInverseSqrt();
  const double l = std::sqrt(1 + g.squaredNorm());
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> s(inv_sqrt * fn.hessian(p) * inv_sqrt / l);
  const Eigen::Vector3d e = s.eigenvalues(); // ascending
  return Eigen::Vector3d(-e[0], -e[1], -e[2]);
}

Point4 exact_normal(const Function& fn, const Eigen::Vector3d& p)
{
  const Eigen::Vector3d g = fn.gradient(p);
  const double l = std::sqrt(1 + g.squaredNorm());
  return {-g.x() / l, -g.y() / l, -g.z() / l, 1 / l};
}

// The N^3 grid over [-1, 1]^3 (N = 26: x_i = -1 + i/12.5), every cube split into the
// 6 Kuhn tetrahedra around the given diagonal, positively oriented.
struct Grid
{
  int n;
  Mesh mesh;
  std::vector<Eigen::Vector3d> domain;
  std::vector<char> interior;
};

Grid make_grid(int n, const Function& fn, Kuhn_diagonal diagonal = Kuhn_diagonal::main)
{
  const ce_test::Tetrahedral_grid kuhn = ce_test::kuhn_grid(n, diagonal);
  Grid g;
  g.n = n;
  g.domain = kuhn.points;
  for (const Eigen::Vector3d& p : g.domain)
    g.mesh.points.push_back({p.x(), p.y(), p.z(), fn.f(p)});
  g.mesh.cells = kuhn.cells;
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        g.interior.push_back(i > 0 && j > 0 && k > 0 && i < n - 1 && j < n - 1 && k < n - 1);
  return g;
}

struct Result
{
  std::vector<Principal> principal;
  std::vector<double> H, K;
  std::vector<Status> status;
  double seconds = 0;
};

template <typename Concurrency = CGAL::Sequential_tag, typename Extra>
Result run(const Mesh& mesh, const Extra& extra)
{
  Result r;
  const std::size_t n = mesh.points.size();
  r.principal.resize(n);
  r.H.resize(n);
  r.K.resize(n);
  r.status.resize(n);
  const auto start = std::chrono::steady_clock::now();
  CE::hypersurface_paraboloid_fitting_curvatures<Concurrency>(
    mesh, extra.vertex_principal_curvatures_and_directions_map(CGAL::make_property_map(r.principal))
            .vertex_mean_curvature_map(CGAL::make_property_map(r.H))
            .vertex_Gaussian_curvature_map(CGAL::make_property_map(r.K))
            .vertex_estimation_status_map(CGAL::make_property_map(r.status)));
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

struct Rms
{
  double H_all, K_all, H_interior, K_interior;
  std::size_t failed;
};

Rms rms_errors(const Grid& g, const Function& fn, const Result& r)
{
  ce_test::Error_accumulator H_all, K_all, H_interior, K_interior;
  std::size_t failed = 0;
  for (std::size_t v = 0; v < g.domain.size(); ++v) {
    const Eigen::Vector3d k = exact_curvatures(fn, g.domain[v]);
    if (r.status[v] == Status::not_estimable)
      ++failed;
    H_all.add(k.sum() / 3, r.H[v]);
    K_all.add(k.prod(), r.K[v]);
    if (g.interior[v]) {
      H_interior.add(k.sum() / 3, r.H[v]);
      K_interior.add(k.prod(), r.K[v]);
    }
  }
  return {H_all.stats().rms, K_all.stats().rms, H_interior.stats().rms, K_interior.stats().rms, failed};
}

Mesh exact_normals_of(const Grid& g, const Function& fn, std::vector<Point4>& normals)
{
  normals.clear();
  for (const Eigen::Vector3d& p : g.domain)
    normals.push_back(exact_normal(fn, p));
  return g.mesh;
}

// Table 4.2, computed once for both normal modes and printed next to the thesis.
struct Table_row
{
  Rms exact, estimated;
};

const std::vector<Table_row>& table_4_2()
{
  static std::vector<Table_row> rows;
  if (!rows.empty())
    return rows;
  double seconds = 0;
  std::size_t vertices = 0;
  for (const Function& fn : table_functions()) {
    // The split's diagonal: the thesis refers to its chapter 3.2 for the 6 tetrahedra.
    // Only the cubic, the one function not even in x and in y, depends on it: its K with
    // exact normals is 1.01x the thesis with the anti diagonal and 1.52x with the main one
    // (H: 0.81x and 0.93x); the other rows are identical. The anti diagonal is the one
    // whose faces z = const carry the surface grid's triangulation that reproduces the
    // thesis' Table 4.1 to 3 digits (test_paraboloid_fitting.cpp), where the cubic also
    // tells the diagonals apart (its k1: 1.00x against 1.91x with the printed diagonal).
    // With the main diagonal no boundary rule reaches 1.5x: interior and face vertices
    // (1-rings, well-conditioned) alone give 1.45x.
    const Grid g = make_grid(26, fn, Kuhn_diagonal::anti);
    std::vector<Point4> normals;
    exact_normals_of(g, fn, normals);
    const Result exact = run(g.mesh, CE::parameters::vertex_normal_map(CGAL::make_property_map(normals)));
    const Result estimated = run(g.mesh, CE::parameters::default_values());
    seconds += estimated.seconds;
    vertices += g.domain.size();
    rows.push_back({rms_errors(g, fn, exact), rms_errors(g, fn, estimated)});
  }
  std::printf("Table 4.2 (26^3 grid, Kuhn split around (i+1,j,k)-(i,j+1,k+1)): RMS errors of H and K\n");
  std::printf("%-20s | %-17s | %-35s | %-35s\n", "function", "thesis H / K", "exact normals: all H/K, interior H/K",
              "estimated normals: all H/K, interior H/K");
  const auto fs = table_functions();
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const Rms& e = rows[i].exact;
    const Rms& d = rows[i].estimated;
    std::printf("%-20s | %.6f %.6f | %.6f %.6f  %.6f %.6f | %.6f %.6f  %.6f %.6f\n", fs[i].name, fs[i].thesis_H,
                fs[i].thesis_K, e.H_all, e.K_all, e.H_interior, e.K_interior, d.H_all, d.K_all, d.H_interior,
                d.K_interior);
  }
  std::printf("time per vertex (estimated normals, sequential): %.2f us\n", 1e6 * seconds / double(vertices));
  return rows;
}

// Table 4.2 with the normals `normals` of each row: the linear function exact to
// rounding; every vertex of the others estimated, within `factor` times the thesis.
void expect_table_4_2_within(Rms Table_row::*normals, double factor)
{
  const auto& rows = table_4_2();
  const auto fs = table_functions();
  const Rms& linear = rows[0].*normals;
  EXPECT_LT(linear.H_all, 1e-12);
  EXPECT_LT(linear.K_all, 1e-12);
  for (std::size_t i = 1; i < rows.size(); ++i) {
    SCOPED_TRACE(fs[i].name);
    const Rms& e = rows[i].*normals;
    EXPECT_EQ(e.failed, 0u);
    EXPECT_LE(e.H_all, factor * fs[i].thesis_H);
    EXPECT_LE(e.K_all, factor * fs[i].thesis_K);
  }
}

TEST(Hypersurface_table_4_2, ExactNormalsWithin1_5TimesTheThesis) { expect_table_4_2_within(&Table_row::exact, 1.5); }

TEST(Hypersurface_table_4_2, DefaultEstimatedNormalsWithin2TimesTheThesis)
{
  expect_table_4_2_within(&Table_row::estimated, 2);
}

TEST(Hypersurface_paraboloid_fitting, TrigonometricFunctionConvergesAtSecondOrderInTheInterior)
{
  const Function fn = table_functions()[5];
  const int sizes[3] = {14, 26, 51};
  double H[3], K[3], h[3];
  for (int s = 0; s < 3; ++s) {
    const Grid g = make_grid(sizes[s], fn);
    const Result r = run<CGAL::Parallel_if_available_tag>(g.mesh, CE::parameters::default_values());
    const Rms e = rms_errors(g, fn, r);
    H[s] = e.H_interior;
    K[s] = e.K_interior;
    h[s] = 2.0 / (sizes[s] - 1);
    std::printf("N = %2d: interior RMS H %.3e K %.3e (all: H %.3e K %.3e), %.2f s\n", sizes[s], H[s], K[s], e.H_all,
                e.K_all, r.seconds);
  }
  for (int s = 1; s < 3; ++s) {
    const double order_H = ce_test::observed_order(H[s - 1], H[s], h[s - 1], h[s]);
    const double order_K = ce_test::observed_order(K[s - 1], K[s], h[s - 1], h[s]);
    std::printf("observed order N = %d -> %d: H %.3f, K %.3f\n", sizes[s - 1], sizes[s], order_H, order_K);
    EXPECT_GE(order_H, 1.9);
  }
}

// An n^3 grid whose interior points are moved by up to `jitter` in each coordinate.
Grid jittered_grid(int n, const Function& fn, double jitter)
{
  Grid g = make_grid(n, fn);
  CGAL::Random random(7);
  for (std::size_t v = 0; v < g.domain.size(); ++v)
    if (g.interior[v]) {
      Eigen::Vector3d& p = g.domain[v];
      for (int c = 0; c < 3; ++c)
        p[c] += random.get_double(-jitter, jitter);
      g.mesh.points[v] = {p.x(), p.y(), p.z(), fn.f(p)};
    }
  return g;
}

// f4 on a jittered 9^3 grid: small, irregular, with boundary.
Grid small_jittered_grid(const Function& fn) { return jittered_grid(9, fn, 0.04); }

// fit_degree(3): the cubic Taylor fit with linear terms over 2 rings, the same core as for
// surfaces. On grids whose interior points are moved by up to 0.3 of the step, its interior
// H RMS converges at second order, where Hamann's fit (with its default normal) is of first.
TEST(Hypersurface_paraboloid_fitting, FitDegreeThreeConvergesAtSecondOrderOnJitteredGrids)
{
  const Function fn = table_functions()[5];
  const int sizes[3] = {9, 13, 19};
  for (const int degree : {2, 3}) {
    ce_test::Convergence H;
    for (const int n : sizes) {
      const double step = 2.0 / (n - 1);
      const Grid g = jittered_grid(n, fn, 0.3 * step);
      const Result r = run<CGAL::Parallel_if_available_tag>(g.mesh, CE::parameters::fit_degree(degree));
      const Rms e = rms_errors(g, fn, r);
      EXPECT_EQ(e.failed, 0u) << "degree " << degree << ", n " << n;
      const std::optional<double> order = H.add(step, e.H_interior);
      std::printf("fit_degree(%d), jittered %2d^3: interior H RMS %.3e K RMS %.3e", degree, n, e.H_interior,
                  e.K_interior);
      if (order)
        std::printf(", order %.2f", *order);
      std::printf("\n");
      if (order && degree == 3 && n == sizes[2]) {
        EXPECT_GE(*order, 1.8);
      }
    }
  }
}

// use_fallbacks(false): the vertices where the fit of degree 3 is refused (the one-sided
// corners of the grid), which the fit of degree 2 serves by default, are not estimable; the
// others are unchanged, to the bit.
TEST(Hypersurface_paraboloid_fitting, WithoutFallbacksTheirVerticesAreNotEstimable)
{
  const Grid g = jittered_grid(9, table_functions()[5], 0.3 * 2.0 / 8);
  const Result with = run(g.mesh, CE::parameters::fit_degree(3));
  const Result without = run(g.mesh, CE::parameters::fit_degree(3).use_fallbacks(false));
  std::size_t fallbacks = 0;
  for (std::size_t v = 0; v < with.status.size(); ++v) {
    SCOPED_TRACE(v);
    if (with.status[v] == Status::fallback) {
      ++fallbacks;
      EXPECT_EQ(without.status[v], Status::not_estimable);
      EXPECT_TRUE(std::isnan(without.H[v]));
      continue;
    }
    EXPECT_EQ(with.status[v], without.status[v]);
    EXPECT_EQ(with.H[v], without.H[v]);
    EXPECT_EQ(with.K[v], without.K[v]);
  }
  EXPECT_GT(fallbacks, 0u);
}

// ball_radius: the fit with a constant term over the part of the complex in the ball of R^4 that
// is joined to the vertex inside it (the same core as for surfaces). A noisy scalar field (Gaussian
// noise of 5% of the grid step on W, on a grid jittered by 0.3 of the step): the interior H RMS
// falls as the radius grows, below half the 1-ring fit's; without noise it converges at a radius of
// a fixed number of steps, at orders about d - 1 as on surfaces (measured 1.91 and 2.07).
TEST(Hypersurface_paraboloid_fitting, BallRadiusAveragesNoiseAndConverges)
{
  const Function fn = table_functions()[5];
  {
    const int n = 13;
    const double step = 2.0 / (n - 1);
    Grid g = jittered_grid(n, fn, 0.3 * step);
    std::mt19937 gen(3);
    for (Point4& p : g.mesh.points)
      p[3] += 0.05 * step * ce_test::standard_normal(gen);
    const double one_ring =
      rms_errors(g, fn, run<CGAL::Sequential_tag>(g.mesh, CE::parameters::default_values())).H_interior;
    std::printf("noisy field, 1-ring fit: interior H RMS %.3e\n", one_ring);
    double previous = 0.5 * one_ring;
    for (const double steps : {2.0, 3.0}) {
      const Rms e = rms_errors(g, fn, run<CGAL::Sequential_tag>(g.mesh, CE::parameters::ball_radius(steps * step)));
      std::printf("noisy field, ball of %.0f steps: interior H RMS %.3e\n", steps, e.H_interior);
      EXPECT_EQ(e.failed, 0u);
      EXPECT_LT(e.H_interior, previous) << steps << " steps";
      previous = e.H_interior;
    }
  }
  for (const int degree : {2, 3}) {
    ce_test::Convergence H;
    std::optional<double> order;
    for (const int n : {9, 13, 19}) {
      const double step = 2.0 / (n - 1);
      const Grid g = jittered_grid(n, fn, 0.3 * step);
      const Rms e = rms_errors(
        g, fn, run<CGAL::Sequential_tag>(g.mesh, CE::parameters::ball_radius(2.5 * step).fit_degree(degree)));
      EXPECT_EQ(e.failed, 0u);
      order = H.add(step, e.H_interior);
      std::printf("fit_degree(%d), ball of 2.5 steps, jittered %2d^3: interior H RMS %.3e", degree, n, e.H_interior);
      if (order)
        std::printf(", order %.2f", *order);
      std::printf("\n");
    }
    EXPECT_GE(*order, degree == 2 ? 0.8 : 1.6) << "degree " << degree;
  }
}

TEST(Hypersurface_paraboloid_fitting, DirectionsAreUnitTangentOrthogonalAndSorted)
{
  const Function fn = table_functions()[3];
  const Grid g = small_jittered_grid(fn);
  std::vector<Point4> normals;
  exact_normals_of(g, fn, normals);
  const Result r = run(g.mesh, CE::parameters::vertex_normal_map(CGAL::make_property_map(normals)));
  for (std::size_t v = 0; v < g.domain.size(); ++v) {
    ASSERT_NE(r.status[v], Status::not_estimable);
    const Principal& p = r.principal[v];
    EXPECT_GE(p.max_curvature, p.mid_curvature);
    EXPECT_GE(p.mid_curvature, p.min_curvature);
    EXPECT_NEAR(r.H[v], (p.max_curvature + p.mid_curvature + p.min_curvature) / 3, 1e-14);
    EXPECT_NEAR(r.K[v], p.max_curvature * p.mid_curvature * p.min_curvature, 1e-14);
    const Eigen::Vector4d n = CE::to_vector_4(normals[v]);
    const Eigen::Vector4d d[3] = {CE::to_vector_4(p.max_direction), CE::to_vector_4(p.mid_direction),
                                  CE::to_vector_4(p.min_direction)};
    for (int i = 0; i < 3; ++i) {
      EXPECT_NEAR(d[i].norm(), 1, 1e-12);
      EXPECT_NEAR(d[i].dot(n), 0, 1e-12);
      for (int j = i + 1; j < 3; ++j)
        EXPECT_NEAR(d[i].dot(d[j]), 0, 1e-12);
    }
  }
}

// A rigid motion (rotation Q, translation t) and a scaling s of R^4: curvatures
// scale by 1/s, directions turn with Q.
void check_invariance(const Eigen::Matrix4d& Q, const Eigen::Vector4d& t, double s)
{
  const Function fn = table_functions()[3];
  const Grid g = small_jittered_grid(fn);
  Mesh moved = g.mesh;
  for (Point4& p : moved.points) {
    const Eigen::Vector4d q = s * (Q * CE::to_vector_4(p)) + t;
    p = {q[0], q[1], q[2], q[3]};
  }
  const Result a = run(g.mesh, CE::parameters::default_values());
  const Result b = run(moved, CE::parameters::default_values());
  for (std::size_t v = 0; v < g.domain.size(); ++v) {
    ASSERT_EQ(a.status[v], b.status[v]);
    const double tolerance =
      1e-9 * (1 + std::abs(a.principal[v].max_curvature) + std::abs(a.principal[v].min_curvature));
    EXPECT_NEAR(s * b.principal[v].max_curvature, a.principal[v].max_curvature, tolerance);
    EXPECT_NEAR(s * b.principal[v].mid_curvature, a.principal[v].mid_curvature, tolerance);
    EXPECT_NEAR(s * b.principal[v].min_curvature, a.principal[v].min_curvature, tolerance);
    EXPECT_NEAR(s * b.H[v], a.H[v], tolerance);
    EXPECT_NEAR(s * s * s * b.K[v], a.K[v], tolerance * (1 + std::abs(a.K[v])));
    // The direction of a well-separated curvature turns with Q (up to sign).
    const double gap = a.principal[v].max_curvature - a.principal[v].mid_curvature;
    if (gap > 1e-3) {
      const Eigen::Vector4d da = Q * CE::to_vector_4(a.principal[v].max_direction);
      const Eigen::Vector4d db = CE::to_vector_4(b.principal[v].max_direction);
      EXPECT_NEAR(std::abs(da.dot(db)), 1, 1e-7);
    }
  }
}

Eigen::Matrix4d random_rotation(unsigned seed)
{
  CGAL::Random random(seed);
  Eigen::Matrix4d m;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      m(i, j) = random.get_double(-1, 1);
  Eigen::Matrix4d Q = m; // Gram-Schmidt
  for (int j = 0; j < 4; ++j) {
    for (int i = 0; i < j; ++i)
      Q.col(j) -= Q.col(i).dot(Q.col(j)) * Q.col(i);
    Q.col(j).normalize();
  }
  if (Q.determinant() < 0)
    Q.col(0) *= -1; // a proper rotation: orientation, hence the normals' side, is kept
  return Q;
}

TEST(Hypersurface_paraboloid_fitting, InvariantUnderRigidMotionsOfR4)
{
  check_invariance(random_rotation(1), Eigen::Vector4d(3, -2, 5, 1), 1);
  check_invariance(random_rotation(2), Eigen::Vector4d(-100, 20, 7, 0.5), 1);
}

TEST(Hypersurface_paraboloid_fitting, UniformScalingScalesCurvaturesInversely)
{
  check_invariance(Eigen::Matrix4d::Identity(), Eigen::Vector4d::Zero(), 1e-6);
  check_invariance(Eigen::Matrix4d::Identity(), Eigen::Vector4d::Zero(), 1e6);
  check_invariance(random_rotation(3), Eigen::Vector4d(1, 2, 3, 4), 1e-3);
}

TEST(Hypersurface_paraboloid_fitting, SequentialAndParallelAreIdentical)
{
  const Function fn = table_functions()[4];
  const Grid g = make_grid(12, fn);
  const Result a = run<CGAL::Sequential_tag>(g.mesh, CE::parameters::default_values());
  const Result b = run<CGAL::Parallel_if_available_tag>(g.mesh, CE::parameters::default_values());
  for (std::size_t v = 0; v < g.domain.size(); ++v) {
    EXPECT_EQ(a.H[v], b.H[v]);
    EXPECT_EQ(a.K[v], b.K[v]);
    EXPECT_EQ(a.principal[v].max_direction, b.principal[v].max_direction);
    EXPECT_EQ(a.status[v], b.status[v]);
  }
}

using Tr_kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Tr = CGAL::Delaunay_triangulation_3<Tr_kernel>;

// A Delaunay triangulation of a jittered point set and the indexed mesh of its
// finite cells (same vertex and cell order) give the same numbers.
TEST(Hypersurface_paraboloid_fitting, Triangulation3AndIndexedMeshGiveTheSameNumbers)
{
  using K = Tr_kernel;
  using Vertex_handle = Tr::Vertex_handle;
  const Function fn = table_functions()[4];
  CGAL::Random random(11);
  std::vector<K::Point_3> points;
  for (int k = 0; k < 8; ++k)
    for (int j = 0; j < 8; ++j)
      for (int i = 0; i < 8; ++i)
        points.emplace_back(-1 + i / 3.5 + random.get_double(-0.05, 0.05),
                            -1 + j / 3.5 + random.get_double(-0.05, 0.05),
                            -1 + k / 3.5 + random.get_double(-0.05, 0.05));
  const Tr tr(points.begin(), points.end());

  std::map<Vertex_handle, double> f;
  for (auto v = tr.finite_vertices_begin(); v != tr.finite_vertices_end(); ++v)
    f[v] = fn.f(Eigen::Vector3d(v->point().x(), v->point().y(), v->point().z()));
  const auto vpm = CE::make_graph_point_map(CE::Tetrahedral_complex_traits<Tr>::Default_point_map(),
                                            boost::make_assoc_property_map(f));

  std::map<Vertex_handle, double> H_map, K_map;
  std::map<Vertex_handle, Status> status_map;
  std::map<Vertex_handle, Principal> principal_map;
  CE::hypersurface_paraboloid_fitting_curvatures(
    tr, CE::parameters::vertex_point_map(vpm)
          .vertex_mean_curvature_map(boost::make_assoc_property_map(H_map))
          .vertex_Gaussian_curvature_map(boost::make_assoc_property_map(K_map))
          .vertex_estimation_status_map(boost::make_assoc_property_map(status_map))
          .vertex_principal_curvatures_and_directions_map(boost::make_assoc_property_map(principal_map)));

  Mesh mesh;
  std::map<Vertex_handle, std::size_t> index;
  for (auto v = tr.finite_vertices_begin(); v != tr.finite_vertices_end(); ++v) {
    index[v] = mesh.points.size();
    mesh.points.push_back(get(vpm, Vertex_handle(v)));
  }
  for (auto c = tr.finite_cells_begin(); c != tr.finite_cells_end(); ++c)
    mesh.cells.push_back({index[c->vertex(0)], index[c->vertex(1)], index[c->vertex(2)], index[c->vertex(3)]});
  const Result r = run(mesh, CE::parameters::default_values());

  std::size_t estimated = 0;
  for (auto v = tr.finite_vertices_begin(); v != tr.finite_vertices_end(); ++v) {
    const std::size_t i = index[v];
    EXPECT_EQ(status_map[v], r.status[i]);
    if (r.status[i] == Status::not_estimable)
      continue;
    ++estimated;
    EXPECT_EQ(H_map[v], r.H[i]);
    EXPECT_EQ(K_map[v], r.K[i]);
    EXPECT_EQ(principal_map[v].min_direction, r.principal[i].min_direction);
    // Delaunay cells are positively oriented: the estimated normal points to
    // increasing W, so the curvatures agree in sign with the exact upward ones
    // (f5 is a cap: all three negative near the top).
  }
  // Not asserted (reported): the default normal leaves a few hull vertices of a
  // Delaunay triangulation not estimable, see the integration note.
  std::printf("Delaunay 8^3, default normals: %zu of %zu vertices estimated\n", estimated, points.size());
  // The exact values, loosely, at the innermost vertices: orientation and sign are right.
  for (auto v = tr.finite_vertices_begin(); v != tr.finite_vertices_end(); ++v) {
    const Eigen::Vector3d p(v->point().x(), v->point().y(), v->point().z());
    if (p.norm() < 0.3) {
      EXPECT_NEAR(H_map[v], exact_curvatures(fn, p).sum() / 3, 0.1);
    }
  }
}

TEST(Hypersurface_paraboloid_fitting, EpickDPointsAreAccepted)
{
  using KD = CGAL::Epick_d<CGAL::Dimension_tag<4>>;
  using Point_d = KD::Point_d;
  using Vector_d = KD::Vector_d;
  const Function fn = table_functions()[3];
  const Grid g = make_grid(6, fn);
  CE::Indexed_tetrahedral_mesh<Point_d> mesh;
  for (const Point4& p : g.mesh.points)
    mesh.points.emplace_back(p.begin(), p.end());
  mesh.cells = g.mesh.cells;
  std::vector<double> H(mesh.points.size());
  std::vector<CE::Hypersurface_principal_curvatures_and_directions<Vector_d>> principal(mesh.points.size());
  CE::hypersurface_paraboloid_fitting_curvatures(
    mesh, CE::parameters::vertex_mean_curvature_map(CGAL::make_property_map(H))
            .vertex_principal_curvatures_and_directions_map(CGAL::make_property_map(principal)));
  const Result r = run(g.mesh, CE::parameters::default_values());
  for (std::size_t v = 0; v < H.size(); ++v) {
    EXPECT_EQ(H[v], r.H[v]);
    EXPECT_EQ(principal[v].max_direction[3], r.principal[v].max_direction[3]);
  }
}

TEST(Hypersurface_paraboloid_fitting, NotEstimableVerticesGetNaNAndStatus)
{
  // One tetrahedron (3 neighbors for 6 unknowns, nothing to widen to), an isolated
  // vertex, and a vertex with a NaN coordinate in a good grid.
  const Function fn = table_functions()[1];
  Grid g = make_grid(6, fn);
  Mesh mesh = g.mesh;
  const std::size_t bad = 3 * 36 + 3 * 6 + 3; // interior vertex (3,3,3)
  mesh.points[bad][3] = std::numeric_limits<double>::quiet_NaN();
  const std::size_t isolated = mesh.points.size();
  mesh.points.push_back({5, 5, 5, 5});
  const std::size_t tet = mesh.points.size();
  for (int i = 0; i < 4; ++i)
    mesh.points.push_back({10.0 + (i == 1), 10.0 + (i == 2), 10.0 + (i == 3), 0.0});
  mesh.cells.push_back({tet, tet + 1, tet + 2, tet + 3});
  for (bool given : {false, true}) {
    std::vector<Point4> normals(mesh.points.size(), Point4{0, 0, 0, 1});
    const Result r = given ? run(mesh, CE::parameters::vertex_normal_map(CGAL::make_property_map(normals)))
                           : run(mesh, CE::parameters::default_values());
    for (std::size_t v : {bad, isolated, tet, tet + 1, tet + 2, tet + 3}) {
      SCOPED_TRACE(v);
      EXPECT_EQ(r.status[v], Status::not_estimable);
      EXPECT_TRUE(std::isnan(r.H[v]));
      EXPECT_TRUE(std::isnan(r.K[v]));
      EXPECT_TRUE(std::isnan(r.principal[v].max_curvature));
      EXPECT_TRUE(std::isnan(r.principal[v].min_direction[0]));
    }
    // A far vertex of the grid is unharmed (its rings do not reach the NaN).
    EXPECT_NE(r.status[0], Status::not_estimable);
    EXPECT_TRUE(std::isfinite(r.H[0]));
  }
}

TEST(Hypersurface_paraboloid_fitting, InvalidParametersThrow)
{
  const Grid g = make_grid(4, table_functions()[1]);
  std::vector<double> H(g.mesh.points.size());
  EXPECT_THROW(CE::hypersurface_paraboloid_fitting_curvatures(
                 g.mesh, CE::parameters::vertex_mean_curvature_map(CGAL::make_property_map(H)).neighborhood_rings(0)),
               std::invalid_argument);
  EXPECT_THROW(CE::hypersurface_paraboloid_fitting_curvatures(
                 g.mesh, CE::parameters::vertex_mean_curvature_map(CGAL::make_property_map(H))
                           .vertex_normal_method(CE::Vertex_normal_method::angle_weighted)),
               std::invalid_argument);
  Mesh broken = g.mesh;
  broken.cells.push_back({0, 1, 2, 999});
  EXPECT_THROW(CE::hypersurface_paraboloid_fitting_curvatures(
                 broken, CE::parameters::vertex_mean_curvature_map(CGAL::make_property_map(H))),
               std::invalid_argument);
}

} // namespace
