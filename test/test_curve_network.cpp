// SPDX-License-Identifier: GPL-3.0-or-later
// Wollmann's curve-network estimator: the pure curve and Euler functions on exact
// inputs, the paper's Fig. 3 (convergence orders 2, 4, 6 on a parametric
// ellipsoid), curve_network_curvatures on grid and irregular meshes (orders,
// statuses, comparison with the paraboloid fit), bad input and concurrency.
#include <CGAL/Curvature_estimation/curve_network.h>
#include <CGAL/Curvature_estimation/internal/curve_curvature.h>
#include <CGAL/Curvature_estimation/internal/meusnier_euler.h>
#include <CGAL/Curvature_estimation/paraboloid_fitting.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <gtest/gtest.h>

#include "degenerate_input.h"
#include "estimator_runs.h"
#include "principal_directions.h"
#include "rotations.h"
#include "test_surfaces.h"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <optional>
#include <vector>

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Vector = Kernel::Vector_3;
using Mesh = CGAL::Surface_mesh<Point>;
using Curvatures = CGAL::Curvature_estimation::Principal_curvatures_and_directions<Kernel>;
using CGAL::Curvature_estimation::Curve_model;
using CGAL::Curvature_estimation::Estimation_status;
namespace CE = CGAL::Curvature_estimation;
namespace CEI = CGAL::Curvature_estimation::internal;
namespace params = CGAL::Curvature_estimation::parameters;

using ce_test::rotation;

// ---------------------------------------------------------------------------
// Curves through three points
// ---------------------------------------------------------------------------

TEST(Curve_curvature, CircleThroughThreePointsOfACircleIsExact)
{
  // A circle of radius 2.5 in a tilted plane, points unevenly spaced.
  const Eigen::Matrix3d Q = rotation(0.3, 1.2, -0.7);
  const Eigen::Vector3d centre(1, -2, 3), e1 = Q.col(0), e2 = Q.col(1);
  const double radius = 2.5;
  auto at = [&](double t) { return Eigen::Vector3d(centre + radius * (std::cos(t) * e1 + std::sin(t) * e2)); };
  const double t0 = 0.4, t1 = 0.7, t2 = 1.5;
  const CEI::Curve_estimate c = CEI::circle_curve_curvature(at(t0), at(t1), at(t2));
  ASSERT_TRUE(c.valid);
  EXPECT_NEAR(c.curvature, 1 / radius, 1e-14);
  const Eigen::Vector3d inward = (centre - at(t1)).normalized();
  const Eigen::Vector3d forward = -std::sin(t1) * e1 + std::cos(t1) * e2; // d/dt, towards p2
  EXPECT_NEAR((c.principal_normal - inward).norm(), 0, 1e-13);
  EXPECT_NEAR((c.tangent - forward).norm(), 0, 1e-13);
  EXPECT_NEAR((c.curvature_vector - inward / radius).norm(), 0, 1e-13);

  // Collinear points: a straight line, zero curvature, tangent along the line.
  const CEI::Curve_estimate line =
    CEI::circle_curve_curvature(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 1, 1), Eigen::Vector3d(3, 3, 3));
  ASSERT_TRUE(line.valid);
  EXPECT_EQ(line.curvature, 0);
  EXPECT_NEAR((line.tangent - Eigen::Vector3d(1, 1, 1).normalized()).norm(), 0, 1e-15);
  // Coincident points: no estimate.
  EXPECT_FALSE(
    CEI::circle_curve_curvature(Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(2, 0, 0)).valid);
}

TEST(Curve_curvature, BezierOnAParabolaIsExact)
{
  // c(t) = (t, a t^2, 0): central differences are exact on a quadratic, so the
  // Bezier segment through c(t0 - h), c(t0), c(t0 + h) has c'(t0) = (1, 2 a t0, 0),
  // c'' = (0, 2a, 0) and kappa = 2a / (1 + 4 a^2 t0^2)^(3/2), for every h.
  const double a = 0.7;
  const Eigen::Matrix3d Q = rotation(-0.4, 0.9, 2.1);
  for (double t0 : {0.0, 0.35, -1.2})
    for (double h : {0.5, 0.05}) {
      auto c = [&](double t) { return Eigen::Vector3d(Q * Eigen::Vector3d(t, a * t * t, 0)); };
      const CEI::Curve_estimate e = CEI::bezier_curve_curvature(c(t0 - h), c(t0), c(t0 + h));
      ASSERT_TRUE(e.valid);
      const double speed2 = 1 + 4 * a * a * t0 * t0;
      EXPECT_NEAR(e.curvature, 2 * a / std::pow(speed2, 1.5), 1e-13) << t0 << ' ' << h;
      const Eigen::Vector3d tangent = Q * Eigen::Vector3d(1, 2 * a * t0, 0) / std::sqrt(speed2);
      const Eigen::Vector3d normal = Q * Eigen::Vector3d(-2 * a * t0, 1, 0) / std::sqrt(speed2);
      EXPECT_NEAR((e.tangent - tangent).norm(), 0, 1e-13);
      EXPECT_NEAR((e.principal_normal - normal).norm(), 0, 1e-13);
      // Eq. (1) written out.
      const Eigen::Vector3d d1 = c(t0 + h) - c(t0 - h), d2 = c(t0 + h) + c(t0 - h) - 2 * c(t0);
      EXPECT_NEAR(e.curvature, 4 * d1.cross(d2).norm() / std::pow(d1.norm(), 3), 1e-13);
    }
}

