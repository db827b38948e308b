// SPDX-License-Identifier: GPL-3.0-or-later
// Tests of internal/taylor_fit/: the Taylor fit of every order on exact
// polynomials in rotated frames, the scaled and whitened condition tests against
// an independent condition number, solving again, the curvature's quartic term
// and the weights. Every expected value is computed from the mathematics of the
// input, never from the code under test.
#include "local_fit_inputs.h"

#include <gtest/gtest.h>

namespace {

using namespace ce_test::local_fit;

// ---------------------------------------------------------------------------
// Hamann's fit Taylor_fit<2, 2, 2>
// ---------------------------------------------------------------------------

TEST(HamannFit, RecoversParaboloidAndCurvaturesInRotatedFrames)
{
  Random random(21);
  double worst_coefficient = 0, worst_curvature = 0, worst_direction = 0;
  for (int trial = 0; trial < 60; ++trial) {
    const int m = 6 + trial % 15; // 6..20 samples
    const Vec<2> lambda = separated_eigenvalues<2>(random, -3, 3, 0.2);
    const double theta = random.uniform(0, pi);
    const Mat<2, 2> eigenvectors = rotation2(theta);
    const Mat<2, 2> c = symmetric_from<2>(lambda, eigenvectors);
    const double a = c(0, 0), b = c(0, 1), cc = c(1, 1);
    const auto height = [&](const Vec<2>& x) {
      return 0.5 * (a * x[0] * x[0] + 2 * b * x[0] * x[1] + cc * x[1] * x[1]);
    };
    const std::vector<Vec<2>> xs = spread_stencil_2d(random, m);
    const Frame<3> frame = test_frame<3>(random, trial);
    const Vec<3> n = frame.normal();
    const Mat<3, 2> t = CEI::tangent_basis<3>(n);

    CEI::Taylor_fit<2, 2, 2> fit;
    add_samples(fit, xs, height, frame, t);
    EXPECT_EQ(fit.size(), m);
    ASSERT_TRUE(fit.solve(1e3)) << "trial " << trial << ", condition " << fit.condition_number();
    EXPECT_EQ(fit.gradient(), Vec<2>::Zero());

    // In the fit's frame the parameters are x' = Q x, Q = T^T R_2 (an orthogonal
    // 2x2 matrix, possibly a reflection), so the Hessian is Q C Q^T.
    const Mat<2, 2> q = t.transpose() * frame.tangents();
    ASSERT_LE(orthonormality_error(q), 1e-14);
    const Mat<2, 2> expected_hessian = q * c * q.transpose();
    const Mat<2, 2> back = q.transpose() * fit.hessian() * q; // a, b, c recovered
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j) {
        EXPECT_NEAR(fit.hessian()(i, j), expected_hessian(i, j), 1e-12) << "trial " << trial;
        worst_coefficient = (std::max)(worst_coefficient, std::abs(fit.hessian()(i, j) - expected_hessian(i, j)));
      }
    EXPECT_NEAR(back(0, 0), a, 1e-12) << "trial " << trial;
    EXPECT_NEAR(back(0, 1), b, 1e-12) << "trial " << trial;
    EXPECT_NEAR(back(1, 1), cc, 1e-12) << "trial " << trial;
    if (trial == 0) { // identity frame: T = [e_x e_y] exactly, the Hessian is [[a b][b c]] itself
      EXPECT_LE((fit.hessian() - c).cwiseAbs().maxCoeff(), 1e-12);
    }

    // Curvatures: -(eigenvalues of C), decreasing; directions R_2 (eigenvectors).
    const auto check_curvature = [&](const Mat<3, 2>& tangents, const char* what) {
      const CEI::Graph_curvature<3> gc = CEI::graph_curvature<3>(fit.hessian(), fit.gradient(), tangents, n);
      for (int i = 0; i < 2; ++i) {
        EXPECT_NEAR(gc.curvatures[i], -lambda[i], 1e-12) << what << ", trial " << trial;
        worst_curvature = (std::max)(worst_curvature, std::abs(gc.curvatures[i] + lambda[i]));
        const Vec<3> expected_direction = frame.tangents() * eigenvectors.col(i);
        const double e = distance_up_to_sign(gc.directions.col(i), expected_direction);
        EXPECT_LE(e, 1e-11) << what << ", trial " << trial << ", direction " << i;
        worst_direction = (std::max)(worst_direction, e);
        EXPECT_NEAR(gc.directions.col(i).norm(), 1.0, 1e-14);
        EXPECT_LE(std::abs(gc.directions.col(i).dot(n)), 1e-14);
      }
      EXPECT_GE(gc.curvatures[0], gc.curvatures[1]);
      EXPECT_LE(std::abs(gc.directions.col(0).dot(gc.directions.col(1))), 1e-14);
      EXPECT_LE((gc.normal - n).norm(), 1e-15);
    };
    check_curvature(t, "tangent_basis frame");

    // The same in a frame turned in the tangent plane (and one reflected): the
    // curvatures must not depend on the in-plane rotation of the frame.
    const Mat<3, 2> t_turned = t * rotation2(random.uniform(0, 2 * pi));
    Mat<2, 2> flip;
    flip << 0, 1, 1, 0;
    for (const Mat<3, 2>& other : {t_turned, Mat<3, 2>(t * flip)}) {
      CEI::Taylor_fit<2, 2, 2> fit2;
      add_samples(fit2, xs, height, frame, other);
      ASSERT_TRUE(fit2.solve(1e3));
      const Mat<2, 2> q2 = other.transpose() * frame.tangents();
      EXPECT_LE((fit2.hessian() - q2 * c * q2.transpose()).cwiseAbs().maxCoeff(), 1e-12);
      fit = fit2;
      check_curvature(other, "turned frame");
    }
  }
  std::cout << "Hamann fit: max |Hessian error| " << worst_coefficient << ", max |curvature error| " << worst_curvature
            << ", max direction error " << worst_direction << "\n";
}

TEST(HamannFit, PlaneGivesZeroCurvature)
{
  Random random(22);
  for (int trial = 0; trial < 40; ++trial) {
    const std::vector<Vec<2>> xs = spread_stencil_2d(random, 6 + trial % 15);
    const Frame<3> frame = test_frame<3>(random, trial);
    const Mat<3, 2> t = CEI::tangent_basis<3>(frame.normal());
    CEI::Taylor_fit<2, 2, 2> fit;
    add_samples(
      fit, xs, [](const Vec<2>&) { return 0.0; }, frame, t);
    ASSERT_TRUE(fit.solve(1e3)) << "trial " << trial;
    const CEI::Graph_curvature<3> gc = CEI::graph_curvature<3>(fit.hessian(), fit.gradient(), t, frame.normal());
    EXPECT_LE(gc.curvatures.cwiseAbs().maxCoeff(), 1e-14) << "trial " << trial;
    if (trial == 0) { // identity frame: every height is exactly 0
      EXPECT_EQ(gc.curvatures.cwiseAbs().maxCoeff(), 0.0);
    }
  }
}

