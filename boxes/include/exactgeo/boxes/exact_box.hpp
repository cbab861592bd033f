#pragma once

// A closed box of doubles, exactly as the points it holds: the exact counterpart of
// FloatBox (float_box.hpp), for tests that decide (a swept region's box against an
// element's, a mesh's bounding box) rather than propose candidates.

#include <algorithm>
#include <initializer_list>
#include <span>

#include "exactgeo/predicates/point.hpp"

namespace exactgeo::boxes {

struct ExactBox {
  Point3 lower;
  Point3 upper;

  /// The box of one point.
  static ExactBox of(const Point3& p) noexcept { return {p, p}; }

  /// The box of points (at least one).
  static ExactBox of(std::span<const Point3> points) noexcept {
    ExactBox box = of(points.front());
    for (const Point3& p : points)
      box.add(p);
    return box;
  }
  static ExactBox of(std::initializer_list<Point3> points) noexcept {
    return of(std::span(points.begin(), points.size()));
  }

  /// Grows the box to hold p.
  void add(const Point3& p) noexcept {
    for (int k = 0; k < 3; ++k) {
      lower[k] = std::min(lower[k], p[k]);
      upper[k] = std::max(upper[k], p[k]);
    }
  }

  /// Grows the box to hold another.
  void add(const ExactBox& other) noexcept {
    for (int k = 0; k < 3; ++k) {
      lower[k] = std::min(lower[k], other.lower[k]);
      upper[k] = std::max(upper[k], other.upper[k]);
    }
  }

  /// p in the closed box.
  bool holds(const Point3& p) const noexcept {
    for (int k = 0; k < 3; ++k) {
      if (p[k] < lower[k] || p[k] > upper[k]) return false;
    }
    return true;
  }

  /// The closed boxes share a point (coordinates compare exactly).
  bool meets(const ExactBox& other) const noexcept {
    for (int k = 0; k < 3; ++k) {
      if (upper[k] < other.lower[k] || other.upper[k] < lower[k]) return false;
    }
    return true;
  }
};

}  // namespace exactgeo::boxes
