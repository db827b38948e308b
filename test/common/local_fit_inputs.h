// SPDX-License-Identifier: GPL-3.0-or-later
// Exact inputs for the tests of the local fit (test_taylor_fit, test_shape_operator,
// test_tangent_frame): deterministic random frames, stencils and symmetric
// matrices, the closed-form shape operator of a graph, and an independent
// long-double condition number. Random numbers come from the raw output of
// std::mt19937 with fixed seeds, so the inputs are the same on every platform.
#ifndef CE_TEST_COMMON_LOCAL_FIT_INPUTS_H
#define CE_TEST_COMMON_LOCAL_FIT_INPUTS_H

#include <CGAL/Curvature_estimation/internal/shape_operator.h>
#include <CGAL/Curvature_estimation/internal/tangent_frame.h>
#include <CGAL/Curvature_estimation/internal/taylor_fit/taylor_fit.h>

#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <Eigen/LU>

#include "random_numbers.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace ce_test {
namespace local_fit {

namespace CEI = CGAL::Curvature_estimation::internal;

constexpr double pi = 3.14159265358979323846;

template <int R, int C>
using Mat = Eigen::Matrix<double, R, C>;
template <int N>
using Vec = Eigen::Matrix<double, N, 1>;

// ---------------------------------------------------------------------------
// Deterministic random numbers
// ---------------------------------------------------------------------------

class Random
{
public:
  explicit Random(std::uint32_t seed)
      : gen_(seed)
  {}

  double uniform(double lo, double hi) { return ce_test::uniform(gen_, lo, hi); }

  template <int N>
  Vec<N> in_cube(double half_width = 1.0)
  {
    Vec<N> v;
    for (int i = 0; i < N; ++i)
      v[i] = uniform(-half_width, half_width);
    return v;
  }

  // A unit vector (rejection sampling in the unit ball, so no direction is favoured).
  template <int N>
  Vec<N> unit_vector()
  {
    for (;;) {
      const Vec<N> v = in_cube<N>();
      const double r = v.norm();
      if (r > 0.1 && r <= 1.0)
        return v / r;
    }
  }