// F = 1: the fit with linear terms through the vertex; F = 0: with a constant
// term too, on heights offset by a constant (the vertex is off the graph).
template <int F, int L>
void check_gradient_fit(std::uint32_t seed, double tolerance)
{
  Random random(seed);
  double worst = 0;
  for (int trial = 0; trial < 60; ++trial) {
    constexpr int unknowns = CEI::Taylor_fit<2, F, L>::unknowns;
    static_assert(unknowns == (F == 0 ? 1 : 0) + (L == 2   ? 5
                                                  : L == 3 ? 9
                                                           : 14),
                  "[1 constant +] 2 gradient + 3 Hessian [+ 4 cubic [+ 5 quartic]] unknowns");
    const int m = unknowns + 2 + trial % 10;
    const double offset = F == 0 ? random.uniform(-1, 1) : 0.0;
    const Mat<2, 2> c =
      symmetric_from<2>(separated_eigenvalues<2>(random, -3, 3, 0.2), rotation2(random.uniform(0, pi)));
    const Vec<2> g = random.in_cube<2>();
    std::array<double, 4> e{}; // cubic coefficients of x^3, x^2 y, x y^2, y^3
    std::array<double, 5> f{}; // quartic coefficients of x^4, x^3 y, x^2 y^2, x y^3, y^4
    if (L >= 3)
      for (double& coefficient : e)
        coefficient = random.uniform(-2, 2);
    if (L == 4)
      for (double& coefficient : f)
        coefficient = random.uniform(-2, 2);
    const auto height = [&](const Vec<2>& x) {
      const double u = x[0], v = x[1];
      return offset + g.dot(x) + 0.5 * x.dot(c * x) + e[0] * u * u * u + e[1] * u * u * v + e[2] * u * v * v +
             e[3] * v * v * v + f[0] * u * u * u * u + f[1] * u * u * u * v + f[2] * u * u * v * v +
             f[3] * u * v * v * v + f[4] * v * v * v * v;
    };
    const std::vector<Vec<2>> xs = spread_stencil_2d(random, m, 0.3, 1.0);
    const Frame<3> frame = test_frame<3>(random, trial);
    const Vec<3> n = frame.normal();
    const Mat<3, 2> t = CEI::tangent_basis<3>(n);
    CEI::Taylor_fit<2, F, L> fit;
    add_samples(fit, xs, height, frame, t);
    ASSERT_TRUE(fit.solve(L == 4 ? 1e8 : 1e5)) << "trial " << trial << ", condition " << fit.condition_number();

    const Mat<2, 2> q = t.transpose() * frame.tangents();
    const Vec<2> expected_gradient = q * g;
    const Mat<2, 2> expected_hessian = q * c * q.transpose();
    const double error = (std::max)((fit.gradient() - expected_gradient).cwiseAbs().maxCoeff(),
                                    (fit.hessian() - expected_hessian).cwiseAbs().maxCoeff());
    worst = (std::max)(worst, error);
    EXPECT_LE(error, tolerance) << "trial " << trial << ", condition " << fit.condition_number();

    // Curvatures of the graph from the exact g and C (any frame gives the same ones;
    // compute them in the fit's frame, with the exact coefficients).
    const CEI::Graph_curvature<3> gc = CEI::graph_curvature<3>(fit.hessian(), fit.gradient(), t, n);
    const Exact_graph_curvature exact = exact_graph_curvature(expected_hessian, expected_gradient, t, n);
    const std::string name = "Taylor_fit<2," + std::to_string(F) + "," + std::to_string(L) + ">";
    check_graph_curvature(gc, exact, 10 * tolerance, name.c_str(), trial);
    // ... and the normal is (n - T g) / l, which in the original frame is R (-g, 1) / l.
    Vec<3> upward;
    upward << -g, 1;
    EXPECT_LE((gc.normal - frame.rotation * upward / std::sqrt(1 + g.squaredNorm())).norm(), 10 * tolerance);
  }
  std::cout << "Taylor_fit<2," << F << "," << L << ">: max |gradient or Hessian error| " << worst << "\n";
}

TEST(GradientFit, QuadraticRecoversGradientHessianAndCurvatures) { check_gradient_fit<1, 2>(41, 1e-12); }

TEST(GradientFit, CubicRecoversGradientHessianAndCurvatures) { check_gradient_fit<1, 3>(42, 1e-11); }

TEST(GradientFit, QuarticRecoversGradientHessianAndCurvatures) { check_gradient_fit<1, 4>(44, 1e-9); }

TEST(ConstantTermFit, RecoversGradientHessianAndCurvaturesOfEveryDegreeOffTheVertex)
{
  check_gradient_fit<0, 2>(45, 1e-12);
  check_gradient_fit<0, 3>(46, 1e-11);
  check_gradient_fit<0, 4>(47, 1e-9);
}

TEST(GradientFit, SlopedPlaneGivesZeroCurvature)
{
  Random random(43);
  double worst_cubic = 0;
  for (int trial = 0; trial < 40; ++trial) {
    const Vec<2> g = random.in_cube<2>();
    const auto height = [&](const Vec<2>& x) { return g.dot(x); };
    const Frame<3> frame = test_frame<3>(random, trial);
    const Mat<3, 2> t = CEI::tangent_basis<3>(frame.normal());
    const Mat<2, 2> q = t.transpose() * frame.tangents();

    CEI::Taylor_fit<2, 1, 2> quadratic;
    add_samples(quadratic, spread_stencil_2d(random, 8 + trial % 10), height, frame, t);
    ASSERT_TRUE(quadratic.solve(1e3)) << "trial " << trial;
    const CEI::Graph_curvature<3> gc =
      CEI::graph_curvature<3>(quadratic.hessian(), quadratic.gradient(), t, frame.normal());
    EXPECT_LE(gc.curvatures.cwiseAbs().maxCoeff(), 1e-14) << "trial " << trial;
    EXPECT_LE((quadratic.gradient() - q * g).cwiseAbs().maxCoeff(), 1e-14) << "trial " << trial;

    CEI::Taylor_fit<2, 1, 3> cubic;
    add_samples(cubic, spread_stencil_2d(random, 12 + trial % 10), height, frame, t);
    ASSERT_TRUE(cubic.solve(1e5)) << "trial " << trial;
    const CEI::Graph_curvature<3> gc3 = CEI::graph_curvature<3>(cubic.hessian(), cubic.gradient(), t, frame.normal());
    // The cubic fit's condition numbers are 1e2..1e4 here, its rounding noise larger.
    EXPECT_LE(gc3.curvatures.cwiseAbs().maxCoeff(), 1e-13)
      << "trial " << trial << ", condition " << cubic.condition_number();
    worst_cubic = (std::max)(worst_cubic, gc3.curvatures.cwiseAbs().maxCoeff());

    // And Hamann's fit of the level plane through the same frame (h = 0).
    CEI::Taylor_fit<2, 2, 2> level;
    add_samples(
      level, spread_stencil_2d(random, 6), [](const Vec<2>&) { return 0.0; }, frame, t);
    ASSERT_TRUE(level.solve(1e3));
    EXPECT_LE(level.hessian().cwiseAbs().maxCoeff(), 1e-14);
  }
  std::cout << "sloped plane, Taylor_fit<2,1,3>: max |curvature| " << worst_cubic << "\n";
}

// ---------------------------------------------------------------------------
// The hypersurface core, D = 3
// ---------------------------------------------------------------------------

TEST(HypersurfaceFit, RecoversHessianAndThreeCurvatures)
{
  Random random(51);
  double worst_hessian = 0, worst_curvature = 0;
  for (int trial = 0; trial < 60; ++trial) {
    const Vec<3> lambda = separated_eigenvalues<3>(random, -3, 3, 0.3);
    const Mat<3, 3> eigenvectors = random.rotation<3>();
    const Mat<3, 3> c = symmetric_from<3>(lambda, eigenvectors);
    const auto height = [&](const Vec<3>& x) { return 0.5 * x.dot(c * x); };
    const std::vector<Vec<3>> xs = spread_stencil_3d(random, 12 + trial % 9);
    const Frame<4> frame = test_frame<4>(random, trial);
    const Vec<4> n = frame.normal();
    const Mat<4, 3> t = CEI::tangent_basis<4>(n);

    CEI::Taylor_fit<3, 2, 2> fit;
    static_assert(CEI::Taylor_fit<3, 2, 2>::unknowns == 6, "6 Hessian coefficients");
    add_samples(fit, xs, height, frame, t);
    ASSERT_TRUE(fit.solve(1e3)) << "trial " << trial << ", condition " << fit.condition_number();
    const Mat<3, 3> q = t.transpose() * frame.tangents();
    ASSERT_LE(orthonormality_error(q), 1e-14);
    const double hessian_error = (fit.hessian() - q * c * q.transpose()).cwiseAbs().maxCoeff();
    EXPECT_LE(hessian_error, 1e-12) << "trial " << trial;
    EXPECT_EQ(fit.hessian(), fit.hessian().transpose());
    worst_hessian = (std::max)(worst_hessian, hessian_error);

    const CEI::Graph_curvature<4> gc = CEI::graph_curvature<4>(fit.hessian(), fit.gradient(), t, n);
    for (int i = 0; i < 3; ++i) {
      EXPECT_NEAR(gc.curvatures[i], -lambda[i], 1e-12) << "trial " << trial;
      worst_curvature = (std::max)(worst_curvature, std::abs(gc.curvatures[i] + lambda[i]));
      EXPECT_LE(distance_up_to_sign(gc.directions.col(i), frame.tangents() * eigenvectors.col(i)), 1e-11)
        << "trial " << trial << ", direction " << i;
    }
    EXPECT_GE(gc.curvatures[0], gc.curvatures[1]);
    EXPECT_GE(gc.curvatures[1], gc.curvatures[2]);
    EXPECT_LE(orthonormality_error(gc.directions), 1e-14) << "trial " << trial;
    EXPECT_LE((gc.directions.transpose() * n).cwiseAbs().maxCoeff(), 1e-14) << "trial " << trial;
    EXPECT_LE((gc.normal - n).norm(), 1e-15);
  }
  std::cout << "Taylor_fit<3,2,2>: max |Hessian error| " << worst_hessian << ", max |curvature error| "
            << worst_curvature << "\n";
}

