// SPDX-License-Identifier: GPL-3.0-or-later
// point_set_curvatures(): the fits of the mesh estimators over nearest neighbors. Against the mesh fit over the same
// ball; exact on polynomial graphs of the fit's degree; invariant under rigid motions and scaling; the orientation
// outward on closed surfaces and one-sided on open patches; every point-set file of CGAL's data tarball with its
// status counts; on the tarball's spheres no worse than CGAL's jet fitting on the same nearest neighbors.
#include <CGAL/Curvature_estimation/mean_edge_length.h>
#include <CGAL/Curvature_estimation/paraboloid_fitting.h>
#include <CGAL/Curvature_estimation/point_set_curvatures.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Monge_via_jet_fitting.h>
#include <CGAL/Point_set_3.h>
#include <CGAL/Point_set_3/IO.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/property_map.h>

#include <gtest/gtest.h>

#include "estimator_runs.h"
#include "noisy_meshes.h"
#include "random_numbers.h"
#include "test_surfaces.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <map>
#include <string>
#include <vector>

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Vector = Kernel::Vector_3;
using Mesh = CGAL::Surface_mesh<Point>;
using Point_set = CGAL::Point_set_3<Point>;
using Status = CGAL::Curvature_estimation::Estimation_status;
namespace CE = CGAL::Curvature_estimation;
namespace params = CGAL::Curvature_estimation::parameters;

// The outputs at points given as a vector, keyed by index.
struct Outputs
{
  std::vector<double> H, K;
  std::vector<Status> status;
  std::vector<Vector> normal;
  std::vector<std::size_t> part;
  std::vector<double> confidence;
};

template <typename ConcurrencyTag = CGAL::Sequential_tag, typename Extra>
Outputs run(const std::vector<Eigen::Vector3d>& points, const Extra& extra)
{
  std::vector<Point> p;
  for (const Eigen::Vector3d& q : points)
    p.emplace_back(q.x(), q.y(), q.z());
  std::vector<std::size_t> indices(p.size());
  for (std::size_t i = 0; i < p.size(); ++i)
    indices[i] = i;
  Outputs o;
  o.H.resize(p.size());
  o.K.resize(p.size());
  o.status.resize(p.size());
  o.normal.resize(p.size());
  o.part.resize(p.size());
  o.confidence.resize(p.size());
  CE::point_set_curvatures<ConcurrencyTag>(indices,
                                           extra.point_map(CGAL::make_property_map(p))
                                             .vertex_mean_curvature_map(CGAL::make_property_map(o.H))
                                             .vertex_Gaussian_curvature_map(CGAL::make_property_map(o.K))
                                             .vertex_estimation_status_map(CGAL::make_property_map(o.status))
                                             .estimated_normal_map(CGAL::make_property_map(o.normal))
                                             .orientation_component_map(CGAL::make_property_map(o.part))
                                             .orientation_confidence_map(CGAL::make_property_map(o.confidence)));
  return o;
}

double rms_error(const std::vector<double>& estimated, const std::vector<double>& exact)
{
  ce_test::Error_accumulator a;
  for (std::size_t i = 0; i < exact.size(); ++i)
    a.add(exact[i], estimated[i]);
  return a.stats().rms;
}

std::vector<double> exact_H(const std::vector<ce_test::Exact_curvature>& exact)
{
  std::vector<double> H;
  for (const auto& e : exact)
    H.push_back(e.H);
  return H;
}

