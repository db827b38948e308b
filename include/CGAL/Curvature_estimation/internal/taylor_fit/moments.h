// SPDX-License-Identifier: GPL-3.0-or-later
// The sums a Taylor fit accumulates over its samples: the moments that its
// normal matrix is made of, and the sums of the weighted heights times its
// monomials (its right-hand side, before the monomials' scales).
#ifndef CGAL_CURVATURE_ESTIMATION_INTERNAL_TAYLOR_FIT_MOMENTS_H
#define CGAL_CURVATURE_ESTIMATION_INTERNAL_TAYLOR_FIT_MOMENTS_H

#include <CGAL/Curvature_estimation/internal/taylor_fit/monomials.h>
#include <CGAL/Curvature_estimation/internal/taylor_fit/pairs.h>

#include <Eigen/Core>

#include <algorithm>
#include <cstddef>
#include <utility>

namespace CGAL {
namespace Curvature_estimation {
namespace internal {

// `Unknowns` height sums: the first accumulated rows of the tables.
template <int D, int FirstOrder, int LastOrder, int Unknowns, bool QuarticMoments>
class Moments
{
public:
  using Tables = Monomial_tables<D, FirstOrder, LastOrder, QuarticMoments>;
  using Point = Eigen::Matrix<double, D, 1>;
  static constexpr Tables tables{};
  // Whether the sums are added in pairs (fill_windows): surfaces at degrees 3 and 4.
  static constexpr bool paired_products = Tables::paired;

  Moments() { reset(); }

  // Zeroes the moments, the height sums and the count.
  void reset()
  {
    std::fill(moments_, moments_ + Tables::moments(), 0.0);
    clear_heights();
    size_ = 0;
  }

  void clear_heights() { std::fill(height_sums_, height_sums_ + Unknowns, 0.0); }

  int size() const { return size_; }
  double moment(int m) const { return moments_[m]; }
  // Sum of w h x^e over the samples, e = tables.accumulated_row[slot].
  double height_sum(int slot) const { return height_sums_[slot]; }
  void subtract_from_height_sum(int slot, double value) { height_sums_[slot] -= value; }

  // Entry (i, j) of the normal matrix (i, j in the tested monomials).
  double normal_entry(int i, int j) const
  {
    const int k = i >= j ? i * (i + 1) / 2 + j : j * (j + 1) / 2 + i;
    return tables.entry_scale[k] * moments_[tables.entry_moment[k]];
  }

  // Adds a sample to the moments from `first` on (those of the fit's own block,
  // or all) and to the height sums.
  template <int first>
  CGAL_CURVATURE_ESTIMATION_INLINE void add(const Point& x, double height, double weight)
  {
    if constexpr (paired_products) {
      constexpr int W = Tables::highest_degree;
      Pair lead[W], ys[W];
      fill_windows(x, weight, lead, ys);
      static_assert(first == 0, "a paired fit has linear terms: its own block needs every moment");
      add_products<false>(lead, ys, std::make_index_sequence<Tables::moments()>());
      Pair weighted_heights[LastOrder];
      CGAL_CURVATURE_ESTIMATION_UNROLL
      for (int s = 0; s < LastOrder; ++s)
        weighted_heights[s] = height * lead[W - LastOrder + s];
      add_products<true>(weighted_heights, ys, std::make_index_sequence<Unknowns>());
    } else {
      double powers[D][Tables::highest_degree + 1];
      fill_powers(x, weight, powers);
      add_moments<first>(powers, std::make_index_sequence<Tables::moments() - first>());
      double weighted_heights[LastOrder + 1];
      CGAL_CURVATURE_ESTIMATION_UNROLL
      for (int k = 0; k <= LastOrder; ++k)
        weighted_heights[k] = height * powers[0][k];
      add_heights(weighted_heights, powers, std::make_index_sequence<Unknowns>());
    }
    ++size_;
  }

  // Adds w h r(x) to the height sums alone (weighted_height = w h).
  CGAL_CURVATURE_ESTIMATION_INLINE void add_heights(const Point& x, double weighted_height)
  {
    if constexpr (paired_products) {
      Pair lead[LastOrder], ys[LastOrder];
      fill_windows(x, weighted_height, lead, ys);
      add_products<true>(lead, ys, std::make_index_sequence<Unknowns>());
    } else {
      double powers[D][LastOrder + 1];
      fill_powers(x, weighted_height, powers);
      add_heights(powers[0], powers, std::make_index_sequence<Unknowns>());
    }
  }

private:
  template <int first, std::size_t... m>
  void add_moments(const double (&powers)[D][Tables::highest_degree + 1], std::index_sequence<m...>)
  {
    ((moments_[first + m] += product_of_powers(tables.moment[first + m], powers[0], powers)), ...);
  }

