#pragma once

// Bringing coordinates to magnitude 1 by an exact power of two: the one window both
// products use (CCD for a query or a mesh step, point-in-volume for a mesh and its points).
//
// Every sign a predicate takes is the sign of a polynomial homogeneous in the coordinates
// (or in coordinate differences), so multiplying every coordinate by one power of two
// changes no answer. The filters, though, certify only where products neither overflow
// nor underflow: each is guarded by a range of its inputs' largest magnitude (2^+-242 for
// det3, 2^+-96 for the ray-patch quartic phi, docs/predicates.md), and an input at 2^+-900
// misses every filter and pays expansion or rational arithmetic for every sign.
//
// The window [2^-64, 2^64]: inside it nothing is scaled, since a largest magnitude below
// 2^64 is inside every guard's upper end (phi's 2^96 is the lowest), and one above 2^-64
// leaves the guards' lower ends (2^-96 at the highest) to inputs 2^-32 below the largest,
// rare. Outside it, the values are multiplied by 2^-e with the largest in [1/2, 1), where
// every guard holds as for data of size 1. A scaling is used only when every product is
// exact: a value about 1,000 binades below the largest would become subnormal and lose
// bits, and then the caller keeps the values as given (exact, only slower).

#include <algorithm>
#include <cmath>
#include <span>

#include "exactgeo/predicates/kernel/power_of_two.hpp"

namespace exactgeo::kernel {

/// Largest magnitudes inside [kUnitWindowLow, kUnitWindowHigh] are left as they are.
inline constexpr double kUnitWindowLow = 0x1p-64;
inline constexpr double kUnitWindowHigh = 0x1p64;

inline double largest_magnitude(std::span<const double> values) noexcept {
  double largest = 0.0;
  for (const double v : values)
    largest = std::max(largest, std::fabs(v));
  return largest;
}

/// Whether values whose largest magnitude is `largest` are left as they are.
inline bool near_unit_magnitude(double largest) noexcept {
  return largest == 0.0 || (largest >= kUnitWindowLow && largest <= kUnitWindowHigh);
}

/// The e with `largest` in [2^(e-1), 2^e), so that largest 2^-e lies in [1/2, 1); 1025 for
/// an infinite `largest` (a sum of finite extents wider than DBL_MAX), above every finite
/// one. Precondition: largest > 0, not NaN.
inline int unit_exponent(double largest) noexcept {
  if (!std::isfinite(largest)) return 1025;
  int e = 0;
  std::frexp(largest, &e);
  return e;
}

/// Multiplies every value by 2^-unit_exponent(largest), when that largest magnitude is not
/// near_unit_magnitude and every product is exact (none became subnormal and lost bits).
/// Returns whether it did; on false the values may be partly scaled, so call it on a copy.
/// `largest` must be largest_magnitude(values) (callers that know it pass it on).
inline bool scale_to_unit_magnitude(std::span<double> values, double largest) noexcept {
  if (near_unit_magnitude(largest)) return false;
  const ExactPowerOfTwo down(-unit_exponent(largest));
  bool exact = true;
  for (double& v : values)
    v = down(v, exact);
  return exact;
}

inline bool scale_to_unit_magnitude(std::span<double> values) noexcept {
  return scale_to_unit_magnitude(values, largest_magnitude(values));
}

}  // namespace exactgeo::kernel
