// SPDX-License-Identifier: GPL-3.0-or-later
// Least-squares Taylor fit of a height function over a tangent space, the
// numerical core shared by the surface (D = 2) and hypersurface (D = 3)
// estimators:
//
//   h(x) = [[c +] g . x] + 1/2 x^T C x [+ cubic [+ quartic] terms],   x in R^D,   C symmetric,
//
// the terms of orders FirstOrder..LastOrder (FirstOrder 0 to 2, LastOrder 2 to 4).
// FirstOrder = 2 trusts the frame's normal (Hamann's fit); FirstOrder = 1 fits
// the gradient, i.e. corrects the normal; FirstOrder = 0 the height c at the
// vertex too, which is then a sample like the others and not a point the fit
// must pass through (the fits over a ball of a noisy mesh, whose vertex carries
// noise that the fit would otherwise divide by the squared radius); LastOrder = 3 takes the cubic part out
// of the gradient, which a one-sided (boundary) stencil does not cancel, and out
// of C, which an uneven stencil does not cancel either (fit_degree 3); LastOrder
// = 4 the quartic part too (fit_degree 4).
//
// When a fit is accepted: two tests of conditioning. The samples x_i (weights
// w_i) are given in tangent coordinates scaled by a length of the mesh (the mean
// 1-ring edge). Let r(x) be the row of the monomials of orders min(FirstOrder, 1)..LastOrder,
// each order in orthonormal coordinates of the symmetric tensors (see add),
// N = sum w_i r(x_i) r(x_i)^T, and N_own its block of the fit's own orders
// FirstOrder..LastOrder.
//
//   (a) solve:           cond_1(N_own) <= max_condition.
//   (b) solve_whitened:  cond_1(N_y) <= max_condition, N_y = sum w_i r(y_i) r(y_i)^T
//                        in the whitened coordinates y = W x.
//
// Whitening. M = D sum w_i x_i x_i^T / sum w_i, the samples' second moments
// about the vertex, scaled so that the weighted mean of |y|^2 is 1; M = L L^T
// (Cholesky) and W = L^-1, so that the second moments of the y_i are the
// identity. A monomial of y = W x is a combination of the monomials of x of its
// own order: r(W x) = T r(x), T block-diagonal (1 on the constant, W on the linear terms, the maps
// it induces on the symmetric tensors on the others), hence N_y = T N T^T. Two
// whitenings differ by an orthogonal map, which acts on N_y by an orthogonal
// congruence: cond_1(N_y) is invariant, to a factor bounded by the number of
// unknowns, under every linear change of the tangent coordinates. (a) is not: a
// 1-ring stretched by s in one direction (the long thin triangles of CAD and
// marching-cubes meshes) multiplies cond_1(N_own) by about s^(2 LastOrder)
// (1e8 for a stretch of 100 in Hamann's fit), and widening keeps the stretch;
// its N_y is that of the unstretched ring, and widening adds samples in every
// direction, which lowers cond_1(N_y). N_y is accumulated from the y_i, not
// computed as T N T^T, which would lose the digits that cond_1(N) costs.
//
// What (b) still refuses. N_y is singular exactly where a polynomial of orders
// 1..LastOrder vanishes at every sample, and nearly singular near that: samples
// on a line, on two lines through the vertex, on a conic through the vertex (a
// cubic curve for LastOrder 3, e.g. three rows of samples). The linear terms are
// in N also for FirstOrder = 2, which does not solve for them: a stencil that is
// degenerate in the parameter plane (on a line) seen in a frame tilted by t has
// tangent coordinates on a parabola whose width is t times its heights.
// Whitening stretches that parabola to unit width, where Hamann's quadratic
// terms alone are well-conditioned (condition 50) and their fit is garbage (the
// coefficient across the line is the quartic term over t^2); the parabola is a
// conic through the vertex, and (b) refuses it (1e16, or singular). M itself
// must be regular: samples on a line through the vertex make it singular, to
// rounding, and the whitening is not trusted beyond max_whitening_condition.
//
// The solution does not depend on the coordinates (the least-squares
// polynomial is the same function of the point): solve_whitened computes it in y
// and maps it back, a_x = T^T a_y, i.e. g = W^T g_y and C = W^T C_y W.
//
// A fit can be solved again on the same samples with other heights (solve_again): only the right-hand side changes, and
// the inverse of the normal matrix, in the coordinates where it was accepted, is kept for that.
//
// The curvature's own quartic term. For a surface in Monge form at p, principal
// curvatures k1, k2 along x and y, the quartic part of the height is
//   1/8 (k1^3 x^4 + k1 k2 (k1 + k2) x^2 y^2 + k2^3 y^4)
// plus terms in the derivatives of the principal curvatures; on a sphere and a
// cylinder (constant principal curvatures) it is all of it (r - sqrt(r^2 - x^2)
// = x^2 / 2r + x^4 / 8r^3 + ...). In any frame and dimension that part is
//   curvature_quartic(C, x) = (x^T C x) |C x|^2 / 8,   C the Hessian of the height.
// A degree-2 (or 3) fit takes the quartic part, through an uneven stencil, into
// C: an O(h^2) error, which on spheres and cylinders (the surfaces CAD meshes are
// made of) is all the error. Fitting again with the heights less
// curvature_quartic(C, x), C from the first fit, removes it: the error of C in it
// is O(h^2) (or O(h)), times |x|^4 / |x|^2, hence of higher order. That
// quartic is a product of two quadratic forms, x^T C x and x^T C^2 x, so that its
// sums times the fit's monomials are combinations of moments of degree up to
// LastOrder + 4: where the moments reach that degree (subtract_curvature_quartic),
// the new right-hand side follows from them, without a second pass over the samples.
//
// Cost. The entry (i, j) of N is sum_k w_k m_i(x_k) m_j(x_k), and m_i m_j is a
// monomial of degree 2 to 2 LastOrder: N is a table of the moments
// sum_k w_k x_k^a, fewer than its entries (42 against 105 for surfaces at
// LastOrder 4, 25 against 45 at 3, with 8 more of degree 7 for the quartic
// term above), which add sums per sample; the right-hand side is summed in the
// unscaled monomials, scaled once per solve. For surfaces at LastOrder 3 and 4
// both are summed two at a time, in pairs of SSE2 lanes (see fill_windows). N = L L^T (Cholesky, read from the moments,
// in pairs of lanes too) solves by substitution. Test (a) takes the first of three upper bounds of cond_1(N) that is
// below the threshold: one from L alone (two triangular solves), one from L^-1 (inverting L, in pairs of lanes, costs
// as much as the factorisation), and the exact number (N^-1 = L^-T L^-1, as costly again), so that the decisions are
// those of the exact number. Each lane computes what the scalar loops would, in the same order: the results do not
// depend on the pairs, to the bit.
//
// The estimators (platelet_fit.h) try (a) on each neighborhood up to the widest,
// and (b) on the widest where (a) accepts none: where (a) accepts, the fit and
// its rounding are those of the scaled coordinates, as without (b); (a) is also
// the only test of a fit with fewer samples than the monomials of orders
// 1..LastOrder (Hamann's fit on 3 or 4 neighbors).
#ifndef CGAL_CURVATURE_ESTIMATION_INTERNAL_QUADRIC_FIT_H
#define CGAL_CURVATURE_ESTIMATION_INTERNAL_QUADRIC_FIT_H

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>

