#include <algorithm>
#include <cmath>
#include <vector>

#include "box_distance.hpp"
#include "double_interval.hpp"
#include "exactgeo/predicates/boundary_tree.hpp"

// How far w can move over a box that misses the surface: boundary_tree.hpp, "Variation
// over a box" (the gradient of a solid angle is the Biot-Savart integral over its
// boundary, at most (1/4 pi) |m| length / distance^2 per edge, in turns).

namespace exactgeo {
namespace {

/// Above 1 / (4 pi) = 0.0795774...: the gradient's factor in turns.
constexpr double kOneOverFourPiAbove = 0.0796;
/// A node is taken whole where its box is at least this many of its diagonals from the
/// cell (opening it would gain little); a cost, not a certificate.
constexpr double kSeparation = 2.0;

/// Covers the rounding of dipole_bound's operations (a root, two products, two
/// quotients, a sum: within 7u relatively, u = 2^-53) with room to spare.
constexpr double kDipoleRounding = 1 + 0x1p-49;

double up(double x) noexcept {
  return internal::DoubleInterval::up(x);
}

/// |b - a| from above: three differences, three squares, two sums and a root, each within
/// u relatively (a difference that underflows is exact; the squares' underflow is covered
/// by the absolute term), within 9u < 2^-49 of the exact length.
double edge_length_above(const Point3& a, const Point3& b) noexcept {
  double sum = 0.0;
  for (int i = 0; i < 3; ++i) {
    const double d = b[i] - a[i];
    sum += d * d;
  }
  return std::sqrt(sum) * (1 + 0x1p-49) + 0x1p-500;
}

}  // namespace

/// 2 F / d^3 + X / d^2, from above, for d^2 >= d2 > 0 (boundary_tree.hpp, "Variation
/// over a box": the node's triangle loops and ends as currents); +inf where F or X is.
double BoundaryTree::dipole_bound(const Node& node, double d2) noexcept {
  const double d = std::sqrt(d2);
  return (2 * node.fan / (d2 * d) + node.end_length / d2) * kDipoleRounding;
}

std::optional<double> BoundaryTree::variation(const Point3& lower, const Point3& upper,
                                              const Point3& centre, double most) const {
  if (nodes_.empty()) return 0.0;
  // rho: the reach of the box from the centre, rounded up.
  double reach2 = 0.0;
  for (int i = 0; i < 3; ++i) {
    const double r = up(std::max(up(centre[i] - lower[i]), up(upper[i] - centre[i])));
    reach2 = up(reach2 + up(r * r));
  }
  const double reach = up(std::sqrt(reach2));
  if (!std::isfinite(reach)) return std::nullopt;
  // The sum of L_N / d_N^2 over the cut, in plain doubles: each quotient within u of its
  // exact value (L_N and d_N^2 bounds already), the recursive sum of k positive terms
  // within (k - 1) u of their sum; (k + 2) u more covers both. Past `limit` the bound
  // exceeds `most`.
  const double limit = most / (kOneOverFourPiAbove * reach);
  double sum = 0.0;
  std::size_t terms = 0;
  std::vector<std::uint32_t> stack{0};
  while (!stack.empty()) {
    const Node& node = nodes_[stack.back()];
    stack.pop_back();
    const double d2 = internal::box_distance2_below(lower, upper, node.lower, node.upper);
    double diagonal2 = 0.0;
    for (int i = 0; i < 3; ++i) {
      const double extent = node.upper[i] - node.lower[i];
      diagonal2 += extent * extent;
    }
    const bool separated = d2 > 0.0 && diagonal2 * (kSeparation * kSeparation) <= d2;
    if (node.left == 0 && !separated) {
      // A near leaf: its edges one by one, each from its own box (the field of an edge
      // is at most |m| length / d^2 with d its distance from C, at least its box's).
      for (std::uint32_t i = node.first; i < node.first + node.count; ++i) {
        const BoundaryEdge& e = edges_[i];
        const Point3& a = vertices_[e.from];
        const Point3& b = vertices_[e.to];
        const Point3 low{std::min(a[0], b[0]), std::min(a[1], b[1]), std::min(a[2], b[2])};
        const Point3 high{std::max(a[0], b[0]), std::max(a[1], b[1]), std::max(a[2], b[2])};
        const double e2 = internal::box_distance2_below(lower, upper, low, high);
        // The box meets the edge's box; or the square overflowed (L / inf would be 0).
        if (!(e2 > 0.0) || !std::isfinite(e2)) return std::nullopt;
        sum += edge_length_above(a, b) * std::abs(static_cast<double>(e.multiplicity)) / e2;
        ++terms;
      }
      if (!(sum <= limit)) return std::nullopt;
      continue;
    }
    if (separated) {
      // The square overflowed (L / inf would be 0).
      if (!std::isfinite(d2)) return std::nullopt;
      sum += std::min(node.length / d2, dipole_bound(node, d2));
      ++terms;
      if (!(sum <= limit)) return std::nullopt;
      continue;
    }
    // The nearer child first: the sum passes the limit soonest there.
    const Node& left = nodes_[node.left];
    const Node& right = nodes_[node.right];
    const bool left_nearer = internal::box_distance2_below(lower, upper, left.lower, left.upper) <=
                             internal::box_distance2_below(lower, upper, right.lower, right.upper);
    stack.push_back(left_nearer ? node.right : node.left);
    stack.push_back(left_nearer ? node.left : node.right);
  }
  const double above = up(sum * (1 + static_cast<double>(terms + 2) * 0x1p-52));
  const double bound = up(up(kOneOverFourPiAbove * above) * reach);
  if (!(bound <= most)) return std::nullopt;
  return bound;
}

}  // namespace exactgeo
