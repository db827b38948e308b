// Least-squares Taylor fit of a height function over a tangent space, the
// numerical core shared by the surface (D = 2) and hypersurface (D = 3)
// estimators:
//
//   h(x) = [g . x] + 1/2 x^T C x [+ cubic terms],   x in R^D,   C symmetric,
//
// the terms of orders FirstOrder..LastOrder (FirstOrder 1 or 2, LastOrder 2 or 3).
// FirstOrder = 2 trusts the frame's normal (Hamann's fit); FirstOrder = 1 fits
// the gradient, i.e. corrects the normal; LastOrder = 3 takes the cubic part out
// of the gradient, which a one-sided (boundary) stencil does not cancel.
#ifndef CGAL_CURVATURE_ESTIMATION_INTERNAL_QUADRIC_FIT_H
#define CGAL_CURVATURE_ESTIMATION_INTERNAL_QUADRIC_FIT_H

#include <Eigen/Core>

#include <cmath>

#include <limits>

// Full unrolling of the fixed-size loops below: with constant indices the packed
// matrix addressing folds away (without it GCC leaves them as loops that cost
// several times more). Not for Clang, which warns that it cannot unroll the
// nested loops as asked; its own heuristics decide there.
#if defined(__GNUC__) && !defined(__clang__)
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

template <int D, int FirstOrder, int LastOrder>
class Taylor_fit
{
  static_assert(FirstOrder >= 1 && FirstOrder <= 2 && LastOrder >= 2 && LastOrder <= 3, "orders out of range");

public:
  static constexpr int unknowns = (FirstOrder == 1 ? number_of_monomials(D, 1) : 0) + number_of_monomials(D, 2) +
                                  (LastOrder == 3 ? number_of_monomials(D, 3) : 0);

  using Point = Eigen::Matrix<double, D, 1>;
  using Hessian = Eigen::Matrix<double, D, D>;

  Taylor_fit() { clear(); }

  void clear()
  {
    CGAL_CURVATURE_ESTIMATION_UNROLL
    for (double& a : normal_matrix_)
      a = 0;
    CGAL_CURVATURE_ESTIMATION_UNROLL
    for (double& b : right_hand_side_)
      b = 0;
    size_ = 0;
  }

  // One sample: a point of the tangent space, the height above it, its weight.
  void add(const Point& x, double height, double weight = 1.0)
  {
    double row[unknowns];
    int column = 0;
    // Each order's monomials are scaled to be orthonormal coordinates of the
    // symmetric tensor x (x) ... (x) x (sqrt of the multiplicity), so that a
    // rotation of the tangent frame acts on each block of the normal matrix by an
    // orthogonal matrix and the condition number does not depend on how the frame
    // is turned in the tangent space. Quadratic terms first so that their
    // coefficients do not depend on FirstOrder.
    CGAL_CURVATURE_ESTIMATION_UNROLL
    for (int i = 0; i < D; ++i)
      CGAL_CURVATURE_ESTIMATION_UNROLL
      for (int j = i; j < D; ++j)
        row[column++] = (i == j ? 0.5 : half_sqrt2) * x[i] * x[j];
    if constexpr (FirstOrder == 1)
      CGAL_CURVATURE_ESTIMATION_UNROLL
      for (int i = 0; i < D; ++i)
        row[column++] = x[i];
    if constexpr (LastOrder == 3)
      CGAL_CURVATURE_ESTIMATION_UNROLL
      for (int i = 0; i < D; ++i)
        CGAL_CURVATURE_ESTIMATION_UNROLL
        for (int j = i; j < D; ++j)
          CGAL_CURVATURE_ESTIMATION_UNROLL
          for (int k = j; k < D; ++k)
            row[column++] = sqrt_multiplicity(i, j, k) * x[i] * x[j] * x[k];
    // The lower triangle only, row by row: the matrix is symmetric.
    CGAL_CURVATURE_ESTIMATION_UNROLL
    for (int i = 0, k = 0; i < unknowns; ++i) {
      const double weighted = weight * row[i];
      CGAL_CURVATURE_ESTIMATION_UNROLL
      for (int j = 0; j <= i; ++j)
        normal_matrix_[k++] += weighted * row[j];
      right_hand_side_[i] += weight * height * row[i];
    }
    ++size_;
  }

  int size() const { return size_; }

  // Solves the normal equations. Returns false when there are fewer samples than
  // unknowns, when the normal matrix is singular, or when its condition number
  // (1-norm, exact for this small matrix) exceeds `max_condition`: a stencil that
  // is singular in the tangent space can still be solvable in floating point once
  // tilted, and its solution is then garbage. The caller scales the samples to a
  // unit length (the mean 1-ring edge), so the number does not depend on the
  // mesh's scale, and by the choice of monomials (see add) it depends on the turn
  // of the frame by at most a factor of the number of unknowns.
  bool solve(double max_condition)
  {
    condition_ = std::numeric_limits<double>::infinity();
    if (size_ < unknowns)
      return false;
    double inverse[packed];
    if (!invert(normal_matrix_, inverse))
      return false;
    condition_ = one_norm(normal_matrix_) * one_norm(inverse);
    if (!(condition_ <= max_condition))
      return false;

    double coefficients[unknowns];
    CGAL_CURVATURE_ESTIMATION_UNROLL
    for (int i = 0; i < unknowns; ++i) {
      double value = 0;
      CGAL_CURVATURE_ESTIMATION_UNROLL
      for (int j = 0; j < unknowns; ++j)
        value += inverse[index(i, j)] * right_hand_side_[j];
      coefficients[i] = value;
    }
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
    if constexpr (FirstOrder == 1)
      CGAL_CURVATURE_ESTIMATION_UNROLL
      for (int i = 0; i < D; ++i)
        gradient_[i] = coefficients[column + i];
    else
      gradient_.setZero();
    return true;
  }