  // A rotation (orthogonal, determinant +1) by Gram-Schmidt of random vectors.
  template <int N>
  Mat<N, N> rotation()
  {
    Mat<N, N> q;
    for (int j = 0; j < N;) {
      Vec<N> v = unit_vector<N>();
      for (int pass = 0; pass < 2; ++pass)
        for (int i = 0; i < j; ++i)
          v -= q.col(i).dot(v) * q.col(i);
      if (v.norm() < 0.1)
        continue;
      q.col(j) = v.normalized();
      ++j;
    }
    if (q.determinant() < 0)
      q.col(0) = -q.col(0);
    return q;
  }

private:
  std::mt19937 gen_;
};

// ---------------------------------------------------------------------------
// Small exact helpers
// ---------------------------------------------------------------------------

template <typename M>
double orthonormality_error(const M& m)
{
  using Square = Eigen::Matrix<double, M::ColsAtCompileTime, M::ColsAtCompileTime>;
  return (m.transpose() * m - Square::Identity()).cwiseAbs().maxCoeff();
}

// Distance between two unit vectors up to sign (directions have no orientation).
template <typename A, typename B>
double distance_up_to_sign(const A& a, const B& b)
{
  return (std::min)((a - b).norm(), (a + b).norm());
}

inline Mat<2, 2> rotation2(double angle)
{
  Mat<2, 2> r;
  r << std::cos(angle), -std::sin(angle), std::sin(angle), std::cos(angle);
  return r;
}

// Rotation of R^3 about the unit `axis` by `angle` (Rodrigues).
inline Mat<3, 3> rotation3(const Vec<3>& axis, double angle)
{
  Mat<3, 3> k;
  k << 0, -axis.z(), axis.y(), axis.z(), 0, -axis.x(), -axis.y(), axis.x(), 0;
  return Mat<3, 3>::Identity() + std::sin(angle) * k + (1 - std::cos(angle)) * k * k;
}

// Stencil in the plane: m points at stratified angles (one per sector 2 pi / m,
// jittered inside it) and radii in [rmin, rmax]; well spread by construction.
inline std::vector<Vec<2>> spread_stencil_2d(Random& random, int m, double rmin = 0.4, double rmax = 1.0)
{
  std::vector<Vec<2>> out;
  const double offset = random.uniform(0, 2 * pi);
  for (int k = 0; k < m; ++k) {
    const double angle = offset + 2 * pi * (k + random.uniform(0.1, 0.9)) / m;
    const double radius = random.uniform(rmin, rmax);
    out.push_back(radius * Vec<2>(std::cos(angle), std::sin(angle)));
  }
  return out;
}

// Stencil in R^3: m points with radii in [rmin, 1], one per octant first, then anywhere.
inline std::vector<Vec<3>> spread_stencil_3d(Random& random, int m, double rmin = 0.4)
{
  std::vector<Vec<3>> out;
  for (int k = 0; static_cast<int>(out.size()) < m; ++k) {
    Vec<3> v = random.unit_vector<3>() * random.uniform(rmin, 1.0);
    if (k < 8)
      for (int i = 0; i < 3; ++i)
        v[i] = ((k >> i) & 1 ? 1.0 : -1.0) * std::abs(v[i]);
    out.push_back(v);
  }
  return out;
}

// A symmetric matrix with the prescribed eigenvalues (ascending) and eigenvectors
// (the columns of the orthogonal `vectors`).
template <int D>
Mat<D, D> symmetric_from(const Vec<D>& eigenvalues, const Mat<D, D>& vectors)
{
  return vectors * eigenvalues.asDiagonal() * vectors.transpose();
}

// Prescribed eigenvalues, ascending, at least `gap` apart.
template <int D>
Vec<D> separated_eigenvalues(Random& random, double lo, double hi, double gap)
{
  for (;;) {
    Vec<D> l;
    for (int i = 0; i < D; ++i)
      l[i] = random.uniform(lo, hi);
    std::sort(l.data(), l.data() + D);
    bool ok = true;
    for (int i = 0; i + 1 < D; ++i)
      ok = ok && (l[i + 1] - l[i] >= gap);
    if (ok)
      return l;
  }
}

// A frame of R^N: origin, rotation R; the graph is o + R (x, h(x)), its normal R e_N.
template <int N>
struct Frame
{
  Vec<N> origin;
  Mat<N, N> rotation;
  Vec<N> normal() const { return rotation.col(N - 1); }
  Mat<N, N - 1> tangents() const { return rotation.template leftCols<N - 1>(); }
};

// Frames used by the rotated-frame tests: the identity, the flipped frame, normals
// on other axes, nearly on an axis, then random rotations.
template <int N>
Frame<N> test_frame(Random& random, int index)
{
  Frame<N> f;
  f.origin = random.in_cube<N>();
  if (index == 0) {
    f.rotation.setIdentity();
  } else if (index == 1) { // normal -e_N, a rotation by pi about e_1
    f.rotation.setIdentity();
    f.rotation(1, 1) = -1;
    f.rotation(N - 1, N - 1) = -1;
  } else if (index < 2 + N - 1) { // cyclic permutation of the axes: normal on another axis
    const int shift = index - 1;
    f.rotation.setZero();
    for (int j = 0; j < N; ++j)
      f.rotation((j + shift) % N, j) = 1;
    if (f.rotation.determinant() < 0)
      f.rotation.col(0) = -f.rotation.col(0);
  } else if (index < 2 + N - 1 + 2) { // nearly on an axis: a tiny random rotation
    Mat<N, N> a = Mat<N, N>::Zero();
    const double size = index % 2 ? 1e-9 : 1e-4;
    for (int i = 0; i < N; ++i)
      for (int j = i + 1; j < N; ++j) {
        a(i, j) = size * random.uniform(-1, 1);
        a(j, i) = -a(i, j);
      }
    // Cayley transform: an exact-enough rotation close to the identity.
    f.rotation = (Mat<N, N>::Identity() - a).inverse() * (Mat<N, N>::Identity() + a);
  } else {
    f.rotation = random.rotation<N>();
  }
  return f;
}

// Adds the samples (x, h(x)), placed in R^N by `frame`, to `fit`, expressed in the
// frame (origin, tangents T, normal n): x' = T^T (p - o), h' = n . (p - o).
template <int D, int F, int L, typename Height>
void add_samples(CEI::Taylor_fit<D, F, L>& fit, const std::vector<Vec<D>>& xs, const Height& height,
                 const Frame<D + 1>& frame, const Mat<D + 1, D>& tangents)
{
  const Vec<D + 1> n = frame.normal();
  for (const Vec<D>& x : xs) {
    Vec<D + 1> local;
    local << x, height(x);
    const Vec<D + 1> q = (frame.origin + frame.rotation * local) - frame.origin;
    fit.add(tangents.transpose() * q, n.dot(q));
  }
}

// Exact curvatures and directions of the graph of h(x) = g.x + 1/2 x^T C x over
// the frame (T, n) at the origin (D = 2), by the closed form of the 2x2
// (non-symmetric) Weingarten matrix M = (1/l) G^-1 C, G = I + g g^T,
// l = sqrt(1 + |g|^2): its eigenvalues mu are the upward normal curvatures, the
// library's curvatures are -mu, sorted decreasing; a direction is X_a = T a + n (g.a)
// for an eigenvector a of M.
struct Exact_graph_curvature
{
  std::array<double, 2> curvatures; // decreasing
  std::array<Vec<3>, 2> directions; // unit
  Vec<3> normal;
};

inline Exact_graph_curvature exact_graph_curvature(const Mat<2, 2>& c, const Vec<2>& g, const Mat<3, 2>& t,
                                                   const Vec<3>& n)
{
  const long double g0 = g[0], g1 = g[1];
  const long double l2 = 1.0L + g0 * g0 + g1 * g1;
  const long double l = std::sqrt(l2);
  // G^-1 = I - g g^T / l^2 (Sherman-Morrison)
  const long double gi00 = 1 - g0 * g0 / l2, gi01 = -g0 * g1 / l2, gi11 = 1 - g1 * g1 / l2;
  const long double c00 = c(0, 0), c01 = c(0, 1), c11 = c(1, 1);
  const long double m00 = (gi00 * c00 + gi01 * c01) / l, m01 = (gi00 * c01 + gi01 * c11) / l;
  const long double m10 = (gi01 * c00 + gi11 * c01) / l, m11 = (gi01 * c01 + gi11 * c11) / l;
  const long double half_trace = 0.5L * (m00 + m11);
  const long double det = m00 * m11 - m01 * m10;
  const long double disc = std::sqrt((std::max)(0.0L, half_trace * half_trace - det));
  const long double mu[2] = {half_trace - disc, half_trace + disc}; // ascending
  Exact_graph_curvature r;
  for (int i = 0; i < 2; ++i) {
    r.curvatures[i] = static_cast<double>(-mu[i]);
    // (M - mu I) a = 0: take the longer of the two candidate null vectors.
    const long double a1x = m01, a1y = mu[i] - m00;
    const long double a2x = mu[i] - m11, a2y = m10;
    const bool first = a1x * a1x + a1y * a1y >= a2x * a2x + a2y * a2y;
    const Vec<2> a(static_cast<double>(first ? a1x : a2x), static_cast<double>(first ? a1y : a2y));
    r.directions[i] = (t * a + n * g.dot(a)).normalized();
  }
  r.normal = (n - t * g) / static_cast<double>(l);
  return r;
}

// Independent 1-norm condition number of a symmetric positive definite matrix
// after scaling it to a unit diagonal, in long double with Gauss-Jordan inversion.
// (Invariant to any diagonal scaling and permutation of the unknowns, so the
// monomials may be scaled and ordered differently from the library's.)
inline long double one_norm_condition(std::vector<std::vector<long double>> a)
{
  const std::size_t n = a.size();
  auto norm1 = [n](const std::vector<std::vector<long double>>& m) {
    long double best = 0;
    for (std::size_t j = 0; j < n; ++j) {
      long double sum = 0;
      for (std::size_t i = 0; i < n; ++i)
        sum += std::abs(m[i][j]);
      best = (std::max)(best, sum);
    }
    return best;
  };
  const long double norm = norm1(a);
  std::vector<std::vector<long double>> inv(n, std::vector<long double>(n, 0));
  for (std::size_t i = 0; i < n; ++i)
    inv[i][i] = 1;
  for (std::size_t col = 0; col < n; ++col) {
    std::size_t pivot = col;
    for (std::size_t r = col + 1; r < n; ++r)
      if (std::abs(a[r][col]) > std::abs(a[pivot][col]))
        pivot = r;
    std::swap(a[col], a[pivot]);
    std::swap(inv[col], inv[pivot]);
    const long double p = a[col][col];
    for (std::size_t j = 0; j < n; ++j) {
      a[col][j] /= p;
      inv[col][j] /= p;
    }
    for (std::size_t r = 0; r < n; ++r)
      if (r != col) {
        const long double f = a[r][col];
        for (std::size_t j = 0; j < n; ++j) {
          a[r][j] -= f * a[col][j];
          inv[r][j] -= f * inv[col][j];
        }
      }
  }
  return norm * norm1(inv);
}

// The documented sample coordinates of the fit <D, F, L> at x: x itself, then
// the coordinates of x x^T / 2 and of x (x) x (x) x in orthonormal bases of the
// symmetric tensors (entry times the square root of the number of its index
// orderings). The 1-norm condition does not depend on their order.
template <int D>
std::vector<long double> monomials(const Vec<D>& x, int first_order, int last_order)
{
  std::vector<long double> m;
  if (first_order == 1)
    for (int i = 0; i < D; ++i)
      m.push_back(x[i]);
  for (int i = 0; i < D; ++i)
    for (int j = i; j < D; ++j)
      m.push_back((i == j ? 1.0L : std::sqrt(2.0L)) * static_cast<long double>(x[i]) * x[j] / 2);
  if (last_order == 3)
    for (int i = 0; i < D; ++i)
      for (int j = i; j < D; ++j)
        for (int k = j; k < D; ++k) {
          const int orderings = i == k ? 1 : (i == j || j == k) ? 3 : 6;
          m.push_back(std::sqrt(static_cast<long double>(orderings)) * static_cast<long double>(x[i]) * x[j] * x[k]);
        }
  return m;
}

template <int D>
long double independent_condition(const std::vector<Vec<D>>& xs, int first_order, int last_order)
{
  const std::size_t n = monomials<D>(Vec<D>::Zero(), first_order, last_order).size();
  std::vector<std::vector<long double>> a(n, std::vector<long double>(n, 0));
  for (const Vec<D>& x : xs) {
    const std::vector<long double> m = monomials<D>(x, first_order, last_order);
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = 0; j < n; ++j)
        a[i][j] += m[i] * m[j];
  }
  return one_norm_condition(a);
}

