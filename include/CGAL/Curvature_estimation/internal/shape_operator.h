// SPDX-License-Identifier: GPL-3.0-or-later
// Principal curvatures and directions of the graph of a height function over a
// tangent frame, at the frame's origin.
#ifndef CGAL_CURVATURE_ESTIMATION_INTERNAL_SHAPE_OPERATOR_H
#define CGAL_CURVATURE_ESTIMATION_INTERNAL_SHAPE_OPERATOR_H

#include <CGAL/Curvature_estimation/internal/symmetric_eigen.h>

#include <Eigen/Core>

#include <cmath>

namespace CGAL {
namespace Curvature_estimation {
namespace internal {

// Curvatures in the package's convention, decreasing; directions unit tangent
// vectors of R^N, column i for curvature i; `normal` the graph's at the origin.
template <int N>
struct Graph_curvature
{
  static constexpr int D = N - 1;
  Eigen::Matrix<double, D, 1> curvatures;
  Eigen::Matrix<double, N, D> directions;
  Eigen::Matrix<double, N, 1> normal;
};

// The graph of h(x) = g.x + 1/2 x^T C x over the frame: G = I + g g^T,
// l = sqrt(1 + |g|^2); the shape operator G^-1 C / l diagonalised in the symmetric
// form G^-1/2 C G^-1/2 / l, whose eigenvectors w give the directions G^-1/2 w.
template <int N>
Graph_curvature<N>
graph_curvature(const Eigen::Matrix<double, N - 1, N - 1>& hessian, const Eigen::Matrix<double, N - 1, 1>& gradient,
                const Eigen::Matrix<double, N, N - 1>& tangents, const Eigen::Matrix<double, N, 1>& normal)
{
  constexpr int D = N - 1;
  using Square = Eigen::Matrix<double, D, D>;

  const double gradient_norm2 = gradient.squaredNorm();
  Graph_curvature<N> result;
  Eigen::Matrix<double, D, 1> eigenvalues;
  Square eigenvectors;
  if (gradient_norm2 == 0) {
    // The frame's normal is the graph's: the metric is the identity.
    symmetric_eigen<D>(hessian, eigenvalues, eigenvectors);
    result.curvatures = -eigenvalues;
    result.directions = tangents * eigenvectors;
    result.normal = normal;
    return result;
  }
  const double l = std::sqrt(1.0 + gradient_norm2);
  const Square inverse_sqrt_metric =
    Square::Identity() + ((1.0 / l - 1.0) / gradient_norm2) * (gradient * gradient.transpose());

  const Square symmetric = inverse_sqrt_metric * hessian * inverse_sqrt_metric / l;
  symmetric_eigen<D>(symmetric, eigenvalues, eigenvectors);

  // Ascending eigenvalues of the upward shape operator are, negated, the
  // curvatures in decreasing order.
  result.curvatures = -eigenvalues;
  const Square parameter_directions = inverse_sqrt_metric * eigenvectors;
  result.directions = tangents * parameter_directions + normal * (gradient.transpose() * parameter_directions);
  result.normal = (normal - tangents * gradient) / l;
  return result;
}

// The mean of the curvatures of graph_curvature, without its eigenvectors:
// -tr(G^-1 C) / (D l).
template <int D>
double graph_mean_curvature(const Eigen::Matrix<double, D, D>& hessian, const Eigen::Matrix<double, D, 1>& gradient)
{
  const double gradient_norm2 = gradient.squaredNorm();
  const double trace = hessian.trace() - gradient.dot(hessian * gradient) / (1.0 + gradient_norm2);
  return -trace / (D * std::sqrt(1.0 + gradient_norm2));
}

} // namespace internal
} // namespace Curvature_estimation
} // namespace CGAL

#endif // CGAL_CURVATURE_ESTIMATION_INTERNAL_SHAPE_OPERATOR_H
