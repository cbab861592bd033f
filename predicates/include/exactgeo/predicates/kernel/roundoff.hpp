#pragma once

// Compile-time forward error analysis of a polynomial evaluated in double precision.
//
// Every predicate formula is a template evaluated on several number types; evaluating it
// on Roundoff<G> at compile time yields the constant of its semi-static filter. The
// analysis is the classical one (Higham, "Accuracy and Stability of Numerical
// Algorithms", ch. 2-3; Meyer and Pion, "FPG: a code generator for fast and certified
// geometric predicates", 2008), written out so that the constant is derived in code and
// not copied from a paper.
//
// Model. Inputs are grouped (by coordinate axis, or by vector); every input of group g
// satisfies |x~| <= m_g where x~ is the double the formula receives and m_g is a maximum
// measured at run time. The formula must be homogeneous in every group (checked here at
// compile time), so its exact value and its rounding error both scale with
// prod_g m_g^deg_g. In those units each node of the expression carries
//
//   magnitude  B: |computed value|  <= B,
//   error      E: |computed - exact| <= E + A * eta * U^(d-2),
//   underflow  A: the count of products that may have underflowed, weighted by what
//                 multiplies them afterwards,
//
// with u = 2^-53 (unit roundoff), eta = 2^-1074 (smallest subnormal: the absolute error of
// a product that underflows), d the node's total degree and U = 2^guard_exponent(D) the
// run-time guard on every m_g (see below). B, E and A are polynomials in u with
// nonnegative integer coefficients, so the whole analysis is exact; only the final
// evaluation rounds, upward.
//
// Rules, for computed values x~ = x + dx and y~ = y + dy (|dx| <= E_x etc.):
//   inputs   : B = 1, E = u if the input is itself a rounded difference fl(p - q)
//              (|fl(z) - z| <= u |fl(z)| under round-to-nearest), E = 2u if it is the head
//              of a compressed expansion (within one ulp), E = 0 if exact. A = 0.
//   x~ +- y~ : |fl(s) - s| <= u |s| with |s| <= B_x + B_y, hence
//              B = (1 + u)(B_x + B_y), E = E_x + E_y + u (B_x + B_y), A = A_x + A_y.
//              (A sum that lands in the subnormal range is exact: no eta term.)
//   x~ * y~  : x~ y~ - x y = x~ dy + y dx with |y| <= B_y + E_y, plus one rounding
//              u B_x B_y, plus at most eta if the product underflows:
//              B = (1 + u) B_x B_y, E = B_x E_y + (B_y + E_y) E_x + u B_x B_y,
//              A = B_x A_y + (B_y + E_y + A_y) A_x + E_x A_y + 1
//              (the cross terms use eta U^-2 < 1 and m_g <= U).
//
// Guard. At run time the filter only answers when every m_g lies in [U^-1, U]. Then
// A eta U^(D-2) <= A eta U^(2D-2) prod m (because prod m >= U^-D). Choosing
// U = 2^floor(968 / (2D - 2)) gives eta U^(2D-2) <= 2^-106 = u^2, so the whole underflow
// term is at most A u^2 in the units of prod m, and the certified error bound is
//   epsilon = E + A u^2   (times prod_g m_g^deg_g).
// The same guard keeps every intermediate value below 2^990: no overflow.

#include <array>
#include <cstddef>

namespace exactgeo::kernel {

/// A polynomial sum_k c_k u^k in the unit roundoff u = 2^-53, with nonnegative integer
/// coefficients. Terms beyond kMaxPower are folded into the u^kMaxPower coefficient,
/// which only makes the polynomial larger for 0 < u < 1 (and keeps compile-time
/// evaluation cheap: by u^4 the terms are 2^-159 relative to the first).
class UnitRoundoffPolynomial {
 public:
  static constexpr int kMaxPower = 4;

  constexpr UnitRoundoffPolynomial() = default;
  static constexpr UnitRoundoffPolynomial constant(double c) {
    UnitRoundoffPolynomial p;
    p.c_[0] = c;
    return p;
  }
  static constexpr UnitRoundoffPolynomial unit_roundoff(double c = 1) {
    UnitRoundoffPolynomial p;
    p.c_[1] = c;
    return p;
  }

  friend constexpr UnitRoundoffPolynomial operator+(const UnitRoundoffPolynomial& a,
                                                    const UnitRoundoffPolynomial& b) {
    UnitRoundoffPolynomial r;
    for (int k = 0; k <= kMaxPower; ++k)
      r.c_[k] = checked(a.c_[k] + b.c_[k]);
    return r;
  }

  friend constexpr UnitRoundoffPolynomial operator*(const UnitRoundoffPolynomial& a,
                                                    const UnitRoundoffPolynomial& b) {
    UnitRoundoffPolynomial r;
    for (int i = 0; i <= kMaxPower; ++i) {
      for (int j = 0; j <= kMaxPower; ++j) {
        const int k = i + j < kMaxPower ? i + j : kMaxPower;
        r.c_[k] = checked(r.c_[k] + a.c_[i] * b.c_[j]);
      }
    }
    return r;
  }

  /// (1 + u) * p
  constexpr UnitRoundoffPolynomial times_one_plus_u() const {
    UnitRoundoffPolynomial shift;
    shift.c_[0] = 1;
    shift.c_[1] = 1;
    return *this * shift;
  }

