// SPDX-License-Identifier: GPL-3.0-or-later
// The noise test family: a test soup whose points carry Gaussian noise of a
// given fraction of the soup's mean edge length in each coordinate, seeded, as
// on a scanned or reconstructed mesh. The exact curvature stays that of the
// points before the noise (compute it first).
//
// Header-only, no GoogleTest dependency; everything lives in namespace `ce_test`.
#ifndef CE_TEST_COMMON_NOISY_MESHES_H
#define CE_TEST_COMMON_NOISY_MESHES_H

#include "random_numbers.h"
#include "test_surfaces.h"

#include <cmath>
#include <cstdint>
#include <random>

namespace ce_test {

/// A standard normal deviate (Box-Muller on two uniform01 draws: the same values
/// on every standard library).
inline double standard_normal(std::mt19937& gen)
{
  const double u = 1.0 - uniform01(gen);  // in (0, 1]
  const double v = uniform01(gen);
  return std::sqrt(-2.0 * std::log(u)) * std::cos(6.283185307179586477 * v);
}

/// Adds to each coordinate of each point of `s` Gaussian noise of standard
/// deviation `fraction` times the mean edge length of `s` (before the noise).
inline void add_gaussian_noise(Soup& s, double fraction, std::uint32_t seed)
{
  const double sigma = fraction * mean_edge_length(s);
  std::mt19937 gen(seed);
  for (Eigen::Vector3d& p : s.points)
    for (int k = 0; k < 3; ++k)
      p[k] += sigma * standard_normal(gen);
}

} // namespace ce_test

#endif // CE_TEST_COMMON_NOISY_MESHES_H
