// SPDX-License-Identifier: GPL-3.0-or-later
// The least-squares Taylor fit of a height function over a tangent space, the
// numerical core of the fitting estimators on surfaces (D = 2) and hypersurfaces
// (D = 3):
//
//   h(x) = [[c +] g . x] + 1/2 x^T C x [+ cubic [+ quartic] terms],   x in R^D,
//
// the terms of orders FirstOrder to LastOrder. Two condition tests decide whether
// a fit is accepted: the scaled test (solve) in the given coordinates, and the
// whitened test (solve_whitened) in coordinates whitened by the samples' second
// moments. The manual's "The Taylor fit" says why, and what each refuses.
#ifndef CGAL_CURVATURE_ESTIMATION_INTERNAL_TAYLOR_FIT_TAYLOR_FIT_H
#define CGAL_CURVATURE_ESTIMATION_INTERNAL_TAYLOR_FIT_TAYLOR_FIT_H

#include <CGAL/Curvature_estimation/internal/taylor_fit/condition_bounds.h>
#include <CGAL/Curvature_estimation/internal/taylor_fit/curvature_quartic.h>
#include <CGAL/Curvature_estimation/internal/taylor_fit/moments.h>
#include <CGAL/Curvature_estimation/internal/taylor_fit/monomials.h>
#include <CGAL/Curvature_estimation/internal/taylor_fit/packed_cholesky.h>
#include <CGAL/Curvature_estimation/internal/taylor_fit/whitening.h>

#include <Eigen/Core>
#include <Eigen/LU>

#include <algorithm>
#include <limits>

namespace CGAL {
namespace Curvature_estimation {
namespace internal {

template <int D, int FirstOrder, int LastOrder, bool QuarticMoments = default_quartic_moments(D, FirstOrder, LastOrder)>
class Taylor_fit
{
  static_assert(FirstOrder >= 0 && FirstOrder <= 2 && LastOrder >= 2 && LastOrder <= 4, "orders out of range");
  static_assert(FirstOrder <= 1 || LastOrder == 2, "the own monomials must be a prefix of the tested ones");
  static constexpr int higher_orders =
    (LastOrder >= 3 ? number_of_monomials(D, 3) : 0) + (LastOrder == 4 ? number_of_monomials(D, 4) : 0);

public:
  static constexpr bool constant_term = FirstOrder == 0;
  static constexpr bool linear_terms = FirstOrder <= 1;
  static constexpr int last_order = LastOrder;
  static constexpr bool quartic_moments = QuarticMoments;
  static constexpr int unknowns =
    (constant_term ? 1 : 0) + (linear_terms ? D : 0) + number_of_monomials(D, 2) + higher_orders;
  // The monomials of the whitened test: those of orders min(FirstOrder, 1) to
  // LastOrder, the fit's own first (so that its normal matrix is a leading block).
  static constexpr int tested = (constant_term ? 1 : 0) + D + number_of_monomials(D, 2) + higher_orders;

  using Point = Eigen::Matrix<double, D, 1>;
  using Hessian = Eigen::Matrix<double, D, D>;

  void clear() { sums_.reset(); }

  // One sample: a point of the tangent space, the height above it, its weight.
  CGAL_CURVATURE_ESTIMATION_INLINE void add(const Point& x, double height, double weight = 1.0)
  {
    sums_.template add<Tables::first_own_moment>(x, height, weight);
  }

  int size() const { return sums_.size(); }

  // The scaled test and, where it accepts, the fit: refused where the 1-norm
  // condition number exceeds `max_condition` (or the matrix is singular).
  CGAL_CURVATURE_ESTIMATION_INLINE bool solve(double max_condition)
  {
    condition_ = std::numeric_limits<double>::infinity();
    condition_pending_ = false;
    if (sums_.size() < unknowns)
      return false;
    if (!Cholesky::template factor<unknowns>(sums_, factor_, inverse_diagonal_))
      return false;
    own_norm_ = one_norm<unknowns>(sums_);
    if (own_norm_ * comparison_bound<tested, unknowns>(factor_, inverse_diagonal_) <= max_condition)
      condition_pending_ = true;
    else {
      alignas(16) typename Cholesky::Triangle F;
      Cholesky::template invert<unknowns>(factor_, inverse_diagonal_, F);
      if (own_norm_ * triangular_norms_product<tested, unknowns>(F) <= max_condition)
        condition_pending_ = true;
      else {
        condition_ = own_norm_ * inverse_one_norm<tested, unknowns>(F);
        if (!(condition_ <= max_condition))
          return false;
      }
    }
    whitened_ = false;
    solve_with_factor();
    return true;
  }

