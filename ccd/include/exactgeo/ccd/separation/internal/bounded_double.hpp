#pragma once

// A double with a running bound on its distance to the exact value: the filter of the
// minimum-separation decision, whose polynomials take a few hundred operations each, too
// many shapes for a static bound per formula.
//
// Invariant: |exact - value| <= error. With u = 2^-53 (round to nearest):
//  * a sum's rounding is at most u |fl(sum)| in the normal range and zero in the
//    subnormal range (sums of subnormals are exact), so
//      error(a + b) = a.error + b.error + u |fl(a + b)|;
//  * a product's exact value differs from a.value b.value by at most
//    |a.value| b.error + |b.value| a.error + a.error b.error, and its rounding adds at most
//    u |fl(product)| + 2^-1075 (half the smallest subnormal, where gradual underflow
//    loses bits);
//  * the bound is itself computed in doubles: at most ten operations on nonnegative
//    numbers, each rounding by at most a factor (1 + u), hence the factor
//    kGrow = 1 + 2^-48 > (1 + u)^10; the added 2^-1070 covers a product's own 2^-1075 and
//    the at most four products of the bound that underflow, 2^-1075 each.
// A value or bound that overflows makes the number unusable (not finite): every sign
// test on it answers "not certified".

#include <cmath>

namespace exactgeo::ccd::internal {

struct BoundedDouble {
  double value = 0.0;
  double error = 0.0;

  BoundedDouble() = default;
  /// An exactly known double.
  BoundedDouble(double exact) noexcept : value(exact) {}  // NOLINT: implicit by design
  BoundedDouble(double v, double e) noexcept : value(v), error(e) {}

  static constexpr double kUnit = 0x1p-53;
  static constexpr double kGrow = 1.0 + 0x1p-48;
  static constexpr double kTiny = 0x1p-1070;

  /// exact > 0, certified.
  bool certainly_positive() const noexcept { return value - error > 0.0 && usable(); }
  /// exact < 0, certified.
  bool certainly_negative() const noexcept { return value + error < 0.0 && usable(); }
  /// exact >= 0, certified (an exactly known zero counts).
  bool certainly_nonnegative() const noexcept { return value - error >= 0.0 && usable(); }
  /// exact <= 0, certified.
  bool certainly_nonpositive() const noexcept { return value + error <= 0.0 && usable(); }
  bool usable() const noexcept { return std::isfinite(value) && std::isfinite(error); }
};

inline BoundedDouble operator+(const BoundedDouble& a, const BoundedDouble& b) noexcept {
  const double v = a.value + b.value;
  return {v, (a.error + b.error + BoundedDouble::kUnit * std::fabs(v)) * BoundedDouble::kGrow};
}

inline BoundedDouble operator-(const BoundedDouble& a, const BoundedDouble& b) noexcept {
  const double v = a.value - b.value;
  return {v, (a.error + b.error + BoundedDouble::kUnit * std::fabs(v)) * BoundedDouble::kGrow};
}

inline BoundedDouble operator*(const BoundedDouble& a, const BoundedDouble& b) noexcept {
  const double v = a.value * b.value;
  const double propagated =
      std::fabs(a.value) * b.error + std::fabs(b.value) * a.error + a.error * b.error;
  return {v, (propagated + BoundedDouble::kUnit * std::fabs(v) + BoundedDouble::kTiny) *
                 BoundedDouble::kGrow};
}

}  // namespace exactgeo::ccd::internal
