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

}  // namespace exactgeo::internal
