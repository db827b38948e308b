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

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <string>
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

/// The noisy family of the scale-selection tests and of the report's scale-selection
/// section: an ellipsoid of 2,562 points, a torus of 10,240 and a Delaunay mesh of 6,000
/// random points over Hamann's trigonometric graph, with Gaussian noise of a fraction of
/// the mean edge length h in each coordinate. `exact` is the curvature before the noise,
/// `sigma` the noise's standard deviation per point, `interior` the points whose balls of
/// up to 16 h stay on the surface (closed surfaces: every point).
enum class Noisy_shape
{
  ellipsoid,
  torus,
  delaunay
};

struct Noisy_family_soup
{
  std::string name; // "torus 5%", "delaunay varying"
  Soup soup;
  std::vector<Exact_curvature> exact;
  std::vector<double> sigma;
  std::vector<bool> interior;
};

/// The noise fractions of the family: 1%, 5% and 15% of h, and -1, which
/// noisy_family_soup takes as noise varying from 0 to 15% of h across x.
inline const std::vector<double>& noisy_family_fractions()
{
  static const std::vector<double> fractions = {0.01, 0.05, 0.15, -1};
  return fractions;
}

/// The fixed radii the family's selection is measured against: 1 to 16 mean edges in
/// steps of 2^(1/2).
inline std::vector<double> noisy_family_radii_in_edges()
{
  std::vector<double> radii;
  for (int k = 0; k <= 8; ++k)
    radii.push_back(std::exp2(k / 2.0));
  return radii;
}

/// `fraction` of the mean edge length, or where negative, from 0 to 0.15 across x; `seed`
/// draws the noise (the tests' draw by default).
inline Noisy_family_soup noisy_family_soup(Noisy_shape shape, double fraction, unsigned seed = 11)
{
  Noisy_family_soup m;
  const auto functions = hamann_table1_functions();
  switch (shape) {
    case Noisy_shape::ellipsoid:
      m.soup = ellipsoid_soup(1, 0.8, 0.6, 4, 0.2, 3);
      m.exact = ellipsoid_curvatures(1, 0.8, 0.6, m.soup);
      m.name = "ellipsoid";
      break;
    case Noisy_shape::torus:
      m.soup = torus_soup(1, 0.4, 160, 64, 0.2, 3);
      m.exact = torus_curvatures(1, 0.4, m.soup);
      m.name = "torus";
      break;
    case Noisy_shape::delaunay:
      m.soup = delaunay_graph_soup(functions[8], 6000, -1, 1, 3);
      m.exact = graph_curvatures(functions[8], m.soup);
      m.name = "delaunay";
      break;
  }
  const double h = mean_edge_length(m.soup);
  double lo = 1e300, hi = -1e300;
  for (const auto& p : m.soup.points) {
    lo = (std::min)(lo, p.x());
    hi = (std::max)(hi, p.x());
  }
  std::mt19937 gen(seed);
  for (auto& p : m.soup.points) {
    const double f = fraction >= 0 ? fraction : 0.15 * (p.x() - lo) / (hi - lo);
    m.sigma.push_back(f * h);
    m.interior.push_back(shape != Noisy_shape::delaunay ||
                         (std::abs(p.x()) < 1 - 17 * h && std::abs(p.y()) < 1 - 17 * h));
    for (int k = 0; k < 3; ++k)
      p[k] += f * h * standard_normal(gen);
  }
  m.name += fraction < 0 ? " varying" : " " + std::to_string(static_cast<int>(std::lround(100 * fraction))) + "%";
  return m;
}

/// The RMS error of `mean` (one H per point) over the interior points of `m`.
inline double interior_rms(const Noisy_family_soup& m, const std::vector<double>& mean)
{
  double sum = 0;
  std::size_t count = 0;
  for (std::size_t i = 0; i < mean.size(); ++i)
    if (m.interior[i]) {
      sum += (mean[i] - m.exact[i].H) * (mean[i] - m.exact[i].H);
      ++count;
    }
  return std::sqrt(sum / count);
}

} // namespace ce_test

#endif // CE_TEST_COMMON_NOISY_MESHES_H
