// SPDX-License-Identifier: GPL-3.0-or-later
// The kinds of Taylor fit that the attempts name, and a new fit of a kind.
#ifndef CGAL_CURVATURE_ESTIMATION_INTERNAL_FIT_KINDS_H
#define CGAL_CURVATURE_ESTIMATION_INTERNAL_FIT_KINDS_H

#include <CGAL/Curvature_estimation/internal/taylor_fit/taylor_fit.h>

#include <type_traits>

namespace CGAL {
namespace Curvature_estimation {
namespace internal {

// Which Taylor fit (taylor_fit.h): Hamann's paraboloid, or a fit of a degree with
// the gradient, or with the gradient and an intercept.
enum class Fit_kind : unsigned char
{
  paraboloid,
  gradient_2,
  gradient_3,
  gradient_4,
  intercept_2,
  intercept_3,
  intercept_4
};

constexpr Fit_kind gradient_fit_of_degree(int degree)
{
  return degree == 2 ? Fit_kind::gradient_2 : degree == 3 ? Fit_kind::gradient_3 : Fit_kind::gradient_4;
}
constexpr Fit_kind intercept_fit_of_degree(int degree)
{
  return degree == 2 ? Fit_kind::intercept_2 : degree == 3 ? Fit_kind::intercept_3 : Fit_kind::intercept_4;
}

// The Taylor fit types a walk may meet (Fit_kinds<...>), by kind.
template <Fit_kind... kinds>
struct Fit_kinds
{};

// The orders of the fit of a kind: FirstOrder 2 for Hamann's paraboloid, 1 with
// the gradient, 0 with an intercept; LastOrder its degree.
constexpr int first_order(Fit_kind kind)
{
  return kind == Fit_kind::paraboloid ? 2 : kind <= Fit_kind::gradient_4 ? 1 : 0;
}
constexpr int last_order(Fit_kind kind)
{
  switch (kind) {
    case Fit_kind::gradient_3:
    case Fit_kind::intercept_3:
      return 3;
    case Fit_kind::gradient_4:
    case Fit_kind::intercept_4:
      return 4;
    default:
      return 2;
  }
}

template <int D, Fit_kind kind>
using Fit_of_kind = Taylor_fit<D, first_order(kind), last_order(kind)>;

// use(fit) with a new fit of `kind`, one of `kinds`.
template <int D, Fit_kind... kinds, typename Use>
void with_fit(Fit_kinds<kinds...>, Fit_kind kind, const Use& use)
{
  const auto use_new = [&](auto* tag) {
    std::remove_pointer_t<decltype(tag)> fit;
    use(fit);
  };
  ((kind == kinds ? use_new(static_cast<Fit_of_kind<D, kinds>*>(nullptr)) : void()), ...);
}

} // namespace internal
} // namespace Curvature_estimation
} // namespace CGAL

#endif // CGAL_CURVATURE_ESTIMATION_INTERNAL_FIT_KINDS_H
