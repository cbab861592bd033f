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
// - A query origin q in the frame's box is rounded to the nearest float.
//
// c only needs to be the same for boxes and origins, not exact: the map is a translation
// and a scaling, which keep every ray-box incidence, followed by one rounding of
// relative size 2^-53. The rounded c lies between the box's bounds on each axis, so the
// box maps into an interval of length (upper - lower) 2^-e < 2 per axis: every mapped
// point of the box has |x| < 2, and two of them differ by less than 2.
//
// Why kPad suffices (u = 2^-24, the float unit roundoff; Embree 3.13.5, whose traversal of
// user geometry is the non-robust one whatever the scene flags say):
// - The origin's rounding moves it by at most u per coordinate (|q| < 2).
// - The slab test computes, per axis, t = (b - o) / d for each box bound b with rdir, a
//   reciprocal of d: rcp_ps (relative error <= 1.5 2^-12) refined by one Newton step,
//   r0 + r0 (1 - d r0), whose error is the square of rcp_ps's, (1.5 2^-12)^2 = 2.25u,
//   plus the step's own roundings, 2u with SSE arithmetic (u with FMA, and rcp14 starts
//   from 2^-14): at most 4.26u. Then t = fl(fl(b - o) rdir) (SSE) is the exact
//   (b' - o) / d of a bound b' within |b - o| (4.26u + 2u) of b, and with FMA,
//   t = fl(b rdir - fl(o rdir)), within |b - o| (3.26u + u) + |o| u. Points of the box
//   differ by less than 2 and the padding adds 2^-19, |o| < 2: every bound the traversal
//   uses is off by at most 12.6u from the float box's bound.
// - The ray directions are floats with no zero component (kFloatExactRayDirections), so
//   no bound is replaced by a reciprocal's infinity, and the node boxes above a leaf are
//   unions of its boxes (min and max, exact).
// So if the exact ray q + s d meets a face's box at p, the float ray q' + s d (same s)
// passes within u of it, and the traversal sees the box's bounds moved inward by at most
// 12.6u: a padding of 13.6u suffices, and kPad = 16u leaves about 17% to spare. The ray's
// parameter range starts at 0 (tnear) and is unbounded, so p's own s is in it.
// tests/inside/candidates_test.cpp checks the candidates against every face the exact
// predicates say a ray touches, with rays through vertices, edge points and from points on
// faces, at magnitudes 2^-1000 to 2^1000.

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

  /// The nearest float to the mapped coordinate (for a ray origin in the box: the argument
  /// above holds for no other point).
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