  // Adds w h r(x), without the monomials' scales, to the height sums: `lead` is
  // w h times the powers of x[0], `powers` those of the other coordinates.
  template <int L, int P, std::size_t... i>
  void add_heights(const double (&lead)[L], const double (&powers)[D][P], std::index_sequence<i...>)
  {
    ((height_sums_[i] += product_of_powers(tables.accumulated_row[i], lead, powers)), ...);
  }

  // powers[d][k] = x[d]^k, times `factor` for d = 0.
  template <int P>
  static void fill_powers(const Point& x, double factor, double (&powers)[D][P])
  {
    CGAL_CURVATURE_ESTIMATION_UNROLL
    for (int d = 0; d < D; ++d) {
      powers[d][0] = d == 0 ? factor : 1.0;
      CGAL_CURVATURE_ESTIMATION_UNROLL
      for (int k = 1; k < P; ++k)
        powers[d][k] = powers[d][k - 1] * x[d];
    }
  }

  // For surfaces, the powers of x = (x0, x1) as windows of two entries, for
  // add_products: lead[s] = factor (x0^(W - s), x0^(W - 1 - s)), ys[s] = (x1^s, x1^(s + 1)).
  template <int W>
  static void fill_windows(const Point& x, double factor, Pair (&lead)[W], Pair (&ys)[W])
  {
    // From broadcasts, in registers: a pair written as two scalars and read as one stalls.
    lead[W - 1] = Pair::Constant(factor) * (Pair::Constant(x[0]) * Pair(1.0, 0.0) + Pair(0.0, 1.0));
    ys[0] = Pair::Constant(x[1]) * Pair(0.0, 1.0) + Pair(1.0, 0.0);
    CGAL_CURVATURE_ESTIMATION_UNROLL
    for (int s = 1; s < W; ++s) {
      lead[W - 1 - s] = lead[W - s] * x[0];
      ys[s] = ys[s - 1] * x[1];
    }
  }

  // For surfaces, adds factor x0^a x1^b for each monomial of the accumulated rows
  // (Heights) or of the moments, from the windows; a pair x0^a x1^b, x0^(a-1) x1^(b+1)
  // takes lead[W - a] * ys[b] at once.
  template <bool Heights, int W, int V, std::size_t... m>
  void add_products(const Pair (&lead)[W], const Pair (&ys)[V], std::index_sequence<m...>)
  {
    (add_product<Heights, m>(lead, ys), ...);
  }

  template <bool Heights, int m, int W, int V>
  void add_product(const Pair (&lead)[W], const Pair (&ys)[V])
  {
    constexpr const Monomial_exponents* exponents = Heights ? tables.accumulated_row : tables.moment;
    constexpr int paired = Heights ? tables.paired_rows : tables.paired_moments;
    constexpr int a = exponents[m].power[0];
    constexpr int b = exponents[m].power[1];
    double* target = Heights ? height_sums_ + m : moments_ + m;
    if constexpr (m >= paired) {
      // factor x0^a is the first entry of lead[W - a] (the second of lead[W - 1] for a = 0).
      // (if constexpr: clang checks the indices of a branch not taken)
      double lead_power, y_power;
      if constexpr (a > 0)
        lead_power = lead[W - a][0];
      else
        lead_power = lead[W - 1][1];
      if constexpr (b < V)
        y_power = ys[b][0];
      else
        y_power = ys[V - 1][1];
      *target += lead_power * y_power;
    } else if constexpr (m % 2 == 0)
      pair_at(target) += lead[W - a] * ys[b];
  }

  // x^e, the powers of x[0] from `lead` (with any factor), the others' from `powers`.
  template <int L, int P>
  static double product_of_powers(const Monomial_exponents& e, const double (&lead)[L], const double (&powers)[D][P])
  {
    double value = lead[e.power[0]];
    CGAL_CURVATURE_ESTIMATION_UNROLL
    for (int d = 1; d < D; ++d)
      value *= powers[d][e.power[d]];
    return value;
  }

private:
  // Aligned, so that the pairs at even indices are.
  alignas(16) double moments_[Tables::moments()];
  alignas(16) double height_sums_[Unknowns];
  int size_ = 0;
};

} // namespace internal
} // namespace Curvature_estimation
} // namespace CGAL

#endif // CGAL_CURVATURE_ESTIMATION_INTERNAL_TAYLOR_FIT_MOMENTS_H
