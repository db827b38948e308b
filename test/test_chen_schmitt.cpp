// SPDX-License-Identifier: GPL-3.0-or-later
// chen_schmitt_curvatures (Chen and Schmitt 1992), a baseline of Chen, Wu and Chi (2005): exact
// where its formula is, zero on planes, the sign convention with the default normals, the paper's
// random polynomial experiment against a reference median, bad input, concurrency.
#include <CGAL/Curvature_estimation/chen_schmitt.h>

#include <gtest/gtest.h>

#include "chen_wu_chi.h"

#include <stdexcept>

namespace {

using namespace ce_test::chen_wu_chi;
using CGAL::Curvature_estimation::Neighbor_weighting;
namespace CE = CGAL::Curvature_estimation;

// chen_schmitt_curvatures with the concurrency tag of `tag`.
const auto chen_schmitt = [](auto tag, const Mesh& mesh, const auto& np) {
  CE::chen_schmitt_curvatures<decltype(tag)>(mesh, np);
};

TEST(Chen_schmitt, ExactOnASphereWithExactNormals)
{
  // Every neighbor of a sphere's vertex lies on the circle of radius r tangent
  // to the plane: k_n(t_i) = 1/r exactly. Euler's formula then fits C1 = C3 = 1/r,
  // C2 = 0 exactly.
  Sphere_with_exact_normals sphere;
  const double radius = sphere.radius;
  const Mesh& mesh = sphere.mesh;
  const auto& exact = sphere.exact;
  const auto normals = sphere.normals;
  const Estimates cs = estimate(chen_schmitt, mesh, params::vertex_normal_map(normals));
  for (std::size_t i = 0; i < exact.size(); ++i) {
    EXPECT_NEAR(cs.principal[i].max_curvature, 1 / radius, 1e-12 / radius);
    EXPECT_NEAR(cs.principal[i].min_curvature, 1 / radius, 1e-12 / radius);
    EXPECT_NEAR(cs.gaussian[i], 1 / (radius * radius), 1e-11 / (radius * radius));
  }
}

TEST(Chen_schmitt, PlaneGivesZeroForEveryNormalChoice)
{
  // It alone may refuse a vertex, at the grid's corners (two or three directions).
  expect_zero_on_a_plane_with_every_normal_choice("chen_schmitt", chen_schmitt, true);
}

TEST(Chen_schmitt, ClosedSphereWithDefaultNormalsHasPositiveCurvatureOneOverRadius)
{
  expect_positive_one_over_radius_on_a_closed_sphere_with_default_normals("chen_schmitt", chen_schmitt);
}

TEST(Chen_schmitt, RandomPolynomialFansReproduceTheReferenceMedians)
{
  expect_reference_medians_on_random_polynomial_fans(
    {{"Chen-Schmitt", 0.885, 0.564, [](const Mesh& mesh, const Normal_map&) {
        return estimate(chen_schmitt, mesh,
                        params::vertex_normal_method(Vertex_normal_method::centroid_weighted)
                          .neighbor_weighting(Neighbor_weighting::uniform));
      }}});
}

TEST(Chen_schmitt, IsolatedAndNaNVerticesAreNotEstimableWithoutHarmingNeighbors)
{
  auto [mesh, isolated, broken] = ce_test::grid_with_isolated_and_nan_vertex<Mesh>();
  expect_isolated_and_nan_vertices_not_estimable("chen_schmitt", chen_schmitt, mesh, isolated, broken);
  // It refuses the weightings it does not define.
  for (Neighbor_weighting w : {Neighbor_weighting::area, Neighbor_weighting::centroid})
    EXPECT_THROW(CE::chen_schmitt_curvatures(mesh, params::neighbor_weighting(w)), std::invalid_argument);
}

#ifdef CGAL_LINKED_WITH_TBB
TEST(Chen_schmitt, SequentialAndParallelAreIdentical)
{
  expect_sequential_and_parallel_identical("chen_schmitt", chen_schmitt);
}
#endif

} // namespace
