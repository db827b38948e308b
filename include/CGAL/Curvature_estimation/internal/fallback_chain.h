// SPDX-License-Identifier: GPL-3.0-or-later
// An estimator's fallback chain: its own estimate, then other estimators' where
// it finds none, in an order that the estimator declares in one place.
#ifndef CGAL_CURVATURE_ESTIMATION_INTERNAL_FALLBACK_CHAIN_H
#define CGAL_CURVATURE_ESTIMATION_INTERNAL_FALLBACK_CHAIN_H

#include <CGAL/Curvature_estimation/internal/surface_estimate.h>

#include <cstddef>

namespace CGAL {
namespace Curvature_estimation {
namespace internal {

// What a fit at one vertex found, for the links of a chain.
template <typename Estimate>
struct Vertex_fit
{
  Estimate estimate;         // not_estimable where no fit was accepted
  std::size_t neighbors = 0; // the neighbors gathered, on every ring reached or in the ball
  bool whitened = false;     // whether the whitened test accepted the fit or its normal's
  bool on_border = false;
};

// What a link of a chain found at a vertex: an estimate (accepted), an estimate
// that a later link may replace (provisional), none (refused), or none and none
// to be had from any link (hopeless: the vertex carries no information).
enum class Verdict
{
  accepted,
  provisional,
  refused,
  hopeless
};

template <typename Estimate>
struct Link_result
{
  Estimate estimate; // not_estimable unless accepted or provisional
  Verdict verdict = Verdict::refused;
};

// The verdict on an estimate that is final where it exists.
template <typename Estimate>
Link_result<Estimate> accepted_or_refused(const Estimate& e)
{
  return {e, e.status == Estimation_status::not_estimable ? Verdict::refused : Verdict::accepted};
}

// Where a fallback link is tried: where the links before it found nothing, or
// also where they found only a provisional estimate.
enum class Tried_where
{
  refused,
  refused_or_provisional
};

template <typename Link>
struct Fallback
{
  Tried_where where;
  Link link; // link() returns a Link_result
};

template <typename Link>
Fallback<Link> fallback(Tried_where where, Link link)
{
  return {where, link};
}

// The estimate of `first()`, unless it is refused or provisional and
// `use_fallbacks`: then that of the first of `fallbacks` tried there that accepts,
// with the status fallback; where none does, a provisional estimate stands and a
// refused vertex is not estimable. A hopeless verdict ends the chain.
template <typename Estimate, typename First, typename... Links>
Estimate estimate_with_fallbacks(bool use_fallbacks, const First& first, const Fallback<Links>&... fallbacks)
{
  Link_result<Estimate> best = first();
  if (!use_fallbacks || best.verdict == Verdict::accepted)
    return best.estimate;
  bool from_fallback = false;
  const auto try_link = [&](const auto& f) { // true: the chain ends
    if (best.verdict == Verdict::hopeless)
      return true;
    if (best.verdict == Verdict::provisional && f.where == Tried_where::refused)
      return false;
    const Link_result<Estimate> r = f.link();
    if (r.verdict == Verdict::accepted || (best.verdict == Verdict::refused && r.verdict != Verdict::refused)) {
      best = r;
      from_fallback = true;
    }
    return best.verdict == Verdict::accepted;
  };
  (try_link(fallbacks) || ...);
  return from_fallback ? as_fallback(best.estimate) : best.estimate;
}

} // namespace internal
} // namespace Curvature_estimation
} // namespace CGAL

#endif // CGAL_CURVATURE_ESTIMATION_INTERNAL_FALLBACK_CHAIN_H
