// SPDX-License-Identifier: GPL-3.0-or-later
// The three estimators that Chen, Wu and Chi (2005) compare, gauss_map_curvatures and its
// baselines taubin_curvatures and chen_schmitt_curvatures, on a CGAL::Surface_mesh: running
// one, the checks their tests share (planes, a closed sphere, bad input, concurrency) and the
// paper's random polynomial experiment (section 5) against reference medians.
//
// An estimator here is a callable `run(tag, mesh, np)` that calls one of them with the concurrency
// tag of `tag` (CGAL::Sequential_tag or CGAL::Parallel_tag); `name` names it in messages.
#ifndef CE_TEST_COMMON_CHEN_WU_CHI_H
#define CE_TEST_COMMON_CHEN_WU_CHI_H

#include <CGAL/Curvature_estimation/Principal_curvatures_and_directions.h>
#include <CGAL/Curvature_estimation/Vertex_normal_method.h>
#include <CGAL/Curvature_estimation/parameters.h>
#include <CGAL/Curvature_estimation/vertex_normals.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/tags.h>

#include <Eigen/Dense>

#include <gtest/gtest.h>

#include "degenerate_input.h"
#include "estimator_runs.h"
#include "test_surfaces.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <limits>
#include <random>
#include <vector>

namespace ce_test {
namespace chen_wu_chi {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Vector = Kernel::Vector_3;
using Mesh = CGAL::Surface_mesh<Point>;
using vertex_descriptor = Mesh::Vertex_index;
using Normal_map = Mesh::Property_map<vertex_descriptor, Vector>;
using Curvatures = CGAL::Curvature_estimation::Principal_curvatures_and_directions<Kernel>;
using Estimates = ce_test::Estimates<Kernel>;
using CGAL::Curvature_estimation::Estimation_status;
using CGAL::Curvature_estimation::Vertex_normal_method;
namespace params = CGAL::Curvature_estimation::parameters;

// Runs the estimator `run` with every output requested; `extra` adds parameters.
template <typename ConcurrencyTag = CGAL::Sequential_tag, typename Run, typename Extra>
Estimates estimate(Run run, const Mesh& mesh, const Extra& extra)
{
  return run_with_all_outputs<Kernel>(
    mesh, [run](const Mesh& m, const auto& np) { run(ConcurrencyTag(), m, np); }, extra);
}

template <typename Run>
Estimates estimate(Run run, const Mesh& mesh)
{
  return estimate(run, mesh, params::default_values());
}

inline Normal_map exact_normal_map(Mesh& mesh, const std::vector<Exact_curvature>& exact)
{
  return ce_test::exact_normal_map<Kernel>(mesh, exact);
}

// A sphere of radius 0.5 (sphere_soup, 3 subdivisions), its exact curvatures and its exact
// normals as a vertex_normal_map.
struct Sphere_with_exact_normals
{
  double radius = 0.5;
  Soup soup = sphere_soup(radius, 3);
  Mesh mesh = to_mesh<Mesh>(soup);
  std::vector<Exact_curvature> exact = sphere_curvatures(radius, soup);
  Normal_map normals = exact_normal_map(mesh, exact);
};

inline void expect_unit_orthogonal_tangent(const Curvatures& c, const Eigen::Vector3d& normal, double tangent_tolerance)
{
  const Eigen::Vector3d d_max(c.max_direction.x(), c.max_direction.y(), c.max_direction.z());
  const Eigen::Vector3d d_min(c.min_direction.x(), c.min_direction.y(), c.min_direction.z());
  EXPECT_NEAR(d_max.norm(), 1, 1e-12);
  EXPECT_NEAR(d_min.norm(), 1, 1e-12);
  EXPECT_NEAR(d_max.dot(d_min), 0, 1e-12);
  EXPECT_NEAR(d_max.dot(normal), 0, tangent_tolerance);
  EXPECT_NEAR(d_min.dot(normal), 0, tangent_tolerance);
}

// ---------------------------------------------------------------------------
// The checks every estimator of the comparison passes
// ---------------------------------------------------------------------------

// Zero curvature on a regular and a jittered grid of a plane, with exact, fitted and
// centroid-weighted normals. `may_refuse`: the estimator may find some vertices not estimable
// (Chen-Schmitt, at the grid's corners: two or three directions).
template <typename Run>
void expect_zero_on_a_plane_with_every_normal_choice(const char* name, Run run, bool may_refuse)
{
  const Graph_function plane = hamann_table1_functions()[0];
  ASSERT_EQ(plane.name, "plane");
  for (const Soup& soup : {grid_graph_soup(plane, 9), jittered_grid_graph_soup(plane, 9, -1, 1, 0.2, 5)}) {
    Mesh mesh = to_mesh<Mesh>(soup);
    const auto exact = graph_curvatures(plane, soup);
    const auto normals = exact_normal_map(mesh, exact);
    const Estimates given = estimate(run, mesh, params::vertex_normal_map(normals));
    const Estimates fitted = estimate(run, mesh);
    const Estimates centroid =
      estimate(run, mesh, params::vertex_normal_method(Vertex_normal_method::centroid_weighted));
    for (const Estimates* e : {&given, &fitted, &centroid})
      for (std::size_t i = 0; i < exact.size(); ++i) {
        if (e->status[i] == Estimation_status::not_estimable) {
          EXPECT_TRUE(may_refuse) << name << " vertex " << i;
          continue;
        }
        EXPECT_NEAR(e->principal[i].max_curvature, 0, 1e-12) << name << " vertex " << i;
        EXPECT_NEAR(e->principal[i].min_curvature, 0, 1e-12) << name << " vertex " << i;
        EXPECT_NEAR(e->gaussian[i], 0, 1e-12) << name << " vertex " << i;
      }
  }
}

// The sign convention with the default normals: on a closed icosphere of radius 3, positive
// principal curvatures near 1/3 and unit orthogonal tangent directions.
template <typename Run>
void expect_positive_one_over_radius_on_a_closed_sphere_with_default_normals(const char* name, Run run)
{
  const double radius = 3.0;
  const Soup soup = sphere_soup(radius, 4);
  const Mesh mesh = to_mesh<Mesh>(soup);
  const auto exact = sphere_curvatures(radius, soup);
  const Estimates e = estimate(run, mesh);
  const Curvature_errors r = curvature_errors(e, exact);
  std::printf("icosphere level 4, default normals, %-12s: H RMS relative error %.2e\n", name,
              r.mean.stats().rms * radius);
  for (std::size_t i = 0; i < exact.size(); ++i) {
    ASSERT_EQ(e.status[i], Estimation_status::ok) << name;
    EXPECT_GT(e.principal[i].min_curvature, 0) << name;
    EXPECT_GE(e.principal[i].max_curvature, e.principal[i].min_curvature) << name;
    EXPECT_GT(e.gaussian[i], 0) << name;
    expect_unit_orthogonal_tangent(e.principal[i], exact[i].normal, 1e-3);
  }
  EXPECT_LT(r.mean.stats().rms, 0.02 / radius) << name;
}

// On `mesh` (grid_with_isolated_and_nan_vertex), the vertices `isolated` and `broken` are not
// estimable, with NaN in every output, and the neighbors of `broken` are estimated; an empty
// mesh is no error.
template <typename Run>
void expect_isolated_and_nan_vertices_not_estimable(const char* name, Run run, const Mesh& mesh,
                                                    vertex_descriptor isolated, vertex_descriptor broken)
{
  const Estimates e = estimate(run, mesh);
  for (vertex_descriptor v : {isolated, broken}) {
    const std::size_t i = std::size_t(v);
    EXPECT_EQ(e.status[i], Estimation_status::not_estimable) << name;
    EXPECT_TRUE(std::isnan(e.principal[i].max_curvature) && std::isnan(e.principal[i].min_curvature));
    EXPECT_TRUE(std::isnan(e.mean[i]) && std::isnan(e.gaussian[i]));
    EXPECT_TRUE(std::isnan(e.principal[i].max_direction.x()) && std::isnan(e.principal[i].min_direction.x()));
  }
  for (vertex_descriptor w : vertices_around_target(halfedge(broken, mesh), mesh)) {
    EXPECT_NE(e.status[std::size_t(w)], Estimation_status::not_estimable) << name << " " << w;
    EXPECT_TRUE(std::isfinite(e.mean[std::size_t(w)])) << name << " " << w;
  }
  Mesh empty;
  EXPECT_NO_THROW(estimate(run, empty));
}

#ifdef CGAL_LINKED_WITH_TBB
// The same outputs, bit for bit, from CGAL::Sequential_tag and CGAL::Parallel_tag.
template <typename Run>
void expect_sequential_and_parallel_identical(const char* name, Run run)
{
  const Soup soup = torus_soup(3, 1, 96, 48, 0.2, 3);
  const Mesh mesh = to_mesh<Mesh>(soup);
  const Estimates sequential = estimate<CGAL::Sequential_tag>(run, mesh, params::default_values());
  const Estimates parallel = estimate<CGAL::Parallel_tag>(run, mesh, params::default_values());
  for (std::size_t i = 0; i < soup.points.size(); ++i) {
    EXPECT_EQ(std::memcmp(&sequential.mean[i], &parallel.mean[i], sizeof(double)), 0) << name;
    EXPECT_EQ(std::memcmp(&sequential.gaussian[i], &parallel.gaussian[i], sizeof(double)), 0) << name;
    EXPECT_EQ(sequential.principal[i].max_direction, parallel.principal[i].max_direction) << name;
    EXPECT_EQ(sequential.status[i], parallel.status[i]) << name;
  }
}
#endif

// ---------------------------------------------------------------------------
// The paper's experiment (section 5), made precise in the issue
// ---------------------------------------------------------------------------

// f(u,v) = sum_{i<=m, j<=n} c_ij u^i v^j.
struct Polynomial
{
  int m = 0, n = 0;
  double c[5][5] = {};

