// SPDX-License-Identifier: GPL-3.0-or-later
// Deterministic random numbers for the tests and the accuracy benchmarks: the same values
// on every standard library, as they use only the raw output of std::mt19937 (whose
// sequence the C++ standard fixes; std::uniform_real_distribution's is not).
//
// Header-only, no GoogleTest dependency; everything lives in namespace `ce_test`.
#ifndef CE_TEST_COMMON_RANDOM_NUMBERS_H
#define CE_TEST_COMMON_RANDOM_NUMBERS_H

#include <cstdint>
#include <random>

namespace ce_test {

/// Uniform double in [0, 1) with 53 random bits, built from two raw outputs of std::mt19937.
inline double uniform01(std::mt19937& gen)
{
  const std::uint32_t a = static_cast<std::uint32_t>(gen()) >> 5; // 27 bits
  const std::uint32_t b = static_cast<std::uint32_t>(gen()) >> 6; // 26 bits
  return (static_cast<double>(a) * 67108864.0 + static_cast<double>(b)) * (1.0 / 9007199254740992.0);
}

/// Uniform double in [-1, 1).
inline double uniform_symmetric(std::mt19937& gen) { return 2.0 * uniform01(gen) - 1.0; }

/// Uniform double in [lo, hi): lo + (hi - lo) * uniform01(gen).
inline double uniform(std::mt19937& gen, double lo, double hi) { return lo + (hi - lo) * uniform01(gen); }

} // namespace ce_test

#endif // CE_TEST_COMMON_RANDOM_NUMBERS_H
