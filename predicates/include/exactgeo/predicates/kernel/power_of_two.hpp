#pragma once

// Scaling by a power of two, the one change of magnitude that keeps every sign and, in
// the normal range, every bit: the CCD's unit-magnitude scaling, the classifier's exact
// frame and the float boxes of the box trees all use it.

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

/// Multiplication by 2^k that tells whether it was exact: scaling the result back by
/// 2^-k lands on x exactly iff no bit was lost on the way (an overflow gives infinity,
/// which does not scale back; a result that became subnormal and lost bits scales back,
/// exactly, to a number other than x).
class ExactPowerOfTwo {
 public:
  explicit ExactPowerOfTwo(int k) noexcept : there_(k), back_(-k) {}
  /// x 2^k; `exact` becomes false when that is not x 2^k exactly (it is never set true).
  double operator()(double x, bool& exact) const noexcept {
    const double y = there_(x);
    exact &= back_(y) == x;
    return y;
  }

 private:
  PowerOfTwo there_;
  PowerOfTwo back_;
};

}  // namespace exactgeo::kernel
