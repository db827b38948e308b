// SPDX-License-Identifier: GPL-3.0-or-later
// The monomials of a Taylor fit and the moments its normal matrix is made of.
#ifndef CGAL_CURVATURE_ESTIMATION_INTERNAL_TAYLOR_FIT_MONOMIALS_H
#define CGAL_CURVATURE_ESTIMATION_INTERNAL_TAYLOR_FIT_MONOMIALS_H

namespace CGAL {
namespace Curvature_estimation {
namespace internal {

constexpr int number_of_monomials(int D, int order)
{
  // (D + order - 1) choose order
  return order == 0 ? 1 : number_of_monomials(D, order - 1) * (D + order - 1) / order;
}

// The exponents of a monomial of R^D, D <= 3.
struct Monomial_exponents
{
  int power[3] = {0, 0, 0};
};

// Whether the moments of Taylor_fit<D, FirstOrder, LastOrder> reach degree
// LastOrder + 4 by default: the surfaces' cubic fit with the gradient.
constexpr bool default_quartic_moments(int D, int FirstOrder, int LastOrder)
{
  return D == 2 && FirstOrder == 1 && LastOrder == 3;
}

// The tested monomials of Taylor_fit<D, FirstOrder, LastOrder> (row, scale) and
// the moments sum w x^a of its normal matrix: entry k = (i, j) of its packed lower
// triangle is entry_scale[k] moment[entry_moment[k]]. Where paired, the pairs come
// first, each at an even index (a pair split across cache lines stalls the sums).
template <int D, int FirstOrder, int LastOrder, bool QuarticMoments = default_quartic_moments(D, FirstOrder, LastOrder)>
struct Monomial_tables
{
  static_assert(!QuarticMoments || (D == 2 && LastOrder <= 3), "the curvature's quartic term is that of a surface");
  static constexpr bool paired = D == 2 && LastOrder >= 3;
  static constexpr int tested = (FirstOrder == 0 ? 1 : 0) + D + number_of_monomials(D, 2) +
                                (LastOrder >= 3 ? number_of_monomials(D, 3) : 0) +
                                (LastOrder == 4 ? number_of_monomials(D, 4) : 0);
  // The degree of the lowest moment: that of the product of the lowest tested monomial with itself.
  static constexpr int lowest_degree = FirstOrder == 0 ? 0 : 2;
  // Whether the moments reach degree LastOrder + 4, so that the heights less the
  // curvature's quartic term need no second pass over the samples (curvature_quartic.h).
  static constexpr bool quartic_moments = QuarticMoments;
  // The degree of the highest moment.
  static constexpr int highest_degree = quartic_moments ? LastOrder + 4 : 2 * LastOrder;
  static constexpr int moments()
  {
    int count = 0;
    for (int degree = lowest_degree; degree <= highest_degree; ++degree)
      count += number_of_monomials(D, degree);
    return count;
  }
  // The first moment of degree 2 FirstOrder, the lowest that the fit's own block needs.
  static constexpr int first_own_moment = FirstOrder <= 1 ? 0 : number_of_monomials(D, 2) + number_of_monomials(D, 3);

  Monomial_exponents row[tested] = {};
  double scale[tested] = {};
  Monomial_exponents accumulated_row[tested] = {};
  int row_slot[tested] = {};
  Monomial_exponents moment[moments()] = {};
  // The pairs come first: the moments and accumulated rows below these counts, two by two.
  int paired_moments = 0;
  int paired_rows = 0;
  int entry_moment[tested * (tested + 1) / 2] = {};
  double entry_scale[tested * (tested + 1) / 2] = {};
  // Where quartic_moments, the moment of accumulated_row[k] times the quartic
  // monomial x0^(4 - j) x1^j: quartic_moment[k][j].
  int quartic_moment[tested][5] = {};

