// SPDX-License-Identifier: GPL-3.0-or-later
// Running an estimator with every output requested and comparing the results
// with exact curvature: shared by the estimators' tests.
#ifndef CE_TEST_ESTIMATOR_RUNS_H
#define CE_TEST_ESTIMATOR_RUNS_H

#include <CGAL/Curvature_estimation/Principal_curvatures_and_directions.h>

#include "test_surfaces.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <vector>

namespace ce_test {

// Per-vertex results in vertex order (= soup order for meshes made by to_mesh).
template <typename Kernel>
struct Estimates
{
  std::vector<CGAL::Curvature_estimation::Principal_curvatures_and_directions<Kernel>> principal;
  std::vector<double> mean, gaussian;
  std::vector<CGAL::Curvature_estimation::Estimation_status> status;
};

// Calls `run(mesh, np)` (one estimator) on a CGAL::Surface_mesh with every
// output requested; `extra` is a pack of further parameters to chain onto.
template <typename Kernel, typename Mesh, typename Run, typename Extra>
Estimates<Kernel> run_with_all_outputs(const Mesh& mesh, Run run, const Extra& extra)
{
  using Vertex = typename Mesh::Vertex_index;
  using Curvatures = CGAL::Curvature_estimation::Principal_curvatures_and_directions<Kernel>;
  using Status = CGAL::Curvature_estimation::Estimation_status;
  Mesh& m = const_cast<Mesh&>(mesh); // only to add and remove the output maps
  auto principal = m.template add_property_map<Vertex, Curvatures>("v:test_pcd").first;
  auto mean = m.template add_property_map<Vertex, double>("v:test_H").first;
  auto gaussian = m.template add_property_map<Vertex, double>("v:test_K").first;
  auto status = m.template add_property_map<Vertex, Status>("v:test_status").first;
  run(mesh, extra.vertex_principal_curvatures_and_directions_map(principal)
              .vertex_mean_curvature_map(mean)
              .vertex_Gaussian_curvature_map(gaussian)
              .vertex_estimation_status_map(status));
  Estimates<Kernel> e;
  for (Vertex v : vertices(mesh)) {
    e.principal.push_back(principal[v]);
    e.mean.push_back(mean[v]);
    e.gaussian.push_back(gaussian[v]);
    e.status.push_back(status[v]);
  }
  m.remove_property_map(principal);
  m.remove_property_map(mean);
  m.remove_property_map(gaussian);
  m.remove_property_map(status);
  return e;
}

struct Curvature_errors
{
  Error_accumulator k_max, k_min, mean, gaussian;
};

// Errors against the exact curvature at the vertices `include(i)` selects.
template <typename Kernel, typename Include>
Curvature_errors curvature_errors(const Estimates<Kernel>& e, const std::vector<Exact_curvature>& exact,
                                  Include include)
{
  Curvature_errors t;
  for (std::size_t i = 0; i < exact.size(); ++i) {
    if (!include(i))
      continue;
    t.k_max.add(exact[i].k_max, e.principal[i].max_curvature);
    t.k_min.add(exact[i].k_min, e.principal[i].min_curvature);
    t.mean.add(exact[i].H, e.mean[i]);
    t.gaussian.add(exact[i].K, e.gaussian[i]);
  }
  return t;
}

template <typename Kernel>
Curvature_errors curvature_errors(const Estimates<Kernel>& e, const std::vector<Exact_curvature>& exact)
{
  return curvature_errors(e, exact, [](std::size_t) { return true; });
}

// A normal map of `mesh` holding the exact normals of its soup's points.
template <typename Kernel, typename Mesh>
auto exact_normal_map(Mesh& mesh, const std::vector<Exact_curvature>& exact)
{
  using Vertex = typename Mesh::Vertex_index;
  auto normals = mesh.template add_property_map<Vertex, typename Kernel::Vector_3>("v:exact_normal").first;
  std::size_t i = 0;
  for (Vertex v : vertices(mesh)) {
    const Eigen::Vector3d& n = exact[i++].normal;
    normals[v] = typename Kernel::Vector_3(n.x(), n.y(), n.z());
  }
  return normals;
}

// The same run without and with fallbacks: at a vertex that a fallback served
// (`with` fallback) `without` has the method's own estimate or none; everywhere
// else the two are the same to the bit. Returns the number of vertices of each
// kind: fallback vertices left not_estimable, and those with an own estimate.
struct Fallback_counts
{
  std::size_t not_estimable = 0, own = 0;
};

template <typename Kernel>
Fallback_counts compare_without_fallbacks(const Estimates<Kernel>& with, const Estimates<Kernel>& without)
{
  using Status = CGAL::Curvature_estimation::Estimation_status;
  Fallback_counts counts;
  for (std::size_t i = 0; i < with.status.size(); ++i) {
    SCOPED_TRACE(i);
    if (with.status[i] == Status::fallback) {
      EXPECT_NE(without.status[i], Status::fallback);
      if (without.status[i] == Status::not_estimable) {
        EXPECT_TRUE(std::isnan(without.mean[i]));
        ++counts.not_estimable;
      } else
        ++counts.own;
      continue;
    }
    EXPECT_EQ(with.status[i], without.status[i]);
    if (with.status[i] == Status::not_estimable)
      continue;
    EXPECT_EQ(with.mean[i], without.mean[i]);
    EXPECT_EQ(with.gaussian[i], without.gaussian[i]);
    EXPECT_EQ(with.principal[i].max_curvature, without.principal[i].max_curvature);
    EXPECT_EQ(with.principal[i].min_curvature, without.principal[i].min_curvature);
  }
  return counts;
}

} // namespace ce_test

#endif // CE_TEST_ESTIMATOR_RUNS_H
