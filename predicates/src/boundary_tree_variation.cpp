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

double up(double x) noexcept {
  return internal::DoubleInterval::up(x);
}

}  // namespace

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
    if (node.left == 0 || separated) {
      // The box meets a leaf's box; or the square overflowed (L / inf would be 0).
      if (!(d2 > 0.0) || !std::isfinite(d2)) return std::nullopt;
      sum += node.length / d2;
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