// Full unrolling of the fixed-size loops below: with constant indices the packed
// matrix addressing folds away (without it GCC leaves them as loops that cost
// several times more). Not for Clang, which warns that it cannot unroll the
// nested loops as asked; its own heuristics decide there. Not under GCC's
// AddressSanitizer either, whose instrumented loops GCC warns it cannot unroll
// as asked (and whose builds are for finding errors, not for speed).
#if defined(__GNUC__) && !defined(__clang__) && !defined(__SANITIZE_ADDRESS__)
#define CGAL_CURVATURE_ESTIMATION_UNROLL _Pragma("GCC unroll 32")
#else
#define CGAL_CURVATURE_ESTIMATION_UNROLL
#endif

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

// The monomials of the rows of Taylor_fit<D, FirstOrder, LastOrder> (row: their
// exponents, scale: their factors), and the moments that the entries of its
// normal matrix are (see Taylor_fit::accumulate): every monomial of degree 2 to
// 2 LastOrder (moment), ordered by degree, and for the packed entry k = (i, j)
// of the normal matrix, entry_moment[k], the moment of the product of monomials
// i and j, and entry_scale[k] = scale[i] scale[j].
//
// Where the sums are added in pairs (paired, see Taylor_fit::fill_windows), the
// moments and the right-hand side are summed in an order that puts the pairs
// first: moment, and accumulated_row, row i being summed at row_slot[i]. Each
// pair then starts at an even index, so that it is never split across two
// cache lines. A split pair costs more than the pair gains: in a sum carried
// from sample to sample, the load after a split store waits for the store to
// complete (measured: fit_degree 4 2.07 or 2.59 us per vertex on the 317 x 317
// grid, depending on where the stack put the fit).
template <int D, int FirstOrder, int LastOrder>
struct Monomial_tables
{
  static constexpr bool paired = D == 2 && LastOrder >= 3;
  static constexpr int tested = (FirstOrder == 0 ? 1 : 0) + D + number_of_monomials(D, 2) +
                                (LastOrder >= 3 ? number_of_monomials(D, 3) : 0) +
                                (LastOrder == 4 ? number_of_monomials(D, 4) : 0);
  // The degree of the lowest moment: that of the product of the lowest tested monomial with itself.
  static constexpr int lowest_degree = FirstOrder == 0 ? 0 : 2;
  // Whether the moments reach degree LastOrder + 4 too, so that the right-hand
  // side of the heights less the curvature's quartic term follows from them (see
  // Taylor_fit::subtract_curvature_quartic): for surfaces at LastOrder 3, one
  // degree more (8 moments more than 25), in place of a second pass over the
  // samples (fit_degree 3 on the 317 x 317 grid, median of 8 placements of the
  // stack: 1,014 -> 919 ns per vertex; bunny00 2,086 -> 1,877). Not at LastOrder
  // 2, which would need two degrees more (13 moments more than 12), and which
  // every vertex of the default fits twice, once for the normal only: there the
  // default took 680 instead of 636 ns on the grid, 1,426 instead of 1,184 on bunny00.
  static constexpr bool quartic_moments = D == 2 && FirstOrder == 1 && LastOrder == 3;
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
    // Each order's monomials are scaled to be orthonormal coordinates of the
    // symmetric tensor x (x) ... (x) x (sqrt of the multiplicity), so that a
    // rotation of the tangent frame acts on each block of the normal matrix by an
    // orthogonal matrix and the condition number does not depend on how the frame
    // is turned in the tangent space. Quadratic terms first so that their
    // coefficients do not depend on FirstOrder; the fit's own monomials first.
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
  // windows of Taylor_fit::fill_windows: of a degree, x0^a x1^b then x0^(a-1) x1^(b+1).
  static constexpr bool pairs_with_next(const Monomial_exponents* e, int count, int k)
  {
    return k + 1 < count && e[k + 1].power[0] + 1 == e[k].power[0] && e[k + 1].power[1] == e[k].power[1] + 1;
  }