// ---------------------------------------------------------------------------
// Conditioning
// ---------------------------------------------------------------------------

TEST(Conditioning, SamplesOnALineThroughTheOriginAreRejected)
{
  // Points on the paraboloid above the line t d (t on both sides and one-sided),
  // in the frame of the paraboloid's own normal e_z: the parameters t d lie on a
  // line, the quadratic monomials t^2 (d_x^2/2, d_x d_y, d_y^2/2) are proportional.
  const Vec<3> d(std::cos(0.5), std::sin(0.5), 0);
  const std::vector<std::vector<double>> parameter_sets = {{-1, -0.6, -0.3, 0.3, 0.6, 1},
                                                           {0.2, 0.4, 0.6, 0.8, 1.0, 1.2, 1.4, 1.6, 1.8, 2.0}};
  for (const auto& ts : parameter_sets) {
    CEI::Taylor_fit<2, 2, 2> hamann;
    CEI::Taylor_fit<2, 1, 2> quadratic;
    CEI::Taylor_fit<2, 1, 3> cubic;
    const Vec<3> n = Vec<3>::UnitZ();
    const Mat<3, 2> t = CEI::tangent_basis<3>(n);
    for (double s : ts) {
      const Vec<3> p = s * d + 0.5 * s * s * n;
      hamann.add(t.transpose() * p, n.dot(p));
      quadratic.add(t.transpose() * p, n.dot(p));
      cubic.add(t.transpose() * p, n.dot(p));
    }
    EXPECT_FALSE(hamann.solve(1e3)) << "condition " << hamann.condition_number();
    EXPECT_FALSE(quadratic.solve(1e3)) << "condition " << quadratic.condition_number();
    EXPECT_FALSE(cubic.solve(1e5)) << "condition " << cubic.condition_number();
    // Even a huge threshold does not accept them: the matrix is singular up to rounding.
    EXPECT_FALSE(hamann.solve(1e12)) << "condition " << hamann.condition_number();
    std::cout << "line stencil (" << ts.size() << " samples): condition numbers " << hamann.condition_number()
              << " (Hamann), " << quadratic.condition_number() << " (degree 2), " << cubic.condition_number()
              << " (degree 3)\n";
  }
}

TEST(Conditioning, TiltedLineStencilIsIllConditioned)
{
  // The same curve of samples, seen in the frame of a normal tilted by a small
  // angle about the line's direction: their projections now lie on a curve, the
  // normal matrix is regular, but nearly singular; it must not be accepted.
  const std::vector<double> ts = {-1, -0.75, -0.5, 0.25, 0.5, 0.75, 1};
  for (double angle : {0.5, 1.2}) {
    const Vec<3> d(std::cos(angle), std::sin(angle), 0);
    for (double tilt : {1e-2, 1e-3}) {
      const Vec<3> n = rotation3(d, tilt) * Vec<3>::UnitZ();
      const Mat<3, 2> t = CEI::tangent_basis<3>(n);
      CEI::Taylor_fit<2, 2, 2> fit;
      std::vector<Vec<2>> xs;
      for (double s : ts) {
        const Vec<3> p = s * d + 0.5 * s * s * Vec<3>::UnitZ();
        xs.push_back(t.transpose() * p);
        fit.add(xs.back(), n.dot(p));
      }
      EXPECT_FALSE(fit.solve(1e3));
      const double condition = fit.condition_number();
      std::cout << "line at " << angle << " rad from e_x, tilt " << tilt << ": condition number " << condition
                << " (independent: " << static_cast<double>(independent_condition<2>(xs, 2, 2)) << ")\n";
      EXPECT_GT(condition, 1e5) << "angle " << angle << ", tilt " << tilt;
    }
  }
}

// A line of samples along a frame axis, tilted by 1e-2: the same stencil as
// above turned in the tangent plane. Scaling the normal matrix to a unit
// diagonal would remove exactly the factors that make it nearly singular (it
// gave a condition number of 38, an accepted fit and a curvature of -1e4 across
// the line on a unit sphere); the rotation-covariant coordinates do not.
TEST(Conditioning, TiltedLineStencilAlongAFrameAxisIsIllConditioned)
{
  const Vec<3> d = Vec<3>::UnitX();
  const Vec<3> n = rotation3(d, 1e-2) * Vec<3>::UnitZ();
  const Mat<3, 2> t = CEI::tangent_basis<3>(n);
  CEI::Taylor_fit<2, 2, 2> fit;
  for (double s : {-1.0, -0.75, -0.5, 0.25, 0.5, 0.75, 1.0}) {
    // a great circle of the unit sphere through the origin, centre e_z
    const Vec<3> p = std::sin(s) * d + (1 - std::cos(s)) * Vec<3>::UnitZ();
    fit.add(t.transpose() * p, n.dot(p));
  }
  const bool accepted = fit.solve(1e3);
  std::cout << "line along a frame axis, tilt 1e-2: condition number " << fit.condition_number() << "\n";
  EXPECT_GT(fit.condition_number(), 1e5);
  EXPECT_FALSE(accepted) << "accepted with curvatures "
                         << CEI::graph_curvature<3>(fit.hessian(), fit.gradient(), t, n).curvatures.transpose()
                         << " (exact: -1 -1)";
}

TEST(Conditioning, FewerSamplesThanUnknownsAreRejected)
{
  Random random(61);
  const auto height = [](const Vec<2>& x) { return x.squaredNorm(); };
  const auto run = [&](auto fit, int count) {
    for (const Vec<2>& x : spread_stencil_2d(random, count))
      fit.add(x, height(x));
    EXPECT_FALSE(fit.solve(1e300)) << count << " samples, " << decltype(fit)::unknowns << " unknowns";
    EXPECT_EQ(fit.condition_number(), std::numeric_limits<double>::infinity());
  };
  run(CEI::Taylor_fit<2, 2, 2>(), 2);
  run(CEI::Taylor_fit<2, 1, 2>(), 4);
  run(CEI::Taylor_fit<2, 1, 3>(), 8);
  // And nothing at all.
  CEI::Taylor_fit<2, 2, 2> empty;
  EXPECT_FALSE(empty.solve(1e300));
  CEI::Taylor_fit<3, 2, 2> hyper;
  for (const Vec<3>& x : spread_stencil_3d(random, 5))
    hyper.add(x, x.squaredNorm());
  EXPECT_FALSE(hyper.solve(1e300));
}

TEST(Conditioning, Valence6StencilIsWellConditioned)
{
  // The 6 neighbors of a valence-6 vertex of a triangulated grid.
  const std::vector<Vec<2>> xs = {Vec<2>(1, 0),  Vec<2>(-1, 0), Vec<2>(0, 1),
                                  Vec<2>(0, -1), Vec<2>(1, -1), Vec<2>(-1, 1)};
  CEI::Taylor_fit<2, 2, 2> fit;
  for (const Vec<2>& x : xs)
    fit.add(x, 0.5 * (0.3 * x[0] * x[0] - 2 * 0.2 * x[0] * x[1] + 0.7 * x[1] * x[1]));
  ASSERT_TRUE(fit.solve(1e3));
  // By hand: with rows (u^2/2, uv/sqrt 2, v^2/2) the normal matrix is
  // S = [[1 -r 1/2][-r 1 -r][1/2 -r 1]], r = 1/sqrt 2, det S = 1/4,
  // S^-1 = [[2 2r 0][2r 3 2r][0 2r 2]]; ||S||_1 = 1 + sqrt 2, ||S^-1||_1 = 3 + 2 sqrt 2,
  // so the condition number is (1 + sqrt 2)^3 = 14.071...
  const double expected = std::pow(1 + std::sqrt(2.0), 3);
  EXPECT_NEAR(fit.condition_number(), expected, 1e-12 * expected);
  const long double r = 1 / std::sqrt(2.0L);
  EXPECT_NEAR(static_cast<double>(one_norm_condition({{1, -r, 0.5L}, {-r, 1, -r}, {0.5L, -r, 1}})), expected,
              1e-12 * expected);
  EXPECT_NEAR(fit.condition_number(), static_cast<double>(independent_condition<2>(xs, 2, 2)),
              1e-12 * fit.condition_number());
  EXPECT_LT(fit.condition_number(), 100);
  std::cout << "valence-6 stencil: condition number " << fit.condition_number() << "\n";
  EXPECT_NEAR(fit.hessian()(0, 0), 0.3, 1e-15);
  EXPECT_NEAR(fit.hessian()(0, 1), -0.2, 1e-15);
  EXPECT_NEAR(fit.hessian()(1, 1), 0.7, 1e-15);
}

