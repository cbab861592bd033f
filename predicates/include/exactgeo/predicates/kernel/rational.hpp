#pragma once

// Exact rational numbers (GMP), the last-resort stage of every predicate and the number
// type of the reference kernel. Every finite double converts exactly.

#include <gmpxx.h>

#include "exactgeo/predicates/sign.hpp"

namespace exactgeo::kernel {

/// A thin value wrapper around mpq_class. Its operators return values, not GMP
/// expression templates, so generic formulas can hold intermediate results in `auto`.
class Rational {
 public:
  Rational() = default;
  explicit Rational(double x) : q_(x) {}  // mpq_set_d: exact for finite x
  explicit Rational(mpq_class q) : q_(std::move(q)) {}

  const mpq_class& value() const noexcept { return q_; }
  Sign sign() const noexcept { return sign_of(static_cast<double>(sgn(q_))); }

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
  Rational operator-() const {
    Rational r;
    mpq_neg(r.q_.get_mpq_t(), q_.get_mpq_t());
    return r;
  }

 private:
  mpq_class q_;
};

}  // namespace exactgeo::kernel
