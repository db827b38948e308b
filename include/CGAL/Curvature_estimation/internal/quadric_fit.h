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
  using Row = Eigen::Matrix<double, unknowns, 1>;
  using Normal_matrix = Eigen::Matrix<double, unknowns, unknowns>;

  Taylor_fit() { clear(); }

  void clear()
  {
    normal_matrix_.setZero();
    right_hand_side_.setZero();
    size_ = 0;
  }

  // One sample: a point of the tangent space, the height above it, its weight.
  void add(const Point& x, double height, double weight = 1.0)
  {
    Row row;
    int column = 0;
    // Each order's monomials are scaled to be orthonormal coordinates of the
    // symmetric tensor x (x) ... (x) x (sqrt of the multiplicity), so that a
    // rotation of the tangent frame acts on each block of the normal matrix by an
    // orthogonal matrix and the condition number does not depend on how the frame
    // is turned in the tangent space. Quadratic terms first so that their
    // coefficients do not depend on FirstOrder.
    for (int i = 0; i < D; ++i)
      for (int j = i; j < D; ++j)
        row[column++] = (i == j ? 0.5 : half_sqrt2) * x[i] * x[j];
    if constexpr (FirstOrder == 1)
      for (int i = 0; i < D; ++i)
        row[column++] = x[i];
    if constexpr (LastOrder == 3)
      for (int i = 0; i < D; ++i)
        for (int j = i; j < D; ++j)
          for (int k = j; k < D; ++k)
            row[column++] = std::sqrt(double(multiplicity(i, j, k))) * x[i] * x[j] * x[k];
    normal_matrix_.noalias() += weight * row * row.transpose();
    right_hand_side_.noalias() += (weight * height) * row;
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
    Normal_matrix inverse;
    if (!invert(normal_matrix_, inverse))
      return false;
    condition_ = normal_matrix_.cwiseAbs().colwise().sum().maxCoeff() * inverse.cwiseAbs().colwise().sum().maxCoeff();
    if (!(condition_ <= max_condition))
      return false;

    const Row coefficients = inverse * right_hand_side_;
    int column = 0;
    for (int i = 0; i < D; ++i)
      for (int j = i; j < D; ++j) {
        const double value = (i == j ? 1.0 : half_sqrt2) * coefficients[column];
        hessian_(i, j) = value;
        hessian_(j, i) = value;
        ++column;
      }
    if constexpr (FirstOrder == 1)
      gradient_ = coefficients.template segment<D>(column);
    else
      gradient_.setZero();
    return true;
  }

  double condition_number() const { return condition_; }
  const Hessian& hessian() const { return hessian_; }
  const Point& gradient() const { return gradient_; }

private:
  static constexpr double half_sqrt2 = 0.70710678118654752440;

  // Number of distinct orderings of the indices i <= j <= k.
  static constexpr int multiplicity(int i, int j, int k) { return i == k ? 1 : (i == j || j == k) ? 3 : 6; }

  // The inverse of a symmetric matrix, by Cholesky factorisation in plain loops
  // (fully unrolled for these fixed sizes; Eigen's small triangular solves are
  // several times slower); false if it is not positive definite.
  static bool invert(const Normal_matrix& m, Normal_matrix& inverse)
  {
    constexpr int n = unknowns;
    double L[n][n] = {};
    for (int j = 0; j < n; ++j) {
      double diagonal = m(j, j);
      for (int k = 0; k < j; ++k)
        diagonal -= L[j][k] * L[j][k];
      if (!(diagonal > 0))
        return false;
      L[j][j] = std::sqrt(diagonal);
      for (int i = j + 1; i < n; ++i) {
        double value = m(i, j);
        for (int k = 0; k < j; ++k)
          value -= L[i][k] * L[j][k];
        L[i][j] = value / L[j][j];
      }
    }
    // L^-1, lower triangular, then inverse = L^-T L^-1.
    double Linv[n][n] = {};
    for (int j = 0; j < n; ++j) {
      Linv[j][j] = 1 / L[j][j];
      for (int i = j + 1; i < n; ++i) {
        double value = 0;
        for (int k = j; k < i; ++k)
          value -= L[i][k] * Linv[k][j];
        Linv[i][j] = value / L[i][i];
      }
    }
    for (int i = 0; i < n; ++i)
      for (int j = 0; j <= i; ++j) {
        double value = 0;
        for (int k = i; k < n; ++k)
          value += Linv[k][i] * Linv[k][j];
        inverse(i, j) = value;
        inverse(j, i) = value;
      }
    return true;
  }

  Normal_matrix normal_matrix_;
  Row right_hand_side_;
  int size_ = 0;
  double condition_ = std::numeric_limits<double>::infinity();
  Hessian hessian_ = Hessian::Zero();
  Point gradient_ = Point::Zero();
};

} // namespace internal
} // namespace Curvature_estimation
} // namespace CGAL

#endif // CGAL_CURVATURE_ESTIMATION_INTERNAL_QUADRIC_FIT_H