template <int D, int F, int L>
void check_condition_against_independent(Random& random, int trials)
{
  for (int trial = 0; trial < trials; ++trial) {
    std::vector<Vec<D>> xs;
    const int m = CEI::Taylor_fit<D, F, L>::unknowns + 1 + trial % 8;
    if constexpr (D == 2)
      xs = spread_stencil_2d(random, m, 0.2, 1.0);
    else
      xs = spread_stencil_3d(random, m, 0.2);
    CEI::Taylor_fit<D, F, L> fit;
    for (const Vec<D>& x : xs)
      fit.add(x, random.uniform(-1, 1));
    fit.solve(1e300);
    const double expected = static_cast<double>(independent_condition<D>(xs, F, L));
    EXPECT_NEAR(fit.condition_number(), expected, 1e-9 * expected)
      << "Taylor_fit<" << D << "," << F << "," << L << ">, trial " << trial;
  }
}

TEST(Conditioning, ConditionNumberIsTheOneNormConditionInOrthonormalTensorCoordinates)
{
  Random random(62);
  check_condition_against_independent<2, 2, 2>(random, 30);
  check_condition_against_independent<2, 1, 2>(random, 30);
  check_condition_against_independent<2, 1, 3>(random, 30);
  check_condition_against_independent<3, 2, 2>(random, 30);
  check_condition_against_independent<3, 1, 2>(random, 30);
}

template <int F, int L>
void check_scale_invariance(Random& random)
{
  for (int trial = 0; trial < 10; ++trial) {
    const std::vector<Vec<2>> xs = spread_stencil_2d(random, CEI::Taylor_fit<2, F, L>::unknowns + 3, 0.3, 1.0);
    const Mat<2, 2> c =
      symmetric_from<2>(separated_eigenvalues<2>(random, -3, 3, 0.2), rotation2(random.uniform(0, pi)));
    const Vec<2> g = F == 1 ? Vec<2>(random.in_cube<2>()) : Vec<2>::Zero();
    const double e = L == 3 ? random.uniform(-1, 1) : 0.0;
    const auto height = [&](const Vec<2>& x) { return g.dot(x) + 0.5 * x.dot(c * x) + e * x[0] * x[0] * x[1]; };
    CEI::Taylor_fit<2, F, L> unit;
    for (const Vec<2>& x : xs)
      unit.add(x, height(x));
    ASSERT_TRUE(unit.solve(1e5));
    for (double s : {1e-6, 1e6}) {
      // The same surface scaled by s: samples (s x, s h(x)); gradient unchanged, Hessian / s.
      CEI::Taylor_fit<2, F, L> scaled;
      for (const Vec<2>& x : xs)
        scaled.add(s * x, s * height(x));
      // Every entry of a single-order normal matrix scales by the same power of s;
      // mixed orders do not, which is why the estimators scale the samples to the
      // mean 1-ring edge before fitting.
      ASSERT_TRUE(scaled.solve(1e300)) << "scale " << s;
      if (F == 2 && L == 2) {
        EXPECT_NEAR(scaled.condition_number(), unit.condition_number(), 1e-9 * unit.condition_number())
          << "scale " << s;
      }
      EXPECT_LE((scaled.hessian() * s - c).cwiseAbs().maxCoeff(), 1e-11) << "scale " << s;
      EXPECT_LE((scaled.gradient() - g).cwiseAbs().maxCoeff(), 1e-11) << "scale " << s;
    }
  }
}

TEST(Conditioning, ScalingTheSamplesScalesTheFitAndKeepsASingleOrderConditionNumber)
{
  Random random(63);
  check_scale_invariance<2, 2>(random);
  check_scale_invariance<1, 2>(random);
  check_scale_invariance<1, 3>(random);
}

template <int F, int L>
void check_rotation(Random& random)
{
  constexpr int n = CEI::Taylor_fit<2, F, L>::unknowns;
  for (int trial = 0; trial < 20; ++trial) {
    const std::vector<Vec<2>> xs = spread_stencil_2d(random, n + 2 + trial % 6, 0.2, 1.0);
    CEI::Taylor_fit<2, F, L> fit, turned;
    const Mat<2, 2> r = rotation2(random.uniform(0, 2 * pi));
    for (const Vec<2>& x : xs) {
      fit.add(x, 0);
      turned.add(r * x, 0);
    }
    fit.solve(1e300);
    turned.solve(1e300);
    // Each order's block turns by an orthogonal matrix: the 2-norm condition is
    // unchanged, and the 1-norm one is within a factor n of it.
    EXPECT_LE(turned.condition_number(), n * n * fit.condition_number()) << "trial " << trial;
    EXPECT_LE(fit.condition_number(), n * n * turned.condition_number()) << "trial " << trial;
  }
}

TEST(Conditioning, TurningTheFrameInTheTangentPlaneChangesTheConditionNumberByBoundedFactor)
{
  Random random(64);
  check_rotation<2, 2>(random);
  check_rotation<1, 2>(random);
  check_rotation<1, 3>(random);
}

// ---------------------------------------------------------------------------
// Whitened conditioning: Taylor_fit::solve_whitened, test (b) of quadric_fit.h
// ---------------------------------------------------------------------------

// The samples of a fit, kept to be added again by Taylor_fit::solve_whitened.
template <int D>
struct Samples
{
  std::vector<Vec<D>> x;
  std::vector<double> height;

  void push(const Vec<D>& p, double h)
  {
    x.push_back(p);
    height.push_back(h);
  }

  template <typename Add>
  void operator()(const Add& add) const
  {
    for (std::size_t i = 0; i < x.size(); ++i)
      add(x[i], height[i], 1.0);
  }

  // The fit of these samples after test (a) (`scaled`: whether it accepted) and
  // then test (b) (`whitened`), which leaves the fit's solution.
  template <typename Fit>
  Fit fit(double max_condition, bool& scaled, bool& whitened) const
  {
    Fit fit;
    (*this)([&](const Vec<D>& p, double h, double w) { fit.add(p, h, w); });
    scaled = fit.solve(max_condition);
    whitened = fit.solve_whitened(max_condition, *this);
    return fit;
  }

  // Whether test (b) accepts, and its condition number.
  template <typename Fit>
  bool whitened(double max_condition, double& condition) const
  {
    bool scaled = false, accepted = false;
    condition = fit<Fit>(max_condition, scaled, accepted).whitened_condition_number();
    return accepted;
  }
};

// The orders of a Taylor_fit<D, F, L>, and the six fits of the estimators
// (Hamann's, the normal's, the boundary normal's cubic one; D = 2 and 3).
template <int D, int F, int L>
struct Orders
{};

template <typename Check>
void for_each_fit(const Check& check)
{
  check(Orders<2, 2, 2>());
  check(Orders<2, 1, 2>());
  check(Orders<2, 1, 3>());
  check(Orders<3, 2, 2>());
  check(Orders<3, 1, 2>());
  check(Orders<3, 1, 3>());
}

// A D x D matrix R diag(stretch, 1, ...) Q: a rotation Q, a stretch along the
// first axis, then another rotation R (an anisotropic 1-ring, turned).
template <int D>
Mat<D, D> stretch_map(Random& random, double stretch)
{
  Mat<D, D> s = Mat<D, D>::Identity();
  s(0, 0) = stretch;
  return random.rotation<D>() * s * random.rotation<D>();
}

// The samples mapped by `a` and scaled to a unit mean length, as the estimators scale them.
template <int D>
std::vector<Vec<D>> mapped(const std::vector<Vec<D>>& xs, const Mat<D, D>& a)
{
  std::vector<Vec<D>> out;
  double length = 0;
  for (const Vec<D>& x : xs) {
    out.push_back(a * x);
    length += out.back().norm();
  }
  for (Vec<D>& x : out)
    x /= length / double(xs.size());
  return out;
}

