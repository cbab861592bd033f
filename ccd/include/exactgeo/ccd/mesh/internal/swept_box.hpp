#pragma once

// Swept boxes in single precision, rounded outward.
//
// Every point of a primitive at time t in [0, 1] is a convex combination of its corners at
// t, and each corner at t is a convex combination of its positions at t0 and t1. So the
// primitive stays inside the box of its corners' t0 and t1 positions during the whole
// step, in exact arithmetic: min and max of doubles are exact. Converting to float rounds
// each lower bound down and each upper bound up (one nextafter when round-to-nearest went
// the wrong way), so the float box contains the double box and two boxes that could share
// a point overlap.
//
// Before that conversion every coordinate of the step is scaled by one power of two
// (StepScale), chosen so that the largest magnitude lands in [1/2, 1): floats cover
// about 2^±126 and doubles 2^±1022, so without it a mesh at 1e300 or at 2^-1000 gets
// infinite or zero-width-rounded boxes that prune nothing. Scaling by a power of two is
// exact wherever the result is a normal double, and where it underflows it still rounds
// monotonically; a monotone map keeps every inequality between bounds that the overlap
// test compares, so it loses no overlap. A mesh and its copy scaled by 2^k get the same
// float boxes, so a step at 2^±1000 prunes exactly like one at 1.

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>

#include "exactgeo/ccd/internal/unit_magnitude.hpp"

namespace exactgeo::ccd::internal {

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

/// x -> x 2^-e for one step: every |x| of the step below 2^e, the largest in [2^(e-1), 2^e).
class StepScale {
 public:
  StepScale() = default;  ///< the identity (e = 0)
  /// The scale for coordinates whose largest magnitude is `max_abs` (finite, >= 0).
  explicit StepScale(double max_abs) noexcept {
    if (max_abs > 0) std::frexp(max_abs, &exponent_);
    scale_ = PowerOfTwo(-exponent_);
  }
  double operator()(double x) const noexcept { return scale_(x); }
  int exponent() const noexcept { return exponent_; }

 private:
  int exponent_ = 0;
  PowerOfTwo scale_{0};
};

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

/// The swept box of vertex v in the step's scale, grown by `margin` (in that scale, >= 0)
/// on every side; positions are 3 doubles per vertex at t0 and t1. A primitive's swept box
/// is the union of its corners' boxes: rounding outward after the scaling is monotone, so
/// the union of the rounded corner boxes is exactly the rounded box of all corners. With a
/// margin, the bound +- margin is a rounded double first, off by at most half a double's
/// ulp of it (or 2^-1075 below the normal range); the float next to it outward is farther
/// than that from the float it rounds to (a float's ulp is 2^29 times a double's, and at
/// least 2^-149), so one more float step outward keeps the box conservative.
inline FloatBox vertex_swept_box(const double* t0, const double* t1, std::size_t v,
                                 const StepScale& scale, double margin = 0.0) noexcept {
  FloatBox box{};
  for (std::size_t k = 0; k < 3; ++k) {
    const double a = t0[3 * v + k], b = t1[3 * v + k];
    if (margin == 0.0) {
      box.lo[k] = float_below(scale(std::min(a, b)));
      box.hi[k] = float_above(scale(std::max(a, b)));
    } else {
      box.lo[k] = float_below_one_more(scale(std::min(a, b)) - margin);
      box.hi[k] = -float_below_one_more(-(scale(std::max(a, b)) + margin));
    }
  }
  return box;
}

}  // namespace exactgeo::ccd::internal