  constexpr Monomial_tables()
  {
    // Each order's monomials scaled to orthonormal coordinates of the symmetric
    // tensors; quadratic terms first, then the fit's own others, then the tested only.
    int column = 0;
    add_order(2, column);
    if (FirstOrder <= 1)
      add_order(1, column);
    if (FirstOrder == 0)
      add_order(0, column);
    for (int order = 3; order <= LastOrder; ++order)
      add_order(order, column);
    if (FirstOrder == 2)
      add_order(1, column);
    for (int degree = lowest_degree, m = 0; degree <= highest_degree; ++degree)
      for (int a = degree; a >= 0; --a)
        for (int b = degree - a; b >= (D == 2 ? degree - a : 0); --b, ++m) {
          moment[m].power[0] = a;
          moment[m].power[1] = b;
          moment[m].power[2] = degree - a - b;
        }
    int moment_slot[moments()] = {};
    paired_moments = accumulation_order(moment, moments(), moment, moment_slot);
    paired_rows = accumulation_order(row, tested, accumulated_row, row_slot);
    for (int i = 0, k = 0; i < tested; ++i)
      for (int j = 0; j <= i; ++j, ++k) {
        Monomial_exponents product;
        for (int d = 0; d < 3; ++d)
          product.power[d] = row[i].power[d] + row[j].power[d];
        entry_moment[k] = moment_index(product);
        entry_scale[k] = scale[i] * scale[j];
      }
    if (quartic_moments)
      for (int k = 0; k < tested; ++k)
        for (int j = 0; j < 5; ++j) {
          Monomial_exponents product = accumulated_row[k];
          product.power[0] += 4 - j;
          product.power[1] += j;
          quartic_moment[k][j] = moment_index(product);
        }
  }

private:
  // Whether monomial k of e[0..count) and the next one make a pair of the
  // windows of Moments::fill_windows: of a degree, x0^a x1^b then x0^(a-1) x1^(b+1).
  static constexpr bool pairs_with_next(const Monomial_exponents* e, int count, int k)
  {
    return k + 1 < count && e[k + 1].power[0] + 1 == e[k].power[0] && e[k + 1].power[1] == e[k].power[1] + 1;
  }

  // `in` into `out` (which may be `in`), the pairs first where paired; slot[k]: the
  // index in `out` of in[k]. Returns the number of paired monomials.
  static constexpr int accumulation_order(const Monomial_exponents* in, int count, Monomial_exponents* out, int* slot)
  {
    int paired_count = 0;
    for (int k = 0; k < count; ++k)
      slot[k] = -1;
    for (int k = 0; k < count; ++k)
      if (paired && pairs_with_next(in, count, k)) {
        slot[k] = paired_count++;
        slot[++k] = paired_count++;
      }
    for (int k = 0, next = paired_count; k < count; ++k)
      if (slot[k] < 0)
        slot[k] = next++;
    Monomial_exponents copy[moments() > tested ? moments() : tested] = {};
    for (int k = 0; k < count; ++k)
      copy[k] = in[k];
    for (int k = 0; k < count; ++k)
      out[slot[k]] = copy[k];
    return paired_count;
  }

  // The monomials of one order, indices i <= j <= ..., each scaled by the square
  // root of the number of distinct orderings of its indices.
  constexpr void add_order(int order, int& column)
  {
    int indices[4] = {0, 0, 0, 0};
    while (true) {
      Monomial_exponents e;
      for (int t = 0; t < order; ++t)
        ++e.power[indices[t]];
      row[column] = e;
      // order! over the product of the factorials of the exponents
      int orderings = 1;
      for (int t = 2; t <= order; ++t)
        orderings *= t;
      for (int d = 0; d < 3; ++d)
        for (int t = 2; t <= e.power[d]; ++t)
          orderings /= t;
      scale[column] = square_root(orderings) / (order == 2 ? 2 : 1); // the quadratic ones as in 1/2 x^T C x
      ++column;
      // the next non-decreasing index tuple
      int t = order - 1;
      while (t >= 0 && indices[t] == D - 1)
        --t;
      if (t < 0)
        return;
      ++indices[t];
      for (int u = t + 1; u < order; ++u)
        indices[u] = indices[t];
    }
  }

  static constexpr double square_root(int n)
  {
    return n == 1    ? 1.0
           : n == 2  ? 1.4142135623730950488
           : n == 3  ? 1.7320508075688772935
           : n == 4  ? 2.0
           : n == 6  ? 2.4494897427831780982
           : n == 12 ? 3.4641016151377545870
                     : 4.8989794855663561964;
  }

  constexpr int moment_index(const Monomial_exponents& e) const
  {
    for (int m = 0; m < moments(); ++m)
      if (moment[m].power[0] == e.power[0] && moment[m].power[1] == e.power[1] && moment[m].power[2] == e.power[2])
        return m;
    return -1;
  }
};

} // namespace internal
} // namespace Curvature_estimation
} // namespace CGAL

#endif // CGAL_CURVATURE_ESTIMATION_INTERNAL_TAYLOR_FIT_MONOMIALS_H
