#pragma once

// Bringing coordinates to magnitude 1 by an exact power of two.
//
// Every polynomial whose sign the parity and exact methods take is homogeneous in the
// coordinates, and times are not scaled, so multiplying every coordinate of a query (or
// of a whole mesh step) by one power of two changes no answer. The filters, though, are
// certified only where products neither overflow nor underflow: a query at 2^±900 misses
// every filter and pays expansion arithmetic for every sign (docs/ccd.md measures how
// much slower). Inside [2^-64, 2^64] the products of the degrees used stay far from both
// limits, so only coordinates outside it are scaled.

#include <algorithm>
#include <cmath>
#include <span>

#include "exactgeo/predicates/kernel/power_of_two.hpp"

namespace exactgeo::ccd::internal {

using kernel::PowerOfTwo;

inline double largest_magnitude(std::span<const double> values) noexcept {
  double largest = 0.0;
  for (const double v : values)
    largest = std::max(largest, std::fabs(v));
  return largest;
}

/// Whether values whose largest magnitude is `largest` are left as they are.
inline bool near_unit_magnitude(double largest) noexcept {
  return largest == 0.0 || (largest >= 0x1p-64 && largest <= 0x1p64);
}

/// Multiplies every value by 2^-e, with e such that the largest magnitude lands in
/// [1/2, 1), when that largest magnitude is not near_unit_magnitude and every product is
/// exact (none became subnormal and lost bits). Returns whether it did; on false the
/// values may be partly scaled, so call it on a copy.
/// `largest` must be largest_magnitude(values) (callers that know it pass it on).
inline bool scale_to_unit_magnitude(std::span<double> values, double largest) noexcept {
  if (near_unit_magnitude(largest)) return false;
  int e = 0;
  std::frexp(largest, &e);  // largest in [2^(e-1), 2^e)
  const kernel::ExactPowerOfTwo down(-e);
  bool exact = true;
  for (double& v : values)
    v = down(v, exact);
  return exact;
}

inline bool scale_to_unit_magnitude(std::span<double> values) noexcept {
  return scale_to_unit_magnitude(values, largest_magnitude(values));
}

}  // namespace exactgeo::ccd::internal