// The same ball about each vertex of a mesh and about each point of its vertex set: the point-set fit's H RMS is
// within 1.2 times the mesh fit's of the same degree.
TEST(PointSetCurvatures, WithinTheMeshFitOverTheSameBall)
{
  struct Case
  {
    const char* name;
    ce_test::Soup soup;
    std::vector<ce_test::Exact_curvature> exact;
  };
  std::vector<Case> cases;
  {
    ce_test::Soup s = ce_test::torus_soup(1, 0.4, 120, 48, 0.2, 7);
    cases.push_back({"jittered torus", s, ce_test::torus_curvatures(1, 0.4, s)});
  }
  {
    ce_test::Soup s = ce_test::ellipsoid_soup(1, 0.8, 0.6, 4, 0.2, 3);
    cases.push_back({"jittered ellipsoid", s, ce_test::ellipsoid_curvatures(1, 0.8, 0.6, s)});
  }
  for (const auto& g : ce_test::hamann_table1_functions())
    if (g.name == "exponential" || g.name == "trigonometric") {
      ce_test::Soup s = ce_test::delaunay_graph_soup(g, 4000, -1, 1, 5);
      cases.push_back({g.name == "exponential" ? "Delaunay exponential" : "Delaunay trigonometric", s,
                       ce_test::graph_curvatures(g, s)});
    }
  for (const Case& c : cases) {
    const Mesh mesh = ce_test::to_mesh<Mesh>(c.soup);
    const double radius = 3 * CE::mean_edge_length(mesh);
    // Interior points only on the graphs, whose domain's edge the two see alike.
    std::vector<std::size_t> kept;
    for (std::size_t i = 0; i < c.soup.points.size(); ++i)
      if (c.soup.params[i].cwiseAbs().maxCoeff() < 1 - 1.5 * radius || c.soup.params[i].cwiseAbs().maxCoeff() > 1.5)
        kept.push_back(i);
    for (int degree = 2; degree <= 4; ++degree) {
      const auto mesh_fit = ce_test::run_with_all_outputs<Kernel>(
        mesh, [](const Mesh& m, const auto& np) { CE::paraboloid_fitting_curvatures(m, np); },
        params::ball_radius(radius).fit_degree(degree));
      const Outputs points = run(c.soup.points, params::neighbor_radius(radius).fit_degree(degree));
      ce_test::Error_accumulator on_mesh, on_points;
      for (std::size_t i : kept) {
        on_mesh.add(c.exact[i].H, mesh_fit.mean[i]);
        on_points.add(c.exact[i].H, points.H[i]);
      }
      std::printf("%-24s degree %d  H RMS: points %.3g, mesh %.3g (ratio %.2f)\n", c.name, degree,
                  on_points.stats().rms, on_mesh.stats().rms, on_points.stats().rms / on_mesh.stats().rms);
      EXPECT_LE(on_points.stats().rms, 1.2 * on_mesh.stats().rms) << c.name << ", degree " << degree;
    }
  }
}

// With the graph's axis as the given normal, the fit of degree 4 is exact on polynomial graphs of degree 2 to 4, at
// random points. (The fits of degree 2 and 3 subtract the quartic term their curvatures imply, as on meshes: exact
// on no polynomial graph, fourth order on spheres.)
TEST(PointSetCurvatures, ExactOnPolynomialGraphsOfTheFitsDegree)
{
  const std::vector<ce_test::Graph_function> graphs = {
    {"quadric", [](double x, double y) { return 0.4 * x * x - 0.3 * x * y + 0.2 * y * y + 0.1 * x; },
     [](double x, double y) { return 0.8 * x - 0.3 * y + 0.1; }, [](double x, double y) { return -0.3 * x + 0.4 * y; },
     [](double, double) { return 0.8; }, [](double, double) { return -0.3; }, [](double, double) { return 0.4; }},
    {"cubic", [](double x, double y) { return 0.15 * (x * x * x + 2 * x * x * y - x * y + 2 * y * y); },
     [](double x, double y) { return 0.15 * (3 * x * x + 4 * x * y - y); },
     [](double x, double y) { return 0.15 * (2 * x * x - x + 4 * y); },
     [](double x, double y) { return 0.15 * (6 * x + 4 * y); }, [](double x, double) { return 0.15 * (4 * x - 1); },
     [](double, double) { return 0.6; }},
    {"quartic", [](double x, double y) { return 0.1 * (x * x * x * x - 2 * x * x * y * y + y * y * y - x * y); },
     [](double x, double y) { return 0.1 * (4 * x * x * x - 4 * x * y * y - y); },
     [](double x, double y) { return 0.1 * (-4 * x * x * y + 3 * y * y - x); },
     [](double x, double y) { return 0.1 * (12 * x * x - 4 * y * y); },
     [](double x, double y) { return 0.1 * (-8 * x * y - 1); },
     [](double x, double y) { return 0.1 * (-4 * x * x + 6 * y); }}};
  std::mt19937 gen(11);
  std::vector<Eigen::Vector2d> xy;
  for (int i = 0; i < 2000; ++i)
    xy.emplace_back(ce_test::uniform_symmetric(gen), ce_test::uniform_symmetric(gen));
  for (const ce_test::Graph_function& g : graphs) {
    const int degree = 4;
    std::vector<Point> points;
    std::vector<std::size_t> indices;
    for (const Eigen::Vector2d& q : xy) {
      indices.push_back(points.size());
      points.emplace_back(q.x(), q.y(), g.f(q.x(), q.y()));
    }
    std::vector<Vector> up(points.size(), Vector(0, 0, 1));
    std::vector<double> H(points.size()), K(points.size());
    CE::point_set_curvatures(indices, params::point_map(CGAL::make_property_map(points))
                                        .normal_map(CGAL::make_property_map(up))
                                        .fit_degree(degree)
                                        .vertex_mean_curvature_map(CGAL::make_property_map(H))
                                        .vertex_Gaussian_curvature_map(CGAL::make_property_map(K)));
    double worst = 0;
    for (std::size_t i = 0; i < xy.size(); ++i) {
      const ce_test::Exact_curvature e = ce_test::graph_curvature(g, xy[i].x(), xy[i].y());
      worst = (std::max)({worst, std::abs(H[i] - e.H), std::abs(K[i] - e.K)});
    }
    EXPECT_LT(worst, 1e-9) << g.name;
  }
}

