#pragma once

// The boundary term's first stage: plain double arithmetic and an a priori bound on its
// error, derived in boundary_term_filter.cpp: far cheaper than outward-rounded intervals
// (docs/inside.md, "Open surfaces", measures it); where its bound cannot settle both
// levels, the caller goes on to them.

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <optional>
#include <span>

#include "arctan2.hpp"
#include "exactgeo/predicates/boundary_term.hpp"

namespace exactgeo::internal {

/// How far the C library's atan2 is trusted, in radians, by the outward-rounded stage
/// (boundary_term.cpp): 2^11 ulps of pi (whose ulp is 2^-51), where every libm in use is
/// within a few. The filter's half angles take arctan2.hpp's instead, whose error bound
/// is derived there.
inline constexpr double kAtan2Error = 0x1p-40;

/// One edge's half angle theta(p; a, b, p + apex) in plain doubles, and a bound on its
/// error (radians, per unit of multiplicity): kind enclosed, or ray_on_edge (the ray meets
/// the edge exactly); nullopt when the filter cannot bound it (p near the edge's line, or
/// on a corner). `d` is `apex` scaled by normalized_apex and `ld` its length.
struct HalfAngle {
  BoundaryTermKind kind = BoundaryTermKind::enclosed;
  double theta = 0.0;
  double error = 0.0;
};
std::optional<Vector3> normalized_apex(const Vector3& apex);

/// normalized's rare case (the largest component beyond 2^+-1000, zero or not finite),
/// through the library; out of line, so that the common case inlines.
[[gnu::noinline]] std::optional<Vector3> normalized_by_ldexp(const Vector3& v, double largest);

/// The sign (+1, -1, or 0 where the ray meets the edge) of det[a - p, b - p, apex], exact:
/// the half angle's side near its branch cut; out of line (rare).
[[gnu::noinline]] double branch_cut_side(const Point3& p, const Point3& pa, const Point3& pb,
                                         const Vector3& apex);

/// The vector scaled by a power of two so that its largest component is in [1, 2);
/// nullopt when it is zero or not finite.
inline std::optional<Vector3> normalized(const Vector3& v) {
  // (Nested std::max: two instructions, where std::max of an initializer list loops.)
  const double largest = std::max(std::abs(v[0]), std::max(std::abs(v[1]), std::abs(v[2])));
  // The common case without library calls: largest = 1.f 2^(b - 1023) with b its biased
  // exponent; for 2^-1000 <= largest < 2^1000 the factor 2^(1023 - b) is a normal double
  // (biased exponent 2046 - b), and a product by it is what ldexp gives (exact, or rounded
  // once where it underflows).
  const auto biased = static_cast<int>(std::bit_cast<std::uint64_t>(largest) >> 52);
  if (biased > 23 && biased < 2023) [[likely]] {
    const double scale = std::bit_cast<double>(static_cast<std::uint64_t>(2046 - biased) << 52);
    return Vector3{v[0] * scale, v[1] * scale, v[2] * scale};
  }
  return normalized_by_ldexp(v, largest);
}

/// One edge's half angle (above); its error bound is derived in boundary_term_filter.cpp.
/// Inline: the boundary tree calls it for every chord and near edge, and the call itself
/// (registers saved, the optional returned through memory) costs more than its rare
/// branches (its cost measured: docs/inside.md, "Many boundary edges near most points").
[[gnu::always_inline]] inline std::optional<HalfAngle> half_angle(const Point3& p, const Vector3& d,
                                                                  double ld, const Point3& pa,
                                                                  const Point3& pb,
                                                                  const Vector3& apex) {
  constexpr double kU = 0x1p-53, kTiny = 0x1p-1000;
  const auto dot = [](const Vector3& x, const Vector3& y) {
    return x[0] * y[0] + x[1] * y[1] + x[2] * y[2];
  };
  const auto a = normalized({pa[0] - p[0], pa[1] - p[1], pa[2] - p[2]});
  const auto b = normalized({pb[0] - p[0], pb[1] - p[1], pb[2] - p[2]});
  if (!a || !b) return std::nullopt;  // the point on a corner, or an overflow
  const Vector3& A = *a;
  const Vector3& B = *b;
  const Vector3& D = d;
  const Vector3 bxd{B[1] * D[2] - B[2] * D[1], B[2] * D[0] - B[0] * D[2],
                    B[0] * D[1] - B[1] * D[0]};
  double num = dot(A, bxd);
  const double la = std::sqrt(dot(A, A)), lb = std::sqrt(dot(B, B));
  const double length = la * lb * ld;
  const double den = length + dot(A, B) * ld + dot(A, D) * lb + dot(B, D) * la;
  const double num_error = 16 * kU * length + kTiny;
  const double den_error = 96 * kU * length + kTiny;
  // r = |(N, D)| from below: the squares and their sum within u each, the root within
  // u/2 (2.5u in all, below the 4u taken off), where the sum is at least 2^-1000 (an
  // underflowing square then changes it by 2^-75 of itself at most); a smaller one (the
  // point within 2^-500 of an edge's line) is left to the intervals.
  const double radius2 = num * num + den * den;
  if (!(radius2 >= 0x1p-1000)) return std::nullopt;
  const double radius = std::sqrt(radius2) * (1 - 4 * kU);
  const double e = num_error + den_error;
  if (!(e <= radius / 4)) return std::nullopt;
  if (!(std::abs(num) > num_error) && !(den > den_error)) {
    if (!(den < -den_error)) return std::nullopt;
    // Near the branch cut: the exact side.
    const double side = branch_cut_side(p, pa, pb, apex);
    if (side == 0.0) return HalfAngle{BoundaryTermKind::ray_on_edge, 0.0, 0.0};
    num = std::copysign(std::abs(num), side);
  }
  return HalfAngle{BoundaryTermKind::enclosed, arctan2(num, den),
                   (4.0 / 3.0) * e / radius + kArctanError};
}

/// The filter's bounds on offset + sum m theta over the edges (theta = Omega / 2, the half
/// angles, in radians), `slack` (an upper bound, in the same unit, on how far that is
/// from what is to be enclosed) included: kind enclosed with lower <= exact <= upper, or
/// kind ray_on_edge (both bounds 0); nullopt when the bound cannot be made. `apex` is
/// -ray.
struct FilteredSum {
  BoundaryTermKind kind = BoundaryTermKind::enclosed;
  double lower = 0.0;
  double upper = 0.0;
};
std::optional<FilteredSum> filtered_sum(const Point3& p, const Vector3& apex,
                                        std::span<const Point3> vertices,
                                        std::span<const BoundaryEdge> edges, double offset,
                                        double slack);

/// The sum against the levels (in turns): kind enclosed with both settled, or the sum's
/// ray_on_edge; nullopt when a level lies within the bounds.
std::optional<BoundaryTerm> settled(const FilteredSum& sum, std::array<double, 2> levels);

/// The sum's bounds in turns (divided by 2 pi), rounded outward.
Enclosure turns_of(const FilteredSum& sum);

/// The term of boundary_term.hpp with both levels settled (kind enclosed), or kind
/// ray_on_edge; nullopt when the bound cannot settle them. `apex` is -ray.
std::optional<BoundaryTerm> filtered_boundary_term(const Point3& p, const Vector3& apex,
                                                   std::span<const Point3> vertices,
                                                   std::span<const BoundaryEdge> edges,
                                                   std::array<double, 2> levels);

}  // namespace exactgeo::internal