  // Where paired, `in` reordered into `out` (which may be `in`): the pairs
  // (taken in order) first, then the monomials left alone; slot[k], the index in
  // `out` of in[k]. Else a copy. Returns the number of paired monomials.
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

// See the header comment for when solve accepts a fit.
template <int D, int FirstOrder, int LastOrder>
class Taylor_fit
{
  static_assert(FirstOrder >= 0 && FirstOrder <= 2 && LastOrder >= 2 && LastOrder <= 4, "orders out of range");
  static_assert(FirstOrder <= 1 || LastOrder == 2, "the own monomials must be a prefix of the tested ones");

  static constexpr int quadratic = number_of_monomials(D, 2);
  static constexpr int cubic = LastOrder >= 3 ? number_of_monomials(D, 3) : 0;
  static constexpr int quartic = LastOrder == 4 ? number_of_monomials(D, 4) : 0;

public:
  static constexpr bool constant_term = FirstOrder == 0;
  static constexpr bool linear_terms = FirstOrder <= 1;
  static constexpr int last_order = LastOrder;
  static constexpr bool quartic_moments = Monomial_tables<D, FirstOrder, LastOrder>::quartic_moments;
  static constexpr int unknowns = (constant_term ? 1 : 0) + (linear_terms ? D : 0) + quadratic + cubic + quartic;
  // The monomials of orders min(FirstOrder, 1)..LastOrder, those of test (b): the
  // fit's own ones first (quadratic, [linear, [constant,]] [cubic, [quartic]]),
  // then for Hamann's fit the linear ones.
  static constexpr int tested = (constant_term ? 1 : 0) + D + quadratic + cubic + quartic;

  using Point = Eigen::Matrix<double, D, 1>;
  using Hessian = Eigen::Matrix<double, D, D>;

  // The whitening is not trusted where the samples' second moments M have a
  // condition number (estimated as tr(M) tr(M^-1)) above this: the tangent
  // coordinates are known to rounding relative to the scaled length 1, which
  // whitening amplifies by sqrt(cond M) in the narrowest direction (at most 1e4:
  // 1e-12 relative), and samples on a line through the vertex show about 1e16.
  static constexpr double max_whitening_condition = 1e8;

  Taylor_fit() { clear(); }

  void clear() { reset(); }

  // One sample: a point of the tangent space, the height above it, its weight.
  void add(const Point& x, double height, double weight = 1.0)
  {
    accumulate<Tables::first_own_moment>(x, height, weight);
  }

  int size() const { return size_; }

  // Test (a) of the header comment: solves the normal equations unless there
  // are fewer samples than unknowns, the normal matrix is singular, or its
  // condition number (1-norm, decided by a bound or else exact: see Cost) exceeds
  // `max_condition`: a stencil that is singular in the tangent space can still
  // be solvable in floating point once tilted, and its solution is then garbage.
  // The caller scales the samples to a unit length (the mean 1-ring edge), so
  // the number does not depend on the mesh's scale, and by the choice of
  // monomials (see add) it depends on the turn of the frame by at most a factor
  // of the number of unknowns.
  bool solve(double max_condition)
  {
    condition_ = std::numeric_limits<double>::infinity();
    condition_pending_ = false;
    if (size_ < unknowns)
      return false;
    if (!cholesky_factor<unknowns>(factor_, inverse_diagonal_))
      return false;
    own_norm_ = one_norm<unknowns>();
    // ||N^-1||_1 = ||L^-T L^-1||_1 <= ||L^-1||_1 ||L^-1||_inf, bounded from L
    // alone; the inverse of L, which costs as much as the factorisation, only
    // where that bound does not decide, and the product, which costs as much
    // again, only where the norms of the inverse do not decide either. The bound
    // from L decides 84% of the degree-4 fits of bunny00.off, 39% of camel.off's,
    // 3% of cheese.off's (long thin fans); without it, fit_degree 4 took 6% more
    // time on the 317 x 317 grid (1,995 against 1,879 ns per vertex, median of 8
    // placements of the stack) and 4% to 5% more on bunny00 and armadillo.
    if (own_norm_ * comparison_bound<unknowns>(factor_, inverse_diagonal_) <= max_condition)
      condition_pending_ = true;
    else {
      alignas(16) double F[factor_size];
      inverse_of_factor<unknowns>(factor_, inverse_diagonal_, F);
      if (own_norm_ * triangular_norms_product<unknowns>(F) <= max_condition)
        condition_pending_ = true;
      else {
        condition_ = own_norm_ * inverse_one_norm<unknowns>(F);
        if (!(condition_ <= max_condition))
          return false;
      }
    }
    whitened_ = false;
    solve_with_factor();
    return true;
  }