  double condition_number() const { return condition_; }
  const Hessian& hessian() const { return hessian_; }
  const Point& gradient() const { return gradient_; }

private:
  static constexpr double half_sqrt2 = 0.70710678118654752440;
  // Symmetric matrices are stored packed: the lower triangle row by row.
  static constexpr int packed = unknowns * (unknowns + 1) / 2;
  static constexpr int index(int i, int j) { return i >= j ? i * (i + 1) / 2 + j : j * (j + 1) / 2 + i; }

  // The square root of the number of distinct orderings of the indices i <= j <= k.
  static constexpr double sqrt_multiplicity(int i, int j, int k)
  {
    return i == k ? 1.0 : (i == j || j == k) ? 1.7320508075688772935 : 2.4494897427831780982;
  }

  // The largest column sum of absolute values of a packed symmetric matrix.
  static double one_norm(const double (&m)[packed])
  {
    double largest = 0;
    CGAL_CURVATURE_ESTIMATION_UNROLL
    for (int j = 0; j < unknowns; ++j) {
      double sum = 0;
      CGAL_CURVATURE_ESTIMATION_UNROLL
      for (int i = 0; i < unknowns; ++i)
        sum += std::abs(m[index(i, j)]);
      largest = sum > largest ? sum : largest;
    }
    return largest;
  }

  // The inverse of a packed symmetric matrix, by Cholesky factorisation in plain
  // loops over fixed sizes (the compiler unrolls them; Eigen's small triangular
  // solves are several times slower); false if it is not positive definite.
  static bool invert(const double (&m)[packed], double (&inverse)[packed])
  {
    constexpr int n = unknowns;
    double L[packed];  // lower triangular factor, packed
    double inverse_diagonal[n];
    CGAL_CURVATURE_ESTIMATION_UNROLL
    for (int j = 0; j < n; ++j) {
      double diagonal = m[index(j, j)];
      CGAL_CURVATURE_ESTIMATION_UNROLL
      for (int k = 0; k < j; ++k)
        diagonal -= L[index(j, k)] * L[index(j, k)];
      if (!(diagonal > 0))
        return false;
      L[index(j, j)] = std::sqrt(diagonal);
      inverse_diagonal[j] = 1 / L[index(j, j)];
      CGAL_CURVATURE_ESTIMATION_UNROLL
      for (int i = j + 1; i < n; ++i) {
        double value = m[index(i, j)];
        CGAL_CURVATURE_ESTIMATION_UNROLL
        for (int k = 0; k < j; ++k)
          value -= L[index(i, k)] * L[index(j, k)];
        L[index(i, j)] = value * inverse_diagonal[j];
      }
    }
    // L^-1, lower triangular, in place of L; then inverse = L^-T L^-1.
    CGAL_CURVATURE_ESTIMATION_UNROLL
    for (int j = 0; j < n; ++j) {
      CGAL_CURVATURE_ESTIMATION_UNROLL
      for (int i = j + 1; i < n; ++i) {
        double value = -L[index(i, j)] * inverse_diagonal[j];
        CGAL_CURVATURE_ESTIMATION_UNROLL
        for (int k = j + 1; k < i; ++k)
          value -= L[index(i, k)] * L[index(k, j)];
        L[index(i, j)] = value * inverse_diagonal[i];
      }
      L[index(j, j)] = inverse_diagonal[j];
    }
    CGAL_CURVATURE_ESTIMATION_UNROLL
    for (int i = 0; i < n; ++i)
      CGAL_CURVATURE_ESTIMATION_UNROLL
      for (int j = 0; j <= i; ++j) {
        double value = 0;
        CGAL_CURVATURE_ESTIMATION_UNROLL
        for (int k = i; k < n; ++k)
          value += L[index(k, i)] * L[index(k, j)];
        inverse[index(i, j)] = value;
      }
    return true;
  }

  double normal_matrix_[packed];
  double right_hand_side_[unknowns];
  int size_ = 0;
  double condition_ = std::numeric_limits<double>::infinity();
  Hessian hessian_ = Hessian::Zero();
  Point gradient_ = Point::Zero();
};

} // namespace internal
} // namespace Curvature_estimation
} // namespace CGAL

#undef CGAL_CURVATURE_ESTIMATION_UNROLL

#endif // CGAL_CURVATURE_ESTIMATION_INTERNAL_QUADRIC_FIT_H
