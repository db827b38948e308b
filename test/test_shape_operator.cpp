// SPDX-License-Identifier: GPL-3.0-or-later
// Tests of internal/shape_operator.h: graph_curvature<N> against the closed-form
// curvatures of tilted graphs in R^3 and R^4.
#include "local_fit_inputs.h"

#include <gtest/gtest.h>

namespace {

using namespace ce_test::local_fit;

TEST(GraphCurvature, ClosedFormOfTiltedGraph)
{
  // graph_curvature<3> alone, with exact g and C: the curvatures of
  // z = g.x + 1/2 x^T C x at the origin.
  Random random(31);
  for (int trial = 0; trial < 200; ++trial) {
    const Mat<2, 2> c =
      symmetric_from<2>(separated_eigenvalues<2>(random, -3, 3, 0.2), rotation2(random.uniform(0, pi)));
    const Vec<2> g = random.in_cube<2>(trial < 100 ? 1.0 : 5.0);
    const Vec<3> n = trial == 0 ? Vec<3>::UnitZ() : random.unit_vector<3>();
    const Mat<3, 2> t = CEI::tangent_basis<3>(n);
    const CEI::Graph_curvature<3> gc = CEI::graph_curvature<3>(c, g, t, n);
    check_graph_curvature(gc, exact_graph_curvature(c, g, t, n), 1e-13, "closed form", trial);
  }
  // A concrete case worked by hand: the cylinder-like graph z = x + x^2/2 (g = (1,0),
  // C = diag(1,0)), n = e_z, T = [e_x e_y]: l = sqrt 2, G = diag(2,1), upward normal
  // curvature C_00 / (l G_00) = 1/(2 sqrt 2); library curvatures 0 and -1/(2 sqrt 2).
  Mat<2, 2> c;
  c << 1, 0, 0, 0;
  const Mat<3, 2> t = Mat<3, 2>::Identity();
  const CEI::Graph_curvature<3> gc = CEI::graph_curvature<3>(c, Vec<2>(1, 0), t, Vec<3>::UnitZ());
  EXPECT_NEAR(gc.curvatures[0], 0.0, 1e-15);
  EXPECT_NEAR(gc.curvatures[1], -1 / (2 * std::sqrt(2.0)), 1e-15);
  EXPECT_LE(distance_up_to_sign(gc.directions.col(0), Vec<3>(0, 1, 0)), 1e-15);
  EXPECT_LE(distance_up_to_sign(gc.directions.col(1), Vec<3>(1, 0, 1) / std::sqrt(2.0)), 1e-15);
  EXPECT_LE((gc.normal - Vec<3>(-1, 0, 1) / std::sqrt(2.0)).norm(), 1e-15);
}

TEST(HypersurfaceFit, GraphCurvatureWithGradient)
{
  // Graph of g.x + 1/2 x^T C x over a frame of R^4, x in R^3. The principal
  // curvatures kappa and parameter directions a solve C a = -kappa l G a,
  // G = I + g g^T; a = T^T d for the returned direction d (T^T n = 0). Checked
  // by the residual of that equation, the trace and the determinant:
  // sum kappa = -tr(G^-1 C)/l, prod kappa = -det(C)/l^5 (det G = l^2).
  Random random(52);
  for (int trial = 0; trial < 100; ++trial) {
    const Mat<3, 3> c = symmetric_from<3>(separated_eigenvalues<3>(random, -3, 3, 0.3), random.rotation<3>());
    const Vec<3> g = random.in_cube<3>();
    const Vec<4> n = random.unit_vector<4>();
    const Mat<4, 3> t = CEI::tangent_basis<4>(n);
    const CEI::Graph_curvature<4> gc = CEI::graph_curvature<4>(c, g, t, n);
    const double l = std::sqrt(1 + g.squaredNorm());
    const Mat<3, 3> metric = Mat<3, 3>::Identity() + g * g.transpose();
    for (int i = 0; i < 3; ++i) {
      const Vec<3> a = t.transpose() * gc.directions.col(i);
      // d is the tangent vector T a + n (g.a) of the graph
      EXPECT_LE((gc.directions.col(i) - (t * a + n * g.dot(a))).norm(), 1e-14);
      EXPECT_LE((c * a + gc.curvatures[i] * l * metric * a).norm(), 1e-13) << "trial " << trial;
    }
    const Mat<3, 3> metric_inverse = Mat<3, 3>::Identity() - g * g.transpose() / (l * l);
    EXPECT_NEAR(gc.curvatures.sum(), -(metric_inverse * c).trace() / l, 1e-13);
    EXPECT_NEAR(gc.curvatures.prod(), -c.determinant() / std::pow(l, 5), 1e-12);
    EXPECT_GE(gc.curvatures[0], gc.curvatures[1]);
    EXPECT_GE(gc.curvatures[1], gc.curvatures[2]);
    EXPECT_LE(orthonormality_error(gc.directions), 1e-14);
    EXPECT_LE((gc.directions.transpose() * gc.normal).cwiseAbs().maxCoeff(), 1e-14);
    Vec<4> expected_normal = (n - t * g) / l;
    EXPECT_LE((gc.normal - expected_normal).norm(), 1e-15);
  }
}

} // namespace