// solve decides test (a) by cheaper upper bounds of the condition number where
// they are below the threshold (quadric_fit.h, Cost): a bound below the number
// would accept fits that the number refuses. Its decisions must be those of the
// number, just above and below it and far from it, on stencils stretched by up
// to 10 (numbers from about 10 to 1e10).
template <int F, int L>
void check_decisions_are_those_of_the_condition_number(Random& random, int trials)
{
  using Fit = CEI::Taylor_fit<2, F, L>;
  for (int trial = 0; trial < trials; ++trial) {
    const int m = Fit::unknowns + 2 + trial % 20;
    const std::vector<Vec<2>> xs =
      mapped<2>(spread_stencil_2d(random, m, 0.2, 1.0), stretch_map<2>(random, std::pow(10.0, random.uniform(0, 1))));
    Fit fit;
    const auto accepts = [&](double max_condition) {
      fit.clear();
      for (const Vec<2>& x : xs)
        fit.add(x, 1.0 + x[0] * x[1]);
      return fit.solve(max_condition);
    };
    ASSERT_TRUE(accepts(1e300)) << "Taylor_fit<2," << F << "," << L << ">, trial " << trial;
    const double condition = fit.condition_number();
    for (double factor : {1 + 1e-9, 2.0, 1e3})
      EXPECT_TRUE(accepts(factor * condition)) << "Taylor_fit<2," << F << "," << L << ">, trial " << trial;
    for (double factor : {1 - 1e-9, 0.5, 1e-3})
      EXPECT_FALSE(accepts(factor * condition)) << "Taylor_fit<2," << F << "," << L << ">, trial " << trial;
  }
}

TEST(Conditioning, SolveAcceptsExactlyWhereTheConditionNumberIsAtMostTheThreshold)
{
  Random random(63);
  check_decisions_are_those_of_the_condition_number<2, 2>(random, 100);
  check_decisions_are_those_of_the_condition_number<1, 2>(random, 100);
  check_decisions_are_those_of_the_condition_number<1, 3>(random, 100);
  check_decisions_are_those_of_the_condition_number<1, 4>(random, 100);
}

template <int D>
std::vector<Vec<D>> spread_stencil(Random& random, int m)
{
  if constexpr (D == 2)
    return spread_stencil_2d(random, m, 0.3, 1.0);
  else
    return spread_stencil_3d(random, m, 0.3);
}

// A Taylor polynomial of orders F..L with random coefficients: g.x + 1/2 x^T C x + sum e_ijk x_i x_j x_k.
template <int D>
struct Polynomial
{
  Vec<D> g = Vec<D>::Zero();
  Mat<D, D> c = Mat<D, D>::Zero();
  std::vector<std::array<int, 3>> cubic_terms;
  std::vector<double> cubic_coefficients;

  Polynomial(Random& random, int first_order, int last_order)
  {
    c = symmetric_from<D>(separated_eigenvalues<D>(random, -3, 3, 0.2), random.rotation<D>());
    if (first_order == 1)
      g = random.in_cube<D>();
    if (last_order == 3)
      for (int i = 0; i < D; ++i)
        for (int j = i; j < D; ++j)
          for (int k = j; k < D; ++k) {
            cubic_terms.push_back({i, j, k});
            cubic_coefficients.push_back(random.uniform(-2, 2));
          }
  }

  double operator()(const Vec<D>& x) const
  {
    double h = g.dot(x) + 0.5 * x.dot(c * x);
    for (std::size_t t = 0; t < cubic_terms.size(); ++t)
      h += cubic_coefficients[t] * x[cubic_terms[t][0]] * x[cubic_terms[t][1]] * x[cubic_terms[t][2]];
    return h;
  }
};

// The condition number of Hamann's quadratic terms alone in whitened coordinates,
// computed here (long double, Cholesky whitening by Eigen): what test (b) would
// measure without the linear terms.
long double whitened_quadratic_only_condition(const std::vector<Vec<2>>& xs)
{
  Mat<2, 2> m = Mat<2, 2>::Zero();
  for (const Vec<2>& x : xs)
    m += x * x.transpose();
  m *= 2.0 / double(xs.size());
  const Mat<2, 2> w = Eigen::LLT<Mat<2, 2>>(m).matrixL().solve(Mat<2, 2>::Identity());
  std::vector<Vec<2>> ys;
  for (const Vec<2>& x : xs)
    ys.push_back(w * x);
  return independent_condition<2>(ys, 2, 2);
}

// Rounding bound of a fit accepted by test (b) on a stencil stretched by 100:
// the coefficients across the stretch are those fitted in y (error a few machine
// epsilons times cond_1(N_y)) times the stretch squared.
double stretched_fit_tolerance(double whitened_condition) { return 1e-15 * whitened_condition * 100 * 100; }

// A stencil stretched by 100 and turned is refused by test (a) and accepted by
// test (b), which recovers the polynomial exactly: the least-squares problem is
// well-posed, only its coordinates are skewed.
template <int D, int F, int L>
void check_stretched_stencil(Random& random, Orders<D, F, L>)
{
  using Fit = CEI::Taylor_fit<D, F, L>;
  constexpr double n2 = double(Fit::tested) * Fit::tested;
  double worst = 0, least_scaled = std::numeric_limits<double>::infinity(), worst_whitened = 0;
  for (int trial = 0; trial < 20; ++trial) {
    const std::vector<Vec<D>> ring = spread_stencil<D>(random, 2 * Fit::tested + trial % 6);
    const Polynomial<D> h(random, F, L);
    Samples<D> stretched, round;
    for (const Vec<D>& x : mapped<D>(ring, stretch_map<D>(random, 100)))
      stretched.push(x, h(x));
    for (const Vec<D>& x : mapped<D>(ring, Mat<D, D>::Identity()))
      round.push(x, h(x));
    bool scaled = true, whitened = false;
    // The estimators' thresholds: 1e3, and 1000 times more for the cubic fit (see platelet_fit.h).
    const Fit fit = stretched.template fit<Fit>(L == 3 ? 1e6 : 1e3, scaled, whitened);
    EXPECT_FALSE(scaled) << "trial " << trial;
    EXPECT_GT(fit.condition_number(), 1e6) << "trial " << trial;
    ASSERT_TRUE(whitened) << "trial " << trial << ", whitened condition " << fit.whitened_condition_number();
    least_scaled = (std::min)(least_scaled, fit.condition_number());
    worst_whitened = (std::max)(worst_whitened, fit.whitened_condition_number());
    const double scale = (std::max)(h.c.cwiseAbs().maxCoeff(), h.g.cwiseAbs().maxCoeff());
    const double error =
      (std::max)((fit.hessian() - h.c).cwiseAbs().maxCoeff(), (fit.gradient() - h.g).cwiseAbs().maxCoeff()) / scale;
    EXPECT_LE(error, stretched_fit_tolerance(fit.whitened_condition_number())) << "trial " << trial;
    worst = (std::max)(worst, error);

    // The unstretched ring has the same whitened condition, to the factor n^2 of an orthogonal turn.
    double round_condition = 0;
    ASSERT_TRUE(round.template whitened<Fit>(1e300, round_condition));
    EXPECT_LE(fit.whitened_condition_number(), n2 * round_condition) << "trial " << trial;
    EXPECT_LE(round_condition, n2 * fit.whitened_condition_number()) << "trial " << trial;
  }
  std::cout << "Taylor_fit<" << D << "," << F << "," << L
            << ">, 1-rings stretched by 100: condition (a) >= " << least_scaled << ", (b) <= " << worst_whitened
            << ", max relative coefficient error " << worst << "\n";
}

TEST(WhitenedConditioning, StretchedStencilIsAcceptedWithTheExactPolynomial)
{
  Random random(81);
  for_each_fit([&](auto orders) { check_stretched_stencil(random, orders); });
}