  double operator()(double u, double v) const { return eval(u, v, 0, 0); }
  // d^(a+b) f / du^a dv^b
  double eval(double u, double v, int a, int b) const
  {
    double sum = 0;
    for (int i = a; i <= m; ++i)
      for (int j = b; j <= n; ++j) {
        double factor = c[i][j];
        for (int k = 0; k < a; ++k)
          factor *= i - k;
        for (int k = 0; k < b; ++k)
          factor *= j - k;
        sum += factor * std::pow(u, i - a) * std::pow(v, j - b);
      }
    return sum;
  }
  Graph_function graph() const
  {
    const Polynomial p = *this;
    return {"random polynomial",
            [p](double u, double v) { return p.eval(u, v, 0, 0); },
            [p](double u, double v) { return p.eval(u, v, 1, 0); },
            [p](double u, double v) { return p.eval(u, v, 0, 1); },
            [p](double u, double v) { return p.eval(u, v, 2, 0); },
            [p](double u, double v) { return p.eval(u, v, 1, 1); },
            [p](double u, double v) { return p.eval(u, v, 0, 2); }};
  }
};

// A setting of the experiment: the reference medians of Err(K) and Err(H) from an independent
// implementation (issue 7; 0 when the setting is printed, not checked), and the estimate on a mesh
// of fans given `normals`: exact at the neighbors, centroid-weighted at the centres.
struct Fan_setting
{
  const char* name;
  double err_K, err_H;
  std::function<Estimates(const Mesh&, const Normal_map& normals)> estimate;
};

// The random polynomial fans of the experiment (1,000 surfaces, 100 fans each: a centre on the
// surface and 5 to 8 neighbors at random angles, every gap below pi, at distances 0.05 to 0.15);
// the median relative errors of K and H at the centres are those of the references within 10%.
inline void expect_reference_medians_on_random_polynomial_fans(const std::vector<Fan_setting>& settings)
{
  constexpr int surfaces = 1000, fans_per_surface = 100;
  const auto start = std::chrono::steady_clock::now();
  std::mt19937 gen(20050901);
  auto uniform = [&](double lo, double hi) { return ce_test::uniform(gen, lo, hi); };
  auto uniform_int = [&](int lo, int hi) {
    return lo + std::min(hi - lo, int((hi - lo + 1) * ce_test::uniform01(gen)));
  };

  std::vector<std::vector<double>> err_K(settings.size()), err_H(settings.size());
  std::vector<std::size_t> not_estimable(settings.size());

  std::vector<vertex_descriptor> centres;
  std::vector<double> angles;
  for (int s = 0; s < surfaces; ++s) {
    Polynomial f;
    f.m = uniform_int(2, 4);
    f.n = uniform_int(2, 4);
    for (int i = 0; i <= f.m; ++i)
      for (int j = 0; j <= f.n; ++j)
        f.c[i][j] = uniform(-5, 5);
    const Exact_curvature exact = graph_curvature(f.graph(), 0, 0);

    // All fans of one surface in one mesh, one connected component each.
    Mesh mesh;
    auto normals = mesh.add_property_map<vertex_descriptor, Vector>("v:normal").first;
    centres.clear();
    std::vector<vertex_descriptor> ring;
    for (int k = 0; k < fans_per_surface; ++k) {
      const int n_v = uniform_int(5, 8);
      // Random angles with every gap (also the wrap-around one) below pi.
      for (;;) {
        angles.clear();
        for (int i = 0; i < n_v; ++i)
          angles.push_back(uniform(0, 2 * pi));
        std::sort(angles.begin(), angles.end());
        double largest_gap = angles.front() + 2 * pi - angles.back();
        for (int i = 1; i < n_v; ++i)
          largest_gap = std::max(largest_gap, angles[i] - angles[i - 1]);
        if (largest_gap < pi)
          break;
      }
      const vertex_descriptor centre = mesh.add_vertex(Point(0, 0, f(0, 0)));
      centres.push_back(centre);
      ring.clear();
      for (int i = 0; i < n_v; ++i) {
        const double r = uniform(0.05, 0.15), x = r * std::cos(angles[i]), y = r * std::sin(angles[i]);
        ring.push_back(mesh.add_vertex(Point(x, y, f(x, y))));
        const Eigen::Vector3d n = Eigen::Vector3d(-f.eval(x, y, 1, 0), -f.eval(x, y, 0, 1), 1).normalized();
        normals[ring.back()] = Vector(n.x(), n.y(), n.z());
      }
      for (int i = 0; i < n_v; ++i)
        ASSERT_NE(mesh.add_face(centre, ring[i], ring[(i + 1) % n_v]), Mesh::null_face());
    }
    // The Gauss map's setting: the centroid-weighted normal at the centre, exact normals at the neighbors.
    auto centroid_normals = mesh.add_property_map<vertex_descriptor, Vector>("v:centroid_normal").first;
    CGAL::Curvature_estimation::estimate_vertex_normals(
      mesh, centroid_normals, params::vertex_normal_method(Vertex_normal_method::centroid_weighted));
    for (vertex_descriptor c : centres)
      normals[c] = centroid_normals[c];

    for (std::size_t setting = 0; setting < settings.size(); ++setting) {
      const Estimates e = settings[setting].estimate(mesh, normals);
      for (vertex_descriptor c : centres) {
        if (e.status[std::size_t(c)] == Estimation_status::not_estimable) {
          ++not_estimable[setting];
          continue;
        }
        err_K[setting].push_back(std::abs(exact.K - e.gaussian[std::size_t(c)]) / std::abs(exact.K));
        err_H[setting].push_back(std::abs(exact.H - e.mean[std::size_t(c)]) / std::abs(exact.H));
      }
    }
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  std::printf("Random polynomial fans, %d surfaces x %d fans (%.1f s): median Err(K), Err(H); ours vs reference\n",
              surfaces, fans_per_surface, seconds);
  for (std::size_t setting = 0; setting < settings.size(); ++setting) {
    const Fan_setting& reference = settings[setting];
    const double k = median(err_K[setting]), h = median(err_H[setting]);
    if (reference.err_K > 0)
      std::printf("  %-36s K %.3f (ref %.3f, %+5.1f%%)  H %.3f (ref %.3f, %+5.1f%%)\n", reference.name, k,
                  reference.err_K, 100 * (k / reference.err_K - 1), h, reference.err_H,
                  100 * (h / reference.err_H - 1));
    else
      std::printf("  %-36s K %.3f              H %.3f\n", reference.name, k, h);
    // Every centre has 5 to 8 neighbors spread over more than a half-turn: always estimable.
    EXPECT_EQ(not_estimable[setting], 0u) << reference.name;
    if (reference.err_K > 0) {
      EXPECT_NEAR(k, reference.err_K, 0.1 * reference.err_K) << reference.name;
      EXPECT_NEAR(h, reference.err_H, 0.1 * reference.err_H) << reference.name;
    }
  }
}

} // namespace chen_wu_chi
} // namespace ce_test

#endif // CE_TEST_COMMON_CHEN_WU_CHI_H