// Rotated, translated and scaled by 1000, the same point set gives the same curvature divided by 1000.
TEST(PointSetCurvatures, InvariantUnderRigidMotionsAndScaling)
{
  std::vector<Eigen::Vector3d> points;
  std::vector<ce_test::Exact_curvature> exact;
  ce_test::torus_samples(3000, 4, points, exact);
  const Eigen::Matrix3d rotation =
    (Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()) * Eigen::AngleAxisd(2.1, Eigen::Vector3d::UnitZ()))
      .toRotationMatrix();
  std::vector<Eigen::Vector3d> moved;
  for (const Eigen::Vector3d& p : points)
    moved.push_back(1000 * (rotation * p) + Eigen::Vector3d(-3e3, 5e2, 7e3));
  for (int degree = 2; degree <= 4; ++degree) {
    const Outputs a = run(points, params::fit_degree(degree));
    const Outputs b = run(moved, params::fit_degree(degree));
    for (std::size_t i = 0; i < points.size(); ++i) {
      ASSERT_EQ(a.status[i], b.status[i]) << i;
      EXPECT_NEAR(1000 * b.H[i], a.H[i], 1e-8 * (1 + std::abs(a.H[i]))) << i << ", degree " << degree;
      EXPECT_NEAR(1e6 * b.K[i], a.K[i], 1e-8 * (1 + std::abs(a.K[i]))) << i << ", degree " << degree;
    }
  }
}

// Without normals: outward on a closed surface (random samples of a torus, its saddle part too), one side on an open
// patch; the outward normal's sign is the package's.
TEST(PointSetCurvatures, OrientationIsConsistent)
{
  std::vector<Eigen::Vector3d> points;
  std::vector<ce_test::Exact_curvature> exact;
  ce_test::torus_samples(20000, 8, points, exact);
  const Outputs torus = run(points, params::default_values());
  std::size_t outward = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    outward += Eigen::Vector3d(torus.normal[i].x(), torus.normal[i].y(), torus.normal[i].z()).dot(exact[i].normal) > 0;
    EXPECT_EQ(torus.part[i], 0u);
  }
  EXPECT_EQ(outward, points.size());
  const double torus_rms = rms_error(torus.H, exact_H(exact));
  std::printf("torus, 20000 random points, k = 16: H RMS %.3g\n", torus_rms);
  EXPECT_LT(torus_rms, 0.05);

  // A patch of the trigonometric graph: a saddle and bumps, all normals to one side.
  const ce_test::Graph_function g = ce_test::hamann_table1_functions()[8];
  std::mt19937 gen(5);
  std::vector<Eigen::Vector3d> patch;
  for (int i = 0; i < 5000; ++i) {
    const double x = ce_test::uniform_symmetric(gen), y = ce_test::uniform_symmetric(gen);
    patch.emplace_back(x, y, g.f(x, y));
  }
  const Outputs open = run(patch, params::default_values());
  std::size_t up = 0;
  for (std::size_t i = 0; i < patch.size(); ++i)
    up += open.normal[i].z() > 0;
  EXPECT_TRUE(up == 0 || up == patch.size()) << up << " of " << patch.size() << " up";

  // unsigned_curvatures: H >= 0 everywhere, |H| as oriented.
  const Outputs absolute = run(points, params::unsigned_curvatures(true));
  for (std::size_t i = 0; i < points.size(); ++i) {
    EXPECT_GE(absolute.H[i], 0);
    EXPECT_NEAR(absolute.H[i], std::abs(torus.H[i]), 1e-9);
    EXPECT_EQ(absolute.part[i], std::size_t(-1));
  }
}

