// SPDX-License-Identifier: GPL-3.0-or-later
// Curvature, tangent and principal normal of a space curve known by a few points
// (Wollmann 2000, sections 2, 3 and 5): the circle through three points
// (Todd and McLeod 1986), the quadratic Bezier segment through three points
// (Wollmann's eq. 1), and its O(h^2n) generalisation from the points at
// +-h, ..., +-nh. Pure functions of the points; no mesh.
#ifndef CGAL_CURVATURE_ESTIMATION_INTERNAL_CURVE_CURVATURE_H
#define CGAL_CURVATURE_ESTIMATION_INTERNAL_CURVE_CURVATURE_H

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cmath>
#include <limits>

namespace CGAL {
namespace Curvature_estimation {
namespace internal {

// The largest extrapolation order (points at +-h ... +-4h): beyond it rounding
// eats the gain (the paper's Fig. 3 levels off at about 1e-16 relative).
constexpr int max_extrapolation_order = 4;

// The curve at the middle point: curvature kappa >= 0, unit tangent (from the
// points before to those after), unit principal normal towards the centre (zero
// where straight), curvature_vector = kappa principal_normal; `valid` false (and
// NaN fields) where the points define no tangent.
struct Curve_estimate
{
  bool valid = false;
  double curvature = std::numeric_limits<double>::quiet_NaN();
  Eigen::Vector3d tangent = Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
  Eigen::Vector3d principal_normal = Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
  Eigen::Vector3d curvature_vector = Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
};

// The curve through the middle point with first derivative `d1` and second
// derivative `d2` there (any parametrisation):
//   kappa = |d1 x d2| / |d1|^3 = sqrt(|d1|^2 |d2|^2 - <d1, d2>^2) / |d1|^3,
//   curvature vector (d2 - <d2, t> t) / |d1|^2, t = d1 / |d1|.
inline Curve_estimate curve_from_derivatives(const Eigen::Vector3d& d1, const Eigen::Vector3d& d2)
{
  Curve_estimate result;
  const double speed2 = d1.squaredNorm();
  if (!(speed2 > 0) || !std::isfinite(speed2) || !d2.allFinite())
    return result;
  const Eigen::Vector3d t = d1 / std::sqrt(speed2);
  const Eigen::Vector3d vector = (d2 - d2.dot(t) * t) / speed2;
  result.valid = true;
  result.tangent = t;
  result.curvature_vector = vector;
  result.curvature = vector.norm();
  result.principal_normal =
    result.curvature > 0 ? Eigen::Vector3d(vector / result.curvature) : Eigen::Vector3d(Eigen::Vector3d::Zero());
  return result;
}

// Wollmann's eq. (1): the quadratic Bezier segment B with B(0) = p0, B(1/2) = p1,
// B(1) = p2; at t = 1/2, B' = p2 - p0 and B'' = 4 (p2 + p0 - 2 p1) (the paper
// prints B'' without the factor 4). Error O(h^2) for points c(-h), c(0), c(h).
inline Curve_estimate bezier_curve_curvature(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1,
                                             const Eigen::Vector3d& p2)
{
  return curve_from_derivatives(p2 - p0, 4.0 * (p2 + p0 - 2.0 * p1));
}

// The circle through p0, p1, p2 (Todd and McLeod), at p1: with a = p0 - p1,
// b = p2 - p1, kappa = 2 |a x b| / (|a| |b| |a - b|), the centre c - p1 =
// ((|a|^2 b - |b|^2 a) x (a x b)) / (2 |a x b|^2); the tangent oriented from p0
// towards p2. Collinear points give kappa = 0 and the tangent p2 - p0.
inline Curve_estimate circle_curve_curvature(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1,
                                             const Eigen::Vector3d& p2)
{
  Curve_estimate result;
  const Eigen::Vector3d a = p0 - p1, b = p2 - p1, chord = b - a;
  const double la = a.norm(), lb = b.norm(), lc = chord.norm();
  if (!(la > 0 && lb > 0 && lc > 0) || !std::isfinite(la + lb + lc))
    return result;
  // Scaled by the chord, so that the cross products neither overflow nor underflow.
  const Eigen::Vector3d as = a / lc, bs = b / lc;
  const Eigen::Vector3d axb = as.cross(bs);
  const double axb2 = axb.squaredNorm();
  Eigen::Vector3d vector = Eigen::Vector3d::Zero();
  if (axb2 > 0) {
    const Eigen::Vector3d to_centre = (as.squaredNorm() * bs - bs.squaredNorm() * as).cross(axb) / (2.0 * axb2);
    vector = to_centre / (to_centre.squaredNorm() * lc);
  }
  const double curvature = vector.norm();
  Eigen::Vector3d tangent = chord;
  if (curvature > 0) {
    const Eigen::Vector3d n = vector / curvature;
    tangent -= chord.dot(n) * n;
  }
  const double tangent_length = tangent.norm();
  if (!(tangent_length > 0) || !vector.allFinite())
    return result;
  result.valid = true;
  result.tangent = tangent / tangent_length;
  result.curvature = curvature;
  result.curvature_vector = vector;
  result.principal_normal =
    curvature > 0 ? Eigen::Vector3d(vector / curvature) : Eigen::Vector3d(Eigen::Vector3d::Zero());
  return result;
}

// Wollmann's section 5: the coefficients alpha_k, beta_k of the odd and even
// parts u_k, g_k of the points at +-k h, k = 1..n, that cancel the Taylor terms
// x^3 .. x^(2n-1) and x^4 .. x^2n: with y_k = k^2, the divided-difference weights
// c_k = 1 / (k^3 prod_{j != k} (y_k - y_j)), b_k = 1 / (k^4 prod_{j != k} (y_k - y_j)),
// normalised as the paper's alpha_k = c_k / sum_j c_j j, beta_k = b_k / sum_j b_j j^2
// (n = 2: alpha = (4/3, -1/6), 2 beta = (8/3, -1/6), the fourth-order central differences).
struct Extrapolation_coefficients
{
  int order = 0;
  double alpha[max_extrapolation_order] = {0, 0, 0, 0};
  double beta[max_extrapolation_order] = {0, 0, 0, 0};
};

inline Extrapolation_coefficients extrapolation_coefficients(int n)
{
  Extrapolation_coefficients coefficients;
  if (n < 1 || n > max_extrapolation_order)
    return coefficients;
  coefficients.order = n;
  double b[max_extrapolation_order], c[max_extrapolation_order];
  double b_moment = 0, c_moment = 0;
  for (int k = 1; k <= n; ++k) {
    double product = 1;
    for (int j = 1; j <= n; ++j)
      if (j != k)
        product *= double(k * k - j * j);
    const double k2 = double(k * k);
    b[k - 1] = 1.0 / (k2 * k2 * product);
    c[k - 1] = 1.0 / (k2 * k * product);
    b_moment += b[k - 1] * k2;
    c_moment += c[k - 1] * k;
  }
  for (int k = 0; k < n; ++k) {
    coefficients.beta[k] = b[k] / b_moment;
    coefficients.alpha[k] = c[k] / c_moment;
  }
  return coefficients;
}

// The O(h^2n) estimate at `center` = c(0) from before[k-1] = c(-k h) and
// after[k-1] = c(k h), k = 1..n, for a curve c sampled at equal parameter steps:
// A and B as above (A/h ~ c', B/h^2 ~ c''), kappa = sqrt(|A|^2|B|^2 - <A,B>^2)/|A|^3,
// T = A/|A|, curvature vector (B - <B,T>T)/|A|^2. For n = 1 this is exactly the
// Bezier estimate. Invalid for n outside 1..max_extrapolation_order.
inline Curve_estimate extrapolated_curve_curvature(const Eigen::Vector3d* before, const Eigen::Vector3d& center,
                                                   const Eigen::Vector3d* after, int n)
{
  const Extrapolation_coefficients coefficients = extrapolation_coefficients(n);
  if (coefficients.order == 0)
    return Curve_estimate();
  Eigen::Vector3d A = Eigen::Vector3d::Zero(), B = Eigen::Vector3d::Zero();
  for (int k = 0; k < n; ++k) {
    // Relative to the centre: a0 drops out and the sums lose no digits to it.
    const Eigen::Vector3d odd = 0.5 * (after[k] - before[k]);
    const Eigen::Vector3d even_minus_a0 = 0.5 * ((after[k] - center) + (before[k] - center));
    A += coefficients.alpha[k] * odd;
    B += 2.0 * coefficients.beta[k] * even_minus_a0;
  }
  return curve_from_derivatives(A, B);
}

} // namespace internal
} // namespace Curvature_estimation
} // namespace CGAL

#endif // CGAL_CURVATURE_ESTIMATION_INTERNAL_CURVE_CURVATURE_H