TEST(WhitenedConditioning, StretchedStencilOnAParaboloidGivesItsExactCurvatures)
{
  // Hamann's fit over a paraboloid placed in R^3 by a random frame: the
  // curvatures are minus the eigenvalues of its Hessian, the directions their
  // eigenvectors (as in HamannFit.RecoversParaboloidAndCurvaturesInRotatedFrames).
  Random random(82);
  for (int trial = 0; trial < 40; ++trial) {
    const Vec<2> lambda = separated_eigenvalues<2>(random, -3, 3, 0.2);
    const Mat<2, 2> eigenvectors = rotation2(random.uniform(0, pi));
    const Mat<2, 2> c = symmetric_from<2>(lambda, eigenvectors);
    const std::vector<Vec<2>> xs = mapped<2>(spread_stencil_2d(random, 6 + trial % 6), stretch_map<2>(random, 100));
    const Frame<3> frame = test_frame<3>(random, trial);
    const Vec<3> n = frame.normal();
    const Mat<3, 2> t = CEI::tangent_basis<3>(n);
    Samples<2> samples;
    for (const Vec<2>& x : xs) {
      Vec<3> local;
      local << x, 0.5 * x.dot(c * x);
      const Vec<3> q = frame.rotation * local;
      samples.push(t.transpose() * q, n.dot(q));
    }
    bool scaled = true, whitened = false;
    const CEI::Taylor_fit<2, 2, 2> fit = samples.fit<CEI::Taylor_fit<2, 2, 2>>(1e3, scaled, whitened);
    EXPECT_FALSE(scaled) << "trial " << trial;
    ASSERT_TRUE(whitened) << "trial " << trial << ", whitened condition " << fit.whitened_condition_number();
    const CEI::Graph_curvature<3> gc = CEI::graph_curvature<3>(fit.hessian(), fit.gradient(), t, n);
    for (int i = 0; i < 2; ++i) {
      const double tolerance = stretched_fit_tolerance(fit.whitened_condition_number());
      EXPECT_NEAR(gc.curvatures[i], -lambda[i], tolerance) << "trial " << trial;
      // Eigenvalues at least 0.2 apart: the directions are as accurate, over the gap.
      EXPECT_LE(distance_up_to_sign(gc.directions.col(i), frame.tangents() * eigenvectors.col(i)), tolerance / 0.2)
        << "trial " << trial << ", direction " << i;
    }
  }
}

template <int F, int L>
void check_same_solution(Random& random)
{
  using Fit = CEI::Taylor_fit<2, F, L>;
  for (int trial = 0; trial < 20; ++trial) {
    // Noisy heights: a true least-squares fit, not an interpolation.
    Samples<2> samples;
    for (const Vec<2>& x : spread_stencil_2d(random, Fit::tested + 3 + trial % 5, 0.3, 1.0))
      samples.push(x, random.uniform(-1, 1));
    Fit scaled;
    samples([&](const Vec<2>& x, double h, double w) { scaled.add(x, h, w); });
    ASSERT_TRUE(scaled.solve(1e6));
    bool accepted = false, whitened = false;
    const Fit fit = samples.fit<Fit>(1e6, accepted, whitened);
    ASSERT_TRUE(whitened);
    const double size = (std::max)(1.0, scaled.hessian().cwiseAbs().maxCoeff());
    EXPECT_LE((fit.hessian() - scaled.hessian()).cwiseAbs().maxCoeff(), 1e-12 * size) << "trial " << trial;
    EXPECT_LE((fit.gradient() - scaled.gradient()).cwiseAbs().maxCoeff(), 1e-12 * size) << "trial " << trial;
  }
}

TEST(WhitenedConditioning, SolutionIsThatOfTheScaledCoordinatesWhereBothTestsAccept)
{
  Random random(83);
  check_same_solution<2, 2>(random);
  check_same_solution<1, 2>(random);
  check_same_solution<1, 3>(random);
}

template <int D, int F, int L>
void check_linear_invariance(Random& random, Orders<D, F, L>)
{
  using Fit = CEI::Taylor_fit<D, F, L>;
  constexpr double n2 = double(Fit::tested) * Fit::tested;
  for (int trial = 0; trial < 20; ++trial) {
    const std::vector<Vec<D>> xs = spread_stencil<D>(random, Fit::tested + 1 + trial % 8);
    // Singular values from 1 to 1001 between two rotations.
    const Vec<D> stretches = random.in_cube<D>().cwiseAbs() * 1e3 + Vec<D>::Ones();
    const Mat<D, D> a = random.rotation<D>() * stretches.asDiagonal() * random.rotation<D>();
    Samples<D> original, changed, scaled;
    for (const Vec<D>& x : xs) {
      original.push(x, 0);
      changed.push(a * x, 0);
      scaled.push(1e-6 * x, 0);
    }
    double c_original = 0, c_changed = 0, c_scaled = 0;
    ASSERT_TRUE(original.template whitened<Fit>(1e300, c_original));
    ASSERT_TRUE(changed.template whitened<Fit>(1e300, c_changed));
    ASSERT_TRUE(scaled.template whitened<Fit>(1e300, c_scaled));
    EXPECT_LE(c_changed, n2 * c_original) << "trial " << trial;
    EXPECT_LE(c_original, n2 * c_changed) << "trial " << trial;
    // Whitening removes the scale too, also from fits of several orders.
    EXPECT_NEAR(c_scaled, c_original, 1e-9 * c_original) << "trial " << trial;
  }
}

TEST(WhitenedConditioning, InvariantUnderLinearMapsOfTheTangentSpace)
{
  Random random(84);
  for_each_fit([&](auto orders) { check_linear_invariance(random, orders); });
}

TEST(WhitenedConditioning, WideningAStretchedGridLowersItButNotTheScaledCondition)
{
  // The k-rings of the triangulated grid (diagonals (i+1, j)-(i, j+1)):
  // max(|i|, |j|, |i + j|) <= k. Stretched by 100 and turned, in units of the
  // mean 1-ring edge, as the estimators see them.
  Random random(85);
  const Mat<2, 2> a = stretch_map<2>(random, 100);
  double one_ring_length = 0;
  for (const Vec<2>& x : {Vec<2>(1, 0), Vec<2>(-1, 0), Vec<2>(0, 1), Vec<2>(0, -1), Vec<2>(1, -1), Vec<2>(-1, 1)})
    one_ring_length += (a * x).norm() / 6;
  double previous = std::numeric_limits<double>::infinity();
  for (int k = 1; k <= 3; ++k) {
    Samples<2> samples;
    for (int i = -k; i <= k; ++i)
      for (int j = -k; j <= k; ++j)
        if ((i != 0 || j != 0) && std::abs(i + j) <= k) {
          const Vec<2> x = a * Vec<2>(i, j) / one_ring_length;
          samples.push(x, x.squaredNorm());
        }
    bool scaled = true, whitened = false;
    const CEI::Taylor_fit<2, 1, 2> fit = samples.fit<CEI::Taylor_fit<2, 1, 2>>(1e3, scaled, whitened);
    EXPECT_FALSE(scaled) << k << " rings";
    EXPECT_GT(fit.condition_number(), 1e7) << k << " rings";
    ASSERT_TRUE(whitened) << k << " rings";
    std::cout << k << "-ring of a grid stretched by 100: condition (a) " << fit.condition_number() << ", (b) "
              << fit.whitened_condition_number() << "\n";
    EXPECT_LT(fit.whitened_condition_number(), previous) << k << " rings";
    previous = fit.whitened_condition_number();
  }
}

TEST(WhitenedConditioning, SamplesOnALineAreRefused)
{
  // Through the vertex (M is singular) and not (the samples lie on a conic
  // through the vertex: that line and the parallel one through the vertex), on
  // both sides and one-sided, along a frame axis and not.
  const std::vector<std::vector<double>> parameter_sets = {{-1, -0.6, -0.3, 0.3, 0.6, 1},
                                                           {0.2, 0.4, 0.6, 0.8, 1.0, 1.2, 1.4, 1.6, 1.8, 2.0}};
  for (const Vec<2>& d : {Vec<2>(1, 0), Vec<2>(std::cos(0.5), std::sin(0.5))})
    for (double offset : {0.0, 0.3})
      for (const auto& ts : parameter_sets) {
        Samples<2> samples;
        for (double s : ts)
          samples.push(s * d + offset * Vec<2>(-d[1], d[0]), 0.5 * s * s);
        double condition = 0;
        EXPECT_FALSE((samples.whitened<CEI::Taylor_fit<2, 2, 2>>(1e12, condition)))
          << "offset " << offset << ", " << condition;
        EXPECT_FALSE((samples.whitened<CEI::Taylor_fit<2, 1, 2>>(1e12, condition)))
          << "offset " << offset << ", " << condition;
        EXPECT_FALSE((samples.whitened<CEI::Taylor_fit<2, 1, 3>>(1e12, condition)))
          << "offset " << offset << ", " << condition;
      }
}

