#pragma once

// Is the origin o on a planar bilinear patch? The exact algebraic test behind the one case
// that orientation signs cannot settle: a non-convex flat patch (concave or butterfly)
// folds over itself, and points of the fold region have two preimages, so the winding
// number of the boundary around them is 0 although they lie on the patch.
//
// The patch is the union over u in [0,1] of the segments S(u) = [A(u), B(u)] with
// A(u) = p(u, 0), B(u) = p(u, 1). With a(u) = A(u) - o, b(u) = B(u) - o (affine in u),
// o lies on S(u) iff
//     h(u) = (a(u) x b(u))_k = 0     (collinear; k a projection axis injective on the plane)
// and g(u) = a(u) . b(u) <= 0        (o between A(u) and B(u)).
// Both are quadratics in u; with c_ij = (a_i x a_j)_k and d_ij = a_i . a_j (a_0 = p00 - o,
// a_1 = p10 - o, a_2 = p01 - o, a_3 = p11 - o), their Bernstein forms give
//     h(u) = (1-u)^2 c_02 + u(1-u) (c_03 + c_12) + u^2 c_13,  and likewise g with d.
// The question "is there u in [0,1] with h(u) = 0 and g(u) <= 0" is decided exactly with
// sign computations only (no square roots): at a root r of h (leading coefficient h2 > 0),
// h2 g(r) = l(r) for the remainder l = h2 g - g2 h, which is linear, and the sign of
// alpha + beta sqrt(D) follows from the signs of alpha, beta and alpha^2 - beta^2 D.
//
// Written once for any ordered field T with exact or approximate signs: Rational (exact)
// and double (the plain-double baseline).

#include <array>

#include "exactgeo/predicates/kernel/formulas.hpp"
#include "exactgeo/predicates/kernel/rational.hpp"
#include "exactgeo/predicates/sign.hpp"

namespace exactgeo::internal {

using kernel::cross2;
using kernel::dot3;
using kernel::Rational;
using kernel::Vec3;

inline Sign sign_of_number(double x) noexcept {
  return sign_of(x);
}
inline Sign sign_of_number(const Rational& x) noexcept {
  return x.sign();
}

/// Sign of alpha + beta * sqrt(discriminant), discriminant >= 0.
template <class T>
Sign sign_with_root(const T& alpha, const T& beta, const T& discriminant) {
  const Sign a = sign_of_number(alpha);
  const Sign b = sign_of_number(beta) * sign_of_number(discriminant);
  if (b == Sign::zero) return a;
  if (a == Sign::zero || a == b) return b;
  // Opposite signs: the larger magnitude wins. |alpha| > |beta| sqrt(D) iff alpha^2 > beta^2 D.
  return a * sign_of_number(alpha * alpha - beta * beta * discriminant);
}

/// A quadratic c0 + c1 u + c2 u^2.
template <class T>
struct Quadratic {
  T c0, c1, c2;
};

template <class T>
Quadratic<T> bernstein_to_power(const T& at0, const T& middle_sum, const T& at1) {
  // (1-u)^2 b0 + u(1-u) m + u^2 b1 = b0 + (m - 2 b0) u + (b0 - m + b1) u^2
  return {at0, middle_sum - at0 - at0, at0 - middle_sum + at1};
}

/// Is there u in [0,1] with h(u) = 0 and g(u) <= 0?
template <class T>
bool common_point_in_unit_interval(Quadratic<T> h, const Quadratic<T>& g) {
  const T zero{};
  auto sgn = [](const T& x) { return sign_of_number(x); };
  auto g_at = [&](const T& u) { return g.c0 + (g.c1 + g.c2 * u) * u; };

  if (sgn(h.c2) == Sign::zero && sgn(h.c1) == Sign::zero) {
    if (sgn(h.c0) != Sign::zero) return false;
    // h vanishes identically: is min over [0,1] of g <= 0?
    const T one = T(1.0);
    if (sgn(g.c0) != Sign::positive || sgn(g_at(one)) != Sign::positive) return true;
    // Interior minimum at u* = -g1 / (2 g2) when g2 > 0 and 0 < u* < 1, with value
    // g0 - g1^2 / (4 g2) <= 0 iff g1^2 - 4 g0 g2 >= 0.
    const T two_g2 = g.c2 + g.c2;
    return sgn(g.c2) == Sign::positive && sgn(g.c1) == Sign::negative &&
           sgn(two_g2 + g.c1) == Sign::positive &&
           sgn(g.c1 * g.c1 - (two_g2 + two_g2) * g.c0) != Sign::negative;
  }
  if (sgn(h.c2) == Sign::zero) {
    // Linear: root r = -h0 / h1, in [0,1] iff h0 h1 <= 0 and (h0 + h1) h1 >= 0; and
    // h1^2 g(r) = g2 h0^2 - g1 h0 h1 + g0 h1^2.
    if (sgn(h.c0) * sgn(h.c1) == Sign::positive) return false;
    if (sgn(h.c0 + h.c1) * sgn(h.c1) == Sign::negative) return false;
    return sgn(g.c2 * h.c0 * h.c0 - g.c1 * h.c0 * h.c1 + g.c0 * h.c1 * h.c1) != Sign::positive;
  }
  if (sgn(h.c2) == Sign::negative) h = {zero - h.c0, zero - h.c1, zero - h.c2};
  const T discriminant = h.c1 * h.c1 - (h.c2 + h.c2 + h.c2 + h.c2) * h.c0;
  if (sgn(discriminant) == Sign::negative) return false;
  // Roots r = (-h1 + e sqrt(D)) / (2 h2), e = +-1 (one root when D = 0); 2 h2 > 0.
  const T two_h2 = h.c2 + h.c2;
  // Remainder l(u) = l1 u + l0 of h2 g - g2 h; sign g(r) = sign l(r) = sign(alpha + e l1 sqrt D)
  // with alpha = 2 h2 l0 - l1 h1.
  const T l1 = h.c2 * g.c1 - g.c2 * h.c1;
  const T l0 = h.c2 * g.c0 - g.c2 * h.c0;
  const T alpha = two_h2 * l0 - l1 * h.c1;
  const T minus_h1 = zero - h.c1;
  const T minus_h1_minus_two_h2 = minus_h1 - two_h2;
  for (const T& e : {T(1.0), T(-1.0)}) {
    const bool at_or_after_0 = sign_with_root(minus_h1, e, discriminant) != Sign::negative;
    const bool at_or_before_1 =
        sign_with_root(minus_h1_minus_two_h2, e, discriminant) != Sign::positive;
    const bool between = sign_with_root(alpha, e * l1, discriminant) != Sign::positive;
    if (at_or_after_0 && at_or_before_1 && between) return true;
    if (sgn(discriminant) == Sign::zero) break;
  }
  return false;
}

/// Is o on the planar patch? `a` are the corners minus o in the order p00, p10, p01, p11;
/// o must lie in the patch's plane and `axis` must be a projection injective on it.
template <class T>
bool origin_on_planar_patch_by_sweep(const std::array<Vec3<T>, 4>& a, int axis) {
  const auto h = bernstein_to_power<T>(cross2(axis, a[0], a[2]),
                                       cross2(axis, a[0], a[3]) + cross2(axis, a[1], a[2]),
                                       cross2(axis, a[1], a[3]));
  const auto g = bernstein_to_power<T>(dot3(a[0], a[2]), dot3(a[0], a[3]) + dot3(a[1], a[2]),
                                       dot3(a[1], a[3]));
  return common_point_in_unit_interval(h, g);
}

}  // namespace exactgeo::internal