// Few points, points on a line, non-finite coordinates: NaN and not_estimable there, nothing thrown.
TEST(PointSetCurvatures, DegenerateInputGivesNotEstimable)
{
  std::vector<Eigen::Vector3d> line;
  for (int i = 0; i < 50; ++i)
    line.emplace_back(0.1 * i, 0.2 * i, -0.05 * i);
  line.emplace_back(std::nan(""), 0, 0);
  const Outputs o = run(line, params::default_values());
  for (std::size_t i = 0; i < line.size(); ++i) {
    EXPECT_EQ(o.status[i], Status::not_estimable) << i;
    EXPECT_TRUE(std::isnan(o.H[i])) << i;
  }
  EXPECT_THROW(run(line, params::number_of_neighbors(2)), std::invalid_argument);
  EXPECT_THROW(run(line, params::number_of_neighbors(8).neighbor_radius(1.0)), std::invalid_argument);
  EXPECT_THROW(run(line, params::fit_degree(5)), std::invalid_argument);
}

// n uniformly random points on the sphere of radius r about the origin, moved along the radius by Gaussian noise
// of deviation `noise`.
std::vector<Eigen::Vector3d> sphere_samples(std::size_t n, double r, double noise, std::uint32_t seed)
{
  std::mt19937 gen(seed);
  std::vector<Eigen::Vector3d> points;
  while (points.size() < n) {
    const double z = ce_test::uniform_symmetric(gen), phi = ce_test::uniform(gen, 0, 2 * ce_test::pi);
    const Eigen::Vector3d u(std::sqrt(1 - z * z) * std::cos(phi), std::sqrt(1 - z * z) * std::sin(phi), z);
    points.push_back((r + noise * ce_test::standard_normal(gen)) * u);
  }
  return points;
}

// RMS of H - h over the points.
double rms_from(const std::vector<double>& H, double h) { return rms_error(H, std::vector<double>(H.size(), h)); }

