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
#include <vector>

namespace ce_test {

/// A standard normal deviate (Box-Muller on two uniform01 draws: the same values
/// on every standard library).
inline double standard_normal(std::mt19937& gen)
{
  const double u = 1.0 - uniform01(gen); // in (0, 1]
  const double v = uniform01(gen);
  return std::sqrt(-2.0 * std::log(u)) * std::cos(6.283185307179586477 * v);
}

/// Adds to each coordinate of each point of `s` Gaussian noise of standard
/// deviation `fraction` times the mean edge length of `s` (before the noise);
/// returns that standard deviation.
inline double add_gaussian_noise(Soup& s, double fraction, std::uint32_t seed)
{
  const double sigma = fraction * mean_edge_length(s);
  std::mt19937 gen(seed);
  for (Eigen::Vector3d& p : s.points)
    for (int k = 0; k < 3; ++k)
      p[k] += sigma * standard_normal(gen);
  return sigma;
}

/// The noisy ellipsoid of the ball_radius tests and of the report's noise section:
/// semi-axes 1, 0.8 and 0.6, the icosphere of 4^s 10 + 2 points (s = `subdivisions`)
/// jittered by 0.2, with Gaussian noise of 7% of the mean edge length in each
/// coordinate. `exact` is the curvature of the points before the noise, `sigma` the
/// noise's standard deviation.
struct Noisy_ellipsoid_soup
{
  Soup soup;
  std::vector<Exact_curvature> exact;
  double sigma = 0;
};

inline Noisy_ellipsoid_soup noisy_ellipsoid_soup(unsigned subdivisions, std::uint32_t seed)
{
  Noisy_ellipsoid_soup e;
  e.soup = ellipsoid_soup(1, 0.8, 0.6, subdivisions, 0.2, seed);
  e.exact = ellipsoid_curvatures(1, 0.8, 0.6, e.soup);
  e.sigma = add_gaussian_noise(e.soup, 0.07, seed);
  return e;
}

} // namespace ce_test

#endif // CE_TEST_COMMON_NOISY_MESHES_H
