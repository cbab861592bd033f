#pragma once

// Intervals of MPFR numbers of a given precision: every operation rounds its lower bound
// down and its upper bound up (MPFR rounds every operation, atan2 and pi included,
// correctly in the direction asked), so the interval holds the exact result. The later
// stages of boundary_term.cpp. MPFR's exponent range is far wider than a double's, so
// nothing here overflows or underflows for double inputs.

#include <mpfr.h>

#include <utility>

namespace exactgeo::internal {

class MpfrInterval {
 public:
  explicit MpfrInterval(mpfr_prec_t precision) {
    mpfr_init2(lo_, precision);
    mpfr_init2(hi_, precision);
  }
  MpfrInterval(const MpfrInterval& other) : MpfrInterval(mpfr_get_prec(other.lo_)) {
    mpfr_set(lo_, other.lo_, MPFR_RNDD);
    mpfr_set(hi_, other.hi_, MPFR_RNDU);
  }
  MpfrInterval& operator=(const MpfrInterval& other) {
    mpfr_set(lo_, other.lo_, MPFR_RNDD);
    mpfr_set(hi_, other.hi_, MPFR_RNDU);
    return *this;
  }
  ~MpfrInterval() {
    mpfr_clear(lo_);
    mpfr_clear(hi_);
  }

  static MpfrInterval exact(double x, mpfr_prec_t precision) {
    MpfrInterval r(precision);
    mpfr_set_d(r.lo_, x, MPFR_RNDD);
    mpfr_set_d(r.hi_, x, MPFR_RNDU);
    return r;
  }
  static MpfrInterval difference(double a, double b, mpfr_prec_t precision) {
    MpfrInterval r = exact(a, precision);
    mpfr_sub_d(r.lo_, r.lo_, b, MPFR_RNDD);
    mpfr_sub_d(r.hi_, r.hi_, b, MPFR_RNDU);
    return r;
  }
  static MpfrInterval two_pi(mpfr_prec_t precision) {
    MpfrInterval r(precision);
    mpfr_const_pi(r.lo_, MPFR_RNDD);
    mpfr_const_pi(r.hi_, MPFR_RNDU);
    mpfr_mul_2ui(r.lo_, r.lo_, 1, MPFR_RNDD);
    mpfr_mul_2ui(r.hi_, r.hi_, 1, MPFR_RNDU);
    return r;
  }

  mpfr_prec_t precision() const noexcept { return mpfr_get_prec(lo_); }
  const __mpfr_struct* lo() const noexcept { return lo_; }
  const __mpfr_struct* hi() const noexcept { return hi_; }
  __mpfr_struct* lo() noexcept { return lo_; }
  __mpfr_struct* hi() noexcept { return hi_; }

 private:
  mpfr_t lo_;
  mpfr_t hi_;
};

inline MpfrInterval operator+(const MpfrInterval& a, const MpfrInterval& b) {
  MpfrInterval r(a.precision());
  mpfr_add(r.lo(), a.lo(), b.lo(), MPFR_RNDD);
  mpfr_add(r.hi(), a.hi(), b.hi(), MPFR_RNDU);
  return r;
}

inline MpfrInterval operator-(const MpfrInterval& a, const MpfrInterval& b) {
  MpfrInterval r(a.precision());
  mpfr_sub(r.lo(), a.lo(), b.hi(), MPFR_RNDD);
  mpfr_sub(r.hi(), a.hi(), b.lo(), MPFR_RNDU);
  return r;
}

/// op (mpfr_mul or mpfr_div) of the four pairs of bounds, each rounded both ways: their
/// least and greatest.
template <class Op>
MpfrInterval of_bound_pairs(const MpfrInterval& a, const MpfrInterval& b, Op op) {
  MpfrInterval r(a.precision());
  mpfr_t t;
  mpfr_init2(t, a.precision());
  bool first = true;
  for (const auto* x : {a.lo(), a.hi()}) {
    for (const auto* y : {b.lo(), b.hi()}) {
      op(t, x, y, MPFR_RNDD);
      if (first || mpfr_less_p(t, r.lo())) mpfr_set(r.lo(), t, MPFR_RNDD);
      op(t, x, y, MPFR_RNDU);
      if (first || mpfr_greater_p(t, r.hi())) mpfr_set(r.hi(), t, MPFR_RNDU);
      first = false;
    }
  }
  mpfr_clear(t);
  return r;
}

inline MpfrInterval operator*(const MpfrInterval& a, const MpfrInterval& b) {
  return of_bound_pairs(a, b, mpfr_mul);
}

/// Precondition: b does not hold 0.
inline MpfrInterval operator/(const MpfrInterval& a, const MpfrInterval& b) {
  return of_bound_pairs(a, b, mpfr_div);
}

/// Of the interval's non-negative part.
inline MpfrInterval sqrt(const MpfrInterval& a) {
  MpfrInterval r(a.precision());
  if (mpfr_sgn(a.lo()) < 0) {
    mpfr_set_zero(r.lo(), 1);
  } else {
    mpfr_sqrt(r.lo(), a.lo(), MPFR_RNDD);
  }
  if (mpfr_sgn(a.hi()) < 0) {
    mpfr_set_zero(r.hi(), 1);
  } else {
    mpfr_sqrt(r.hi(), a.hi(), MPFR_RNDU);
  }
  return r;
}

}  // namespace exactgeo::internal