  // Test (b) of the header comment, and the fit in whitened coordinates mapped
  // back to x, on the samples that `samples(add)` gives by calling
  // add(x, height, weight) for each (twice: once for M, once for N_y, which is
  // accumulated from the y_i; computing it as T N T^T would lose the digits that
  // cond_1(N) costs); the fit then holds them. False when there are fewer
  // samples than the tested monomials, when M or N_y is singular, when the
  // whitening is not trusted (max_whitening_condition) or when cond_1(N_y)
  // exceeds `max_condition`.
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
    if (!(weight_sum > 0) || !whitening((D / weight_sum) * moments, W))
      return false;
    reset();
    samples([&](const Point& x, double height, double weight) { accumulate<0>(W * x, height, weight); });

    alignas(16) double whitened_factor[factor_size];
    double whitened_inverse_diagonal[tested];
    if (!cholesky_factor<tested>(whitened_factor, whitened_inverse_diagonal))
      return false;
    alignas(16) double F[factor_size];
    inverse_of_factor<tested>(whitened_factor, whitened_inverse_diagonal, F);
    whitened_condition_ = one_norm<tested>() * inverse_one_norm<tested>(F);
    if (!(whitened_condition_ <= max_condition))
      return false;
    if (condition_pending_) { // test (a)'s factor is about to be replaced
      condition_ = condition_number();
      condition_pending_ = false;
    }
    // The fit's own block is a leading block of N_y, its Cholesky factor the
    // leading block of N_y's: a prefix of each column.
    std::copy(whitened_factor, whitened_factor + factor_size, factor_);
    std::copy(whitened_inverse_diagonal, whitened_inverse_diagonal + tested, inverse_diagonal_);
    whitened_ = true;
    whitening_ = W;
    solve_with_factor();
    map_back();
    return true;
  }

  // The fit again after an accepted solve or solve_whitened, on the same samples
  // with other heights: `samples(add)` calls add(x, height, weight) for each (any
  // order). Only the right-hand side is accumulated; the factor is the last one.
  template <typename Samples>
  void solve_again(const Samples& samples)
  {
    std::fill(right_hand_side_, right_hand_side_ + unknowns, 0.0);
    samples([&](const Point& x, double height, double weight) {
      add_heights(whitened_ ? Point(whitening_ * x) : x, weight * height);
    });
    solve_with_factor();
    if (whitened_)
      map_back();
  }

  // The fit again after an accepted solve or solve_whitened, on the same samples
  // with the heights less curvature_quartic(C, x), C the fitted Hessian, from
  // the moments alone: curvature_quartic(C, x) = (x^T C x)(x^T C^2 x) / 8 is a
  // combination of the quartic monomials, so that its sum times a monomial of
  // the fit is a combination of moments. In whitened coordinates y = W x, the
  // two quadratic forms are those of W^-T C W^-1 and W^-T C^2 W^-1.
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
    // (x^T A x)(x^T B x) / 8 in the monomials x0^(4 - j) x1^j
    const double quartic[5] = {A(0, 0) * B(0, 0) / 8, (A(0, 0) * B(0, 1) + A(0, 1) * B(0, 0)) / 4,
                               (A(0, 0) * B(1, 1) + A(1, 1) * B(0, 0) + 4 * A(0, 1) * B(0, 1)) / 8,
                               (A(0, 1) * B(1, 1) + A(1, 1) * B(0, 1)) / 4, A(1, 1) * B(1, 1) / 8};
    CGAL_CURVATURE_ESTIMATION_UNROLL
    for (int k = 0; k < unknowns; ++k)
      CGAL_CURVATURE_ESTIMATION_UNROLL
    for (int j = 0; j < 5; ++j)
      right_hand_side_[k] -= quartic[j] * moments_[tables_.quartic_moment[k][j]];
    solve_with_factor();
    if (whitened_)
      map_back();
  }

  // The condition numbers of tests (a) and (b) at the last solve and solve_whitened (infinity where not computed).
  double condition_number() const
  {
    if (!condition_pending_)
      return condition_;
    alignas(16) double F[factor_size];
    inverse_of_factor<unknowns>(factor_, inverse_diagonal_, F);
    return own_norm_ * inverse_one_norm<unknowns>(F);
  }
  double whitened_condition_number() const { return whitened_condition_; }
  const Hessian& hessian() const { return hessian_; }
  const Point& gradient() const { return gradient_; }

