#pragma once

// A lower bound on the squared distance between two axis-aligned boxes, which the trees'
// far-field tests (a point, a box of one point; boundary_tree.cpp, cap_tree.cpp) and the
// cap's variation bound over a box (cap_tree_variation.cpp) take.

#include <algorithm>

#include "exactgeo/predicates/point.hpp"

namespace exactgeo::internal {

/// Below it, an absolute loss of a few 2^-1075 (a squared gap that underflows) is covered.
inline constexpr double kBoxDistanceTiny = 0x1p-1000;

/// A lower bound on the squared distance between boxes a and b (0 when they may meet):
/// each gap and square within u relatively, the sum of three within 2u more, all within
/// 5u < 2^-50; underflows lose at most 3 2^-1075, far below kBoxDistanceTiny.
inline double box_distance2_below(const Point3& lower_a, const Point3& upper_a,
                                  const Point3& lower_b, const Point3& upper_b) noexcept {
  double sum = 0.0;
  for (int i = 0; i < 3; ++i) {
    // The positive one of the two differences, if any (a rounded difference has the
    // exact one's sign): the same value as choosing by comparisons, without branches (two
    // maxsd; std::max of an initializer list loops).
    const double gap = std::max(std::max(lower_b[i] - upper_a[i], lower_a[i] - upper_b[i]), 0.0);
    sum += gap * gap;
  }
  return std::max(0.0, sum * (1 - 0x1p-50) - kBoxDistanceTiny);
}

}  // namespace exactgeo::internal
