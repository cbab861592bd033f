#pragma once

// Scaling by a power of two, the one change of magnitude that keeps every sign and, in
// the normal range, every bit: the CCD's unit-magnitude scaling and the float boxes of
// the box trees both use it.

#include <cmath>

namespace exactgeo::kernel {

/// 2^k as two factors, each a double (2^k alone is not one for k > 1023 or k < -1074):
/// x * first * second is x 2^k, exact wherever that is a normal double (or a subnormal
/// with no bits lost), else rounded, and monotone in x either way.
struct PowerOfTwo {
  explicit PowerOfTwo(int k) noexcept
      : first(std::ldexp(1.0, k / 2)), second(std::ldexp(1.0, k - k / 2)) {}
  double operator()(double x) const noexcept { return x * first * second; }
  double first;
  double second;
};

}  // namespace exactgeo::kernel
