// SPDX-License-Identifier: GPL-3.0-or-later
// smallest_eigenvector (internal/symmetric_eigen.h), the frame of the degree-4 fit: against the
// exact eigenvector of A = R diag(l1, l2, l3) R^T in random rotations R, from a smallest eigenvalue
// of 0 or 1e-14 times the others (points on a plane) to one equal to the next (a double root). A is
// only known to rounding, so the bound on the angle is that of a perturbation of A by a few ulps of
// its largest eigenvalue, 1e-15 l3 / (l2 - l1), where l1 <= l2 / 2: as Eigen's direct solver does
// (measured, 2,000 matrices per case: at most 0.88e-15 l3 / (l2 - l1), Eigen's 0.65e-15). Closer to
// a double root the eigenvalue from the determinant loses a further factor l2 / (l2 - l1).
#include <CGAL/Curvature_estimation/internal/symmetric_eigen.h>

#include <Eigen/Geometry>

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace {

namespace CEI = CGAL::Curvature_estimation::internal;

Eigen::Matrix3d random_rotation(std::mt19937& random)
{
  std::normal_distribution<double> normal;
  Eigen::Quaterniond q(normal(random), normal(random), normal(random), normal(random));
  return q.normalized().toRotationMatrix();
}

// The sine of the angle between two lines.
double line_angle(const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{
  return a.cross(b).norm() / (a.norm() * b.norm());
}

TEST(SmallestEigenvector, SeparatedSmallestEigenvalue)
{
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(0.2, 1.0);
  int cases = 0;
  for (double ratio : {0.0, 1e-14, 1e-10, 1e-6, 1e-3, 1e-2, 0.1, 0.5, 0.9, 0.99})
    for (double scale : {1e-12, 1.0, 1e9})
      for (int trial = 0; trial < 200; ++trial) {
        const double l2 = scale * unit(random), l3 = l2 + scale * unit(random);
        const double l1 = ratio * l2;
        const Eigen::Matrix3d r = random_rotation(random);
        const Eigen::Matrix3d a = r * Eigen::Vector3d(l1, l2, l3).asDiagonal() * r.transpose();
        const Eigen::Vector3d v = CEI::smallest_eigenvector(a);
        ASSERT_NEAR(v.norm(), 1.0, 1e-15) << ratio << " " << scale;
        const double bound = 1e-15 * l3 / (l2 - l1) * (ratio <= 0.5 ? 1.0 : 10 * l2 / (l2 - l1));
        EXPECT_LE(line_angle(v, r.col(0)), bound) << "ratio " << ratio << " scale " << scale;
        ++cases;
      }
  EXPECT_EQ(cases, 10 * 3 * 200);
}

// Where the two smallest eigenvalues are equal, any unit vector of their plane is an answer; the
// eigenvalue, a double root, is known to about the square root of the rounding, and so is the
// plane (measured: at most 1.2e-6 away from it); of rank 1 (points on a line), to rounding.
TEST(SmallestEigenvector, DoubleSmallestEigenvalue)
{
  std::mt19937 random(11);
  for (double l1 : {0.0, 1e-8, 0.3})
    for (int trial = 0; trial < 100; ++trial) {
      const Eigen::Matrix3d r = random_rotation(random);
      const Eigen::Matrix3d a = r * Eigen::Vector3d(l1, l1, 1.0).asDiagonal() * r.transpose();
      const Eigen::Vector3d v = CEI::smallest_eigenvector(a);
      ASSERT_NEAR(v.norm(), 1.0, 1e-15);
      EXPECT_LE(std::abs(v.dot(r.col(2))), l1 == 0 ? 1e-14 : 1e-5) << "l1 " << l1;
    }
}

TEST(SmallestEigenvector, ZeroMatrixGivesNaN)
{
  EXPECT_FALSE(std::isfinite(CEI::smallest_eigenvector(Eigen::Matrix3d::Zero()).sum()));
}

// The least-squares plane of points on a tilted plane, with their order of magnitude far from 1.
TEST(LeastSquaresHyperplaneNormal, PointsOnAPlane)
{
  std::mt19937 random(3);
  std::uniform_real_distribution<double> coordinate(-1, 1);
  const Eigen::Vector3d normal = Eigen::Vector3d(1, -2, 0.5).normalized();
  const Eigen::Vector3d u = normal.unitOrthogonal(), w = normal.cross(u);
  for (double scale : {1e-6, 1.0, 1e6}) {
    Eigen::Vector3d points[37];
    for (Eigen::Vector3d& p : points)
      p = scale * (Eigen::Vector3d(3, 4, 5) + coordinate(random) * u + coordinate(random) * w);
    const Eigen::Vector3d found = CEI::least_squares_hyperplane_normal<3>(points, 37);
    EXPECT_LE(line_angle(found, normal), 1e-13) << scale;
  }
}

} // namespace
