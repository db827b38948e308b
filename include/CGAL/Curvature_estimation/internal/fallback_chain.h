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

// What a fit at one vertex found besides its estimate, for the links of a chain.
struct Vertex_fit
{
  std::size_t neighbors = 0; // the neighbors gathered, on every ring reached or in the ball
  bool whitened = false;     // whether the whitened test accepted the fit or its normal's
  bool on_border = false;
};

// What a link of a chain found at a vertex: an estimate (accepted), an estimate
// that a later link may replace (provisional), none (refused), or none and none
// to be had from any link (hopeless: the vertex carries no information). A link
// is called as link(out) with `out` not estimable, writes its estimate there and
// returns its verdict; `out` stays not estimable unless accepted or provisional.
enum class Verdict
{
  accepted,
  provisional,
  refused,
  hopeless
};

// The verdict on an estimate that is final where it exists.
template <typename Estimate>
Verdict accepted_or_refused(const Estimate& e)
{
  return e.status == Estimation_status::not_estimable ? Verdict::refused : Verdict::accepted;
}

// A link's writing of `e`, an estimate that is final where it exists, into `out`.
template <typename Estimate>
Verdict final_estimate(Estimate& out, const Estimate& e)
{
  out = e;
  return accepted_or_refused(out);
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
  Link link;
};

template <typename Link>
Fallback<Link> fallback(Tried_where where, Link link)
{
  return {where, link};
}

// Writes into `out` (not estimable on entry) the estimate of `first`, unless it is
// refused or provisional and `use_fallbacks`: then that of the first of `fallbacks`
// tried there that accepts, with the status fallback; where none does, a
// provisional estimate stands and a refused vertex is not estimable. A hopeless
// verdict ends the chain.
template <typename Estimate, typename First, typename... Links>
void estimate_with_fallbacks(Estimate& out, bool use_fallbacks, const First& first, const Fallback<Links>&... fallbacks)
{
  Verdict best = first(out);
  if (!use_fallbacks || best == Verdict::accepted)
    return;
  bool from_fallback = false;
  const auto try_link = [&](const auto& f) { // true: the chain ends
    if (best == Verdict::hopeless)
      return true;
    if (best == Verdict::provisional && f.where == Tried_where::refused)
      return false;
    Estimate e;
    const Verdict r = f.link(e);
    if (r == Verdict::accepted || (best == Verdict::refused && r != Verdict::refused)) {
      out = e;
      best = r;
      from_fallback = true;
    }
    return best == Verdict::accepted;
  };
  (try_link(fallbacks) || ...);
  if (from_fallback && out.status != Estimation_status::not_estimable)
    out.status = Estimation_status::fallback;
}

} // namespace internal
} // namespace Curvature_estimation
} // namespace CGAL

#endif // CGAL_CURVATURE_ESTIMATION_INTERNAL_FALLBACK_CHAIN_H
