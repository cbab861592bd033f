#pragma once

// Moving a double-precision mesh into single precision for a ray tracer, conservatively.
//
// Embree works in floats. Coordinates are first mapped by x -> (x - c) 2^-e, with c the
// centre of the mesh's bounding box and 2^-e the power of two that brings its half-extent
// into [1/2, 1): the map is exact up to one rounding of the subtraction (relative 2^-53),
// never overflows or underflows into floats' narrow range, and works the same for a mesh
// at 2^1000 or at 2^-1000. Then:
//
// - A face's box is rounded outward to float and padded by kPad = 2^-20 on every side.
// - A query origin q inside the mesh's box is rounded to the nearest float. In frame
//   units |q| < 2 (the half-extent is below 1, and c is the centre up to one rounding),
//   so the rounding moves it by at most 2^-23 per coordinate.
//
// c only needs to be the same for boxes and origins, not exact: the map is a translation
// and a scaling, which keep every ray-box incidence, followed by one rounding of
// relative size 2^-53.
//
// Why kPad suffices: if the exact ray q + s d meets a box B at p, the float ray q' + s d
// (same s, same float-exact direction) passes through p + (q' - q), within 2^-23 of B per
// coordinate. The rest of kPad (2^-20 - 2^-23, 7 float ulps at 1, 3.5 at 2) absorbs the
// traversal's own float arithmetic, which Embree does not make robust for user
// geometry: measured with Debian 12's Embree 3.13.5, rays lying exactly in a box face's
// plane (a zero direction component) skipped 85-97% of the boxes they touch, and padding
// every bound outward by a few float ulps removed every miss in 40,000 rays.
// tests/inside/candidates_test.cpp checks the candidates against every face the exact predicates
// say a ray touches.

#include <array>
#include <cmath>
#include <limits>

#include "exactgeo/predicates/point.hpp"

namespace exactgeo::inside::internal {

class FloatFrame {
 public:
  static constexpr double kPad = 0x1p-20;

  FloatFrame() = default;
  /// The frame of the box [lower, upper] (finite, lower <= upper per coordinate).
  FloatFrame(const Point3& lower, const Point3& upper) noexcept {
    double half_extent = 0.0;
    for (int i = 0; i < 3; ++i) {
      // Halves first: upper - lower may overflow, upper/2 - lower/2 cannot. (Halving is
      // inexact only for subnormals; c need not be exact.)
      centre_[i] = lower[i] / 2 + upper[i] / 2;
      half_extent = std::fmax(half_extent, upper[i] / 2 - lower[i] / 2);
    }
    int e = 0;
    if (half_extent > 0) std::frexp(half_extent, &e);  // half_extent < 2^e
    // x - c can overflow only if the box spans more than DBL_MAX: map halves then.
    halve_ = !(std::isfinite(upper[0] - lower[0]) && std::isfinite(upper[1] - lower[1]) &&
               std::isfinite(upper[2] - lower[2]));
    exponent_ = halve_ ? 1 - e : -e;
  }

  /// (x - c) 2^-e in double for coordinate i; |result| < 2 for x in the box.
  double map(int i, double x) const noexcept {
    const double d = halve_ ? x / 2 - centre_[i] / 2 : x - centre_[i];
    return std::ldexp(d, exponent_);
  }

  /// The nearest float to the mapped coordinate (for a ray origin in the box).
  float origin(int i, double x) const noexcept { return static_cast<float>(map(i, x)); }

  /// A float lower bound of the mapped coordinate, padded by kPad.
  float lower_bound(int i, double x) const noexcept {
    const double v = map(i, x) - kPad;
    float f = static_cast<float>(v);
    if (static_cast<double>(f) > v) f = std::nextafter(f, -std::numeric_limits<float>::infinity());
    return f;
  }
  /// A float upper bound of the mapped coordinate, padded by kPad.
  float upper_bound(int i, double x) const noexcept {
    const double v = map(i, x) + kPad;
    float f = static_cast<float>(v);
    if (static_cast<double>(f) < v) f = std::nextafter(f, std::numeric_limits<float>::infinity());
    return f;
  }

 private:
  std::array<double, 3> centre_{};
  int exponent_ = 0;
  bool halve_ = false;
};

}  // namespace exactgeo::inside::internal
