#pragma once

// The pieces of the cap tree's bound on w's variation over a box (cap_tree.hpp,
// "Variation over a box") with their rounding arguments: the gradient's factor in turns,
// the rounding of a dipole bound, when a node is taken whole, the box's reach from its
// centre, a segment's length from above (also the tree's build's, for its triangles'
// edges), and the bound from a sum of positive terms.

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "double_interval.hpp"
#include "exactgeo/predicates/point.hpp"

namespace exactgeo::internal {

/// Above 1 / (4 pi) = 0.0795774...: the gradient's factor in turns.
inline constexpr double kOneOverFourPiAbove = 0.0796;

/// Covers the rounding of a dipole bound 2 |m| F / d^3 from F and d^2 (a root, two
/// products, a quotient: within 4u relatively, u = 2^-53) with room to spare.
inline constexpr double kDipoleRounding = 1 + 0x1p-49;

/// A node is taken whole where its box is at least this many of its diagonals from the
/// box asked about (opening it would gain little); a cost, not a certificate.
inline constexpr double kVariationSeparation = 2.0;

/// Whether a node with box [lower, upper] at squared distance d2 (from below) from the
/// box asked about is taken whole (kVariationSeparation). Costs only.
inline bool separated_for_variation(const Point3& lower, const Point3& upper, double d2) noexcept {
  double diagonal2 = 0.0;
  for (int i = 0; i < 3; ++i) {
    const double extent = upper[i] - lower[i];
    diagonal2 += extent * extent;
  }
  return d2 > 0.0 && diagonal2 * (kVariationSeparation * kVariationSeparation) <= d2;
}

/// rho, the reach of the box [lower, upper] from `centre` (a point of it), rounded up;
/// +inf where a square overflows.
inline double reach_above(const Point3& lower, const Point3& upper, const Point3& centre) noexcept {
  const auto up = [](double x) { return DoubleInterval::up(x); };
  double reach2 = 0.0;
  for (int i = 0; i < 3; ++i) {
    const double r = up(std::max(up(centre[i] - lower[i]), up(upper[i] - centre[i])));
    reach2 = up(reach2 + up(r * r));
  }
  return up(std::sqrt(reach2));
}

/// |b - a| from above: three differences, three squares, two sums and a root, each within
/// u relatively (a difference that underflows is exact; the squares' underflow is covered
/// by the absolute term), within 9u < 2^-49 of the exact length.
inline double segment_length_above(const Point3& a, const Point3& b) noexcept {
  double sum = 0.0;
  for (int i = 0; i < 3; ++i) {
    const double d = b[i] - a[i];
    sum += d * d;
  }
  return std::sqrt(sum) * (1 + 0x1p-49) + 0x1p-500;
}

/// The variation's bound rho (1 / 4 pi) sum from above, for `sum` the plain-double
/// recursive sum of `terms` positive terms, each within u of its exact value: the sum is
/// within (terms - 1) u of theirs, and (terms + 2) u covers both.
inline double variation_from_sum(double sum, std::size_t terms, double reach) noexcept {
  const auto up = [](double x) { return DoubleInterval::up(x); };
  const double above = up(sum * (1 + static_cast<double>(terms + 2) * 0x1p-52));
  return up(up(kOneOverFourPiAbove * above) * reach);
}

}  // namespace exactgeo::internal
