#include "exactgeo/ccd/separation/internal/real_roots.hpp"

#include <cassert>
#include <utility>

namespace exactgeo::ccd::internal {

namespace {

/// The signed remainder sequence a, b, -rem(a, b), ... (to the last nonzero member).
std::vector<RationalPolynomial> signed_remainders(const RationalPolynomial& a,
                                                  const RationalPolynomial& b) {
  std::vector<RationalPolynomial> s{a};
  if (b.is_zero()) return s;
  s.push_back(b);
  while (s.back().degree() > 0) {
    const RationalPolynomial r = s[s.size() - 2] % s.back();
    if (r.is_zero()) break;
    s.push_back(r * RationalPolynomial({Rational(-1)}));
  }
  return s;
}

/// The Sturm sequence p, p', -rem(p, p'), ... of a squarefree p.
std::vector<RationalPolynomial> sturm_sequence(const RationalPolynomial& p) {
  if (p.degree() < 1) return {p};
  return signed_remainders(p, p.derivative());
}

/// Sign changes of the sequence at t, zeros skipped.
int sign_changes(const std::vector<RationalPolynomial>& sequence, const Rational& t) {
  int changes = 0;
  Sign previous = Sign::zero;
  for (const RationalPolynomial& p : sequence) {
    const Sign s = p.sign_at(t);
    if (s == Sign::zero) continue;
    if (previous != Sign::zero && s != previous) ++changes;
    previous = s;
  }
  return changes;
}

/// Distinct roots in (lo, hi]: Sturm's theorem for a squarefree p. It holds with either
/// end a root: at a simple root the sequence's first member is skipped and the second, p',
/// has the sign p takes just after it, so the count there is the count just after.
int roots_in_half_open(const std::vector<RationalPolynomial>& sequence, const Rational& lo,
                       const Rational& hi) {
  return sign_changes(sequence, lo) - sign_changes(sequence, hi);
}

/// The roots in the open (lo, hi), either end possibly a root, in increasing order.
void isolate(const RationalPolynomial& p, const std::vector<RationalPolynomial>& sequence,
             const Rational& lo, const Rational& hi, std::vector<IsolatedRoot>& out) {
  const bool hi_is_root = p.sign_at(hi) == Sign::zero;
  const int count = roots_in_half_open(sequence, lo, hi) - (hi_is_root ? 1 : 0);
  if (count == 0) return;
  if (count == 1 && !hi_is_root && p.sign_at(lo) != Sign::zero) {
    out.push_back({std::nullopt, lo, hi});
    return;
  }
  // Two roots or more, or an end is a root: halve (the single root then soon lies in a
  // half whose ends are not roots).
  const Rational mid = (lo + hi) / 2;
  isolate(p, sequence, lo, mid, out);
  if (p.sign_at(mid) == Sign::zero) out.push_back({mid, mid, mid});
  isolate(p, sequence, mid, hi, out);
}

}  // namespace

RationalPolynomial::RationalPolynomial(std::vector<Rational> coefficients)
    : c_(std::move(coefficients)) {
  trim();
}

void RationalPolynomial::trim() {
  while (!c_.empty() && c_.back().is_zero())
    c_.pop_back();
}

RationalPolynomial RationalPolynomial::from_homogeneous(const std::vector<Rational>& d) {
  const int n = static_cast<int>(d.size()) - 1;
  const RationalPolynomial one_minus_t({Rational(1), Rational(-1)});
  const RationalPolynomial t({Rational(0), Rational(1)});
  RationalPolynomial sum;
  for (int k = 0; k <= n; ++k) {
    RationalPolynomial term({d[k]});
    for (int i = 0; i < n - k; ++i)
      term = term * one_minus_t;
    for (int i = 0; i < k; ++i)
      term = term * t;
    std::vector<Rational> c = sum.c_;
    c.resize(std::max(c.size(), term.c_.size()));
    for (std::size_t i = 0; i < term.c_.size(); ++i)
      c[i] += term.c_[i];
    sum = RationalPolynomial(std::move(c));
  }
  return sum;
}

Rational RationalPolynomial::operator()(const Rational& t) const {
  Rational value = 0;
  for (auto k = c_.rbegin(); k != c_.rend(); ++k)
    value = value * t + *k;
  return value;
}

Sign RationalPolynomial::sign_at(const Rational& t) const {
  return (*this)(t).sign();
}

RationalPolynomial RationalPolynomial::derivative() const {
  std::vector<Rational> d;
  for (std::size_t k = 1; k < c_.size(); ++k)
    d.push_back(c_[k] * static_cast<long>(k));
  return RationalPolynomial(std::move(d));
}

RationalPolynomial operator*(const RationalPolynomial& a, const RationalPolynomial& b) {
  if (a.is_zero() || b.is_zero()) return {};
  std::vector<Rational> c(a.c_.size() + b.c_.size() - 1);
  for (std::size_t i = 0; i < a.c_.size(); ++i) {
    for (std::size_t j = 0; j < b.c_.size(); ++j)
      c[i + j] += a.c_[i] * b.c_[j];
  }
  return RationalPolynomial(std::move(c));
}

namespace {

/// Quotient and remainder of a by the nonzero b.
std::pair<std::vector<Rational>, std::vector<Rational>> divide(std::vector<Rational> r,
                                                               const std::vector<Rational>& b) {
  assert(!b.empty());
  std::vector<Rational> q(r.size() >= b.size() ? r.size() - b.size() + 1 : 0);
  while (r.size() >= b.size()) {
    const Rational factor = r.back() / b.back();
    const std::size_t shift = r.size() - b.size();
    q[shift] = factor;
    for (std::size_t i = 0; i < b.size(); ++i)
      r[shift + i] -= factor * b[i];
    r.pop_back();  // exactly zero now
    while (!r.empty() && r.back().is_zero())
      r.pop_back();
  }
  return {std::move(q), std::move(r)};
}

}  // namespace

RationalPolynomial operator%(const RationalPolynomial& a, const RationalPolynomial& b) {
  return RationalPolynomial(divide(a.c_, b.c_).second);
}

RationalPolynomial operator/(const RationalPolynomial& a, const RationalPolynomial& b) {
  return RationalPolynomial(divide(a.c_, b.c_).first);
}

RationalPolynomial gcd(RationalPolynomial a, RationalPolynomial b) {
  while (!b.is_zero()) {
    RationalPolynomial r = a % b;
    a = std::move(b);
    b = std::move(r);
  }
  if (a.is_zero()) return a;
  std::vector<Rational> c = a.coefficients();
  const Rational lead = c.back();
  for (Rational& x : c)
    x /= lead;
  return RationalPolynomial(std::move(c));
}

RationalPolynomial squarefree_part(const RationalPolynomial& p) {
  assert(!p.is_zero());
  if (p.degree() < 1) return p;
  return p / gcd(p, p.derivative());
}

std::vector<IsolatedRoot> roots_between(const RationalPolynomial& p, const Rational& lo,
                                        const Rational& hi) {
  std::vector<IsolatedRoot> out;
  if (p.degree() >= 1) isolate(p, sturm_sequence(p), lo, hi, out);
  return out;
}

void halve_isolating_interval(const RationalPolynomial& p, IsolatedRoot& root) {
  const Rational mid = (root.lo + root.hi) / 2;
  const Sign at_mid = p.sign_at(mid);
  if (at_mid == Sign::zero) {
    root = {mid, mid, mid};
  } else if (at_mid == p.sign_at(root.lo)) {
    root.lo = mid;
  } else {
    root.hi = mid;
  }
}

TarskiQueries::TarskiQueries(const RationalPolynomial& p, const std::vector<RationalPolynomial>& qs)
    : sturm_(sturm_sequence(p)) {
  for (const RationalPolynomial& q : qs)
    sequences_.push_back(signed_remainders(p, p.derivative() * q));
}

int TarskiQueries::count(const Rational& lo, const Rational& hi) const {
  return sign_changes(sturm_, lo) - sign_changes(sturm_, hi);
}

int TarskiQueries::query(std::size_t i, const Rational& lo, const Rational& hi) const {
  return sign_changes(sequences_[i], lo) - sign_changes(sequences_[i], hi);
}

Sign sign_at_root(const RationalPolynomial& q, const RationalPolynomial& p, IsolatedRoot root) {
  if (root.exact) return q.sign_at(*root.exact);
  if (q.is_zero()) return Sign::zero;
  // The Tarski query: over the roots r of p in (lo, hi), the sign changes of the signed
  // remainder sequence of p and p' q fall by (number with q(r) > 0) - (number with
  // q(r) < 0). With r alone in the interval that is q's sign at r, however close q's own
  // roots come, and without refining.
  const std::vector<RationalPolynomial> sequence = signed_remainders(p, p.derivative() * q);
  const int query = sign_changes(sequence, root.lo) - sign_changes(sequence, root.hi);
  return query > 0 ? Sign::positive : query < 0 ? Sign::negative : Sign::zero;
}

}  // namespace exactgeo::ccd::internal