// Random samples of a sphere of radius r, k nearest neighbors: k points of N spread over 4 pi r^2 fill a disc of
// radius R, R^2 = 4 k r^2 / N. A sphere has no cubic term in its own frame; in the frame of the plane of an
// asymmetric neighborhood (tilted by about R / r) the cubic terms it gets are of order R / r^2, and their leak into
// the quadratic coefficients a relative error of order (R / r)^2 = 4k / N: allowed k / N at every degree (the
// quartic term is subtracted at degrees 2 and 3, fitted at 4). Convergence as N quadruples at the same k: the error
// at least 2.5 times smaller (4 expected at degree 2, more at 3 and 4). With radial noise of deviation sigma, the s^2
// coefficient of a least squares fit over k points spread uniformly in s^2 in [0, R^2] has a deviation of about
// sigma sqrt(c / k) / R^2 in H, c = 12 with the basis (1, s^2) at degrees 2 and 3 (the cubic terms, odd, are
// uncorrelated with it), c = 192 with (1, s^2, s^4) at degree 4 (the inverse of the 3 x 3 Hilbert matrix): allowed
// three times that on top of the noise-free bound.
TEST(PointSetCurvatures, RandomSphereSamplesConvergeToTheExactCurvature)
{
  const double r = 2;
  for (int degree = 2; degree <= 4; ++degree) {
    const double k = double(CE::internal::default_point_set_neighbors(degree));
    double errors[2];
    for (int j = 0; j < 2; ++j) {
      const std::size_t n = j == 0 ? 2000 : 8000;
      const std::vector<Eigen::Vector3d> points = sphere_samples(n, r, 0, 21 + j);
      const Outputs o = run(points, params::fit_degree(degree));
      errors[j] = rms_from(o.H, 1 / r) * r;
      std::printf("sphere, %zu random points, degree %d, k = %g: relative H RMS %.3g (k/N = %.3g)\n", n, degree, k,
                  errors[j], k / double(n));
      EXPECT_LT(errors[j], k / double(n)) << n << " points, degree " << degree;
      for (std::size_t i = 0; i < n; ++i)
        ASSERT_NE(o.status[i], Status::not_estimable) << i;
    }
    std::printf("  order of convergence as N quadruples: %.2f\n", errors[0] / errors[1]);
    EXPECT_GT(errors[0] / errors[1], 2.5) << "degree " << degree;
  }
  // Noisy: sigma a tenth of the mean spacing.
  const std::size_t n = 8000;
  const double spacing = std::sqrt(4 * ce_test::pi * r * r / n), sigma = 0.1 * spacing;
  for (int degree = 2; degree <= 4; ++degree) {
    const double k = double(CE::internal::default_point_set_neighbors(degree));
    const double R2 = 4 * k * r * r / n;
    const Outputs o = run(sphere_samples(n, r, sigma, 5), params::fit_degree(degree));
    const double error = rms_from(o.H, 1 / r),
                 allowed = k / (n * r) + 3 * sigma * std::sqrt((degree == 4 ? 192 : 12) / k) / R2;
    std::printf("sphere, %zu random points, noise %.3g, degree %d: H RMS %.3g (allowed %.3g)\n", n, sigma, degree,
                error, allowed);
    EXPECT_LT(error, allowed) << "degree " << degree;
  }
}

// Random samples of an ellipsoid (not uniform by area), k nearest and radius neighborhoods: both converge to the
// exact curvature. At degree 2 the cubic terms of the surface leak into the quadratic coefficients of an asymmetric
// neighborhood, an error of order R (order 1 in the spacing, as on irregular meshes): at least 1.6 times smaller as
// the points quadruple (2 expected). Without normals every normal points outward.
TEST(PointSetCurvatures, RandomEllipsoidSamplesNearestAndRadius)
{
  const double a = 1, b = 0.8, c = 0.6;
  for (int by_radius = 0; by_radius < 2; ++by_radius) {
    double errors[2];
    for (int j = 0; j < 2; ++j) {
      const std::size_t n = j == 0 ? 3000 : 12000;
      std::vector<Eigen::Vector3d> points;
      std::vector<double> exact;
      std::vector<Eigen::Vector3d> outward;
      for (const Eigen::Vector3d& u : sphere_samples(n, 1, 0, 40 + j)) {
        points.emplace_back(a * u.x(), b * u.y(), c * u.z());
        const ce_test::Exact_curvature e = ce_test::ellipsoid_curvature(a, b, c, points.back());
        exact.push_back(e.H);
        outward.push_back(e.normal);
      }
      // The radius holding 16 points on average on the ellipsoid's area (about 4 pi (abc)^(2/3)).
      const double radius = std::sqrt(16 * 4 * std::pow(a * b * c, 2.0 / 3) / n);
      const Outputs o =
        by_radius ? run(points, params::neighbor_radius(radius)) : run(points, params::default_values());
      std::size_t inward = 0;
      for (std::size_t i = 0; i < n; ++i)
        inward += Eigen::Vector3d(o.normal[i].x(), o.normal[i].y(), o.normal[i].z()).dot(outward[i]) <= 0;
      EXPECT_EQ(inward, 0u);
      errors[j] = rms_error(o.H, exact);
      std::printf("ellipsoid, %zu random points, %s: H RMS %.3g\n", n, by_radius ? "radius" : "16 nearest", errors[j]);
    }
    std::printf("  order of convergence as N quadruples: %.2f\n", errors[0] / errors[1]);
    EXPECT_GT(errors[0] / errors[1], 1.6) << (by_radius ? "radius" : "nearest");
  }
}