TEST(Curve_curvature, ExtrapolationCoefficientsSatisfyTheMomentConditions)
{
  for (int n = 1; n <= CEI::max_extrapolation_order; ++n) {
    const CEI::Extrapolation_coefficients c = CEI::extrapolation_coefficients(n);
    ASSERT_EQ(c.order, n);
    // sum alpha_k k = 1, sum alpha_k k^(2m+1) = 0 (m = 1..n-1);
    // sum beta_k k^2 = 1, sum beta_k k^(2m) = 0 (m = 2..n).
    for (int m = 0; m < n; ++m) {
      double odd = 0, even = 0;
      for (int k = 1; k <= n; ++k) {
        odd += c.alpha[k - 1] * std::pow(double(k), 2 * m + 1);
        even += c.beta[k - 1] * std::pow(double(k), 2 * m + 2);
      }
      EXPECT_NEAR(odd, m == 0 ? 1.0 : 0.0, 1e-12) << n << ' ' << m;
      EXPECT_NEAR(even, m == 0 ? 1.0 : 0.0, 1e-12) << n << ' ' << m;
    }
  }
  // n = 2: the classical fourth-order central differences
  // f' ~ (8 (f1 - f-1) - (f2 - f-2)) / 12h, f'' ~ (-f-2 + 16 f-1 - 30 f0 + 16 f1 - f2) / 12h^2.
  const CEI::Extrapolation_coefficients c2 = CEI::extrapolation_coefficients(2);
  EXPECT_NEAR(c2.alpha[0], 4.0 / 3, 1e-15);
  EXPECT_NEAR(c2.alpha[1], -1.0 / 6, 1e-15);
  EXPECT_NEAR(2 * c2.beta[0], 8.0 / 3, 1e-15);
  EXPECT_NEAR(2 * c2.beta[1], -1.0 / 6, 1e-15);
  EXPECT_EQ(CEI::extrapolation_coefficients(0).order, 0);
  EXPECT_EQ(CEI::extrapolation_coefficients(5).order, 0);
}

TEST(Curve_curvature, OrderNIsExactOnPolynomialCurvesOfDegree2n)
{
  // The combination cancels every Taylor term up to degree 2n of the first and
  // second derivatives: on a polynomial curve of degree 2n it is exact, and for
  // n = 1 it is the Bezier estimate.
  for (int n = 1; n <= CEI::max_extrapolation_order; ++n) {
    const int degree = 2 * n;
    std::vector<Eigen::Vector3d> a(degree + 1);
    for (int d = 0; d <= degree; ++d)
      a[d] = Eigen::Vector3d(std::sin(1.0 + d), std::cos(2.0 * d + 0.5), 0.3 * d - 0.7) / (1.0 + d);
    a[1] = Eigen::Vector3d(1.0, 0.2, -0.4); // a regular curve
    auto c = [&](double t) {
      Eigen::Vector3d p = Eigen::Vector3d::Zero();
      for (int d = degree; d >= 0; --d)
        p = p * t + a[d];
      return p;
    };
    const double h = 0.3;
    Eigen::Vector3d before[CEI::max_extrapolation_order], after[CEI::max_extrapolation_order];
    for (int k = 1; k <= n; ++k) {
      before[k - 1] = c(-k * h);
      after[k - 1] = c(k * h);
    }
    const CEI::Curve_estimate e = CEI::extrapolated_curve_curvature(before, c(0), after, n);
    const CEI::Curve_estimate exact = CEI::curve_from_derivatives(a[1], 2 * a[2]);
    ASSERT_TRUE(e.valid && exact.valid);
    EXPECT_NEAR(e.curvature, exact.curvature, 1e-12 * exact.curvature) << n;
    EXPECT_NEAR((e.tangent - exact.tangent).norm(), 0, 1e-12) << n;
    EXPECT_NEAR((e.curvature_vector - exact.curvature_vector).norm(), 0, 1e-12) << n;
    if (n == 1) {
      const CEI::Curve_estimate bezier = CEI::bezier_curve_curvature(before[0], c(0), after[0]);
      EXPECT_NEAR(e.curvature, bezier.curvature, 1e-14);
    }
  }
}

// ---------------------------------------------------------------------------
// Meusnier and Euler
// ---------------------------------------------------------------------------

