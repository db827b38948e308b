// SPDX-License-Identifier: GPL-3.0-or-later
// Pairs of doubles in one SSE2 register, the unrolling of fixed-size loops and
// the inlining of the fits' per-sample work (see the manual, "What a fit costs").
#ifndef CGAL_CURVATURE_ESTIMATION_INTERNAL_TAYLOR_FIT_PAIRS_H
#define CGAL_CURVATURE_ESTIMATION_INTERNAL_TAYLOR_FIT_PAIRS_H

#include <Eigen/Core>

// Full unrolling, so that constant indices fold the packed addressing away. Not
// for Clang, which cannot unroll the nested loops as asked and warns, nor under
// GCC's AddressSanitizer, whose instrumented loops it cannot unroll either.
#if defined(__GNUC__) && !defined(__clang__) && !defined(__SANITIZE_ADDRESS__)
#define CGAL_CURVATURE_ESTIMATION_UNROLL _Pragma("GCC unroll 32")
#else
#define CGAL_CURVATURE_ESTIMATION_UNROLL
#endif

// Inlining that GCC's heuristics decline where a fit type is used at many call
// sites, in the per-sample and per-fit loops.
#if defined(__GNUC__)
#define CGAL_CURVATURE_ESTIMATION_INLINE inline __attribute__((always_inline))
#else
#define CGAL_CURVATURE_ESTIMATION_INLINE inline
#endif

namespace CGAL {
namespace Curvature_estimation {
namespace internal {

using Pair = Eigen::Array2d;

// The pair at p, which must be 16-byte aligned.
inline Eigen::Map<Pair, Eigen::Aligned16> pair_at(double* p) { return Eigen::Map<Pair, Eigen::Aligned16>(p); }
inline Eigen::Map<const Pair, Eigen::Aligned16> pair_at(const double* p)
{
  return Eigen::Map<const Pair, Eigen::Aligned16>(p);
}

} // namespace internal
} // namespace Curvature_estimation
} // namespace CGAL

#endif // CGAL_CURVATURE_ESTIMATION_INTERNAL_TAYLOR_FIT_PAIRS_H
