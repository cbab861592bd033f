#pragma once

// A double with a rigorous bound on its distance from the exact value it stands for
// (running error analysis, Wilkinson; Higham, "Accuracy and Stability of Numerical
// Algorithms", section 3.3). Used where a polynomial's coefficients are too many for a
// hand-derived filter constant (slice_sides.hpp).
//
// With |x - value_x| <= error_x and |y - value_y| <= error_y, u = 2^-53 and eta = 2^-1074:
//   x + y : |fl(s) - s| <= u |fl(s)| for the computed sum s (exact when it underflows), so
//           error = error_x + error_y + u |value|;
//   x * y : x y - value_x value_y = value_x dy + value_y dx + dx dy, and the product
//           rounds by at most u |value| + eta (eta: a product that underflows), so
//           error = |value_x| error_y + |value_y| error_x + error_x error_y + u |value| + eta.
// The error is itself computed in double: at most 7 roundings that are relative (each a
// factor at most 1 + u, covered by multiplying by 1 + 2^-48 = 1 + 32u, whose own rounding
// is in that slack too) and at most 4 products that may underflow and lose up to eta/2
// each (covered by adding 4 eta, which the analysis above needs at most one of). An
// infinite or NaN value or error never certifies a sign.

#include <cmath>

#include "exactgeo/predicates/sign.hpp"

namespace exactgeo::ccd::internal {

struct Bounded {
  double value = 0.0;
  double error = 0.0;

  /// A rounded input: |value - exact| <= u |value| (a rounded difference of doubles);
  /// eta covers the rounding of u |value| itself when it underflows.
  static Bounded rounded(double value) noexcept {
    return {value, kUnitRoundoff * std::fabs(value) + kSmallestSubnormal};
  }

  /// The sign of the exact value when the bound proves it (strictly), else zero.
  Sign certified_sign() const noexcept {
    if (value - error > 0.0) return Sign::positive;  // false for NaN
    if (value + error < 0.0) return Sign::negative;
    return Sign::zero;
  }

  static constexpr double kUnitRoundoff = 0x1p-53;
  static constexpr double kSmallestSubnormal = 0x1p-1074;
  static constexpr double kInflation = 1.0 + 0x1p-48;
  static constexpr double kUnderflowSlack = 4 * kSmallestSubnormal;
};

inline Bounded operator+(const Bounded& x, const Bounded& y) noexcept {
  const double value = x.value + y.value;
  return {value, (x.error + y.error + Bounded::kUnitRoundoff * std::fabs(value) +
                  Bounded::kUnderflowSlack) *
                     Bounded::kInflation};
}

inline Bounded operator-(const Bounded& x, const Bounded& y) noexcept {
  const double value = x.value - y.value;
  return {value, (x.error + y.error + Bounded::kUnitRoundoff * std::fabs(value) +
                  Bounded::kUnderflowSlack) *
                     Bounded::kInflation};
}

inline Bounded operator*(const Bounded& x, const Bounded& y) noexcept {
  const double value = x.value * y.value;
  return {value, (std::fabs(x.value) * y.error + std::fabs(y.value) * x.error + x.error * y.error +
                  Bounded::kUnitRoundoff * std::fabs(value) + Bounded::kUnderflowSlack) *
                     Bounded::kInflation};
}

/// x times an exact double constant (a small integer or a power of two).
inline Bounded operator*(double c, const Bounded& x) noexcept {
  return Bounded{c, 0.0} * x;
}

/// (x + y) / 2, the de Casteljau step.
inline Bounded midpoint(const Bounded& x, const Bounded& y) noexcept {
  return 0.5 * (x + y);
}

}  // namespace exactgeo::ccd::internal