  // The whitened test and, where it accepts, the fit in whitened coordinates mapped
  // back, on the samples of `samples(add)`, which calls add(x, height, weight) for
  // each (twice: for the second moments, then for the whitened normal matrix).
  template <typename Samples>
  bool solve_whitened(double max_condition, const Samples& samples)
  {
    whitened_condition_ = std::numeric_limits<double>::infinity();
    Hessian moments = Hessian::Zero();
    double weight_sum = 0;
    int count = 0;
    samples([&](const Point& x, double, double weight) {
      moments.noalias() += weight * x * x.transpose();
      weight_sum += weight;
      ++count;
    });
    if (count < tested)
      return false;
    Hessian W;
    if (!(weight_sum > 0) || !whitening<D>((D / weight_sum) * moments, W))
      return false;
    sums_.reset();
    samples([&](const Point& x, double height, double weight) { sums_.template add<0>(W * x, height, weight); });

    alignas(16) typename Cholesky::Triangle whitened_factor;
    typename Cholesky::Diagonal whitened_inverse_diagonal;
    if (!Cholesky::template factor<tested>(sums_, whitened_factor, whitened_inverse_diagonal))
      return false;
    alignas(16) typename Cholesky::Triangle F;
    Cholesky::template invert<tested>(whitened_factor, whitened_inverse_diagonal, F);
    whitened_condition_ = one_norm<tested>(sums_) * inverse_one_norm<tested, tested>(F);
    if (!(whitened_condition_ <= max_condition))
      return false;
    if (condition_pending_) { // the scaled test's factor is about to be replaced
      condition_ = condition_number();
      condition_pending_ = false;
    }
    // The fit's own block is a leading block, its factor a prefix of each column.
    std::copy(whitened_factor, whitened_factor + Cholesky::size, factor_);
    std::copy(whitened_inverse_diagonal, whitened_inverse_diagonal + tested, inverse_diagonal_);
    whitened_ = true;
    whitening_ = W;
    solve_with_factor();
    map_back();
    return true;
  }

  // The fit again after an accepted solve or solve_whitened, on the same samples
  // with other heights: `samples(add)` calls add(x, height, weight) for each.
  template <typename Samples>
  void solve_again(const Samples& samples)
  {
    sums_.clear_heights();
    samples([&](const Point& x, double height, double weight) {
      sums_.add_heights(whitened_ ? Point(whitening_ * x) : x, weight * height);
    });
    solve_with_factor();
    if (whitened_)
      map_back();
  }

  // The fit again with the heights less curvature_quartic(C, x), C the fitted
  // Hessian, from the moments alone (whitened: the forms of W^-T C W^-1 and W^-T C^2 W^-1).
  void subtract_curvature_quartic()
  {
    static_assert(Tables::quartic_moments, "the moments must reach degree LastOrder + 4");
    Hessian A = hessian_;
    Hessian B = hessian_ * hessian_;
    if (whitened_) {
      const Hessian inverse = whitening_.inverse();
      A = inverse.transpose() * A * inverse;
      B = inverse.transpose() * B * inverse;
    }
    double quartic[5];
    quartic_product_coefficients(A, B, quartic);
    CGAL_CURVATURE_ESTIMATION_UNROLL
    for (int k = 0; k < unknowns; ++k) {
      CGAL_CURVATURE_ESTIMATION_UNROLL
      for (int j = 0; j < 5; ++j)
        sums_.subtract_from_height_sum(k, quartic[j] * sums_.moment(Moments_type::tables.quartic_moment[k][j]));
    }
    solve_with_factor();
    if (whitened_)
      map_back();
  }

  // The condition numbers of the last tests (infinity where not computed).
  double condition_number() const
  {
    if (!condition_pending_)
      return condition_;
    alignas(16) typename Cholesky::Triangle F;
    Cholesky::template invert<unknowns>(factor_, inverse_diagonal_, F);
    return own_norm_ * inverse_one_norm<tested, unknowns>(F);
  }
  double whitened_condition_number() const { return whitened_condition_; }
  const Hessian& hessian() const { return hessian_; }
  const Point& gradient() const { return gradient_; }

  // After an accepted solve: the variance of the mean of the Hessian's diagonal
  // (the mean curvature where the gradient is zero) per unit variance of the
  // heights, for unit weights and independent heights: l^T M^-1 l.
  double mean_curvature_variance() const
  {
    double mean_of_diagonal[unknowns] = {};
    for (int i = 0, column = 0; i < D; column += D - i, ++i)
      mean_of_diagonal[column] = 1.0 / D;
    double solution[unknowns];
    Cholesky::template solve<unknowns>(factor_, inverse_diagonal_, mean_of_diagonal, solution);
    double variance = 0;
    for (int i = 0; i < unknowns; ++i)
      variance += mean_of_diagonal[i] * solution[i];
    return variance;
  }

