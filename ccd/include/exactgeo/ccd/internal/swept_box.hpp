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
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>

#include "exactgeo/ccd/internal/unit_magnitude.hpp"

namespace exactgeo::ccd::internal {

/// The largest float <= x (x finite).
inline float float_below(double x) noexcept {
  constexpr double kMax = std::numeric_limits<float>::max();
  if (x > kMax) return std::numeric_limits<float>::max();
  if (x < -kMax) return -std::numeric_limits<float>::infinity();
  const float f = static_cast<float>(x);
  return static_cast<double>(f) > x ? std::nextafter(f, -std::numeric_limits<float>::infinity())
                                    : f;
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

struct SweptBox {
  std::array<float, 3> lo;
  std::array<float, 3> hi;
  std::uint32_t id;  ///< the vertex, edge or face the box belongs to
};

/// Closed boxes: touching counts as overlapping.
inline bool overlap(const SweptBox& a, const SweptBox& b) noexcept {
  for (int k = 0; k < 3; ++k) {
    if (a.hi[k] < b.lo[k] || b.hi[k] < a.lo[k]) return false;
  }
  return true;
}

/// The swept box of the corners `ids` (vertex indices) of one primitive, in the step's
/// scale; positions are 3 doubles per vertex at t0 and at t1.
template <std::size_t N>
SweptBox swept_box(const std::array<std::uint32_t, N>& ids, std::uint32_t id, const double* t0,
                   const double* t1, const StepScale& scale = {}) noexcept {
  SweptBox box{};
  box.id = id;
  for (int k = 0; k < 3; ++k) {
    double lo = t0[3 * ids[0] + k];
    double hi = lo;
    for (const double* frame : {t0, t1}) {
      for (const std::uint32_t v : ids) {
        lo = std::min(lo, frame[3 * v + k]);
        hi = std::max(hi, frame[3 * v + k]);
      }
    }
    box.lo[k] = float_below(scale(lo));
    box.hi[k] = float_above(scale(hi));
  }
  return box;
}

}  // namespace exactgeo::ccd::internal
