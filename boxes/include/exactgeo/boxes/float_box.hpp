#pragma once

// Closed axis-aligned boxes in single precision, rounded outward from doubles, for the box
// trees of the mesh broad phase (ccd) and of self-intersection (mesh), and for Embree's
// candidate search (inside).
//
// A float box holds the double box it was made from: converting rounds each lower bound
// down and each upper bound up (one float step when round-to-nearest went the wrong way),
// so two double boxes that share a point give float boxes that overlap. Min and max of
// doubles are exact, so a box of points (a primitive's corners) holds every convex
// combination of them.
//
// Before that conversion every coordinate is scaled by one power of two (Scale), chosen
// so that the largest magnitude lands in [1/2, 1): floats cover about 2^+-126 and doubles
// 2^+-1022, so without it coordinates near 1e300 or 2^-1000 get infinite or zero-width
// boxes that prune nothing. Scaling by a power of two is exact wherever the result is a
// normal double, and where it underflows it still rounds monotonically; a monotone map
// keeps every inequality between bounds that the overlap test compares, so it loses no
// overlap. Points and their copy scaled by 2^k get the same float boxes.

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

#include "exactgeo/predicates/kernel/power_of_two.hpp"
#include "exactgeo/predicates/point.hpp"

namespace exactgeo::boxes {

/// An axis-aligned box in single precision, closed.
struct FloatBox {
  std::array<float, 3> lo;
  std::array<float, 3> hi;
};

/// Closed boxes: touching counts as overlapping.
inline bool overlap(const FloatBox& a, const FloatBox& b) noexcept {
  for (int k = 0; k < 3; ++k) {
    if (a.hi[k] < b.lo[k] || b.hi[k] < a.lo[k]) return false;
  }
  return true;
}

inline FloatBox united(FloatBox a, const FloatBox& b) noexcept {
  for (int k = 0; k < 3; ++k) {
    a.lo[k] = std::min(a.lo[k], b.lo[k]);
    a.hi[k] = std::max(a.hi[k], b.hi[k]);
  }
  return a;
}

/// Width plus height plus depth (in double: no overflow for any finite float box).
inline double half_perimeter(const FloatBox& b) noexcept {
  double sum = 0.0;
  for (int k = 0; k < 3; ++k)
    sum += static_cast<double>(b.hi[k]) - static_cast<double>(b.lo[k]);
  return sum;
}

/// The float next below f, for a finite f above the lowest float (std::nextafter toward
/// -inf, without the library call: floats of one sign are ordered like their bit patterns).
inline float next_float_down(float f) noexcept {
  const auto bits = std::bit_cast<std::uint32_t>(f);
  if (f > 0) return std::bit_cast<float>(bits - 1);
  if (f == 0) return -std::numeric_limits<float>::denorm_min();
  return std::bit_cast<float>(bits + 1);
}

/// The largest float <= x (x finite).
inline float float_below(double x) noexcept {
  constexpr double kMax = std::numeric_limits<float>::max();
  if (x > kMax) return std::numeric_limits<float>::max();
  if (x < -kMax) return -std::numeric_limits<float>::infinity();
  // Here -kMax <= x, so when f rounded above x, f > -kMax and the float below it is finite.
  const float f = static_cast<float>(x);
  return static_cast<double>(f) > x ? next_float_down(f) : f;
}

/// One float below float_below(x): a lower bound for every value within half a double's
/// ulp of x (x finite or infinite).
inline float float_below_one_more(double x) noexcept {
  if (!(x > -std::numeric_limits<double>::max())) return -std::numeric_limits<float>::infinity();
  if (x > std::numeric_limits<double>::max()) return std::numeric_limits<float>::max();
  const float f = float_below(x);
  return f == -std::numeric_limits<float>::infinity() ? f : next_float_down(f);
}

/// The smallest float >= x (x finite).
inline float float_above(double x) noexcept {
  return -float_below(-x);
}

/// x -> x 2^-e for one set of coordinates: every |x| below 2^e, the largest in
/// [2^(e-1), 2^e).
class Scale {
 public:
  Scale() = default;  ///< the identity (e = 0)
  /// The scale for coordinates whose largest magnitude is `max_abs` (finite, >= 0).
  explicit Scale(double max_abs) noexcept {
    if (max_abs > 0) std::frexp(max_abs, &exponent_);
    scale_ = kernel::PowerOfTwo(-exponent_);
  }
  double operator()(double x) const noexcept { return scale_(x); }
  int exponent() const noexcept { return exponent_; }

 private:
  int exponent_ = 0;
  kernel::PowerOfTwo scale_{0};
};

/// The float box of one point (finite), in `scale`.
inline FloatBox point_box(const Point3& p, const Scale& scale) noexcept {
  FloatBox box{};
  for (int k = 0; k < 3; ++k) {
    const double x = scale(p[k]);
    box.lo[k] = float_below(x);
    box.hi[k] = float_above(x);
  }
  return box;
}

}  // namespace exactgeo::boxes
