#pragma once

// Exact dyadic rationals m 2^e (m a GMP integer): the number type of the rational stage.
//
// Every input of a predicate is a dyadic rational (a double, or a sum of doubles), and
// sums, differences and products of dyadic rationals are dyadic again, so the polynomials
// the predicates take signs of never need a denominator other than a power of two. GMP's
// mpq keeps every value in lowest terms, and on the rare path of CCD (time pieces with
// exact-vector corners) that canonicalization, a gcd per operation, was most of the time;
// an integer with a binary exponent needs none: an addition shifts one operand, a product
// multiplies the integers and adds the exponents.

#include <gmp.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include "exactgeo/predicates/sign.hpp"

namespace exactgeo::kernel {

class Dyadic {
 public:
  Dyadic() noexcept { mpz_init(m_); }
  /// Exactly x (finite).
  explicit Dyadic(double x) noexcept : Dyadic(sum_of(&x, 1)) {}
  Dyadic(const Dyadic& o) noexcept : e_(o.e_) { mpz_init_set(m_, o.m_); }
  Dyadic(Dyadic&& o) noexcept : e_(o.e_) {
    mpz_init(m_);
    mpz_swap(m_, o.m_);
  }
  Dyadic& operator=(Dyadic o) noexcept {
    mpz_swap(m_, o.m_);
    std::swap(e_, o.e_);
    return *this;
  }
  ~Dyadic() { mpz_clear(m_); }

  /// Exactly the sum of `count` finite doubles (an expansion's components, or a head and a
  /// negated tail), built in one integer: no intermediate value per component.
  static Dyadic sum_of(const double* components, int count) noexcept {
    Dyadic r;
    // Each component is s_i 2^(x_i - 53) with s_i an integer below 2^53.
    long lowest = 0;
    bool any = false;
    for (int i = 0; i < count; ++i) {
      if (components[i] == 0.0) continue;
      int exponent = 0;
      std::frexp(components[i], &exponent);
      lowest = any ? std::min<long>(lowest, exponent - 53) : exponent - 53;
      any = true;
    }
    if (!any) return r;
    mpz_t term;
    mpz_init(term);
    for (int i = 0; i < count; ++i) {
      if (components[i] == 0.0) continue;
      int exponent = 0;
      const double fraction = std::frexp(components[i], &exponent);
      mpz_set_d(term, std::ldexp(fraction, 53));
      mpz_mul_2exp(term, term, static_cast<mp_bitcnt_t>(exponent - 53 - lowest));
      mpz_add(r.m_, r.m_, term);
    }
    mpz_clear(term);
    r.e_ = lowest;
    return r;
  }

  Sign sign() const noexcept { return static_cast<Sign>(mpz_sgn(m_)); }

  friend Dyadic operator+(const Dyadic& a, const Dyadic& b) noexcept { return sum(a, b, false); }
  friend Dyadic operator-(const Dyadic& a, const Dyadic& b) noexcept { return sum(a, b, true); }
  friend Dyadic operator*(const Dyadic& a, const Dyadic& b) noexcept {
    Dyadic r;
    mpz_mul(r.m_, a.m_, b.m_);
    r.e_ = a.e_ + b.e_;
    return r;
  }
  Dyadic operator-() const noexcept {
    Dyadic r(*this);
    mpz_neg(r.m_, r.m_);
    return r;
  }

  /// m and e, for tests.
  const mpz_t& significand() const noexcept { return m_; }
  long exponent() const noexcept { return e_; }

 private:
  /// a + b, or a - b: the operand with the larger exponent is shifted to the smaller one.
  static Dyadic sum(const Dyadic& a, const Dyadic& b, bool subtract) noexcept {
    Dyadic r;
    if (a.e_ >= b.e_) {
      mpz_mul_2exp(r.m_, a.m_, static_cast<mp_bitcnt_t>(a.e_ - b.e_));
      (subtract ? mpz_sub : mpz_add)(r.m_, r.m_, b.m_);
      r.e_ = b.e_;
    } else {
      mpz_mul_2exp(r.m_, b.m_, static_cast<mp_bitcnt_t>(b.e_ - a.e_));
      if (subtract) {
        mpz_sub(r.m_, a.m_, r.m_);
      } else {
        mpz_add(r.m_, r.m_, a.m_);
      }
      r.e_ = a.e_;
    }
    return r;
  }

  mpz_t m_;
  long e_ = 0;
};

}  // namespace exactgeo::kernel
