#include "boundary_term_filter.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <numbers>

#include "arctan2.hpp"
#include "exactgeo/predicates/kernel/signs.hpp"

// The error bound, with u = 2^-53 and every vector first scaled by a power of two so that
// its largest component is in [1, 2) (solid angles depend only on directions):
//
//  - A = fl(a - p) is within u|A| of a - p per component (a difference that underflows is
//    exact); the scaling is exact unless a component falls below 2^-1022, where it loses
//    at most 2^-1075. The direction -r is exact. So each input is within u|A| + 2^-1074.
//  - N = fl(A . fl(B x D)): the cross product and the dot add up to gamma_5 P, with P the
//    permanent sum |A_i| (|B_j||D_k| + |B_k||D_j|); the inputs' own errors, through
//    trilinearity, add (2u + u^2) P. So |N - N*| <= 7.01u P.
//  - |A| = fl(sqrt(fl(A . A))): within (1.5 gamma_3 + u) of the computed vector's length,
//    and that within u + 2^-1074 of the exact one's: 7u in all, relative.
//  - P is not computed: P = sum_i |A_i| w_i with w_i = |B_j||D_k| + |B_k||D_j|, and each of
//    the two vectors (|B_j||D_k|)_i has length at most |B||D| (its squares are some of the
//    products B_j^2 D_k^2, which add up to |B|^2 |D|^2), so |w| <= 2 |B||D| and, by
//    Cauchy-Schwarz, P <= |A||w| <= 2 |A||B||D|. The computed L = fl(fl(|A||B|)|D|) is
//    within (1 - 7u)^-3 (1 - u)^-2 < 1 + 24u of it, so |N - N*| <= 14.02u (1 + 24u) L
//    < 14.1u L, and 16u L, rounded down by at most u, covers it.
//  - D = |A||B||D| + (A.B)|D| + (A.D)|B| + (B.D)|A|, with L = |A||B||D|: every term is at
//    most L (Cauchy-Schwarz); the first is off by at most (3 x 7 + 2)u L, each of the
//    others by (gamma_3 + 2.01u + 7u + u) L <= 13u L (dot, inputs, a length, a product),
//    and the three additions by u times partial sums below 4L each: 23 + 39 + 12 = 74u L,
//    taken as 96u L.
//  - Underflowing products of these O(1) numbers lose at most 2^-1075 each, far below the
//    absolute 2^-1000 added to both bounds.
//  - The exact point (N*, D*) is within E = |dN| + |dD| of the computed one. Where
//    E <= r / 4, r = |(N, D)|, the segment between them stays 3r/4 from the origin, so the
//    half angles differ by at most (4/3) E / r, provided the segment does not cross the
//    branch cut (N = 0, D < 0): it does not where |N| > |dN| (same half plane, upper or
//    lower) or D > |dD| (right half plane); where D < -|dD| the exact sign of N* (an exact
//    predicate) is given to the computed N, which moves it no further from N*. Otherwise
//    the filter gives up. The arctangent adds its own error, at most kArctanError
//    (arctan2.hpp derives it; the C library's atan2 is not called here).
//  - The sum of the B weighted half angles rounds within (B + 1) u times the sum of their
//    magnitudes (gamma_B, and the products by the multiplicities); 2 pi times a level
//    rounds within 1.5u of its magnitude (pi's double is within 0.4u of pi).

namespace exactgeo::internal {
namespace {

constexpr double kU = 0x1p-53;
constexpr double kTiny = 0x1p-1000;

}  // namespace

std::optional<Vector3> normalized_apex(const Vector3& apex) {
  return normalized(apex);
}

std::optional<Vector3> normalized_by_ldexp(const Vector3& v, double largest) {
  if (largest == 0.0 || !std::isfinite(largest)) return std::nullopt;
  const int shift = -std::ilogb(largest);
  return Vector3{std::ldexp(v[0], shift), std::ldexp(v[1], shift), std::ldexp(v[2], shift)};
}

double branch_cut_side(const Point3& p, const Point3& pa, const Point3& pb, const Vector3& apex) {
  const Sign side = kernel::ExactSigns{}.det3_by_vector(
      kernel::Offset::between(p, pa), kernel::Offset::between(p, pb), kernel::Offset::vector(apex));
  return side == Sign::zero ? 0.0 : side == Sign::positive ? 1.0 : -1.0;
}

std::optional<FilteredSum> filtered_sum(const Point3& p, const Vector3& apex,
                                        std::span<const Point3> vertices,
                                        std::span<const BoundaryEdge> edges, double offset,
                                        double slack) {
  const auto d = normalized(apex);
  if (!d) return std::nullopt;
  const double ld = std::sqrt((*d)[0] * (*d)[0] + (*d)[1] * (*d)[1] + (*d)[2] * (*d)[2]);
  double sum = offset, magnitudes = std::abs(offset), errors = 0.0;
  for (const BoundaryEdge& edge : edges) {
    const auto angle = half_angle(p, *d, ld, vertices[edge.from], vertices[edge.to], apex);
    if (!angle) return std::nullopt;
    if (angle->kind == BoundaryTermKind::ray_on_edge) {
      return FilteredSum{BoundaryTermKind::ray_on_edge, 0.0, 0.0};
    }
    const double m = edge.multiplicity;
    sum += m * angle->theta;
    magnitudes += std::abs(m * angle->theta);
    errors += std::abs(m) * angle->error;
  }
  // (The offset is one more term of the sum.)
  const double rounding = (static_cast<double>(edges.size()) + 3) * kU * magnitudes;
  // slack, an upper bound already, joins the sum inside the factor that covers the
  // rounding of these additions.
  const double bound = (errors + rounding + slack) * (1 + 8 * kU) + kTiny;
  return FilteredSum{BoundaryTermKind::enclosed, sum - bound,
                     sum + bound};  // each within an ulp of exact
}

std::optional<BoundaryTerm> settled(const FilteredSum& sum, std::array<double, 2> levels) {
  if (sum.kind != BoundaryTermKind::enclosed) return BoundaryTerm{sum.kind, {}, {}};
  const double lower = sum.lower, upper = sum.upper;
  constexpr double two_pi = 2 * std::numbers::pi;
  BoundaryTerm term{BoundaryTermKind::enclosed, {}, {}};
  for (std::size_t i = 0; i < 2; ++i) {
    const double threshold = two_pi * levels[i];
    const double slack =
        2 * kU * std::abs(threshold) + 4 * kU * (std::abs(lower) + std::abs(upper));
    term.versus[i] = upper + slack < threshold   ? Versus::below
                     : lower - slack > threshold ? Versus::above
                                                 : Versus::unsure;
    if (term.versus[i] == Versus::unsure) return std::nullopt;
  }
  term.turns = turns_of(sum);
  return term;
}

Enclosure turns_of(const FilteredSum& sum) {
  // The turns, widened by the division's rounding and pi's.
  constexpr double two_pi = 2 * std::numbers::pi;
  const double low = sum.lower / two_pi, high = sum.upper / two_pi;
  return {low - 4 * kU * std::abs(low) - kTiny, high + 4 * kU * std::abs(high) + kTiny};
}

std::optional<BoundaryTerm> filtered_boundary_term(const Point3& p, const Vector3& apex,
                                                   std::span<const Point3> vertices,
                                                   std::span<const BoundaryEdge> edges,
                                                   std::array<double, 2> levels) {
  const std::optional<FilteredSum> sum = filtered_sum(p, apex, vertices, edges, 0.0, 0.0);
  if (!sum) return std::nullopt;
  return settled(*sum, levels);
}

}  // namespace exactgeo::internal
