// SPDX-License-Identifier: GPL-3.0-or-later
// taubin_curvatures (Taubin 1995), a baseline of Chen, Wu and Chi (2005): its mean curvature
// is exact where its formula is, zero on planes, the sign convention with the default normals,
// the paper's random polynomial experiment against reference medians, bad input, concurrency.
#include <CGAL/Curvature_estimation/taubin.h>

#include <gtest/gtest.h>

#include "chen_wu_chi.h"

#include <stdexcept>

namespace {

using namespace ce_test::chen_wu_chi;
using CGAL::Curvature_estimation::Neighbor_weighting;
namespace CE = CGAL::Curvature_estimation;

// taubin_curvatures with the concurrency tag of `tag`.
const auto taubin = [](auto tag, const Mesh& mesh, const auto& np) { CE::taubin_curvatures<decltype(tag)>(mesh, np); };

TEST(Taubin, MeanCurvatureIsExactOnASphereWithExactNormals)
{
  // Every neighbor of a sphere's vertex lies on the circle of radius r tangent
  // to the plane: k_n(t_i) = 1/r exactly. Taubin's tensor is (1/r) sum w_i t_i t_i^T,
  // of trace 1/r: its H = (k1 + k2)/2 = tr M is exact, its k1, k2 only on
  // isotropic stencils.
  Sphere_with_exact_normals sphere;
  const double radius = sphere.radius;
  const Mesh& mesh = sphere.mesh;
  const auto& exact = sphere.exact;
  const auto normals = sphere.normals;
  for (Neighbor_weighting w : {Neighbor_weighting::area, Neighbor_weighting::centroid}) {
    const Estimates e = estimate(taubin, mesh, params::vertex_normal_map(normals).neighbor_weighting(w));
    for (std::size_t i = 0; i < exact.size(); ++i)
      EXPECT_NEAR(e.mean[i], 1 / radius, 1e-12 / radius);
  }
}

TEST(Taubin, PlaneGivesZeroForEveryNormalChoice)
{
  expect_zero_on_a_plane_with_every_normal_choice("taubin", taubin, false);
}

TEST(Taubin, ClosedSphereWithDefaultNormalsHasPositiveCurvatureOneOverRadius)
{
  expect_positive_one_over_radius_on_a_closed_sphere_with_default_normals("taubin", taubin);
}

TEST(Taubin, RandomPolynomialFansReproduceTheReferenceMedians)
{
  expect_reference_medians_on_random_polynomial_fans(
    {{"Taubin, area weights", 0.957, 0.662,
      [](const Mesh& mesh, const Normal_map&) {
        return estimate(taubin, mesh,
                        params::vertex_normal_method(Vertex_normal_method::area_weighted)
                          .neighbor_weighting(Neighbor_weighting::area));
      }},
     {"Taubin, centroid weights", 1.015, 0.645, [](const Mesh& mesh, const Normal_map&) {
        return estimate(taubin, mesh,
                        params::vertex_normal_method(Vertex_normal_method::centroid_weighted)
                          .neighbor_weighting(Neighbor_weighting::centroid));
      }}});
}

TEST(Taubin, IsolatedAndNaNVerticesAreNotEstimableWithoutHarmingNeighbors)
{
  auto [mesh, isolated, broken] = ce_test::grid_with_isolated_and_nan_vertex<Mesh>();
  expect_isolated_and_nan_vertices_not_estimable("taubin", taubin, mesh, isolated, broken);
  // It refuses the weighting it does not define.
  EXPECT_THROW(CE::taubin_curvatures(mesh, params::neighbor_weighting(Neighbor_weighting::uniform)),
               std::invalid_argument);
}

#ifdef CGAL_LINKED_WITH_TBB
TEST(Taubin, SequentialAndParallelAreIdentical) { expect_sequential_and_parallel_identical("taubin", taubin); }
#endif

} // namespace
