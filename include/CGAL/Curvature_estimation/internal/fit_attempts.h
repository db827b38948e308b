// SPDX-License-Identifier: GPL-3.0-or-later
// The widening policy of the fitting estimators as data: for each thing a
// vertex fit looks for (its normal, its curvature at fit_degree 2, 3 or 4, over
// rings or a ball), the list of attempts, in order. An attempt is one Taylor fit
// over a range of rings (or the ball) under one condition test; the first one
// accepted gives the result. The manual's "Widening" says why each is there and
// how its threshold was measured.
#ifndef CGAL_CURVATURE_ESTIMATION_INTERNAL_FIT_ATTEMPTS_H
#define CGAL_CURVATURE_ESTIMATION_INTERNAL_FIT_ATTEMPTS_H

#include <CGAL/Curvature_estimation/internal/fit_kinds.h>
#include <CGAL/Curvature_estimation/internal/fit_settings.h>

#include <algorithm>

namespace CGAL {
namespace Curvature_estimation {
namespace internal {

// The scaled test: conditioning in tangent coordinates scaled by the mean 1-ring
// edge, at each ring from first to last until one accepts. The whitened test: in
// coordinates whitened by the samples' second moments, at the widest ring reached.
enum class Condition_test : unsigned char
{
  scaled,
  whitened
};

enum class Sample_weights : unsigned char
{
  uniform,
  gaussian, // exp(-|x|^2), x in units of the mean 1-ring edge
  smooth    // (1 - |x|^2 / r^2)^2 in a ball of radius r
};

// The frame of the fit: that of the vertex's current normal, or that of the
// least-squares plane of the vertex and the rings fitted (oriented as the normal).
enum class Frame_choice : unsigned char
{
  normal,
  plane
};

struct Fit_attempt
{
  Fit_kind fit;
  Condition_test test;
  int first_rings; // 0 for the ball
  int last_rings;
  double max_condition;
  Sample_weights weights = Sample_weights::uniform;
  Frame_choice frame = Frame_choice::normal;
};

// At most four attempts, walked in order.
class Fit_attempts
{
public:
  void add(const Fit_attempt& attempt) { attempts_[count_++] = attempt; }
  const Fit_attempt* begin() const { return attempts_; }
  const Fit_attempt* end() const { return attempts_ + count_; }
  // The most rings an attempt takes (0 for none, and for the ball's).
  int widest_rings() const
  {
    int rings = 0;
    for (const Fit_attempt& a : *this)
      rings = (std::max)(rings, a.last_rings);
    return rings;
  }

private:
  Fit_attempt attempts_[4];
  int count_ = 0;
};

// The condition thresholds, as factors of max_condition_number.
// The cubic fits of fit_degree 2: well-posed cubic stencils show about 1e4,
// those singular in the tangent plane above 1e16.
constexpr double cubic_condition_factor = 1e3;
// fit_degree 3 and 4.
constexpr double degree_condition_factor(int degree) { return degree == 2 ? 1 : degree == 3 ? 1e2 : 1e5; }
// Balls, whose vertex may be at their edge (one-sided for the intercept too).
constexpr double ball_condition_factor = 10;
// The plane-frame fit.
constexpr double plane_fit_condition_factor = 1e3;
// The cubic fits of fit_degree 2 take at least 3 rings: an edge vertex of a grid
// has only three rows of samples on 2.
constexpr int cubic_min_rings = 3;

// The weights of the cubic fits of fit_degree 2: Gaussian of width the mean 1-ring
// edge (the quartic remainder, largest at the far samples, otherwise leaks into a
// one-sided stencil's gradient). Where fits of degree 3 and 4 fall back to degree
// 2, uniform, as theirs.
inline Sample_weights cubic_weights(const Fit_settings& s)
{
  return s.degree == 2 ? Sample_weights::gaussian : Sample_weights::uniform;
}

// The second-order normal (fit_degree 2): the gradient of a quadratic fit corrects
// the first-order normal; at a boundary vertex, whose one-sided stencil does not
// cancel the odd terms, a Gaussian-weighted cubic fit first.
inline Fit_attempts normal_attempts(const Fit_settings& s, bool on_border)
{
  const int start = s.start_rings(on_border);
  const int cubic_first = (std::max)(cubic_min_rings, start);
  const int cubic_last = (std::max)(cubic_first, s.max_rings);
  const double cubic_condition = cubic_condition_factor * s.max_condition;
  Fit_attempts attempts;
  if (on_border)
    attempts.add(
      {Fit_kind::gradient_3, Condition_test::scaled, cubic_first, cubic_last, cubic_condition, cubic_weights(s)});
  attempts.add({Fit_kind::gradient_2, Condition_test::scaled, start, s.max_rings, s.max_condition});
  if (s.whitened_conditioning) {
    if (on_border)
      attempts.add(
        {Fit_kind::gradient_3, Condition_test::whitened, cubic_first, cubic_last, cubic_condition, cubic_weights(s)});
    attempts.add({Fit_kind::gradient_2, Condition_test::whitened, start, s.max_rings, s.max_condition});
  }
  return attempts;
}

// The curvature at fit_degree 2 with the fitted normal at an interior vertex: the
// quadratic fit with the gradient, on the first rings alone, then with the cubic
// terms over more (a paraboloid's error grows as the square of its radius).
// `first`: the rings the normal's fit took, or the starting rings.
inline Fit_attempts gradient_curvature_attempts(const Fit_settings& s, int first)
{
  const double cubic_condition = cubic_condition_factor * s.max_condition;
  Fit_attempts attempts;
  attempts.add({Fit_kind::gradient_2, Condition_test::scaled, first, first, s.max_condition});
  attempts.add(
    {Fit_kind::gradient_3, Condition_test::scaled, first + 1, s.max_rings, cubic_condition, cubic_weights(s)});
  attempts.add({Fit_kind::gradient_2, Condition_test::scaled, first + 1, s.max_rings, s.max_condition});
  if (s.whitened_conditioning)
    attempts.add({Fit_kind::gradient_2, Condition_test::whitened, first, s.max_rings, s.max_condition});
  return attempts;
}

// Hamann's paraboloid in the frame of the normal: with a given or face-averaged
// normal, at boundary vertices, and where the gradient's fits are refused.
inline Fit_attempts paraboloid_attempts(const Fit_settings& s, int first)
{
  Fit_attempts attempts;
  attempts.add({Fit_kind::paraboloid, Condition_test::scaled, first, s.max_rings, s.max_condition});
  if (s.whitened_conditioning)
    attempts.add({Fit_kind::paraboloid, Condition_test::whitened, first, s.max_rings, s.max_condition});
  return attempts;
}

// The rings a fit of fit_degree 3 or 4 starts on.
inline int first_rings_of_degree(const Fit_settings& s, bool on_border)
{
  return (std::max)(s.start_rings(on_border), s.degree - 1);
}

// fit_degree 3 or 4: the fit of that degree with the gradient, over degree - 1
// rings at least, up to max_neighborhood_rings or one ring more. With an
// estimated normal, degree 4 first in the frame of the rings' least-squares
// plane (three lopsided rings leave the far samples steep in another frame).
inline Fit_attempts degree_attempts(const Fit_settings& s, bool on_border, bool estimated_normal)
{
  const int first = first_rings_of_degree(s, on_border);
  const int last = (std::max)(s.max_rings, first + 1);
  const double max_condition = degree_condition_factor(s.degree) * s.max_condition;
  const Fit_kind fit = gradient_fit_of_degree(s.degree);
  Fit_attempts attempts;
  if (s.degree == 4 && estimated_normal)
    attempts.add(
      {fit, Condition_test::scaled, first, first, max_condition, Sample_weights::uniform, Frame_choice::plane});
  attempts.add({fit, Condition_test::scaled, first, last, max_condition});
  if (s.whitened_conditioning)
    attempts.add({fit, Condition_test::whitened, first, last, max_condition});
  return attempts;
}

// The fit with an intercept over the ball (ball_radius), at each radius the ball
// grows to (see fit_in_growing_ball).
inline Fit_attempts ball_attempts(const Fit_settings& s)
{
  const double max_condition = ball_condition_factor * degree_condition_factor(s.degree) * s.max_condition;
  const Fit_kind fit = intercept_fit_of_degree(s.degree);
  const Sample_weights weights = s.smooth_weights ? Sample_weights::smooth : Sample_weights::uniform;
  Fit_attempts attempts;
  attempts.add({fit, Condition_test::scaled, 0, 0, max_condition, weights});
  if (s.whitened_conditioning)
    attempts.add({fit, Condition_test::whitened, 0, 0, max_condition, weights});
  return attempts;
}

// The intercept fit of the degree over rings (ring_intercept), from the starting
// rings on.
inline Fit_attempts ring_intercept_attempts(const Fit_settings& s)
{
  const double max_condition = degree_condition_factor(s.degree) * s.max_condition;
  const Fit_kind fit = intercept_fit_of_degree(s.degree);
  Fit_attempts attempts;
  attempts.add({fit, Condition_test::scaled, s.rings, s.max_rings, max_condition});
  if (s.whitened_conditioning)
    attempts.add({fit, Condition_test::whitened, s.rings, s.max_rings, max_condition});
  return attempts;
}

// The plane-frame fit (the paraboloid estimator's first fallback): the quadratic
// fit with an intercept in the frame of the least-squares plane of the vertex and
// its rings, as CGAL's jet fitting fits, from the starting rings on.
inline Fit_attempts plane_frame_attempts(const Fit_settings& s, bool on_border)
{
  Fit_attempts attempts;
  attempts.add({Fit_kind::intercept_2, Condition_test::scaled, s.start_rings(on_border), s.max_rings,
                plane_fit_condition_factor * s.max_condition, Sample_weights::uniform, Frame_choice::plane});
  return attempts;
}

} // namespace internal
} // namespace Curvature_estimation
} // namespace CGAL

#endif // CGAL_CURVATURE_ESTIMATION_INTERNAL_FIT_ATTEMPTS_H