TEST(Euler_fit, MeusnierOnASphereGivesOneOverRadiusWithOutwardNormals)
{
  // Every curve on a sphere of radius r through p has normal curvature 1/r for
  // the outward normal: a great circle (kappa = 1/r) and a small circle of
  // latitude (kappa = 1/(r sin theta), tilted by theta from the normal).
  const double r = 2;
  const double theta = 0.6, phi = 0.3;
  const Eigen::Vector3d p =
    r * Eigen::Vector3d(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
  const Eigen::Vector3d outward = p.normalized();
  auto latitude = [&](double f) {
    return Eigen::Vector3d(
      r * Eigen::Vector3d(std::sin(theta) * std::cos(f), std::sin(theta) * std::sin(f), std::cos(theta)));
  };
  auto meridian = [&](double t) {
    return Eigen::Vector3d(r * Eigen::Vector3d(std::sin(t) * std::cos(phi), std::sin(t) * std::sin(phi), std::cos(t)));
  };
  const CEI::Curve_estimate small = CEI::circle_curve_curvature(latitude(phi - 0.1), p, latitude(phi + 0.2));
  const CEI::Curve_estimate great = CEI::circle_curve_curvature(meridian(theta - 0.1), p, meridian(theta + 0.05));
  EXPECT_NEAR(small.curvature, 1 / (r * std::sin(theta)), 1e-13);
  EXPECT_NEAR(CEI::meusnier_normal_curvature(small.curvature_vector, outward), 1 / r, 1e-13);
  EXPECT_NEAR(CEI::meusnier_normal_curvature(great.curvature_vector, outward), 1 / r, 1e-13);
  EXPECT_NEAR(CEI::meusnier_normal_curvature(great.curvature_vector, -outward), -1 / r, 1e-13);
}

TEST(Euler_fit, ThreeDirectionsExactlyMoreByLeastSquares)
{
  // Exact normal curvatures k(d) = k1 cos^2 + k2 sin^2 of the angle to the first
  // principal direction, in a tilted tangent plane.
  const Eigen::Matrix3d Q = rotation(1.1, -0.3, 0.8);
  const Eigen::Vector3d normal = Q.col(2), e1 = Q.col(0), e2 = Q.col(1);
  const double k1 = 2.0, k2 = -0.5, principal_angle = 0.4;
  auto direction = [&](double angle) { return Eigen::Vector3d(std::cos(angle) * e1 + std::sin(angle) * e2); };
  auto euler = [&](double angle) {
    const double c = std::cos(angle - principal_angle), s = std::sin(angle - principal_angle);
    return k1 * c * c + k2 * s * s;
  };
  for (std::size_t count : {3, 5}) {
    std::vector<Eigen::Vector3d> directions;
    std::vector<double> curvatures;
    const double angles[5] = {0.0, 0.9, 1.9, 2.4, -0.7};
    for (std::size_t i = 0; i < count; ++i) {
      // Directions of any length and slightly off the plane: they are projected.
      directions.push_back((1.0 + i) * direction(angles[i]) + 0.01 * normal);
      curvatures.push_back(euler(angles[i]));
    }
    const CEI::Euler_solution s = CEI::euler_fit(directions.data(), curvatures.data(), count, normal);
    ASSERT_TRUE(s.valid);
    EXPECT_NEAR(s.max_curvature, k1, 1e-13);
    EXPECT_NEAR(s.min_curvature, k2, 1e-13);
    EXPECT_NEAR(std::abs(s.max_direction.dot(direction(principal_angle))), 1, 1e-13);
    EXPECT_NEAR(std::abs(s.min_direction.dot(direction(principal_angle + ce_test::pi / 2))), 1, 1e-13);
    EXPECT_NEAR(s.max_direction.norm(), 1, 1e-14);
    EXPECT_NEAR(s.min_direction.norm(), 1, 1e-14);
    EXPECT_NEAR(s.max_direction.dot(s.min_direction), 0, 1e-14);
    EXPECT_NEAR(s.max_direction.dot(normal), 0, 1e-14);
  }
  // Two of three directions equal (up to sign): Euler's system is singular.
  const Eigen::Vector3d same[3] = {e1, e2, -e1};
  const double k[3] = {1, 2, 1};
  EXPECT_FALSE(CEI::euler_fit(same, k, 3, normal).valid);
  EXPECT_FALSE(CEI::euler_fit(same, k, 2, normal).valid);
}

TEST(Euler_fit, NormalFromTangentsIsThePlaneNormalOrientedAsAsked)
{
  const Eigen::Vector3d t[3] = {Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0.6, 0.8, 0), Eigen::Vector3d(-0.6, 0.8, 0)};
  Eigen::Vector3d n;
  ASSERT_TRUE(CEI::normal_from_tangents(t, 2, Eigen::Vector3d(0.1, 0, -1), n));
  EXPECT_NEAR((n - Eigen::Vector3d(0, 0, -1)).norm(), 0, 1e-15);
  ASSERT_TRUE(CEI::normal_from_tangents(t, 3, Eigen::Vector3d(0, 0.3, 1), n));
  EXPECT_NEAR((n - Eigen::Vector3d(0, 0, 1)).norm(), 0, 1e-15);
  const Eigen::Vector3d parallel[2] = {Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(-1, 0, 0)};
  EXPECT_FALSE(CEI::normal_from_tangents(parallel, 2, Eigen::Vector3d(0, 0, 1), n));
}

// ---------------------------------------------------------------------------
// Wollmann's Fig. 3
// ---------------------------------------------------------------------------

// The paper's ellipsoid X(u, v) = (cos u cos v, 3 sin u cos v, 5 sin v) at
// (u0, v0) = (0.3, 0.5): three curves (the u-line, the v-line and the diagonal
// (u0 + t, v0 + t), all at parameter step h), the normal from the two
// parameter lines' tangents (the paper's N = X_u x X_v / |X_u x X_v|), Meusnier,
// Euler's theorem solved exactly. Returns K.
double fig3_gaussian_curvature(double h, int n, Curve_model model)
{
  const double u0 = 0.3, v0 = 0.5;
  auto X = [](double u, double v) {
    return Eigen::Vector3d(std::cos(u) * std::cos(v), 3 * std::sin(u) * std::cos(v), 5 * std::sin(v));
  };
  const Eigen::Vector2d steps[3] = {{1, 0}, {0, 1}, {1, 1}};
  Eigen::Vector3d tangents[3], vectors[3];
  for (int line = 0; line < 3; ++line) {
    Eigen::Vector3d before[CEI::max_extrapolation_order], after[CEI::max_extrapolation_order];
    for (int k = 1; k <= n; ++k) {
      before[k - 1] = X(u0 - k * h * steps[line].x(), v0 - k * h * steps[line].y());
      after[k - 1] = X(u0 + k * h * steps[line].x(), v0 + k * h * steps[line].y());
    }
    const CEI::Curve_estimate c = model == Curve_model::circle
                                    ? CEI::circle_curve_curvature(before[0], X(u0, v0), after[0])
                                    : CEI::extrapolated_curve_curvature(before, X(u0, v0), after, n);
    EXPECT_TRUE(c.valid);
    tangents[line] = c.tangent;
    vectors[line] = c.curvature_vector;
  }
  Eigen::Vector3d normal;
  EXPECT_TRUE(CEI::normal_from_tangents(tangents, 2, X(u0, v0), normal)); // outward
  double k[3];
  for (int line = 0; line < 3; ++line)
    k[line] = CEI::meusnier_normal_curvature(vectors[line], normal);
  const CEI::Euler_solution s = CEI::euler_fit(tangents, k, 3, normal);
  EXPECT_TRUE(s.valid);
  return s.max_curvature * s.min_curvature;
}

