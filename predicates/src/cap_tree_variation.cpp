#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include "box_distance.hpp"
#include "exactgeo/predicates/cap_tree.hpp"
#include "variation_bound.hpp"

// How far w can move over a box that misses the surface, bounded through the cap's
// triangles: cap_tree.hpp, "Variation over a box".

namespace exactgeo {
namespace {

/// The box of two or three points.
std::pair<Point3, Point3> box_of(std::initializer_list<const Point3*> points) noexcept {
  Point3 lower = **points.begin(), upper = lower;
  for (const Point3* p : points) {
    for (int i = 0; i < 3; ++i) {
      lower[i] = std::min(lower[i], (*p)[i]);
      upper[i] = std::max(upper[i], (*p)[i]);
    }
  }
  return {lower, upper};
}

/// A near node is taken whole where its dipole bound is at most this share of the sum's
/// limit: opening it could lower the sum by no more, and the walk below it costs as much
/// as the rest (measured on Spot with a hundred faces cut and elephant-with-holes: 0.001,
/// 0.01 and 0.05 took 9%, 15% and 13% fewer instructions in all than 0, 0.05 labelling
/// half the cells); a cost, not a certificate.
constexpr double kSmallShare = 0.01;

/// 2 F / d^3 from above, for d^2 >= d2 > 0 and F from above.
double dipole_bound(double fan, double d2) noexcept {
  return 2 * fan / (d2 * std::sqrt(d2)) * internal::kDipoleRounding;
}

}  // namespace

/// A near triangle's part of the gradient's sum, from above: the smaller of its boundary
/// loop's Biot-Savart bound, sum |m| length / d^2 over its edges with d from each edge's
/// box, and its dipole bound 2 |m| area / d^3 from its own box; nullopt where the box
/// meets both its own box and an edge's (or a square overflows).
std::optional<double> CapTree::near_triangle_bound(const Point3& lower, const Point3& upper,
                                                   const Triangle& t, const Sizes& sizes) noexcept {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  const double m = std::abs(t.multiplicity);
  double edges = 0.0;
  const std::array<const Point3*, 3> corners{&t.a, &t.b, &t.c};
  for (int k = 0; k < 3 && edges < kInf; ++k) {
    const auto [low, high] = box_of({corners[k], corners[(k + 1) % 3]});
    const double e2 = internal::box_distance2_below(lower, upper, low, high);
    edges = e2 > 0.0 && std::isfinite(e2) ? edges + sizes.lengths[k] * m / e2 : kInf;
  }
  const auto [low, high] = box_of({&t.a, &t.b, &t.c});
  const double d2 = internal::box_distance2_below(lower, upper, low, high);
  const double whole = d2 > 0.0 && std::isfinite(d2) ? dipole_bound(sizes.area * m, d2) : kInf;
  const double bound = std::min(edges, whole);
  if (!std::isfinite(bound)) return std::nullopt;
  return bound;
}

std::optional<double> CapTree::variation(const Point3& lower, const Point3& upper,
                                         const Point3& centre, double most) const {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  if (nodes_.empty()) return 0.0;
  const double reach = internal::reach_above(lower, upper, centre);
  if (!std::isfinite(reach)) return std::nullopt;
  // The gradient's bounds summed over a cut of the tree in plain doubles, each within u
  // of its exact value (variation_from_sum); past `limit` the bound exceeds `most`.
  const double limit = most / (internal::kOneOverFourPiAbove * reach);
  double sum = 0.0;
  std::size_t terms = 0;
  std::vector<std::uint32_t> stack{0};
  while (!stack.empty()) {
    const Node& node = nodes_[stack.back()];
    stack.pop_back();
    if (node.count == 0) continue;  // no triangle, no field
    const double d2 = internal::box_distance2_below(lower, upper, node.lower, node.upper);
    // Taken whole where it is far (kVariationSeparation) or its bound small beside the
    // limit (kSmallShare); any cut gives a bound.
    const double whole = d2 > 0.0 && std::isfinite(d2) ? dipole_bound(node.fan, d2) : kInf;
    if (whole <= kSmallShare * limit ||
        (whole < kInf && internal::separated_for_variation(node.lower, node.upper, d2))) {
      sum += whole;
      ++terms;
      if (!(sum <= limit)) return std::nullopt;
      continue;
    }
    // A near node: its own triangles one by one, then its children, the nearer first (the
    // sum passes the limit soonest there).
    for (std::uint32_t i = node.first; i < node.first + node.own; ++i) {
      const std::optional<double> bound =
          near_triangle_bound(lower, upper, triangles_[i], sizes_[i]);
      if (!bound) return std::nullopt;
      sum += *bound;
      // Three edges' quotients and products, each within u: counted as six terms of the
      // sum (variation_from_sum), or the dipole bound, rounded up on its own.
      terms += 6;
    }
    if (!(sum <= limit)) return std::nullopt;
    if (node.left == 0) continue;
    const Node& left = nodes_[node.left];
    const Node& right = nodes_[node.right];
    const bool left_nearer = internal::box_distance2_below(lower, upper, left.lower, left.upper) <=
                             internal::box_distance2_below(lower, upper, right.lower, right.upper);
    stack.push_back(left_nearer ? node.right : node.left);
    stack.push_back(left_nearer ? node.left : node.right);
  }
  const double bound = internal::variation_from_sum(sum, terms, reach);
  if (!(bound <= most)) return std::nullopt;
  return bound;
}

}  // namespace exactgeo
