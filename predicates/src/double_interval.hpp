#pragma once

// Intervals of doubles rounded outward: every operation's result is the correctly rounded
// one moved one ulp outward (what std::nextafter gives, computed from the bits), which holds the
// exact result because IEEE 754
// +, -, *, / and sqrt are correctly rounded (within half an ulp, or half the subnormal
// spacing when the result underflows). An overflow gives an infinite bound, and the caller
// gives up on the stage. Used by the first stage of boundary_term.cpp.

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

namespace exactgeo::internal {

struct DoubleInterval {
  double lo = 0.0;
  double hi = 0.0;

  /// std::nextafter(x, +inf) without the library call, from the bits: finite doubles of
  /// one sign are ordered as their bit patterns are (IEEE 754), so the next one up is the
  /// pattern plus one for x > 0 and minus one for x < 0 (-inf to -DBL_MAX, DBL_MAX to
  /// +inf, -2^-1074 to -0); either zero goes to 2^-1074; NaN and +inf stay.
  /// (DoubleInterval.UpAndDownAreNextafter holds it to std::nextafter.)
  static double up(double x) noexcept {
    if (!(x < std::numeric_limits<double>::infinity())) return x;
    if (x == 0.0) return std::numeric_limits<double>::denorm_min();
    const auto bits = std::bit_cast<std::uint64_t>(x);
    return std::bit_cast<double>(x > 0.0 ? bits + 1 : bits - 1);
  }
  /// std::nextafter(x, -inf): the mirror image of up.
  static double down(double x) noexcept { return -up(-x); }

  static DoubleInterval exact(double x) noexcept { return {x, x}; }

  /// a - b: the rounded difference and its exact error (two-sum), so that an exact
  /// difference stays a point and an inexact one widens only on the side of its error.
  static DoubleInterval difference(double a, double b) noexcept {
    const double d = a - b;
    constexpr double kInf = std::numeric_limits<double>::infinity();
    if (!std::isfinite(d)) return {-kInf, kInf};
    const double bv = a - d;
    const double error = (a - (d + bv)) + (bv - b);
    if (error > 0) return {d, up(d)};
    if (error < 0) return {down(d), d};
    return {d, d};
  }

  bool finite() const noexcept { return std::isfinite(lo) && std::isfinite(hi); }
};

inline DoubleInterval operator+(const DoubleInterval& a, const DoubleInterval& b) noexcept {
  return {DoubleInterval::down(a.lo + b.lo), DoubleInterval::up(a.hi + b.hi)};
}

inline DoubleInterval operator-(const DoubleInterval& a, const DoubleInterval& b) noexcept {
  return {DoubleInterval::down(a.lo - b.hi), DoubleInterval::up(a.hi - b.lo)};
}

inline DoubleInterval operator*(const DoubleInterval& a, const DoubleInterval& b) noexcept {
  const double p[4] = {a.lo * b.lo, a.lo * b.hi, a.hi * b.lo, a.hi * b.hi};
  return {DoubleInterval::down(std::min({p[0], p[1], p[2], p[3]})),
          DoubleInterval::up(std::max({p[0], p[1], p[2], p[3]}))};
}

/// Precondition: b does not hold 0.
inline DoubleInterval operator/(const DoubleInterval& a, const DoubleInterval& b) noexcept {
  const double q[4] = {a.lo / b.lo, a.lo / b.hi, a.hi / b.lo, a.hi / b.hi};
  return {DoubleInterval::down(std::min({q[0], q[1], q[2], q[3]})),
          DoubleInterval::up(std::max({q[0], q[1], q[2], q[3]}))};
}

/// Of the interval's non-negative part (a sum of squares may dip below 0 only by rounding).
inline DoubleInterval sqrt(const DoubleInterval& a) noexcept {
  return {std::max(0.0, DoubleInterval::down(std::sqrt(std::max(a.lo, 0.0)))),
          DoubleInterval::up(std::sqrt(std::max(a.hi, 0.0)))};
}

}  // namespace exactgeo::internal