constexpr double fig3_exact_K = 0.0085838921720541669;

// log2 |K_i - K_{i+1}| per halving, h_i = 0.2 / 2^(i-1): the slopes between the
// differences i and i + 1, for i = 1 .. last.
std::vector<double> fig3_slopes(int n, int last)
{
  std::vector<double> K;
  for (int i = 1; i <= last + 2; ++i)
    K.push_back(fig3_gaussian_curvature(0.2 / std::pow(2.0, i - 1), n, Curve_model::bezier));
  std::vector<double> slopes;
  for (int i = 0; i < last; ++i)
    slopes.push_back(std::log2(std::abs(K[i + 1] - K[i + 2]) / std::abs(K[i] - K[i + 1])));
  return slopes;
}

TEST(Wollmann_fig3, ErrorOrderTwoFourSixOnTheEllipsoid)
{
  struct Case
  {
    int n;
    int differences;
    double expected, tolerance;
  };
  // The specification: slope of log2|K_i - K_(i+1)| per halving,
  // -2.00 +- 0.03 over i = 1..6 (n = 1), -4.00 +- 0.05 over i = 1..4 (n = 2),
  // -6.0 +- 0.1 over i = 1..2 (n = 3). i differences give i - 1 slopes.
  for (const Case& c : {Case{1, 6, -2.0, 0.03}, Case{2, 4, -4.0, 0.05}, Case{3, 2, -6.0, 0.1}}) {
    const std::vector<double> slopes = fig3_slopes(c.n, c.differences - 1);
    std::printf("Fig. 3, n = %d, slopes per halving:", c.n);
    for (double s : slopes) {
      std::printf(" %.4f", s);
      EXPECT_NEAR(s, c.expected, c.tolerance) << "n = " << c.n;
    }
    std::printf("\n");
  }
  // The paper's Fig. 3 listing (n = 1, differences from the first): 0, -1.96, -3.95, -5.95, ...
  std::printf("Fig. 3, n = 1, log2|K_i - K_(i+1)| - log2|K_1 - K_2|:");
  const double first = std::log2(std::abs(fig3_gaussian_curvature(0.2, 1, Curve_model::bezier) -
                                          fig3_gaussian_curvature(0.1, 1, Curve_model::bezier)));
  for (int i = 1; i <= 8; ++i) {
    const double h = 0.2 / std::pow(2.0, i - 1);
    const double d = std::log2(std::abs(fig3_gaussian_curvature(h, 1, Curve_model::bezier) -
                                        fig3_gaussian_curvature(h / 2, 1, Curve_model::bezier)));
    std::printf(" %.6f", d - first);
  }
  std::printf("\n");
}

TEST(Wollmann_fig3, AbsoluteErrorsMatchTheReference)
{
  // Exact K = 0.0085838921720541669; the reference implementation's |K error| with
  // the Bezier model: 1.736e-4 at h = 0.2, 4.304e-5 at h = 0.1 (four digits: held
  // to one unit in the last digit).
  const double e02 = std::abs(fig3_gaussian_curvature(0.2, 1, Curve_model::bezier) - fig3_exact_K);
  const double e01 = std::abs(fig3_gaussian_curvature(0.1, 1, Curve_model::bezier) - fig3_exact_K);
  const double c02 = std::abs(fig3_gaussian_curvature(0.2, 1, Curve_model::circle) - fig3_exact_K);
  const double c01 = std::abs(fig3_gaussian_curvature(0.1, 1, Curve_model::circle) - fig3_exact_K);
  std::printf("Fig. 3 |K error|, Bezier: h = 0.2 %.4e, h = 0.1 %.4e; circle: %.4e, %.4e (%.1f%%, %.1f%% more)\n", e02,
              e01, c02, c01, 100 * (c02 / e02 - 1), 100 * (c01 / e01 - 1));
  for (int n = 2; n <= 4; ++n)
    std::printf("Fig. 3 |K error|, n = %d: h = 0.2 %.4e, h = 0.1 %.4e\n", n,
                std::abs(fig3_gaussian_curvature(0.2, n, Curve_model::bezier) - fig3_exact_K),
                std::abs(fig3_gaussian_curvature(0.1, n, Curve_model::bezier) - fig3_exact_K));
  EXPECT_NEAR(e02, 1.736e-4, 0.001e-4);
  EXPECT_NEAR(e01, 4.304e-5, 0.001e-5);
  // The circle is second order too.
  EXPECT_NEAR(std::log2(c02 / c01), 2.0, 0.05);
}

// ---------------------------------------------------------------------------
// Meshes
// ---------------------------------------------------------------------------