inline void check_graph_curvature(const CEI::Graph_curvature<3>& gc, const Exact_graph_curvature& exact,
                                  double tolerance, const char* what, int trial)
{
  for (int i = 0; i < 2; ++i) {
    EXPECT_NEAR(gc.curvatures[i], exact.curvatures[i], tolerance) << what << ", trial " << trial;
    EXPECT_LE(distance_up_to_sign(gc.directions.col(i), exact.directions[i]), 1e3 * tolerance)
      << what << ", trial " << trial << ", direction " << i;
    EXPECT_NEAR(gc.directions.col(i).norm(), 1.0, 1e-14) << what << ", trial " << trial;
    EXPECT_LE(std::abs(gc.directions.col(i).dot(gc.normal)), 1e-14) << what << ", trial " << trial;
  }
  EXPECT_GE(gc.curvatures[0], gc.curvatures[1]);
  EXPECT_LE(std::abs(gc.directions.col(0).dot(gc.directions.col(1))), 1e-14) << what << ", trial " << trial;
  EXPECT_LE((gc.normal - exact.normal).norm(), tolerance) << what << ", trial " << trial;
  EXPECT_NEAR(gc.normal.norm(), 1.0, 1e-14);
}

} // namespace local_fit
} // namespace ce_test

#endif // CE_TEST_COMMON_LOCAL_FIT_INPUTS_H
