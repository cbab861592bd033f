#pragma once

// Error-free transformations (Knuth's TwoSum, Dekker's split and TwoProduct), in the form
// used by Shewchuk, "Adaptive Precision Floating-Point Arithmetic and Fast Robust
// Geometric Predicates", Discrete Comput. Geom. 18 (1997), section 2.
//
// Each returns {head, tail} with head = fl(a op b) and a op b = head + tail exactly. This
// holds under IEEE 754 round-to-nearest-even without overflow; two_product additionally
// needs both factors' exponents to sum to at least -969, so that no partial product
// underflows (exponent_range.hpp arranges that before any exact evaluation). These
// routines must be compiled with -ffp-contract=off: a fused multiply-add inserted by the
// compiler would change the rounding they rely on.

#include <cfloat>
#include <cmath>

#if !defined(FLT_EVAL_METHOD) || FLT_EVAL_METHOD != 0
#error "exactgeo needs double operations rounded to double (FLT_EVAL_METHOD == 0, e.g. SSE2)"
#endif
#if defined(__FAST_MATH__)
#error "exactgeo predicates must not be compiled with fast-math optimizations"
#endif

namespace exactgeo::kernel {

struct TwoTerm {
  double head;
  double tail;
};

constexpr TwoTerm two_sum(double a, double b) noexcept {
  const double x = a + b;
  const double b_virtual = x - a;
  const double a_virtual = x - b_virtual;
  return {x, (a - a_virtual) + (b - b_virtual)};
}

constexpr TwoTerm two_diff(double a, double b) noexcept {
  const double x = a - b;
  const double b_virtual = a - x;
  const double a_virtual = x + b_virtual;
  return {x, (a - a_virtual) + (b_virtual - b)};
}

/// Precondition: |a| >= |b| or a == 0.
constexpr TwoTerm fast_two_sum(double a, double b) noexcept {
  const double x = a + b;
  return {x, b - (x - a)};
}

/// Splits a into hi + lo with each half fitting in 26 bits (Dekker). Needs |a| < 2^996.
constexpr TwoTerm split(double a) noexcept {
  constexpr double splitter = 134217729.0;  // 2^27 + 1
  const double c = splitter * a;
  const double a_big = c - a;
  const double hi = c - a_big;
  return {hi, a - hi};
}

inline TwoTerm two_product(double a, double b) noexcept {
  const double x = a * b;
#if defined(__FMA__) || defined(__FP_FAST_FMA)
  return {x, std::fma(a, b, -x)};
#else
  const auto [a_hi, a_lo] = split(a);
  const auto [b_hi, b_lo] = split(b);
  const double err1 = x - a_hi * b_hi;
  const double err2 = err1 - a_lo * b_hi;
  const double err3 = err2 - a_hi * b_lo;
  return {x, a_lo * b_lo - err3};
#endif
}

}  // namespace exactgeo::kernel