using Estimates = ce_test::Estimates<Kernel>;

// Runs the curve network (or, for comparison, the paraboloid fit) with every
// output requested; `extra` adds parameters.
template <typename ConcurrencyTag = CGAL::Sequential_tag, typename Extra>
Estimates estimate(const Mesh& mesh, const Extra& extra, bool paraboloid = false)
{
  return ce_test::run_with_all_outputs<Kernel>(
    mesh,
    [paraboloid](const Mesh& m, const auto& np) {
      if (paraboloid)
        CE::paraboloid_fitting_curvatures<ConcurrencyTag>(m, np);
      else
        CE::curve_network_curvatures<ConcurrencyTag>(m, np);
    },
    extra);
}

Estimates estimate(const Mesh& mesh) { return estimate(mesh, params::default_values()); }

using Errors = ce_test::Curvature_errors;

// Errors at the vertices `include` selects (all when it is empty).
Errors errors(const Estimates& e, const std::vector<ce_test::Exact_curvature>& exact, const std::vector<bool>& include)
{
  return ce_test::curvature_errors(e, exact, [&](std::size_t i) { return include.empty() || include[i]; });
}

TEST(Curve_network, TorusGridConvergesAtOrderTwoAndFour)
{
  // The torus's periodic (u, v) grid triangulation: every vertex interior, of
  // valence 6, the curves exactly the u-line, the v-line and the diagonal, at
  // equal parameter steps: O(h^2) for n = 1 and O(h^4) for n = 2.
  const double R = 3, r = 1;
  const std::size_t sizes[3][2] = {{40, 20}, {80, 40}, {160, 80}};
  for (int n = 1; n <= 3; ++n) {
    ce_test::Convergence H_convergence, K_convergence;
    for (const auto& size : sizes) {
      const auto [soup, mesh, exact] = ce_test::sampled_torus<Mesh>(R, r, size[0], size[1]);
      const Estimates e = estimate(mesh, params::extrapolation_order(n));
      for (Estimation_status s : e.status)
        ASSERT_EQ(s, Estimation_status::ok);
      const Errors t = errors(e, exact, {});
      const double h = ce_test::mean_edge_length(soup);
      std::printf("torus %3zux%-3zu n = %d: RMS k_max %.3e k_min %.3e H %.3e K %.3e", size[0], size[1], n,
                  t.k_max.stats().rms, t.k_min.stats().rms, t.mean.stats().rms, t.gaussian.stats().rms);
      const std::optional<double> order_H = H_convergence.add(h, t.mean.stats().rms);
      const std::optional<double> order_K = K_convergence.add(h, t.gaussian.stats().rms);
      if (order_H && order_K) {
        std::printf(", order H %.2f K %.2f", *order_H, *order_K);
        if (n == 1) {
          EXPECT_GE(*order_H, 1.9);
          EXPECT_GE(*order_K, 1.9);
        } else if (n == 2) {
          EXPECT_GE(*order_H, 3.5);
          EXPECT_GE(*order_K, 3.5);
        }
      }
      std::printf("\n");
    }
  }
}

TEST(Curve_network, DirectionsAreUnitOrthogonalTangentAndFollowTheTorus)
{
  const double R = 3, r = 1;
  const auto [soup, mesh, exact] = ce_test::sampled_torus<Mesh>(R, r, 120, 60);
  const Estimates e = estimate(mesh);
  for (const Curvatures& c : e.principal)
    EXPECT_GE(c.max_curvature, c.min_curvature);
  const double direction = ce_test::max_direction_error(e, exact, 1e-2);
  std::printf("torus 120x60: max 1-|cos| of d_max %.2e\n", direction);
  EXPECT_LT(direction, 1e-3);
}

TEST(Curve_network, SphereSignAndValenceFiveFallback)
{
  // The icosphere: the 12 vertices of valence 5 have two opposite pairs only and
  // fall back (status fallback); the others have three curves. Outward normals: k = +1/r.
  const double radius = 2;
  const ce_test::Soup soup = ce_test::sphere_soup(radius, 4);
  const Mesh mesh = ce_test::to_mesh<Mesh>(soup);
  const Estimates e = estimate(mesh);
  ce_test::Error_accumulator mean_error;
  std::size_t fallbacks = 0;
  std::size_t i = 0;
  for (Mesh::Vertex_index v : vertices(mesh)) {
    const bool valence5 = degree(v, mesh) == 5;
    EXPECT_EQ(e.status[i], valence5 ? Estimation_status::fallback : Estimation_status::ok) << i;
    fallbacks += e.status[i] == Estimation_status::fallback;
    EXPECT_GT(e.principal[i].min_curvature, 0);
    EXPECT_GE(e.principal[i].max_curvature, e.principal[i].min_curvature);
    mean_error.add(1 / radius, e.mean[i]);
    ++i;
  }
  std::printf("icosphere level 4: H RMS error %.2e (1/r = %.2f), %zu fallbacks\n", mean_error.stats().rms, 1 / radius,
              fallbacks);
  EXPECT_EQ(fallbacks, 12u);
  EXPECT_LT(mean_error.stats().rms, 0.01 / radius);
}