TEST(WhitenedConditioning, TiltedLineStencilsAreRefused)
{
  // The stencils of Conditioning.TiltedLineStencil*: on a great circle of the
  // unit sphere through the vertex, seen in a frame tilted by t about its
  // tangent. Their tangent coordinates lie on a parabola of width t times their
  // heights; whitening makes it as wide as long, where the quadratic terms
  // alone are well-conditioned, but the parabola is a conic through the vertex.
  const std::vector<double> ts = {-1, -0.75, -0.5, 0.25, 0.5, 0.75, 1};
  for (double angle : {0.0, 0.5, 1.2}) {
    const Vec<3> d(std::cos(angle), std::sin(angle), 0);
    for (double tilt : {1e-1, 1e-2, 1e-3}) {
      const Vec<3> n = rotation3(d, tilt) * Vec<3>::UnitZ();
      const Mat<3, 2> t = CEI::tangent_basis<3>(n);
      Samples<2> samples;
      for (double s : ts) {
        const Vec<3> p = std::sin(s) * d + (1 - std::cos(s)) * Vec<3>::UnitZ();
        samples.push(t.transpose() * p, n.dot(p));
      }
      const double quadratic_only = static_cast<double>(whitened_quadratic_only_condition(samples.x));
      EXPECT_LT(quadratic_only, 1e3) << "angle " << angle << ", tilt " << tilt;
      double hamann = 0, quadratic = 0;
      EXPECT_FALSE((samples.whitened<CEI::Taylor_fit<2, 2, 2>>(1e3, hamann))) << "angle " << angle << ", tilt " << tilt;
      EXPECT_FALSE((samples.whitened<CEI::Taylor_fit<2, 1, 2>>(1e3, quadratic)))
        << "angle " << angle << ", tilt " << tilt;
      std::cout << "great circle at " << angle << " rad, tilt " << tilt << ": whitened condition " << hamann
                << " (Hamann's quadratic terms alone: " << quadratic_only << ")\n";
    }
  }
}

TEST(WhitenedConditioning, SamplesOnTwoLinesThroughTheVertexAreRefusedByHamannsFit)
{
  // u v = 0 at every sample of a cross, and a linear map of a cross is a cross.
  Random random(86);
  for (int trial = 0; trial < 10; ++trial) {
    const Mat<2, 2> a = stretch_map<2>(random, trial == 0 ? 1.0 : random.uniform(1, 100));
    Samples<2> samples;
    for (double s : {-1.0, -0.5, 0.5, 1.0}) {
      samples.push(a * Vec<2>(s, 0), s * s);
      samples.push(a * Vec<2>(0, s), 2 * s * s);
    }
    bool scaled = true, whitened = true;
    const CEI::Taylor_fit<2, 2, 2> fit = samples.fit<CEI::Taylor_fit<2, 2, 2>>(1e12, scaled, whitened);
    EXPECT_FALSE(scaled) << "trial " << trial << ", condition " << fit.condition_number();
    EXPECT_FALSE(whitened) << "trial " << trial << ", condition " << fit.whitened_condition_number();
  }
}

TEST(WhitenedConditioning, ThreeRowsOfSamplesAreRefusedByTheCubicFitAndFourRowsAccepted)
{
  // A one-sided boundary stencil of rows v = 0, 1, 2 (u = -3..3, the vertex
  // left out): v (v - 1) (v - 2) vanishes at every sample, so the cubic terms
  // are undetermined; a fourth row determines them. Stretched and turned alike.
  Random random(87);
  for (int trial = 0; trial < 5; ++trial) {
    const Mat<2, 2> a = stretch_map<2>(random, trial == 0 ? 1.0 : 30.0);
    for (int rows : {3, 4}) {
      Samples<2> samples;
      for (int v = 0; v < rows; ++v)
        for (int u = -3; u <= 3; ++u)
          if (u != 0 || v != 0) {
            const Vec<2> x = a * Vec<2>(u, v) / 3.0;
            samples.push(x, x.squaredNorm() + x[0] * x[1] * x[1]);
          }
      double condition = 0;
      EXPECT_EQ((samples.whitened<CEI::Taylor_fit<2, 1, 3>>(1e6, condition)), rows == 4)
        << rows << " rows, trial " << trial << ", condition " << condition;
    }
  }
}

TEST(WhitenedConditioning, HypersurfaceSamplesOnAPlaneAreRefused)
{
  // D = 3: samples on a plane of the tangent space through the vertex (M is
  // singular), and the same plane seen in a frame tilted by 1e-2 about it (on
  // a quadric through the vertex).
  Random random(88);
  const std::vector<Vec<2>> plane = spread_stencil_2d(random, 14, 0.3, 1.0);
  for (double tilt : {0.0, 1e-2}) {
    const Vec<4> n = (Vec<4>::UnitW() + tilt * Vec<4>::UnitZ()).normalized();
    const Mat<4, 3> t = CEI::tangent_basis<4>(n);
    Samples<3> samples;
    for (const Vec<2>& u : plane) {
      const Vec<4> p(u[0], u[1], 0, 0.5 * u.squaredNorm());
      samples.push(t.transpose() * p, n.dot(p));
    }
    bool scaled = true, whitened = true;
    samples.fit<CEI::Taylor_fit<3, 2, 2>>(1e3, scaled, whitened);
    EXPECT_FALSE(scaled) << "tilt " << tilt;
    EXPECT_FALSE(whitened) << "tilt " << tilt;
    double condition = 0;
    EXPECT_FALSE((samples.whitened<CEI::Taylor_fit<3, 1, 2>>(1e3, condition))) << "tilt " << tilt << ", " << condition;
  }
}

// ---------------------------------------------------------------------------
// Weights
// ---------------------------------------------------------------------------

template <int F, int L>
void check_zero_weight(Random& random)
{
  for (int trial = 0; trial < 10; ++trial) {
    const std::vector<Vec<2>> xs = spread_stencil_2d(random, CEI::Taylor_fit<2, F, L>::unknowns + 2 + trial % 5);
    const std::vector<Vec<2>> extra = spread_stencil_2d(random, 4, 0.0, 3.0);
    std::vector<double> heights;
    for (std::size_t i = 0; i < xs.size(); ++i)
      heights.push_back(random.uniform(-1, 1)); // noisy data: the fit is a true least-squares fit
    CEI::Taylor_fit<2, F, L> without, with;
    for (std::size_t i = 0; i < xs.size(); ++i) {
      without.add(xs[i], heights[i]);
      with.add(xs[i], heights[i]);
      if (i < extra.size()) // interleaved zero-weight samples with absurd heights
        with.add(extra[i], 1e6 * (i + 1), 0.0);
    }
    ASSERT_TRUE(without.solve(1e6));
    ASSERT_TRUE(with.solve(1e6));
    // Adding 0 * row row^T changes no bit of the normal equations.
    EXPECT_EQ(with.condition_number(), without.condition_number());
    EXPECT_EQ(with.hessian(), without.hessian());
    EXPECT_EQ(with.gradient(), without.gradient());

    // A weight of 2 is a sample counted twice (to rounding).
    CEI::Taylor_fit<2, F, L> doubled, repeated;
    for (std::size_t i = 0; i < xs.size(); ++i) {
      doubled.add(xs[i], heights[i], i == 0 ? 2.0 : 1.0);
      repeated.add(xs[i], heights[i]);
      if (i == 0)
        repeated.add(xs[i], heights[i]);
    }
    ASSERT_TRUE(doubled.solve(1e6));
    ASSERT_TRUE(repeated.solve(1e6));
    EXPECT_LE((doubled.hessian() - repeated.hessian()).cwiseAbs().maxCoeff(), 1e-12);
    EXPECT_LE((doubled.gradient() - repeated.gradient()).cwiseAbs().maxCoeff(), 1e-12);
    // ... and differs from the unweighted fit of noisy data.
    EXPECT_GT((doubled.hessian() - without.hessian()).cwiseAbs().maxCoeff(), 1e-6);
  }
}

// ---------------------------------------------------------------------------
// Solving again with other heights; the curvature's own quartic term
// ---------------------------------------------------------------------------