// A given normal_map orients the result: on the sphere, outward normals give +1/r and the estimated normals
// outward, inward normals -1/r and the estimated normals inward.
TEST(PointSetCurvatures, GivenNormalsOrientTheResult)
{
  const double r = 2;
  const std::vector<Eigen::Vector3d> points = sphere_samples(3000, r, 0, 9);
  for (double side : {1.0, -1.0}) {
    std::vector<Vector> given;
    for (const Eigen::Vector3d& p : points)
      given.emplace_back(side * p.x() / r, side * p.y() / r, side * p.z() / r);
    const Outputs o = run(points, params::normal_map(CGAL::make_property_map(given)));
    for (std::size_t i = 0; i < points.size(); ++i) {
      EXPECT_NEAR(o.H[i], side / r, 0.02 / r) << i;
      EXPECT_GT(o.normal[i] * given[i], 0.99) << i;
      EXPECT_EQ(o.part[i], std::size_t(-1)) << i; // not oriented by the propagation
    }
  }
}

// Scan lines 0.05 apart sampled every 0.005: the 16 nearest neighbors of a point 8 samples or more from the end of
// its line are all on it (collinear), so the fit widens to 32, which reach the next lines; on a plane the widened
// fit is exact (H = 0). Checked on the lines with two neighboring lines on each side.
TEST(PointSetCurvatures, ScanLinesWiden)
{
  const auto plane = [](double x, double y) { return 0.3 * x - 0.2 * y; };
  const int lines = 8, samples = 60;
  std::vector<Eigen::Vector3d> points;
  std::vector<Eigen::Vector2d> xy;
  for (int line = 0; line < lines; ++line)
    for (int i = 0; i < samples; ++i) {
      xy.emplace_back(0.005 * i - 0.15, 0.05 * line - 0.175);
      points.emplace_back(xy.back().x(), xy.back().y(), plane(xy.back().x(), xy.back().y()));
    }
  std::vector<Vector> up(points.size(), Vector(0, 0, 1));
  const Outputs o = run(points, params::normal_map(CGAL::make_property_map(up)));
  std::size_t checked = 0;
  for (int line = 2; line < lines - 2; ++line)
    for (int i = 8; i < samples - 8; ++i) {
      const std::size_t j = std::size_t(line * samples + i);
      EXPECT_EQ(o.status[j], Status::widened) << line << ", " << i;
      EXPECT_NEAR(o.H[j], 0, 1e-9) << line << ", " << i;
      EXPECT_NEAR(o.K[j], 0, 1e-9) << line << ", " << i;
      ++checked;
    }
  EXPECT_EQ(checked, 4u * 44u);
}

// Fewer points than the fit's unknowns, and one non-finite point among good ones: not_estimable and NaN there only.
TEST(PointSetCurvatures, TooFewPointsAndNonFinitePoints)
{
  // 5 points in general position: the degree 2 fit with an intercept has 6 unknowns.
  const std::vector<Eigen::Vector3d> five = {{0, 0, 0}, {1, 0, 0.1}, {0, 1, 0.2}, {1, 1, 0.4}, {0.5, 0.3, 0.9}};
  const Outputs few = run(five, params::default_values());
  for (std::size_t i = 0; i < five.size(); ++i) {
    EXPECT_EQ(few.status[i], Status::not_estimable) << i;
    EXPECT_TRUE(std::isnan(few.H[i]) && std::isnan(few.K[i])) << i;
  }
  std::vector<Eigen::Vector3d> points = sphere_samples(2000, 1, 0, 3);
  points[17].y() = std::numeric_limits<double>::infinity();
  points[1200].z() = std::nan("");
  const Outputs o = run(points, params::default_values());
  for (std::size_t i = 0; i < points.size(); ++i)
    if (i == 17 || i == 1200) {
      EXPECT_EQ(o.status[i], Status::not_estimable) << i;
      EXPECT_TRUE(std::isnan(o.H[i]) && std::isnan(o.K[i])) << i;
    } else {
      EXPECT_NE(o.status[i], Status::not_estimable) << i;
      EXPECT_NEAR(o.H[i], 1, 0.05) << i;
    }
}

