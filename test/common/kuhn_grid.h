// SPDX-License-Identifier: GPL-3.0-or-later
// The Kuhn triangulation of a cube grid: the tetrahedral meshes of the hypersurface tests
// and of the tool's tests of Medit input.
//
// Header-only, no GoogleTest dependency; everything lives in namespace `ce_test`.
#ifndef CE_TEST_COMMON_KUHN_GRID_H
#define CE_TEST_COMMON_KUHN_GRID_H

#include <Eigen/Core>

#include <array>
#include <cstddef>
#include <utility>
#include <vector>

namespace ce_test {

/// Which diagonal of each cube ((i,j,k), ..., (i+1,j+1,k+1)) its 6 Kuhn tetrahedra share.
enum class Kuhn_diagonal
{
  main, ///< (i,j,k)-(i+1,j+1,k+1): the cells' faces z = const are split along (i,j)-(i+1,j+1)
  anti  ///< (i+1,j,k)-(i,j+1,k+1): the faces z = const are split along (i+1,j)-(i,j+1), the
        ///< triangulation of the surface grid that reproduces the thesis' Table 4.1 (test_surfaces.h)
};

/// The orientation of the tetrahedra.
enum class Kuhn_orientation
{
  positive, ///< every tetrahedron positively oriented
  as_built  ///< the vertex order of the walk along the diagonal: half of them negatively oriented
};

/// Points and tetrahedra (vertex indices from 0).
struct Tetrahedral_grid
{
  std::vector<Eigen::Vector3d> points;
  std::vector<std::array<std::size_t, 4>> cells;
};

/// The n^3 grid over [-1, 1]^3, x_i = -1 + 2 i/(n-1) (the same for y and z), point (i,j,k) of
/// index (k n + j) n + i, every cube split into the 6 Kuhn tetrahedra around `diagonal`.
inline Tetrahedral_grid kuhn_grid(int n, Kuhn_diagonal diagonal = Kuhn_diagonal::main,
                                  Kuhn_orientation orientation = Kuhn_orientation::positive)
{
  Tetrahedral_grid g;
  auto index = [n](int i, int j, int k) { return std::size_t((k * n + j) * n + i); };
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        g.points.emplace_back(-1 + 2.0 * i / (n - 1), -1 + 2.0 * j / (n - 1), -1 + 2.0 * k / (n - 1));
  const int permutations[6][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {0, 2, 1}, {2, 1, 0}, {1, 0, 2}};
  const bool anti = diagonal == Kuhn_diagonal::anti;
  for (int k = 0; k + 1 < n; ++k)
    for (int j = 0; j + 1 < n; ++j)
      for (int i = 0; i + 1 < n; ++i)
        for (int p = 0; p < 6; ++p) {
          // From one end of the diagonal to the other, one step along each axis; with the
          // anti diagonal the x step goes from i + 1 to i, a reflection.
          int c[3] = {anti ? i + 1 : i, j, k};
          const int step[3] = {anti ? -1 : 1, 1, 1};
          std::array<std::size_t, 4> cell;
          cell[0] = index(c[0], c[1], c[2]);
          for (int s = 0; s < 3; ++s) {
            c[permutations[p][s]] += step[permutations[p][s]];
            cell[s + 1] = index(c[0], c[1], c[2]);
          }
          // An odd permutation or the reflection: negatively oriented as built.
          if (orientation == Kuhn_orientation::positive && (p >= 3) != anti)
            std::swap(cell[2], cell[3]);
          g.cells.push_back(cell);
        }
  return g;
}

} // namespace ce_test

#endif // CE_TEST_COMMON_KUHN_GRID_H
