#pragma once

// Exact rational numbers (GMP), the last-resort stage of every predicate and the number
// type of the reference kernel. Every finite double converts exactly.

#include <gmpxx.h>

#include <compare>
#include <concepts>
#include <utility>

#include "exactgeo/predicates/sign.hpp"

namespace exactgeo::kernel {

/// Exact rational numbers for every library: a thin value wrapper around mpq_class. Its
/// operators return values, not GMP expression templates, so generic formulas can hold
/// intermediate results in `auto`. Values are kept canonical (GMP's operations do).
class Rational {
 public:
  Rational() = default;
  explicit Rational(double x) : q_(x) {}  // mpq_set_d: exact for finite x
  /// An integer, exactly; implicit, so that 0, 1, 2 read as numbers in formulas.
  template <std::integral I>
  requires(sizeof(I) <= sizeof(long)) Rational(I n)
      : q_(n) {}  // NOLINT(google-explicit-constructor)
  explicit Rational(mpq_class q) : q_(std::move(q)) { q_.canonicalize(); }

  const mpq_class& value() const noexcept { return q_; }
  Sign sign() const noexcept { return static_cast<Sign>(sgn(q_)); }
  bool is_zero() const noexcept { return sgn(q_) == 0; }
  /// The double nearest to zero of the two around the value (mpq_get_d truncates): at
  /// most the value in magnitude, equal to it when the value is a double.
  double toward_zero() const noexcept { return q_.get_d(); }

  friend Rational operator+(const Rational& a, const Rational& b) {
    Rational r;
    mpq_add(r.q_.get_mpq_t(), a.q_.get_mpq_t(), b.q_.get_mpq_t());
    return r;
  }
  friend Rational operator-(const Rational& a, const Rational& b) {
    Rational r;
    mpq_sub(r.q_.get_mpq_t(), a.q_.get_mpq_t(), b.q_.get_mpq_t());
    return r;
  }
  friend Rational operator*(const Rational& a, const Rational& b) {
    Rational r;
    mpq_mul(r.q_.get_mpq_t(), a.q_.get_mpq_t(), b.q_.get_mpq_t());
    return r;
  }
  /// Precondition: b is not zero.
  friend Rational operator/(const Rational& a, const Rational& b) {
    Rational r;
    mpq_div(r.q_.get_mpq_t(), a.q_.get_mpq_t(), b.q_.get_mpq_t());
    return r;
  }
  Rational operator-() const {
    Rational r;
    mpq_neg(r.q_.get_mpq_t(), q_.get_mpq_t());
    return r;
  }
  Rational& operator+=(const Rational& b) { return *this = *this + b; }
  Rational& operator-=(const Rational& b) { return *this = *this - b; }
  Rational& operator*=(const Rational& b) { return *this = *this * b; }
  Rational& operator/=(const Rational& b) { return *this = *this / b; }

  friend bool operator==(const Rational& a, const Rational& b) noexcept {
    return mpq_equal(a.q_.get_mpq_t(), b.q_.get_mpq_t()) != 0;
  }
  friend std::strong_ordering operator<=>(const Rational& a, const Rational& b) noexcept {
    const int c = mpq_cmp(a.q_.get_mpq_t(), b.q_.get_mpq_t());
    return c < 0   ? std::strong_ordering::less
           : c > 0 ? std::strong_ordering::greater
                   : std::strong_ordering::equal;
  }

 private:
  mpq_class q_;
};

}  // namespace exactgeo::kernel