TEST(Curve_network, GridGraphStatusesAtTheBoundaryAndReducedOrder)
{
  // A 21 x 21 grid graph, n = 2: boundary vertices have one opposite pair and fall
  // back (fallback); the vertices next to the boundary have a line that cannot be
  // continued (order 1 on it, widened); the others are ok.
  const std::size_t n = 21;
  const ce_test::Graph_function f = ce_test::hamann_table1_functions()[7];
  const ce_test::Soup soup = ce_test::grid_graph_soup(f, n);
  const Mesh mesh = ce_test::to_mesh<Mesh>(soup);
  const auto exact = ce_test::graph_curvatures(f, soup);
  for (int order : {1, 2}) {
    const Estimates e = estimate(mesh, params::extrapolation_order(order));
    std::vector<bool> deep(soup.points.size());
    for (std::size_t j = 0; j < n; ++j)
      for (std::size_t i = 0; i < n; ++i) {
        const std::size_t k = i + n * j;
        const std::size_t border_distance = std::min(std::min(i, j), std::min(n - 1 - i, n - 1 - j));
        ASSERT_TRUE(std::isfinite(e.mean[k]) && std::isfinite(e.gaussian[k]));
        const Estimation_status expected = border_distance == 0                    ? Estimation_status::fallback
                                           : border_distance >= std::size_t(order) ? Estimation_status::ok
                                                                                   : Estimation_status::widened;
        EXPECT_EQ(e.status[k], expected) << i << ' ' << j << " order " << order;
        deep[k] = border_distance >= 2;
      }
    const Errors t = errors(e, exact, deep);
    std::printf("exponential 21x21 grid, n = %d: H RMS (2 rings from the boundary) %.3e\n", order, t.mean.stats().rms);
  }
}

TEST(Curve_network, RegularAndJitteredTorusNextToTheParaboloidFit)
{
  // The same surface, regular and jittered (0.2 of the parameter step), 80 x 40.
  // Printed for the record; asserted: every vertex has a finite estimate.
  const double R = 3, r = 1;
  for (double jitter : {0.0, 0.2}) {
    const auto [soup, mesh, exact] = ce_test::sampled_torus<Mesh>(R, r, 80, 40, jitter, 5);
    const Estimates n1 = estimate(mesh);
    const Estimates n2 = estimate(mesh, params::extrapolation_order(2));
    const Estimates circle = estimate(mesh, params::curve_model(Curve_model::circle));
    const Estimates hamann = estimate(mesh, params::default_values(), true);
    const Estimates paper = estimate(mesh, params::max_curve_irregularity(std::numeric_limits<double>::infinity()));
    for (const Estimates* e : {&n1, &n2, &circle, &paper})
      for (std::size_t i = 0; i < e->status.size(); ++i) {
        ASSERT_NE(e->status[i], Estimation_status::not_estimable) << i;
        ASSERT_TRUE(std::isfinite(e->mean[i]) && std::isfinite(e->gaussian[i])) << i;
      }
    const char* names[5] = {"curve network n=1 Bezier", "curve network n=2", "curve network n=1 circle",
                            "paraboloid fit", "Wollmann (no line test)"};
    const Estimates* all[5] = {&n1, &n2, &circle, &hamann, &paper};
    for (int k = 0; k < 5; ++k) {
      const Errors t = errors(*all[k], exact, {});
      std::printf("torus 80x40 jitter %.1f, %-25s RMS H %.3e K %.3e k_max %.3e k_min %.3e\n", jitter, names[k],
                  t.mean.stats().rms, t.gaussian.stats().rms, t.k_max.stats().rms, t.k_min.stats().rms);
    }
  }
}

TEST(Curve_network, IrregularDelaunayMeshHasAStatusAndAFiniteValueEverywhere)
{
  const ce_test::Graph_function f = ce_test::hamann_table1_functions()[8];
  const ce_test::Soup soup = ce_test::delaunay_graph_soup(f, 4000, -1, 1, 11);
  const Mesh mesh = ce_test::to_mesh<Mesh>(soup);
  const auto exact = ce_test::graph_curvatures(f, soup);
  const Estimates e = estimate(mesh);
  const Estimates hamann = estimate(mesh, params::default_values(), true);
  std::size_t ok = 0, fallbacks = 0;
  std::vector<bool> interior(soup.points.size());
  std::size_t i = 0;
  for (Mesh::Vertex_index v : vertices(mesh)) {
    ASSERT_NE(e.status[i], Estimation_status::not_estimable) << i;
    ASSERT_TRUE(std::isfinite(e.mean[i]) && std::isfinite(e.gaussian[i]) &&
                std::isfinite(e.principal[i].max_direction.x()))
      << i;
    ok += e.status[i] == Estimation_status::ok;
    fallbacks += e.status[i] == Estimation_status::fallback;
    interior[i] = !CGAL::is_border(v, mesh);
    ++i;
  }
  EXPECT_EQ(ok + fallbacks, soup.points.size());
  const Errors t = errors(e, exact, interior);
  const Errors p = errors(hamann, exact, interior);
  std::printf("Delaunay 4000 points (trigonometric): %zu curve networks, %zu fallbacks; interior RMS H %.3e K %.3e "
              "(paraboloid fit H %.3e K %.3e)\n",
              ok, fallbacks, t.mean.stats().rms, t.gaussian.stats().rms, p.mean.stats().rms, p.gaussian.stats().rms);
}

