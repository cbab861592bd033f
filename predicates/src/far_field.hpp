#pragma once

// What the boundary tree (boundary_tree.hpp, its cone's chords closed into fans) and the
// cap's tree (cap_tree.hpp, triangles) share about a far node: the area bound F, and the
// second-order expansion made certain, from the node's vector area M and moments Q
// accumulated in outward-rounded intervals (boundary_tree.hpp, "Second order", has the
// argument; each tree accumulates its own M and Q, then hands them here).

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "double_interval.hpp"
#include "exactgeo/predicates/point.hpp"

namespace exactgeo::internal {

/// A bound on the expansion's rounding relative to |M| / |c - p|^2 + 4 |Q| / |c - p|^3
/// (|Q| the sum of its entries' magnitudes, which bounds the trace and |v^T Q v| / |v|^2):
/// c - p within u per component, which moves (c - p) / |c - p|^3 by 2u relatively; the
/// dot within 3u of |M| |c - p|; |c - p|^3 within 6u; the quotient u: 12u for the first
/// term; the trace, v^T Q v (six products and five sums, v within u) and the difference,
/// then the two quotients, within 20u of the second's bound: far below this.
inline constexpr double kExpansionRounding = 0x1p-40;

inline double up(double x) noexcept {
  return DoubleInterval::up(x);
}

/// area(a, b, c) (half the cross product's length), its upper end in outward-rounded
/// intervals; +inf when that overflows.
inline double area_above(const Point3& a, const Point3& b, const Point3& c) noexcept {
  std::array<DoubleInterval, 3> u, v;
  for (int i = 0; i < 3; ++i) {
    u[i] = DoubleInterval::difference(a[i], c[i]);
    v[i] = DoubleInterval::difference(b[i], c[i]);
  }
  const DoubleInterval x = u[1] * v[2] - u[2] * v[1];
  const DoubleInterval y = u[2] * v[0] - u[0] * v[2];
  const DoubleInterval z = u[0] * v[1] - u[1] * v[0];
  const double length = sqrt(x * x + y * y + z * z).hi;
  if (!std::isfinite(length)) return std::numeric_limits<double>::infinity();
  return up(0.5 * length);
}

/// The enclosures of a node's M and Q, as a tree accumulates them.
struct Moments {
  std::array<DoubleInterval, 3> m{};
  std::array<std::array<DoubleInterval, 3>, 3> q{};
};

/// A node's expansion from M and Q's enclosures (Q's symmetric part kept: Dg(c) is
/// symmetric): the midpoints, bounds on their distance from the exact values and on their
/// sizes, the box's reach from the centre (rounded up), whether all of it is finite, and
/// the second-order bound's coefficients, each an upper bound by outward rounding: 4
/// rho^2 (where the expansion is first tried: a cost, not a bound), (3/2) rho^2 F over
/// d^4, (1/2) (moment_error + kExpansionRounding moment_size) over d^2 and
/// ((3/2) quad_error + 2 kExpansionRounding quad_size) over d^3. An overflow makes one
/// infinite, and the bound is then never chosen. `Node` has the fields of both trees'
/// nodes: lower, upper, centre and fan set, the others written here.
template <class Node>
void set_far_field(Node& node, const Moments& moments) noexcept {
  const auto& [m, q] = moments;
  const auto midpoint = [](const DoubleInterval& x, double& error) {
    const double mid = std::clamp(0.5 * x.lo + 0.5 * x.hi, x.lo, x.hi);
    error = up(std::max(x.hi - mid, mid - x.lo));
    return mid;
  };
  const Point3& c = node.centre;
  double error = 0.0, size2 = 0.0, reach2 = 0.0;
  for (int i = 0; i < 3; ++i) {
    double e = 0.0;
    node.moment[i] = midpoint(m[i], e);
    error = up(error + e);
    size2 = up(size2 + up(node.moment[i] * node.moment[i]));
    const double r = up(std::max(c[i] - node.lower[i], node.upper[i] - c[i]));
    reach2 = up(reach2 + up(r * r));
  }
  node.moment_error = error;
  node.moment_size = up(std::sqrt(size2));
  node.reach = up(std::sqrt(reach2));
  // The symmetric part, (Q + Q^T) / 2: an off-diagonal entry stands for two of the nine.
  constexpr std::array<std::array<int, 2>, 6> kEntries{
      {{0, 0}, {1, 1}, {2, 2}, {0, 1}, {0, 2}, {1, 2}}};
  double quad_error = 0.0, quad_size = 0.0;
  for (std::size_t k = 0; k < kEntries.size(); ++k) {
    const auto [i, j] = kEntries[k];
    double e = 0.0;
    node.quad[k] = midpoint((q[i][j] + q[j][i]) * DoubleInterval::exact(0.5), e);
    const double copies = i == j ? 1.0 : 2.0;
    quad_error = up(quad_error + copies * e);
    quad_size = up(quad_size + copies * std::abs(node.quad[k]));
  }
  node.quad_error = quad_error;
  node.quad_size = quad_size;
  node.expansion = std::isfinite(error) && std::isfinite(node.moment_size) &&
                   std::isfinite(node.reach) && std::isfinite(quad_error) &&
                   std::isfinite(quad_size);
  node.reach4 = 4 * node.reach * node.reach;
  node.second_fan = up(up(up(1.5 * node.reach) * node.reach) * node.fan);
  node.second_moment = up(0.5 * up(node.moment_error + up(kExpansionRounding * node.moment_size)));
  node.second_quad = up(up(1.5 * node.quad_error) + up(2 * kExpansionRounding * node.quad_size));
}

/// A far node's bound on what its expansion (`expanded`) or its area bound leaves out, in
/// radians of half angle, at squared distance d2 (from below) from the point: F / (2 d^2)
/// moved up past its two roundings (and an underflow; d2 = 0 gives inf or NaN, neither
/// accepted by a caller's `bound <= limit`), or the second-order bound where it is
/// smaller. Below d = 2 rho the zero-order bound is the smaller, and not worth the square
/// root; with 2^-400 < d^2 < 2^400 neither d^4 nor |c - p|^3 overflows or underflows. d
/// from below (the root within u/2); the coefficients are upper bounds (set_far_field),
/// and the three quotients (d^4 and d^3 within u, the quotients within u) and their sum
/// (2u) within 4u, all positive.
struct FarBound {
  double bound = 0.0;
  bool expanded = false;
};
template <class Node>
[[gnu::always_inline]] inline FarBound far_bound(const Node& node, double d2) noexcept {
  constexpr double kU = 0x1p-53, kTiny = 0x1p-1000;
  FarBound far{0.5 * (node.fan / d2) * (1 + 4 * kU) + kTiny, false};
  if (node.expansion && d2 > node.reach4 && d2 > 0x1p-400 && d2 < 0x1p400) {
    const double d = std::sqrt(d2) * (1 - 0x1p-50);
    const double d3 = d2 * d;
    const double second =
        (node.second_fan / (d2 * d2) + node.second_moment / d2 + node.second_quad / d3) *
            (1 + 0x1p-48) +
        kTiny;
    if (second < far.bound) far = {second, true};
  }
  return far;
}

/// The expansion's value at p, in radians of half angle: (1/2) (M.g(c) + Dg(c) : Q) with
/// v = c - p, g(c) = v / |v|^3 and Dg(c) = (I - 3 v v^T / |v|^2) / |v|^3 (trace-free, so
/// Q's symmetric part is all it sees). Its rounding is in the bound (kExpansionRounding).
/// Precondition: far_bound chose the expansion (d <= |c - p| <= d + 2 rho < 2d: c lies in
/// the box).
template <class Node>
[[gnu::always_inline]] inline double expansion_value(const Node& node, const Point3& p) noexcept {
  const Vector3 v{node.centre[0] - p[0], node.centre[1] - p[1], node.centre[2] - p[2]};
  const double r2 = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
  const std::array<double, 6>& s = node.quad;
  const double trace = s[0] + s[1] + s[2];
  const double vqv = s[0] * v[0] * v[0] + s[1] * v[1] * v[1] + s[2] * v[2] * v[2] +
                     2 * (s[3] * v[0] * v[1] + s[4] * v[0] * v[2] + s[5] * v[1] * v[2]);
  const double mv = node.moment[0] * v[0] + node.moment[1] * v[1] + node.moment[2] * v[2];
  return 0.5 * (mv + (trace * r2 - 3 * vqv) / r2) / (r2 * std::sqrt(r2));
}

}  // namespace exactgeo::internal
