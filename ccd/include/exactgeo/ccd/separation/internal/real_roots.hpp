#pragma once

// Exact real roots of univariate polynomials with rational coefficients, and the signs of
// other polynomials at them: the last resort of the minimum-separation decision.
//
//  * Roots in an open interval are isolated by bisection with Sturm counts on the
//    squarefree part p / gcd(p, p'). A midpoint that is itself a root is kept exactly.
//  * The sign of q at an isolated root r of p is a Tarski query: the drop in sign changes
//    of the signed remainder sequence of p and p' q across the isolating interval counts
//    the roots of p there with q > 0 minus those with q < 0 (Sturm-Tarski), and r is the
//    only one. No refinement, however close q's roots come to r.
// Everything is exact (kernel::Rational, GMP); nothing here is fast, and nothing needs to
// be.

#include <optional>
#include <vector>

#include "exactgeo/predicates/kernel/rational.hpp"
#include "exactgeo/predicates/sign.hpp"

namespace exactgeo::ccd::internal {

using kernel::Rational;

/// sum_k c[k] t^k; no trailing zero coefficients (the zero polynomial has none).
class RationalPolynomial {
 public:
  RationalPolynomial() = default;
  explicit RationalPolynomial(std::vector<Rational> coefficients);

  /// sum_k d[k] (1 - t)^(n - k) t^k, n = d.size() - 1 (the homogeneous Bernstein form).
  static RationalPolynomial from_homogeneous(const std::vector<Rational>& d);

  bool is_zero() const noexcept { return c_.empty(); }
  int degree() const noexcept { return static_cast<int>(c_.size()) - 1; }
  const std::vector<Rational>& coefficients() const noexcept { return c_; }

  Rational operator()(const Rational& t) const;
  Sign sign_at(const Rational& t) const;

  RationalPolynomial derivative() const;
  friend RationalPolynomial operator*(const RationalPolynomial& a, const RationalPolynomial& b);
  /// The remainder of the division by a nonzero b.
  friend RationalPolynomial operator%(const RationalPolynomial& a, const RationalPolynomial& b);
  /// The quotient of the division by a nonzero b.
  friend RationalPolynomial operator/(const RationalPolynomial& a, const RationalPolynomial& b);

 private:
  void trim();
  std::vector<Rational> c_;
};

/// The monic greatest common divisor (zero when both are zero).
RationalPolynomial gcd(RationalPolynomial a, RationalPolynomial b);

/// p / gcd(p, p'): the same roots, each simple. p nonzero.
RationalPolynomial squarefree_part(const RationalPolynomial& p);

/// A real root of a squarefree polynomial: the rational `exact`, or the only root in the
/// open interval (lo, hi), at whose ends the polynomial does not vanish.
struct IsolatedRoot {
  std::optional<Rational> exact;
  Rational lo;
  Rational hi;
};

/// The roots of the squarefree p in the open interval (lo, hi), in increasing order (none
/// for a constant p).
std::vector<IsolatedRoot> roots_between(const RationalPolynomial& p, const Rational& lo,
                                        const Rational& hi);

/// Halves the isolating interval of a root of the squarefree p, keeping the root (sets
/// `exact` when a midpoint is the root).
void halve_isolating_interval(const RationalPolynomial& p, IsolatedRoot& root);

/// Counts over the roots of a squarefree p in an open interval whose ends are not roots:
/// how many (Sturm), and for each of some polynomials q_i, how many roots have q_i > 0
/// minus how many have q_i < 0 (a Tarski query). A cluster of roots whose conditions all
/// agree is settled at once, without isolating its roots one by one.
class TarskiQueries {
 public:
  TarskiQueries(const RationalPolynomial& p, const std::vector<RationalPolynomial>& qs);
  int count(const Rational& lo, const Rational& hi) const;
  int query(std::size_t i, const Rational& lo, const Rational& hi) const;

 private:
  std::vector<RationalPolynomial> sturm_;
  std::vector<std::vector<RationalPolynomial>> sequences_;
};

/// The sign of q at `root`, a root of the squarefree `p` (as roots_between returned it).
Sign sign_at_root(const RationalPolynomial& q, const RationalPolynomial& p, IsolatedRoot root);

}  // namespace exactgeo::ccd::internal