// solve_again with other heights gives the fit of those heights, whether the first
// solve was accepted by test (a) (a round stencil) or only by test (b) (one
// stretched by 100): it must reuse the inverse in the coordinates it was accepted in.
template <int D, int F, int L>
void check_solve_again(Random& random, Orders<D, F, L>)
{
  using Fit = CEI::Taylor_fit<D, F, L>;
  const double max_condition = L == 3 ? 1e6 : 1e3;
  for (int trial = 0; trial < 10; ++trial)
    for (const double stretch : {1.0, 100.0}) {
      const std::vector<Vec<D>> xs =
        mapped<D>(spread_stencil<D>(random, 2 * Fit::tested + trial % 6), stretch_map<D>(random, stretch));
      Samples<D> first, second;
      for (const Vec<D>& x : xs) {
        first.push(x, random.uniform(-1, 1));
        second.push(x, random.uniform(-1, 1));
      }
      Fit again, fresh;
      first([&](const Vec<D>& x, double h, double w) { again.add(x, h, w); });
      second([&](const Vec<D>& x, double h, double w) { fresh.add(x, h, w); });
      if (stretch == 1.0) {
        ASSERT_TRUE(again.solve(max_condition)) << "trial " << trial;
        ASSERT_TRUE(fresh.solve(max_condition)) << "trial " << trial;
      } else {
        ASSERT_FALSE(again.solve(max_condition)) << "trial " << trial;
        ASSERT_TRUE(again.solve_whitened(max_condition, first)) << "trial " << trial;
        ASSERT_TRUE(fresh.solve_whitened(max_condition, second)) << "trial " << trial;
      }
      const Mat<D, D> first_hessian = again.hessian();
      again.solve_again(second);
      const double size = (std::max)(fresh.hessian().cwiseAbs().maxCoeff(), fresh.gradient().cwiseAbs().maxCoeff());
      EXPECT_LE((again.hessian() - fresh.hessian()).cwiseAbs().maxCoeff(), 1e-13 * size) << "trial " << trial;
      EXPECT_LE((again.gradient() - fresh.gradient()).cwiseAbs().maxCoeff(), 1e-13 * size) << "trial " << trial;
      // Other heights, another fit: the test could tell.
      EXPECT_GT((first_hessian - fresh.hessian()).cwiseAbs().maxCoeff(), 1e-6 * size) << "trial " << trial;
    }
}

TEST(SolveAgain, IsTheFitOfTheOtherHeightsInScaledAndWhitenedCoordinates)
{
  Random random(91);
  for_each_fit([&](auto orders) { check_solve_again(random, orders); });
}

// subtract_curvature_quartic, from the moments, gives the fit of the heights less
// curvature_quartic(C, x) (C the first fit's Hessian), accumulated sample by
// sample, after test (a) (a round stencil) and after test (b) only (one
// stretched by 100), where the moments are those of the whitened coordinates.
template <int D, int F, int L>
void check_subtract_curvature_quartic(Random& random, Orders<D, F, L>)
{
  using Fit = CEI::Taylor_fit<D, F, L>;
  if constexpr (Fit::quartic_moments) {
    const double max_condition = 1e6;
    // Test (a) alone accepts a round stencil, test (b) alone one stretched by 100.
    const auto solve = [&](Fit& fit, const Samples<D>& samples, double stretch) {
      samples([&](const Vec<D>& x, double h, double w) { fit.add(x, h, w); });
      if (stretch == 1.0)
        return fit.solve(max_condition);
      return !fit.solve(max_condition) && fit.solve_whitened(max_condition, samples);
    };
    for (int trial = 0; trial < 10; ++trial)
      for (const double stretch : {1.0, 100.0}) {
        const std::vector<Vec<D>> xs =
          mapped<D>(spread_stencil<D>(random, 2 * Fit::tested + trial % 6), stretch_map<D>(random, stretch));
        Samples<D> samples;
        for (const Vec<D>& x : xs)
          samples.push(x, random.uniform(-1, 1));
        Fit fit;
        ASSERT_TRUE(solve(fit, samples, stretch)) << "trial " << trial << ", stretch " << stretch;
        const Mat<D, D> first_hessian = fit.hessian();
        Samples<D> corrected;
        for (std::size_t i = 0; i < xs.size(); ++i)
          corrected.push(xs[i], samples.height[i] - CEI::curvature_quartic<D>(first_hessian, xs[i]));
        Fit fresh;
        ASSERT_TRUE(solve(fresh, corrected, stretch)) << "trial " << trial << ", stretch " << stretch;
        fit.subtract_curvature_quartic();
        const double size = (std::max)(fresh.hessian().cwiseAbs().maxCoeff(), fresh.gradient().cwiseAbs().maxCoeff());
        const double difference = (std::max)((fit.hessian() - fresh.hessian()).cwiseAbs().maxCoeff(),
                                             (fit.gradient() - fresh.gradient()).cwiseAbs().maxCoeff()) /
                                  size;
        EXPECT_LE(difference, 1e-12) << "trial " << trial << ", stretch " << stretch;
        // The correction changes the fit: the test could tell.
        EXPECT_GT((first_hessian - fresh.hessian()).cwiseAbs().maxCoeff(), 1e-3 * size) << "trial " << trial;
      }
  }
}

TEST(SubtractCurvatureQuartic, IsTheFitOfTheHeightsLessTheQuarticTermInScaledAndWhitenedCoordinates)
{
  Random random(93);
  for_each_fit([&](auto orders) { check_subtract_curvature_quartic(random, orders); });
}

// The height over the tangent space of a sphere of radius r (k = D) or of a
// cylinder over a sphere of dimension k < D, normal pointing out: -(r - sqrt(r^2 -
// |P x|^2)) = -|P x|^2 / 2r - |P x|^4 / 8r^3 - |P x|^6 / 16r^5 - ..., P the
// orthogonal projection onto k random directions, Hessian C = -P / r. Its
// quartic part is curvature_quartic(C, x); the rest is of order 6.
template <int D>
void check_curvature_quartic(Random& random)
{
  for (int trial = 0; trial < 20; ++trial) {
    const int k = 1 + trial % D; // the sphere's dimension: k = D is a sphere, k < D a cylinder
    const double r = random.uniform(0.5, 2.0);
    const Mat<D, D> q = random.rotation<D>();
    const Mat<D, D> projection = q.leftCols(k) * q.leftCols(k).transpose();
    const Mat<D, D> hessian = -projection / r;
    const Vec<D> direction = random.in_cube<D>().normalized();
    const double rho = (projection * direction).norm();
    for (const double s : {0.1, 0.05}) {
      const Vec<D> x = s * direction;
      const double height = -(r - std::sqrt(r * r - (projection * x).squaredNorm()));
      const double quartic = height - 0.5 * x.dot(hessian * x);
      const double sixth = std::pow(s * rho, 6) / (16 * std::pow(r, 5));
      // The eighth-order term is at most 5 rho^2 / 8 r^2 < 3% of the sixth; 1e-14: rounding.
      EXPECT_NEAR(quartic - CEI::curvature_quartic<D>(hessian, x), -sixth, 0.1 * sixth + 1e-14)
        << "trial " << trial << ", k " << k << ", s " << s;
      // ... where the quartic part itself is |P x|^4 / 8r^3, far larger.
      EXPECT_NEAR(quartic, -std::pow(s * rho, 4) / (8 * std::pow(r, 3)), 2 * sixth + 1e-14) << "trial " << trial;
    }
  }
}

TEST(CurvatureQuartic, IsTheQuarticPartOfTheHeightOfSpheresAndCylinders)
{
  Random random(92);
  check_curvature_quartic<2>(random);
  check_curvature_quartic<3>(random);
}

TEST(Weights, ZeroWeightIsTheSameAsLeavingTheSampleOut)
{
  Random random(71);
  check_zero_weight<2, 2>(random);
  check_zero_weight<1, 2>(random);
  check_zero_weight<1, 3>(random);
}

TEST(Weights, ZeroWeightSamplesDoNotMakeTooFewSamplesSolvable)
{
  // Two real samples and a zero-weight one for three unknowns: still unsolvable.
  CEI::Taylor_fit<2, 2, 2> fit;
  fit.add(Vec<2>(1, 0), 0.5);
  fit.add(Vec<2>(0, 1), 0.5);
  fit.add(Vec<2>(1, 1), 1.0, 0.0);
  EXPECT_FALSE(fit.solve(1e300));
}

} // namespace