// An output map of a range's elements, by their position in the range.
struct Element_map
{
  using key_type = std::pair<Point, Vector>;
  using value_type = double;
  using reference = double&;
  using category = boost::writable_property_map_tag;
  const key_type* first;
  std::vector<double>* values;
  friend void put(const Element_map& map, const key_type& element, double value)
  {
    (*map.values)[std::size_t(&element - map.first)] = value;
  }
};

// A Point_set_3 (its normals given or not, outputs in its properties) and a vector of (point, normal) pairs with a
// point_map give what the index range gives.
TEST(PointSetCurvatures, PointSet3AndPairRanges)
{
  const std::vector<Eigen::Vector3d> points = sphere_samples(2000, 1.5, 0.002, 13);
  std::vector<Vector> outward;
  for (const Eigen::Vector3d& p : points)
    outward.emplace_back(p.x() / p.norm(), p.y() / p.norm(), p.z() / p.norm());
  for (int with_normals = 0; with_normals < 2; ++with_normals) {
    const Outputs expected = with_normals ? run(points, params::normal_map(CGAL::make_property_map(outward)))
                                          : run(points, params::default_values());
    Point_set set(with_normals == 1);
    for (std::size_t i = 0; i < points.size(); ++i) {
      const auto it = set.insert(Point(points[i].x(), points[i].y(), points[i].z()));
      if (with_normals)
        set.normal(*it) = outward[i];
    }
    auto H = set.add_property_map<double>("H").first;
    auto estimated = set.add_property_map<Vector>("estimated normal").first;
    CE::point_set_curvatures(set, params::vertex_mean_curvature_map(H).estimated_normal_map(estimated));
    std::vector<std::pair<Point, Vector>> pairs;
    for (std::size_t i = 0; i < points.size(); ++i)
      pairs.emplace_back(Point(points[i].x(), points[i].y(), points[i].z()), outward[i]);
    std::vector<double> pair_H(points.size());
    const Element_map pair_H_map{pairs.data(), &pair_H};
    const auto pair_point = CGAL::First_of_pair_property_map<std::pair<Point, Vector>>();
    if (with_normals)
      CE::point_set_curvatures(pairs, params::point_map(pair_point)
                                        .normal_map(CGAL::Second_of_pair_property_map<std::pair<Point, Vector>>())
                                        .vertex_mean_curvature_map(pair_H_map));
    else
      CE::point_set_curvatures(pairs, params::point_map(pair_point).vertex_mean_curvature_map(pair_H_map));
    std::size_t i = 0;
    for (Point_set::Index v : set) {
      EXPECT_EQ(H[v], expected.H[i]) << i;
      EXPECT_EQ(estimated[v], expected.normal[i]) << i;
      EXPECT_EQ(pair_H[i], expected.H[i]) << i;
      ++i;
    }
  }
}

// In parallel, the same values bit for bit as in sequence.
TEST(PointSetCurvatures, ParallelEqualsSequential)
{
  std::vector<Eigen::Vector3d> points;
  std::vector<ce_test::Exact_curvature> exact;
  ce_test::torus_samples(6000, 2, points, exact);
  for (int degree = 2; degree <= 4; ++degree) {
    const Outputs a = run<CGAL::Sequential_tag>(points, params::fit_degree(degree));
    const Outputs b = run<CGAL::Parallel_if_available_tag>(points, params::fit_degree(degree));
    for (std::size_t i = 0; i < points.size(); ++i) {
      ASSERT_EQ(a.status[i], b.status[i]) << i;
      ASSERT_EQ(a.H[i], b.H[i]) << i;
      ASSERT_EQ(a.K[i], b.K[i]) << i;
      ASSERT_EQ(a.normal[i], b.normal[i]) << i;
      ASSERT_EQ(a.part[i], b.part[i]) << i;
    }
  }
}