  /// An upper bound of the polynomial's value at u = 2^-53, as a double. Each term
  /// c_k 2^(-53k) is exact (c_k < 2^53, no underflow for k <= kMaxPower); the sum of the
  /// nonnegative terms is rounded at most kMaxPower times, so multiplying by
  /// (1 + 2^-40) > (1 - u)^-kMaxPower more than covers it.
  constexpr double upper_bound_at_unit_roundoff() const {
    double sum = 0;
    double power = 1;
    for (int k = 0; k <= kMaxPower; ++k) {
      sum += c_[k] * power;
      power *= 0x1p-53;
    }
    return sum * (1 + 0x1p-40);
  }

 private:
  // Coefficients must stay exactly representable; a formula that needs more is a bug.
  static constexpr double checked(double c) {
    if (!(c < 0x1p53)) throw "roundoff polynomial coefficient exceeds 2^53";
    return c;
  }

  std::array<double, kMaxPower + 1> c_{};
};

/// Run-time guard exponent for a formula of total degree D (see the header comment).
constexpr int guard_exponent(int total_degree) {
  return 968 / (2 * total_degree - 2);
}

/// The number type of the compile-time analysis. G is the number of input groups.
template <int G>
class Roundoff {
 public:
  using Poly = UnitRoundoffPolynomial;
  enum class InputError { exact, one_rounding, expansion_head };

  static constexpr Roundoff input(int group, InputError error) {
    Roundoff r;
    r.magnitude_ = Poly::constant(1);
    r.error_ = error == InputError::exact          ? Poly{}
               : error == InputError::one_rounding ? Poly::unit_roundoff(1)
                                                   : Poly::unit_roundoff(2);
    r.degree_[group] = 1;
    return r;
  }

  constexpr const Poly& magnitude() const { return magnitude_; }
  constexpr const Poly& error() const { return error_; }
  constexpr const Poly& underflow() const { return underflow_; }
  constexpr int degree(int group) const { return degree_[group]; }
  constexpr int total_degree() const {
    int d = 0;
    for (int g = 0; g < G; ++g)
      d += degree_[g];
    return d;
  }

  friend constexpr Roundoff operator+(const Roundoff& x, const Roundoff& y) {
    require_same_degrees(x, y);
    Roundoff r;
    r.degree_ = x.degree_;
    const Poly sum_bound = x.magnitude_ + y.magnitude_;
    r.magnitude_ = sum_bound.times_one_plus_u();
    r.error_ = x.error_ + y.error_ + Poly::unit_roundoff() * sum_bound;
    r.underflow_ = x.underflow_ + y.underflow_;
    return r;
  }
  friend constexpr Roundoff operator-(const Roundoff& x, const Roundoff& y) { return x + y; }
  constexpr Roundoff operator-() const { return *this; }

  friend constexpr Roundoff operator*(const Roundoff& x, const Roundoff& y) {
    Roundoff r;
    for (int g = 0; g < G; ++g)
      r.degree_[g] = x.degree_[g] + y.degree_[g];
    const Poly product_bound = x.magnitude_ * y.magnitude_;
    const Poly y_exact_bound = y.magnitude_ + y.error_;
    r.magnitude_ = product_bound.times_one_plus_u();
    r.error_ =
        x.magnitude_ * y.error_ + y_exact_bound * x.error_ + Poly::unit_roundoff() * product_bound;
    r.underflow_ = x.magnitude_ * y.underflow_ + (y_exact_bound + y.underflow_) * x.underflow_ +
                   x.error_ * y.underflow_ + Poly::constant(1);
    return r;
  }

 private:
  static constexpr void require_same_degrees(const Roundoff& x, const Roundoff& y) {
    for (int g = 0; g < G; ++g) {
      if (x.degree_[g] != y.degree_[g]) throw "filtered formula is not homogeneous in a group";
    }
  }

  Poly magnitude_;
  Poly error_;
  Poly underflow_;
  std::array<int, G> degree_{};
};

/// Everything a semi-static filter needs at run time, derived from a Roundoff result.
template <int G>
struct FilterConstant {
  double epsilon;             // certified |error| <= epsilon * prod_g m_g^degree_g
  std::array<int, G> degree;  // the formula's degree in each group
  int guard_exponent;         // the filter answers only if 2^-guard <= m_g <= 2^guard
  double guard_low;           // 2^-guard_exponent
  double guard_high;          // 2^guard_exponent
};

constexpr double power_of_two(int exponent) {
  double r = 1;
  for (int i = 0; i < exponent; ++i)
    r *= 2;
  for (int i = 0; i > exponent; --i)
    r /= 2;
  return r;
}

template <int G>
constexpr FilterConstant<G> derive_filter(const Roundoff<G>& r) {
  FilterConstant<G> c{};
  for (int g = 0; g < G; ++g) {
    c.degree[g] = r.degree(g);
    if (c.degree[g] < 1) throw "every group must appear in every term (needed for exact zero)";
  }
  c.guard_exponent = guard_exponent(r.total_degree());
  c.guard_low = power_of_two(-c.guard_exponent);
  c.guard_high = power_of_two(c.guard_exponent);
  const UnitRoundoffPolynomial underflow_term = r.underflow() *
                                                UnitRoundoffPolynomial::unit_roundoff() *
                                                UnitRoundoffPolynomial::unit_roundoff();
  // The run-time bound epsilon * prod m^deg is itself rounded, at most 12 times (degree
  // <= 12), each time by a factor >= 1 - u; (1 + 2^-40) covers that with room to spare.
  c.epsilon = (r.error() + underflow_term).upper_bound_at_unit_roundoff() * (1 + 0x1p-40);
  return c;
}

}  // namespace exactgeo::kernel