// The curves' irregularity (curve_network.h): s^2 for uneven steps and tan^2(delta/2) for a kink,
// the relative errors of the Bezier's normal curvature to leading order, checked against it.
TEST(Curve_network, IrregularityIsTheLeadingRelativeErrorOfTheCurve)
{
  // The paraboloid z = (x^2 + y^2) / 2, normal curvature 1 in every direction at the origin.
  auto point = [](double x, double y) { return Eigen::Vector3d(x, y, (x * x + y * y) / 2); };
  const Eigen::Vector3d up(0, 0, 1);
  struct Case
  {
    double h_a, h_b, kink;
  };
  for (const Case& c : {Case{1e-3, 1e-3, 0.0}, Case{1.5e-3, 0.5e-3, 0.0}, Case{1.2e-3, 0.8e-3, 0.0},
                        Case{1e-3, 1e-3, 0.2}, Case{1e-3, 1e-3, 0.4}})
  {
    const Eigen::Vector3d a = point(-c.h_a * std::cos(c.kink / 2), -c.h_a * std::sin(c.kink / 2));
    const Eigen::Vector3d b = point(c.h_b * std::cos(c.kink / 2), -c.h_b * std::sin(c.kink / 2));
    const CEI::Curve_estimate e = CEI::extrapolated_curve_curvature(&a, Eigen::Vector3d::Zero(), &b, 1);
    const double relative_error = std::abs(CEI::meusnier_normal_curvature(e.curvature_vector, -up) - 1);
    const double irregularity = CEI::curve_irregularity(a, b, -std::cos(c.kink));
    EXPECT_NEAR(relative_error, irregularity, 1e-5) << c.h_a << ' ' << c.h_b << ' ' << c.kink;
  }
}

// Whether the curves through a vertex are mesh lines (irregularity at most max_curve_irregularity,
// 0.04 by default), on a grid of the hyperboloid z = 0.4 (x^2 - y^2) over [-0.5, 0.5]^2 (slopes at
// most 0.4) jittered by 0.15 of its step. Where Wollmann's method (max_curve_irregularity(infinity))
// has no curve network (boundary vertices, a few interior ones), both fall back. At the other
// vertices (valence 6) whose three pairs of neighbors three apart around them are more nearly
// opposite than any other pair (all but a few; at those only the values are checked), these pairs
// are the curves, and the test recomputes their largest irregularity: the vertex is `fallback`
// exactly where it is above 0.04, with the default paraboloid fit's values, and elsewhere `ok` with
// the values of Wollmann's method. On the regular grids of Hamann's nine functions no interior
// vertex falls back.
TEST(Curve_network, FallbackExactlyWhereTheCurvesAreNoMeshLines)
{
  const ce_test::Graph_function f = ce_test::hamann_table1_functions()[4]; // the hyperboloid
  const ce_test::Soup soup = ce_test::jittered_grid_graph_soup(f, 41, -0.5, 0.5, 0.15, 7);
  const Mesh mesh = ce_test::to_mesh<Mesh>(soup);
  const Estimates e = estimate(mesh);
  const Estimates paper = estimate(mesh, params::max_curve_irregularity(std::numeric_limits<double>::infinity()));
  const Estimates hamann = estimate(mesh, params::default_values(), true);
  auto expect_same = [](const Estimates& x, const Estimates& y, std::size_t i) {
    EXPECT_EQ(x.mean[i], y.mean[i]) << i;
    EXPECT_EQ(x.gaussian[i], y.gaussian[i]) << i;
    EXPECT_EQ(std::memcmp(&x.principal[i], &y.principal[i], sizeof(Curvatures)), 0) << i;
  };
  const auto vpm = get(CGAL::vertex_point, mesh);
  std::size_t interior = 0, mesh_lines = 0, not_mesh_lines = 0, ambiguous = 0;
  std::size_t i = 0;
  for (Mesh::Vertex_index v : vertices(mesh)) {
    if (!CGAL::is_border(v, mesh))
      ++interior;
    if (paper.status[i] == Estimation_status::fallback) { // no curve network: boundary, too few pairs, Euler
      EXPECT_EQ(e.status[i], Estimation_status::fallback) << i;
      expect_same(e, hamann, i++);
      continue;
    }
    ASSERT_EQ(paper.status[i], Estimation_status::ok) << i;
    const Eigen::Vector3d center = CEI::point_in_double(vpm, v);
    Eigen::Vector3d normal = CEI::face_average_normal(v, mesh, vpm, CE::Vertex_normal_method::area_weighted);
    normal.normalize();
    std::vector<Eigen::Vector3d> offsets, directions;
    for (Mesh::Halfedge_index h : halfedges_around_target(halfedge(v, mesh), mesh)) {
      offsets.push_back(CEI::point_in_double(vpm, source(h, mesh)) - center);
      const Eigen::Vector3d d = offsets.back() - offsets.back().dot(normal) * normal;
      directions.push_back(d / d.norm());
    }
    ASSERT_EQ(offsets.size(), 6u) << i;
    // The greedy pairing takes the three pairs three apart if they are more nearly opposite
    // than any other pair.
    double irregularity = 0, least_opposite = -1, most_opposite_other = 1;
    for (std::size_t k = 0; k < 6; ++k)
      for (std::size_t l = k + 1; l < 6; ++l) {
        const double cosine = directions[k].dot(directions[l]);
        if (l == k + 3) {
          least_opposite = std::max(least_opposite, cosine);
          irregularity = std::max(irregularity, CEI::curve_irregularity(offsets[k], offsets[l], cosine));
        } else {
          most_opposite_other = std::min(most_opposite_other, cosine);
        }
      }
    const bool other_pairs = !(least_opposite < most_opposite_other);
    if (other_pairs) {
      ++ambiguous;
      expect_same(e, e.status[i] == Estimation_status::ok ? paper : hamann, i);
    } else if (irregularity <= CEI::default_max_curve_irregularity) {
      ++mesh_lines;
      EXPECT_EQ(e.status[i], Estimation_status::ok) << i;
      expect_same(e, paper, i);
    } else {
      ++not_mesh_lines;
      EXPECT_EQ(e.status[i], Estimation_status::fallback) << i;
      expect_same(e, hamann, i);
    }
    ++i;
  }
  std::printf("grid 41x41 jittered by 0.15: of %zu interior vertices %zu keep their curves, %zu (%.1f%%) fall back, "
              "%zu have other pairs as nearly opposite\n",
              interior, mesh_lines, not_mesh_lines, 100.0 * not_mesh_lines / interior, ambiguous);
  EXPECT_GT(mesh_lines, interior / 4);
  EXPECT_GT(not_mesh_lines, interior / 10);
  EXPECT_LT(ambiguous, interior / 20);

  for (const ce_test::Graph_function& g : ce_test::hamann_table1_functions()) {
    const Mesh grid = ce_test::to_mesh<Mesh>(ce_test::grid_graph_soup(g, 21));
    const Estimates r = estimate(grid);
    std::size_t k = 0;
    for (Mesh::Vertex_index v : vertices(grid))
      EXPECT_EQ(r.status[k++] == Estimation_status::fallback, bool(CGAL::is_border(v, grid))) << g.name << ' ' << k;
  }
}