private:
  static constexpr double half_sqrt2 = 0.70710678118654752440;
  // The tables' entries of the normal matrix are packed: the lower triangle row by row.
  static constexpr int index(int i, int j) { return i >= j ? i * (i + 1) / 2 + j : j * (j + 1) / 2 + i; }
  // The triangular factors (L by columns, see cholesky_factor; its inverse by
  // rows) are stored in lines of an even length, so that the leading block of the
  // own unknowns is that of the tested ones.
  static constexpr int factor_stride = (tested + 1) / 2 * 2;
  static constexpr int factor_size = factor_stride * tested;
  static constexpr int factor_index(int i, int j) { return factor_stride * i + j; }

  using Tables = Monomial_tables<D, FirstOrder, LastOrder>;
  using Pair = Eigen::Array2d;
  static Eigen::Map<Pair, Eigen::Aligned16> pair_at(double* p) { return Eigen::Map<Pair, Eigen::Aligned16>(p); }
  static Eigen::Map<const Pair, Eigen::Aligned16> pair_at(const double* p)
  {
    return Eigen::Map<const Pair, Eigen::Aligned16>(p);
  }
  // Whether the sums of products of powers are added in pairs (see fill_windows):
  // for surfaces, in the fits of degree 3 and 4, whose accumulation is a third
  // of their time. Measured on the 317 x 317 grid (best of 4 runs): fit_degree 3
  // 1,016 -> 965 ns per vertex, 4 2,365 -> 2,205; the default, whose fits of
  // degree 2 keep their few sums in registers, 568 -> 596, so it keeps the
  // scalar products. (The factorisation is in pairs for every fit: see cholesky_factor.)
  static constexpr bool paired_products = Monomial_tables<D, FirstOrder, LastOrder>::paired;
  static_assert(Tables::tested == tested, "the tables' rows are the tested monomials");
  static constexpr Tables tables_{};

  // The fit from the Cholesky factor L of the fit's own block (N = L L^T): L y =
  // rhs, then L^T a = y, a the coefficients of the monomials (rhs: the sums of
  // the heights times the monomials, scaled here, see add_heights).
  void solve_with_factor()
  {
    double scaled[unknowns];
    CGAL_CURVATURE_ESTIMATION_UNROLL
    for (int i = 0; i < unknowns; ++i)
      scaled[i] = tables_.scale[i] * right_hand_side_[tables_.row_slot[i]];
    const auto entry = [](double value) { return value; };
    double reduced[unknowns];
    forward_substitution<unknowns>(factor_, inverse_diagonal_, scaled, entry, reduced);
    double coefficients[unknowns];
    backward_substitution<unknowns>(factor_, inverse_diagonal_, reduced, entry, coefficients);
    set_coefficients(coefficients);
  }

  // Solutions of T y = b for T = L (forward) and T = L^T (backward), L from
  // cholesky_factor<n>, with the entries of T off its diagonal read through
  // `entry`: the solve reads them as they are, comparison_bound as -|L_ij|.
  template <int n, typename Entry>
  static void forward_substitution(const double (&L)[factor_size], const double (&inverse_diagonal)[tested],
                                   const double (&b)[n], Entry entry, double (&y)[n])
  {
    CGAL_CURVATURE_ESTIMATION_UNROLL
    for (int i = 0; i < n; ++i) {
      double value = b[i];
      CGAL_CURVATURE_ESTIMATION_UNROLL
      for (int k = 0; k < i; ++k)
        value -= entry(L[factor_index(k, i)]) * y[k];
      y[i] = value * inverse_diagonal[i];
    }
  }
  template <int n, typename Entry>
  static void backward_substitution(const double (&L)[factor_size], const double (&inverse_diagonal)[tested],
                                    const double (&b)[n], Entry entry, double (&y)[n])
  {
    CGAL_CURVATURE_ESTIMATION_UNROLL
    for (int i = n - 1; i >= 0; --i) {
      double value = b[i];
      CGAL_CURVATURE_ESTIMATION_UNROLL
      for (int k = i + 1; k < n; ++k)
        value -= entry(L[factor_index(i, k)]) * y[k];
      y[i] = value * inverse_diagonal[i];
    }
  }

  // The Hessian and gradient from the coefficients of the monomials of x.
  void set_coefficients(const double (&coefficients)[unknowns])
  {
    int column = 0;
    CGAL_CURVATURE_ESTIMATION_UNROLL
    for (int i = 0; i < D; ++i)
      CGAL_CURVATURE_ESTIMATION_UNROLL
    for (int j = i; j < D; ++j) {
      const double value = (i == j ? 1.0 : half_sqrt2) * coefficients[column];
      hessian_(i, j) = value;
      hessian_(j, i) = value;
      ++column;
    }
    if constexpr (linear_terms)
      CGAL_CURVATURE_ESTIMATION_UNROLL
    for (int i = 0; i < D; ++i)
      gradient_[i] = coefficients[column + i];
    else gradient_.setZero();
  }

  // W = L^-1 for M = L L^T (see the header comment), lower triangular; false
  // where M is not positive definite or its condition number, estimated as
  // tr(M) tr(M^-1) (between it and D^2 times it), exceeds max_whitening_condition.
  static bool whitening(const Hessian& M, Hessian& W)
  {
    Hessian L = Hessian::Zero();
    for (int j = 0; j < D; ++j) {
      double diagonal = M(j, j);
      for (int k = 0; k < j; ++k)
        diagonal -= L(j, k) * L(j, k);
      if (!(diagonal > 0))
        return false;
      L(j, j) = std::sqrt(diagonal);
      for (int i = j + 1; i < D; ++i) {
        double value = M(i, j);
        for (int k = 0; k < j; ++k)
          value -= L(i, k) * L(j, k);
        L(i, j) = value / L(j, j);
      }
    }
    W.setZero();
    for (int j = 0; j < D; ++j) {
      W(j, j) = 1 / L(j, j);
      for (int i = j + 1; i < D; ++i) {
        double value = 0;
        for (int k = j; k < i; ++k)
          value -= L(i, k) * W(k, j);
        W(i, j) = value / L(i, i);
      }
    }
    return M.trace() * W.squaredNorm() <= max_whitening_condition; // tr(M^-1) = |W|_F^2
  }

  // From the coefficients of y = W x to those of x:
  // h(x) = g_y . (W x) + 1/2 (W x)^T C_y (W x).
  void map_back()
  {
    hessian_ = whitening_.transpose() * hessian_ * whitening_;
    gradient_ = whitening_.transpose() * gradient_;
  }

  // Zeroes the moments, the right-hand side and the count.
  void reset()
  {
    std::fill(moments_, moments_ + Tables::moments(), 0.0);
    std::fill(right_hand_side_, right_hand_side_ + unknowns, 0.0);
    size_ = 0;
  }

  // Adds a sample to the moments from `first` on (those of the fit's own block,
  // or all) and to the right-hand side. An entry of the normal matrix is a sum of
  // products of two monomials, which is a scaled moment sum_i w_i x_i^a (a
  // monomial of degree 2 to 2 LastOrder): summing the moments (42 for surfaces at
  // fit_degree 4, 25 at 3) costs less than summing the entries (105, 45).
  template <int first>
  void accumulate(const Point& x, double height, double weight)
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
      add_products<true>(weighted_heights, ys, std::make_index_sequence<unknowns>());
    } else {
      double powers[D][Tables::highest_degree + 1];
      fill_powers(x, weight, powers);
      add_moments<first>(powers, std::make_index_sequence<Tables::moments() - first>());
      double weighted_heights[LastOrder + 1];
      CGAL_CURVATURE_ESTIMATION_UNROLL
      for (int k = 0; k <= LastOrder; ++k)
        weighted_heights[k] = height * powers[0][k];
      add_heights(weighted_heights, powers, std::make_index_sequence<unknowns>());
    }
    ++size_;
  }

  template <int first, std::size_t... m>
  void add_moments(const double (&powers)[D][Tables::highest_degree + 1], std::index_sequence<m...>)
  {
    ((moments_[first + m] += product_of_powers(tables_.moment[first + m], powers[0], powers)), ...);
  }

  // Adds to the right-hand side w h r(x) without the monomials' scales (solve_with
  // applies them, once): `lead` is w h times the powers of x[0], `powers` those of
  // the other coordinates.
  template <int L, int P, std::size_t... i>
  void add_heights(const double (&lead)[L], const double (&powers)[D][P], std::index_sequence<i...>)
  {
    ((right_hand_side_[i] += product_of_powers(tables_.accumulated_row[i], lead, powers)), ...);
  }

  void add_heights(const Point& x, double weighted_height)
  {
    if constexpr (paired_products) {
      Pair lead[LastOrder], ys[LastOrder];
      fill_windows(x, weighted_height, lead, ys);
      add_products<true>(lead, ys, std::make_index_sequence<unknowns>());
    } else {
      double powers[D][LastOrder + 1];
      fill_powers(x, weighted_height, powers);
      add_heights(powers[0], powers, std::make_index_sequence<unknowns>());
    }
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

  // For surfaces, the powers of x = (x0, x1) as windows of two consecutive
  // entries, so that the products of add_products are operations on pairs
  // without shuffles (half the instructions of the scalar products per sample):
  // the powers of x0 times `factor` in decreasing order, lead[s] = factor
  // (x0^(W - s), x0^(W - 1 - s)), and those of x1 in increasing order, ys[s] =
  // (x1^s, x1^(s + 1)). Each lane is the same chain of products as fill_powers.
  template <int W>
  static void fill_windows(const Point& x, double factor, Pair (&lead)[W], Pair (&ys)[W])
  {
    // (factor x0, factor) and (1, x1) from broadcasts, in registers: a pair
    // written as two scalars and read as one stalls the load (store forwarding).
    lead[W - 1] = Pair::Constant(factor) * (Pair::Constant(x[0]) * Pair(1.0, 0.0) + Pair(0.0, 1.0));
    ys[0] = Pair::Constant(x[1]) * Pair(0.0, 1.0) + Pair(1.0, 0.0);
    CGAL_CURVATURE_ESTIMATION_UNROLL
    for (int s = 1; s < W; ++s) {
      lead[W - 1 - s] = lead[W - s] * x[0];
      ys[s] = ys[s - 1] * x[1];
    }
  }

  // For surfaces, adds factor x0^a x1^b for each monomial x0^a x1^b of the
  // tables' accumulated rows (to the right-hand side; Heights) or of their
  // moments (to the moments), from the windows of fill_windows. The tables put
  // the pairs first: x0^a x1^b and x0^(a-1) x1^(b+1), which take the windows
  // lead[W - a] and ys[b] and are added as one pair.
  template <bool Heights, int W, int V, std::size_t... m>
  void add_products(const Pair (&lead)[W], const Pair (&ys)[V], std::index_sequence<m...>)
  {
    (add_product<Heights, m>(lead, ys), ...);
  }

  template <bool Heights, int m, int W, int V>
  void add_product(const Pair (&lead)[W], const Pair (&ys)[V])
  {
    constexpr const Monomial_exponents* exponents = Heights ? tables_.accumulated_row : tables_.moment;
    constexpr int paired = Heights ? tables_.paired_rows : tables_.paired_moments;
    constexpr int a = exponents[m].power[0];
    constexpr int b = exponents[m].power[1];
    double* target = Heights ? right_hand_side_ + m : moments_ + m;
    if constexpr (m >= paired) {
      // factor x0^a is the first entry of lead[W - a] (the second of lead[W - 1] for a = 0).
      const double lead_power = a > 0 ? lead[W - a][0] : lead[W - 1][1];
      const double y_power = b < V ? ys[b][0] : ys[V - 1][1];
      *target += lead_power * y_power;
    } else if constexpr (m % 2 == 0)
      pair_at(target) += lead[W - a] * ys[b];
  }

  // Entry (i, j) of the normal matrix, from the moments.
  double normal_entry(int i, int j) const
  {
    const int k = index(i, j);
    return tables_.entry_scale[k] * moments_[tables_.entry_moment[k]];
  }

  // x^e, with the powers of x[0] from `lead` (which may carry a factor) and those
  // of the other coordinates from `powers`.
  template <int L, int P>
  static double product_of_powers(const Monomial_exponents& e, const double (&lead)[L], const double (&powers)[D][P])
  {
    double value = lead[e.power[0]];
    CGAL_CURVATURE_ESTIMATION_UNROLL
    for (int d = 1; d < D; ++d)
      value *= powers[d][e.power[d]];
    return value;
  }

  // The largest column sum of absolute values of the leading n x n block of the normal matrix.
  template <int n>
  double one_norm() const
  {
    double largest = 0;
    CGAL_CURVATURE_ESTIMATION_UNROLL
    for (int j = 0; j < n; ++j) {
      double sum = 0;
      CGAL_CURVATURE_ESTIMATION_UNROLL
      for (int i = 0; i < n; ++i)
        sum += std::abs(normal_entry(i, j));
      largest = sum > largest ? sum : largest;
    }
    return largest;
  }

  // The Cholesky factor L of the leading n x n block of the normal matrix (N = L
  // L^T), lower triangular, stored by columns (L_ij at factor_index(j, i); above
  // the diagonal, in the column's first pair, any finite number), and the
  // inverses of its diagonal; false if the block is not positive definite.
  // Column by column, the dot products of row i and row j of L for all i of
  // column j at once, in aligned pairs of rows, in plain loops over fixed sizes
  // (the compiler unrolls them; Eigen's small triangular solves are several
  // times slower); each entry is the same chain of operations as in the textbook
  // loop, in the same order.
  // The entries of N are computed from the moments where they are needed: a
  // matrix written entry by entry and read in pairs stalls the reads (store
  // forwarding). Measured against the scalar loops (with the inverse of L, then
  // computed in every solve) on the 317 x 317 grid (median over 16 placements of
  // the stack): fit_degree 4 2,196 -> 1,987 ns per vertex, 3 978 -> 958; the
  // default's small fits 572 -> 582.
  template <int n>
  bool cholesky_factor(double (&L)[factor_size], double (&inverse_diagonal)[tested]) const
  {
    static_assert(n <= tested, "array too small");
    constexpr int pairs = (n + 1) / 2;
    CGAL_CURVATURE_ESTIMATION_UNROLL
    for (int j = 0; j < n; ++j) {
      double* column = L + factor_stride * j;
      CGAL_CURVATURE_ESTIMATION_UNROLL
      for (int p = j / 2; p < pairs; ++p) {
        const int i = 2 * p; // rows i and i + 1 (row j - 1 or n: unused, any finite number)
        Pair value(normal_entry(i, j), normal_entry(i + 1 < n ? i + 1 : i, j));
        CGAL_CURVATURE_ESTIMATION_UNROLL
        for (int k = 0; k < j; ++k)
          value -= pair_at(L + factor_stride * k + i) * L[factor_index(k, j)];
        pair_at(column + i) = value;
      }
      const double diagonal = column[j];
      if (!(diagonal > 0))
        return false;
      inverse_diagonal[j] = 1 / std::sqrt(diagonal);
      CGAL_CURVATURE_ESTIMATION_UNROLL
      for (int p = j / 2; p < pairs; ++p)
        pair_at(column + 2 * p) *= inverse_diagonal[j];
    }
    return true;
  }

  // F = L^-1 for L from cholesky_factor<n> (so that N^-1 = F^T F), lower
  // triangular, stored by rows (F_ij at factor_index(i, j), zero above the
  // diagonal up to the row's last pair): row i of F is e_i minus the rows of F
  // above it times the entries of row i of L, divided by L_ii, in aligned pairs
  // of columns, so that a row is summed in registers and written once.
  template <int n>
  static void inverse_of_factor(const double (&L)[factor_size], const double (&inverse_diagonal)[tested],
                                double (&F)[factor_size])
  {
    constexpr int pairs = (n + 1) / 2;
    CGAL_CURVATURE_ESTIMATION_UNROLL
    for (int i = 0; i < n; ++i) {
      Pair row[pairs];
      CGAL_CURVATURE_ESTIMATION_UNROLL
      for (int p = 0; p <= i / 2; ++p)
        row[p] = Pair(2 * p == i ? 1.0 : 0.0, 2 * p + 1 == i ? 1.0 : 0.0);
      CGAL_CURVATURE_ESTIMATION_UNROLL
      for (int k = 0; k < i; ++k) {
        const double entry = L[factor_index(k, i)];
        CGAL_CURVATURE_ESTIMATION_UNROLL
        for (int p = 0; p <= k / 2; ++p)
          row[p] -= pair_at(F + factor_stride * k + 2 * p) * entry;
      }
      CGAL_CURVATURE_ESTIMATION_UNROLL
      for (int p = 0; p <= i / 2; ++p)
        pair_at(F + factor_stride * i + 2 * p) = row[p] * inverse_diagonal[i];
    }
  }

  // A bound of ||L^-1||_1 ||L^-1||_inf, hence of ||N^-1||_1, from L (cholesky_factor<n>)
  // alone, at the cost of two triangular solves: the comparison matrix M of L
  // (|L_ij| on the diagonal, -|L_ij| below it) has M^-1 >= |L^-1| entrywise, so
  // ||L^-1||_inf <= max_i (M^-1 e)_i and ||L^-1||_1 <= max_i (M^-T e)_i, e = (1, ..., 1)
  // (Higham, Accuracy and Stability of Numerical Algorithms, section 8.3).
  template <int n>
  static double comparison_bound(const double (&L)[factor_size], const double (&inverse_diagonal)[tested])
  {
    double ones[n];
    std::fill(ones, ones + n, 1.0);
    const auto entry = [](double value) { return -std::abs(value); };
    double forward[n];
    forward_substitution<n>(L, inverse_diagonal, ones, entry, forward);
    double backward[n];
    backward_substitution<n>(L, inverse_diagonal, ones, entry, backward);
    return *std::max_element(forward, forward + n) * *std::max_element(backward, backward + n);
  }

  // ||F^T F||_1 for a lower triangular n x n F (see inverse_of_factor): the 1-norm of N^-1.
  template <int n>
  static double inverse_one_norm(const double (&F)[factor_size])
  {
    double column_sums[n] = {};
    CGAL_CURVATURE_ESTIMATION_UNROLL
    for (int i = 0; i < n; ++i)
      CGAL_CURVATURE_ESTIMATION_UNROLL
    for (int j = 0; j <= i; ++j) {
      double value = 0;
      CGAL_CURVATURE_ESTIMATION_UNROLL
      for (int k = i; k < n; ++k)
        value += F[factor_index(k, i)] * F[factor_index(k, j)];
      column_sums[j] += std::abs(value);
      if (j != i)
        column_sums[i] += std::abs(value);
    }
    return *std::max_element(column_sums, column_sums + n);
  }

  // ||F||_1 ||F||_inf for a lower triangular n x n F (see inverse_of_factor): a bound of ||F^T F||_1.
  template <int n>
  static double triangular_norms_product(const double (&F)[factor_size])
  {
    double column_sums[n] = {};
    double largest_row_sum = 0;
    CGAL_CURVATURE_ESTIMATION_UNROLL
    for (int i = 0; i < n; ++i) {
      double row_sum = 0;
      CGAL_CURVATURE_ESTIMATION_UNROLL
      for (int j = 0; j <= i; ++j) {
        row_sum += std::abs(F[factor_index(i, j)]);
        column_sums[j] += std::abs(F[factor_index(i, j)]);
      }
      largest_row_sum = row_sum > largest_row_sum ? row_sum : largest_row_sum;
    }
    return largest_row_sum * *std::max_element(column_sums, column_sums + n);
  }

  // The sums of accumulate, in the tables' order (moment, accumulated_row):
  // aligned, so that the pairs at even indices are.
  alignas(16) double moments_[Tables::moments()];
  // From the moments: solve fills the own block, a prefix; solve_whitened all of it.
  alignas(16) double right_hand_side_[unknowns];
  // The Cholesky factor L of the own block N = L L^T and the inverses of its
  // diagonal (see cholesky_factor), at the last accepted solve or solve_whitened,
  // and the own block's 1-norm at the last solve.
  alignas(16) double factor_[factor_size];
  double inverse_diagonal_[tested];
  double own_norm_ = 0;
  // Whether the last solve accepted by the bound of the condition number, which
  // condition_number() then replaces by the number itself.
  bool condition_pending_ = false;
  bool whitened_ = false; // whether that was solve_whitened, in the coordinates whitening_ x
  Hessian whitening_ = Hessian::Identity();
  int size_ = 0;
  double condition_ = std::numeric_limits<double>::infinity();
  double whitened_condition_ = std::numeric_limits<double>::infinity();
  Hessian hessian_ = Hessian::Zero();
  Point gradient_ = Point::Zero();
};

// The quartic part of the height that the Hessian C implies by itself (see the
// header comment): (x^T C x) |C x|^2 / 8.
template <int D>
double curvature_quartic(const Eigen::Matrix<double, D, D>& C, const Eigen::Matrix<double, D, 1>& x)
{
  const Eigen::Matrix<double, D, 1> Cx = C * x;
  return x.dot(Cx) * Cx.squaredNorm() / 8;
}

} // namespace internal
} // namespace Curvature_estimation
} // namespace CGAL

#undef CGAL_CURVATURE_ESTIMATION_UNROLL

#endif // CGAL_CURVATURE_ESTIMATION_INTERNAL_QUADRIC_FIT_H