  // After an accepted solve: the weighted residual sum of squares of the fit, from
  // the sum of the samples' weighted squared heights (which the fit does not keep).
  double residual_sum_of_squares(double weighted_squared_heights) const
  {
    double scaled[unknowns];
    right_hand_side(scaled);
    double coefficients[unknowns];
    Cholesky::template solve<unknowns>(factor_, inverse_diagonal_, scaled, coefficients);
    double explained = 0;
    for (int i = 0; i < unknowns; ++i)
      explained += scaled[i] * coefficients[i];
    return (std::max)(weighted_squared_heights - explained, 0.0);
  }

private:
  using Tables = Monomial_tables<D, FirstOrder, LastOrder, QuarticMoments>;
  using Moments_type = Moments<D, FirstOrder, LastOrder, unknowns, QuarticMoments>;
  using Cholesky = Packed_cholesky<tested>;
  static_assert(Tables::tested == tested, "the tables' rows are the tested monomials");
  static constexpr double half_sqrt2 = 0.70710678118654752440;

  // The coefficients of the monomials from the factor of the fit's own block and
  // the height sums, scaled here by the monomials' scales.
  void solve_with_factor()
  {
    double scaled[unknowns];
    right_hand_side(scaled);
    double coefficients[unknowns];
    Cholesky::template solve<unknowns>(factor_, inverse_diagonal_, scaled, coefficients);
    set_coefficients(coefficients);
  }

  CGAL_CURVATURE_ESTIMATION_INLINE void right_hand_side(double (&scaled)[unknowns]) const
  {
    CGAL_CURVATURE_ESTIMATION_UNROLL
    for (int i = 0; i < unknowns; ++i)
      scaled[i] = Moments_type::tables.scale[i] * sums_.height_sum(Moments_type::tables.row_slot[i]);
  }

  // The Hessian and gradient from the coefficients of the monomials of x.
  void set_coefficients(const double (&coefficients)[unknowns])
  {
    int column = 0;
    CGAL_CURVATURE_ESTIMATION_UNROLL
    for (int i = 0; i < D; ++i) {
      CGAL_CURVATURE_ESTIMATION_UNROLL
      for (int j = i; j < D; ++j) {
        const double value = (i == j ? 1.0 : half_sqrt2) * coefficients[column];
        hessian_(i, j) = value;
        hessian_(j, i) = value;
        ++column;
      }
    }
    if constexpr (linear_terms) {
      CGAL_CURVATURE_ESTIMATION_UNROLL
      for (int i = 0; i < D; ++i)
        gradient_[i] = coefficients[column + i];
    } else
      gradient_.setZero();
  }

  // From the coefficients of y = W x to those of x: h(x) = g_y . (W x) + 1/2 (W x)^T C_y (W x).
  void map_back()
  {
    hessian_ = whitening_.transpose() * hessian_ * whitening_;
    gradient_ = whitening_.transpose() * gradient_;
  }

  Moments_type sums_;
  // The factor of the own block at the last accepted test, and its 1-norm.
  alignas(16) typename Cholesky::Triangle factor_;
  typename Cholesky::Diagonal inverse_diagonal_;
  double own_norm_ = 0;
  // Whether the last solve accepted by a bound (condition_number() computes the number).
  bool condition_pending_ = false;
  bool whitened_ = false; // whether that was solve_whitened, in the coordinates whitening_ x
  Hessian whitening_ = Hessian::Identity();
  double condition_ = std::numeric_limits<double>::infinity();
  double whitened_condition_ = std::numeric_limits<double>::infinity();
  Hessian hessian_ = Hessian::Zero();
  Point gradient_ = Point::Zero();
};

// The fits of the estimators by what they solve for:
// Hamann's paraboloid, orders 2 alone, through the vertex in the given frame;
template <int D>
using Paraboloid_fit = Taylor_fit<D, 2, 2>;
// with the gradient too, which corrects the frame's normal;
template <int D, int Degree>
using Gradient_fit = Taylor_fit<D, 1, Degree>;
// with the height at the vertex too (an intercept), so that the vertex is a sample like the others.
template <int D, int Degree>
using Intercept_fit = Taylor_fit<D, 0, Degree>;
// The same on a surface, with the moments that subtract_curvature_quartic needs.
template <int Degree>
using Quartic_intercept_fit = Taylor_fit<2, 0, Degree, true>;

} // namespace internal
} // namespace Curvature_estimation
} // namespace CGAL

#endif // CGAL_CURVATURE_ESTIMATION_INTERNAL_TAYLOR_FIT_TAYLOR_FIT_H