// use_fallbacks(false): the vertices without a curve network, or whose curves are
// no mesh lines, are not estimable; the others unchanged to the bit.
TEST(Curve_network, WithoutFallbacksTheirVerticesAreNotEstimable)
{
  const ce_test::Graph_function f = ce_test::hamann_table1_functions()[4];
  const Mesh mesh = ce_test::to_mesh<Mesh>(ce_test::jittered_grid_graph_soup(f, 21, -0.5, 0.5, 0.15, 7));
  const ce_test::Fallback_counts counts =
    ce_test::compare_without_fallbacks(estimate(mesh), estimate(mesh, params::use_fallbacks(false)));
  EXPECT_GT(counts.not_estimable, 0u);
  EXPECT_EQ(counts.own, 0u);
}

TEST(Curve_network, BadInputAndParameters)
{
  auto [mesh, isolated, broken] = ce_test::grid_with_isolated_and_nan_vertex<Mesh>();
  const Estimates e = estimate(mesh);
  for (Mesh::Vertex_index v : {isolated, broken})
    ce_test::expect_not_estimable(e, v);
  // The NaN vertex's neighbors lose a curve and fall back, finite.
  ce_test::expect_neighbors_estimated(e, mesh, broken);
  Mesh empty;
  EXPECT_NO_THROW(estimate(empty));
  EXPECT_THROW(estimate(mesh, params::extrapolation_order(0)), std::invalid_argument);
  EXPECT_THROW(estimate(mesh, params::extrapolation_order(5)), std::invalid_argument);
  EXPECT_THROW(estimate(mesh, params::extrapolation_order(2).curve_model(Curve_model::circle)), std::invalid_argument);
  EXPECT_THROW(estimate(mesh, params::max_curve_irregularity(-1)), std::invalid_argument);
  EXPECT_THROW(estimate(mesh, params::max_curve_irregularity(std::numeric_limits<double>::quiet_NaN())),
               std::invalid_argument);
}

TEST(Curve_network, GivenExactNormalsAreUsed)
{
  // With the exact normal of the torus, n = 1 still converges at order 2, and the
  // given normal is the one Meusnier uses (a flipped normal flips every sign).
  const double R = 3, r = 1;
  auto [soup, mesh, exact] = ce_test::sampled_torus<Mesh>(R, r, 80, 40);
  const auto normals = ce_test::exact_normal_map<Kernel>(mesh, exact);
  auto flipped = mesh.add_property_map<Mesh::Vertex_index, Vector>("v:flipped").first;
  for (Mesh::Vertex_index v : vertices(mesh))
    flipped[v] = -normals[v];
  const Estimates e = estimate(mesh, params::vertex_normal_map(normals));
  const Estimates f = estimate(mesh, params::vertex_normal_map(flipped));
  for (std::size_t k = 0; k < exact.size(); ++k) {
    ASSERT_EQ(e.status[k], Estimation_status::ok);
    EXPECT_NEAR(f.mean[k], -e.mean[k], 1e-12 * (1 + std::abs(e.mean[k])));
  }
  const Errors t = errors(e, exact, {});
  std::printf("torus 80x40, exact normals: RMS H %.3e K %.3e\n", t.mean.stats().rms, t.gaussian.stats().rms);
  EXPECT_LT(t.mean.stats().rms, 1e-2);
}

#ifdef CGAL_LINKED_WITH_TBB
TEST(Curve_network, SequentialAndParallelAreIdentical)
{
  // More vertices than one parallel block; irregular, so both paths and the
  // fallback are exercised.
  const ce_test::Soup soup =
    ce_test::jittered_grid_graph_soup(ce_test::hamann_table1_functions()[8], 200, -1, 1, 0.2, 3);
  const Mesh mesh = ce_test::to_mesh<Mesh>(soup);
  const Estimates sequential = estimate<CGAL::Sequential_tag>(mesh, params::extrapolation_order(2));
  const Estimates parallel = estimate<CGAL::Parallel_tag>(mesh, params::extrapolation_order(2));
  for (std::size_t i = 0; i < soup.points.size(); ++i) {
    ASSERT_EQ(sequential.status[i], parallel.status[i]);
    ASSERT_EQ(std::memcmp(&sequential.principal[i], &parallel.principal[i], sizeof(Curvatures)), 0) << i;
  }
}
#endif

} // namespace