#ifdef CE_CGAL_DATA_POINTS_DIR
// Every point set of the tarball, read into a Point_set_3 (its normals, where the file has them, are given normals).
TEST(PointSetCurvatures, TarballPointSetsWithStatusCounts)
{
  namespace fs = std::filesystem;
  const fs::path directory = fs::path(CE_CGAL_DATA_POINTS_DIR) / "data" / "points_3";
  if (!fs::exists(directory))
    GTEST_SKIP() << "CGAL's data archive was not found at configure time";
  std::vector<fs::path> files;
  for (const fs::directory_entry& entry : fs::directory_iterator(directory))
    files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  for (const fs::path& file : files) {
    Point_set points;
    if (!CGAL::IO::read_point_set(file.string(), points) || points.empty()) {
      std::printf("%-28s not read as a point set\n", file.filename().string().c_str());
      continue;
    }
    const bool with_normals = points.has_normal_map();
    auto H = points.add_property_map<double>("H").first;
    auto status = points.add_property_map<Status>("status").first;
    CE::point_set_curvatures<CGAL::Parallel_if_available_tag>(
      points, params::vertex_mean_curvature_map(H).vertex_estimation_status_map(status));
    std::map<Status, std::size_t> counts;
    for (Point_set::Index i : points) {
      ++counts[status[i]];
      EXPECT_EQ(std::isnan(H[i]), status[i] == Status::not_estimable) << file << " point " << std::size_t(i);
    }
    std::printf("%-28s %7zu points%s: ok %zu, widened %zu, fallback %zu, not_estimable %zu\n",
                file.filename().string().c_str(), points.size(), with_normals ? " (normals)" : "", counts[Status::ok],
                counts[Status::widened], counts[Status::fallback], counts[Status::not_estimable]);
  }
}

// The tarball's spheres: H RMS against the sphere fitted to the points no more than that of CGAL's jet fitting
// (degree 2, as users call it) on the same 16 nearest neighbors, both unsigned.
TEST(PointSetCurvatures, TarballSpheresAtLeastAsAccurateAsJetFitting)
{
  namespace fs = std::filesystem;
  const fs::path directory = fs::path(CE_CGAL_DATA_POINTS_DIR) / "data" / "points_3";
  if (!fs::exists(directory))
    GTEST_SKIP() << "CGAL's data archive was not found at configure time";
  for (const char* name : {"sphere926.pwn", "sphere_1k.xyz", "sphere_20k.xyz"}) {
    Point_set points;
    ASSERT_TRUE(CGAL::IO::read_point_set((directory / name).string(), points)) << name;
    points.remove_normal_map();
    std::vector<Eigen::Vector3d> p;
    for (Point_set::Index i : points)
      p.emplace_back(points.point(i).x(), points.point(i).y(), points.point(i).z());
    Eigen::Vector3d center = Eigen::Vector3d::Zero();
    for (const Eigen::Vector3d& q : p)
      center += q / double(p.size());
    double radius = 0;
    for (const Eigen::Vector3d& q : p)
      radius += (q - center).norm() / double(p.size());
    const Outputs ours = run(p, params::number_of_neighbors(16).unsigned_curvatures(true));
    const CE::internal::Point_set_search search(p, CGAL::Sequential_tag());
    CE::internal::Point_set_search::Found found;
    ce_test::Error_accumulator jet, fit;
    std::size_t not_estimable = 0; // compared where point_set_curvatures estimates
    const auto point = [&](std::size_t j) {
      const Eigen::Vector3d& q = search.point(j); // j in the search's order
      return Kernel::Point_3(q.x(), q.y(), q.z());
    };
    for (std::size_t j = 0; j < p.size(); ++j) {
      const std::size_t i = search.original(j);
      search.nearest(CE::internal::Point_set_search::Index(j), 16, found);
      std::vector<Kernel::Point_3> neighborhood{point(j)};
      for (const auto& f : found)
        neighborhood.push_back(point(f.second));
      CGAL::Monge_via_jet_fitting<Kernel> monge;
      const auto form = monge(neighborhood.begin(), neighborhood.end(), 2, 2);
      if (ours.status[i] == Status::not_estimable) {
        ++not_estimable;
        continue;
      }
      jet.add(1 / radius, std::abs(0.5 * (form.principal_curvatures(0) + form.principal_curvatures(1))));
      fit.add(1 / radius, ours.H[i]);
    }
    EXPECT_LE(not_estimable, p.size() / 1000) << name;
    std::printf("%-16s H RMS: point_set_curvatures %.3g, jet fitting %.3g (1/r = %.3g, %zu not estimable)\n", name,
                fit.stats().rms, jet.stats().rms, 1 / radius, not_estimable);
    EXPECT_LE(fit.stats().rms, jet.stats().rms) << name;
  }
}
#endif

} // namespace
