// SPDX-License-Identifier: GPL-3.0-or-later
// Tests of internal/tangent_frame.h: tangent_basis<N> is orthonormal and
// orthogonal to the normal, also near the axes and at ties.
#include "local_fit_inputs.h"

#include <gtest/gtest.h>

namespace {

using namespace ce_test::local_fit;

template <int N>
std::vector<Vec<N>> test_normals(Random& random)
{
  std::vector<Vec<N>> normals;
  for (int k = 0; k < N; ++k)
    for (double sign : {1.0, -1.0}) {
      const Vec<N> axis = sign * Vec<N>::Unit(k);
      normals.push_back(axis);
      // Nearly on the axis, by several orders of magnitude.
      for (double delta : {1e-2, 1e-6, 1e-10, 1e-15, 1e-300}) {
        Vec<N> v = random.unit_vector<N>();
        v -= v.dot(axis) * axis;
        normals.push_back((axis + delta * v.normalized()).normalized());
      }
    }
  // Ties between the largest components: (+-1, ..., +-1)/sqrt(N) and (+-1, +-1, 0, ..)/sqrt 2.
  for (int signs = 0; signs < (1 << N); ++signs) {
    Vec<N> v;
    for (int i = 0; i < N; ++i)
      v[i] = (signs >> i) & 1 ? -1.0 : 1.0;
    normals.push_back(v.normalized());
    Vec<N> w = Vec<N>::Zero();
    w[0] = v[0];
    w[N - 1] = v[N - 1];
    normals.push_back(w.normalized());
  }
  for (int i = 0; i < 2000; ++i)
    normals.push_back(random.unit_vector<N>());
  return normals;
}

template <int N>
void check_tangent_basis(std::uint32_t seed)
{
  Random random(seed);
  const std::vector<Vec<N>> normals = test_normals<N>(random);
  double worst_orthonormality = 0, worst_orthogonality = 0;
  for (const Vec<N>& n : normals) {
    const Mat<N, N - 1> t = CEI::tangent_basis<N>(n);
    ASSERT_TRUE(t.allFinite()) << "n = " << n.transpose();
    const double orthonormality = orthonormality_error(t);
    const double orthogonality = (t.transpose() * n).cwiseAbs().maxCoeff();
    EXPECT_LE(orthonormality, 1e-14) << "n = " << n.transpose();
    EXPECT_LE(orthogonality, 1e-14) << "n = " << n.transpose();
    worst_orthonormality = (std::max)(worst_orthonormality, orthonormality);
    worst_orthogonality = (std::max)(worst_orthogonality, orthogonality);
    // [T n] is then an orthonormal basis of R^N: |det| = 1.
    Mat<N, N> full;
    full << t, n;
    EXPECT_NEAR(std::abs(full.determinant()), 1.0, 1e-13) << "n = " << n.transpose();
  }
  std::cout << "tangent_basis<" << N << ">: " << normals.size()
            << " normals, max |T^T T - I| = " << worst_orthonormality << ", max |T^T n| = " << worst_orthogonality
            << "\n";
}

TEST(TangentBasis, OrthonormalAndOrthogonalToNormalIn3D) { check_tangent_basis<3>(11); }

TEST(TangentBasis, OrthonormalAndOrthogonalToNormalIn4D) { check_tangent_basis<4>(12); }

} // namespace
