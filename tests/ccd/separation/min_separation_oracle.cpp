#include "ccd/separation/min_separation_oracle.hpp"

#include <gmpxx.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <utility>
#include <vector>

namespace exactgeo::testing {
namespace {

using Rational = mpq_class;

// ---------------------------------------------------------------------------------------
// Polynomials in t with rational coefficients.

/// Coefficients lowest degree first, without trailing zeros: the zero polynomial has none.
class Polynomial {
 public:
  Polynomial() = default;
  explicit Polynomial(std::vector<Rational> coefficients) : c_(std::move(coefficients)) { trim(); }
  static Polynomial constant(const Rational& a) { return Polynomial({a}); }
  /// a + b t.
  static Polynomial linear(const Rational& a, const Rational& b) { return Polynomial({a, b}); }

  bool is_zero() const { return c_.empty(); }
  /// -1 for the zero polynomial.
  int degree() const { return static_cast<int>(c_.size()) - 1; }
  std::size_t size() const { return c_.size(); }
  const Rational& operator[](std::size_t i) const { return c_[i]; }
  const Rational& leading() const { return c_.back(); }
  const std::vector<Rational>& coefficients() const { return c_; }

 private:
  void trim() {
    while (!c_.empty() && c_.back() == 0)
      c_.pop_back();
  }
  std::vector<Rational> c_;
};

Polynomial operator+(const Polynomial& a, const Polynomial& b) {
  std::vector<Rational> c(std::max(a.size(), b.size()), Rational(0));
  for (std::size_t i = 0; i < a.size(); ++i)
    c[i] += a[i];
  for (std::size_t i = 0; i < b.size(); ++i)
    c[i] += b[i];
  return Polynomial(std::move(c));
}

Polynomial operator*(const Rational& k, const Polynomial& a) {
  std::vector<Rational> c(a.coefficients());
  for (Rational& x : c)
    x *= k;
  return Polynomial(std::move(c));
}

Polynomial operator-(const Polynomial& a, const Polynomial& b) {
  return a + Rational(-1) * b;
}

Polynomial operator*(const Polynomial& a, const Polynomial& b) {
  if (a.is_zero() || b.is_zero()) return {};
  std::vector<Rational> c(a.size() + b.size() - 1, Rational(0));
  for (std::size_t i = 0; i < a.size(); ++i) {
    for (std::size_t j = 0; j < b.size(); ++j)
      c[i + j] += a[i] * b[j];
  }
  return Polynomial(std::move(c));
}

/// Horner evaluation, exact.
Rational evaluate(const Polynomial& p, const Rational& t) {
  Rational value = 0;
  for (std::size_t i = p.size(); i-- > 0;)
    value = value * t + p[i];
  return value;
}

int sign_of(const Rational& x) {
  return sgn(x);
}

Polynomial derivative(const Polynomial& p) {
  std::vector<Rational> c;
  for (std::size_t i = 1; i < p.size(); ++i)
    c.push_back(p[i] * Rational(static_cast<long>(i)));
  return Polynomial(std::move(c));
}

/// Euclidean division a = quotient * b + remainder, deg remainder < deg b (b nonzero).
std::pair<Polynomial, Polynomial> divide(const Polynomial& a, const Polynomial& b) {
  if (b.is_zero()) throw std::logic_error("min separation oracle: division by zero polynomial");
  std::vector<Rational> r(a.coefficients());
  std::vector<Rational> q(a.size() >= b.size() ? a.size() - b.size() + 1 : 0, Rational(0));
  while (r.size() >= b.size() && !r.empty()) {
    const Rational factor = r.back() / b.leading();
    const std::size_t shift = r.size() - b.size();
    q[shift] = factor;
    for (std::size_t i = 0; i < b.size(); ++i)
      r[shift + i] -= factor * b[i];
    r.pop_back();  // the leading term cancels exactly
    while (!r.empty() && r.back() == 0)
      r.pop_back();
  }
  return {Polynomial(std::move(q)), Polynomial(std::move(r))};
}

Polynomial quotient(const Polynomial& a, const Polynomial& b) {
  return divide(a, b).first;
}
Polynomial remainder(const Polynomial& a, const Polynomial& b) {
  return divide(a, b).second;
}

/// p divided by a positive constant so that its leading coefficient is +-1 (signs kept).
Polynomial normalized(const Polynomial& p) {
  if (p.is_zero()) return p;
  return Rational(1 / abs(p.leading())) * p;
}

/// The monic greatest common divisor (zero when both are zero).
Polynomial gcd(Polynomial a, Polynomial b) {
  while (!b.is_zero()) {
    Polynomial r = remainder(a, b);
    a = std::move(b);
    b = normalized(r);
  }
  if (a.is_zero()) return a;
  return Rational(1 / a.leading()) * a;
}

/// p / gcd(p, p'): the same roots, each simple (p nonzero).
Polynomial squarefree_part(const Polynomial& p) {
  if (p.degree() < 1) return p;
  return normalized(quotient(p, gcd(p, derivative(p))));
}

// ---------------------------------------------------------------------------------------
// Sturm sequences: for p nonzero, p_0 = p, p_1 = p', p_{k+1} = -rem(p_{k-1}, p_k) (each
// scaled by a positive constant, which changes no sign). If a < b are not roots of p, the
// number of distinct roots of p in (a, b) is V(a) - V(b), V(x) being the number of sign
// changes in p_0(x), p_1(x), ... with zeros skipped.

std::vector<Polynomial> sturm_sequence(const Polynomial& p) {
  std::vector<Polynomial> sequence{normalized(p)};
  Polynomial next = normalized(derivative(p));
  while (!next.is_zero()) {
    sequence.push_back(next);
    const std::size_t k = sequence.size();
    next = normalized(Rational(-1) * remainder(sequence[k - 2], sequence[k - 1]));
  }
  return sequence;
}

int sign_changes(const std::vector<Polynomial>& sequence, const Rational& x) {
  int changes = 0, previous = 0;
  for (const Polynomial& p : sequence) {
    const int s = sign_of(evaluate(p, x));
    if (s == 0) continue;
    if (previous != 0 && s != previous) ++changes;
    previous = s;
  }
  return changes;
}

/// Distinct roots of sequence[0] in the open interval (a, b); a < b must not be roots.
int count_roots_open(const std::vector<Polynomial>& sequence, const Rational& a,
                     const Rational& b) {
  return sign_changes(sequence, a) - sign_changes(sequence, b);
}

// ---------------------------------------------------------------------------------------
// Real numbers of [0, 1] that are roots: a rational, or the only root of a squarefree
// polynomial p in an open interval (lo, hi) whose ends are not roots of p (so p changes
// sign between them).

struct RealRoot {
  bool exact = true;
  Rational value;  // when exact
  Polynomial p;    // when not exact
  Rational lo, hi;

  static RealRoot rational(const Rational& x) { return {true, x, {}, x, x}; }
  static RealRoot isolated(const Polynomial& p, const Rational& lo, const Rational& hi) {
    return {false, 0, p, lo, hi};
  }
  /// Bounds of the closed hull: the number is in [lower(), upper()].
  const Rational& lower() const { return exact ? value : lo; }
  const Rational& upper() const { return exact ? value : hi; }
};

/// Halves the isolating interval (or finds the root exactly at the midpoint).
void refine(RealRoot& x) {
  if (x.exact) return;
  const Rational mid = (x.lo + x.hi) / 2;
  const int s = sign_of(evaluate(x.p, mid));
  if (s == 0) {
    x = RealRoot::rational(mid);
  } else if (s == sign_of(evaluate(x.p, x.lo))) {
    x.lo = mid;
  } else {
    x.hi = mid;
  }
}

/// The roots of the squarefree p in (a, b), with p(a), p(b) nonzero, by bisection: a
/// root found at a midpoint m is recorded exactly and divided out (p / (t - m) has the
/// other roots, and m is not one of them).
void isolate(const Polynomial& p, const std::vector<Polynomial>& sturm, const Rational& a,
             const Rational& b, std::vector<RealRoot>& out) {
  if (p.degree() < 1) return;
  if (p.degree() == 1) {
    const Rational root = -p[0] / p[1];
    if (a < root && root < b) out.push_back(RealRoot::rational(root));
    return;
  }
  const int count = count_roots_open(sturm, a, b);
  if (count == 0) return;
  if (count == 1) {
    out.push_back(RealRoot::isolated(p, a, b));
    return;
  }
  const Rational mid = (a + b) / 2;
  if (evaluate(p, mid) == 0) {
    out.push_back(RealRoot::rational(mid));
    const Polynomial rest = quotient(p, Polynomial::linear(-mid, 1));
    const std::vector<Polynomial> rest_sturm = sturm_sequence(rest);
    isolate(rest, rest_sturm, a, mid, out);
    isolate(rest, rest_sturm, mid, b, out);
  } else {
    isolate(p, sturm, a, mid, out);
    isolate(p, sturm, mid, b, out);
  }
}

/// All distinct roots of the nonzero p in the closed interval [0, 1].
std::vector<RealRoot> roots_in_unit_interval(const Polynomial& p) {
  std::vector<RealRoot> roots;
  Polynomial q = squarefree_part(p);
  if (q.degree() < 1) return roots;
  if (evaluate(q, 0) == 0) {
    roots.push_back(RealRoot::rational(0));
    q = quotient(q, Polynomial::linear(0, 1));
  }
  if (evaluate(q, 1) == 0) {
    roots.push_back(RealRoot::rational(1));
    q = quotient(q, Polynomial::linear(-1, 1));
  }
  if (q.degree() >= 1) isolate(q, sturm_sequence(q), 0, 1, roots);
  return roots;
}

/// Whether x and y are the same number. Two isolated roots are equal iff their
/// polynomials have a common root in the intersection of their intervals (the ends of
/// that intersection are ends of one of the intervals, so not roots of the gcd).
bool same_number(const RealRoot& x, const RealRoot& y) {
  if (x.exact && y.exact) return x.value == y.value;
  if (x.exact) return y.lo < x.value && x.value < y.hi && evaluate(y.p, x.value) == 0;
  if (y.exact) return same_number(y, x);
  const Rational lo = std::max(x.lo, y.lo), hi = std::min(x.hi, y.hi);
  if (lo >= hi) return false;
  const Polynomial g = gcd(x.p, y.p);
  return g.degree() >= 1 && count_roots_open(sturm_sequence(g), lo, hi) > 0;
}

bool hulls_meet(const RealRoot& x, const RealRoot& y) {
  return x.lower() <= y.upper() && y.lower() <= x.upper();
}

/// Removes duplicates and refines until the closed hulls are pairwise disjoint, then sorts.
/// (Distinct numbers: refining shrinks each interval around its own number, so the loop
/// ends.)
std::vector<RealRoot> distinct_sorted(std::vector<RealRoot> roots) {
  bool changed = true;
  while (changed) {
    changed = false;
    for (std::size_t i = 0; i < roots.size(); ++i) {
      for (std::size_t j = i + 1; j < roots.size(); ++j) {
        if (!hulls_meet(roots[i], roots[j])) continue;
        changed = true;
        if (same_number(roots[i], roots[j])) {
          if (roots[j].exact) roots[i] = roots[j];  // keep the exact representation
          roots.erase(roots.begin() + static_cast<std::ptrdiff_t>(j));
          --j;
        } else {
          refine(roots[i]);
          refine(roots[j]);
        }
      }
    }
  }
  std::sort(roots.begin(), roots.end(),
            [](const RealRoot& x, const RealRoot& y) { return x.lower() < y.lower(); });
  return roots;
}

/// The rational with the smallest denominator in [lo, hi] (0 <= lo <= hi), by continued
/// fractions.
Rational simplest_rational(const Rational& lo, const Rational& hi) {
  mpz_class whole;
  mpz_fdiv_q(whole.get_mpz_t(), lo.get_num_mpz_t(), lo.get_den_mpz_t());
  const Rational floor_lo(whole);
  if (floor_lo == lo) return lo;
  if (floor_lo + 1 <= hi) return floor_lo + 1;
  // lo, hi in (floor_lo, floor_lo + 1): recurse on the reciprocals of the fractional parts.
  return floor_lo + 1 / simplest_rational(1 / (hi - floor_lo), 1 / (lo - floor_lo));
}

// ---------------------------------------------------------------------------------------
// Sign conditions and their exact evaluation at a real root.

/// A condition polynomial with the Sturm sequence of its squarefree part precomputed.
struct PreparedPolynomial {
  Polynomial p;
  std::vector<Polynomial> sturm;  // empty for a constant (or zero) p
};

PreparedPolynomial prepare(Polynomial p) {
  PreparedPolynomial prepared{std::move(p), {}};
  if (prepared.p.degree() >= 1) prepared.sturm = sturm_sequence(squarefree_part(prepared.p));
  return prepared;
}

/// Whether q has no root in the closed interval [lo, hi].
bool no_root_in_closed(const PreparedPolynomial& q, const Rational& lo, const Rational& hi) {
  if (evaluate(q.p, lo) == 0 || evaluate(q.p, hi) == 0) return false;
  return q.sturm.empty() || count_roots_open(q.sturm, lo, hi) == 0;
}

/// The sign of q at x: an evaluation when x is rational; otherwise 0 iff gcd(p, q) has a
/// root in x's interval, else the sign of q at an end of an interval around x free of
/// roots of q (found by bisection).
int sign_at(const PreparedPolynomial& q, RealRoot x) {
  if (q.p.is_zero()) return 0;
  if (x.exact) return sign_of(evaluate(q.p, x.value));
  if (no_root_in_closed(q, x.lo, x.hi)) return sign_of(evaluate(q.p, x.lo));
  const Polynomial g = gcd(x.p, q.p);
  if (g.degree() >= 1 && count_roots_open(sturm_sequence(g), x.lo, x.hi) > 0) return 0;
  while (!x.exact && !no_root_in_closed(q, x.lo, x.hi))
    refine(x);
  return sign_of(evaluate(q.p, x.lower()));
}

enum class Relation { nonnegative, positive, nonpositive };

struct Condition {
  PreparedPolynomial polynomial;
  Relation relation;
};

/// A conjunction of sign conditions.
using Feature = std::vector<Condition>;

bool holds(const Condition& c, const RealRoot& x) {
  const int s = sign_at(c.polynomial, x);
  switch (c.relation) {
    case Relation::nonnegative:
      return s >= 0;
    case Relation::positive:
      return s > 0;
    case Relation::nonpositive:
      return s <= 0;
  }
  return false;
}

bool holds(const Feature& feature, const RealRoot& x) {
  return std::all_of(feature.begin(), feature.end(),
                     [&](const Condition& c) { return holds(c, x); });
}

// ---------------------------------------------------------------------------------------
// The decision over t in [0, 1] (see the header): samples at 0, 1, every root of every
// condition polynomial, and one point inside each open cell between them, in increasing
// order; the first sample where some feature holds is the earliest time.

MinSeparationAnswer earliest(const std::vector<Feature>& features) {
  std::vector<RealRoot> roots{RealRoot::rational(0), RealRoot::rational(1)};
  for (const Feature& feature : features) {
    for (const Condition& c : feature) {
      if (c.polynomial.p.degree() < 1) continue;
      for (RealRoot& r : roots_in_unit_interval(c.polynomial.p))
        roots.push_back(std::move(r));
    }
  }
  const std::vector<RealRoot> points = distinct_sorted(std::move(roots));

  struct Sample {
    RealRoot point;
    bool inside_cell;  // a point strictly between two consecutive roots
  };
  std::vector<Sample> samples;
  for (std::size_t i = 0; i < points.size(); ++i) {
    samples.push_back({points[i], false});
    if (i + 1 < points.size()) {
      const Rational mid = (points[i].upper() + points[i + 1].lower()) / 2;
      samples.push_back({RealRoot::rational(mid), true});
    }
  }

  for (const Sample& sample : samples) {
    const bool any = std::any_of(features.begin(), features.end(),
                                 [&](const Feature& f) { return holds(f, sample.point); });
    if (!any) continue;
    if (sample.inside_cell) {
      throw std::logic_error("min separation oracle: first satisfying sample inside a cell");
    }
    RealRoot x = sample.point;
    const Rational width_bound = Rational(1) / Rational(mpz_class(1) << 80);
    while (!x.exact && x.hi - x.lo > width_bound)
      refine(x);
    if (!x.exact) {
      const Rational candidate = simplest_rational(x.lo, x.hi);
      if (evaluate(x.p, candidate) == 0) x = RealRoot::rational(candidate);
    }
    return {true, x.lower(), x.upper()};
  }
  return {false, 0, 0};
}

// ---------------------------------------------------------------------------------------
// Moving points as vectors of affine polynomials, and the features.

using PolyVec = std::array<Polynomial, 3>;

Rational exact(double x) {
  if (!std::isfinite(x)) throw std::invalid_argument("min separation oracle: non-finite input");
  return Rational(x);
}

/// x(t) = x_t0 + t (x_t1 - x_t0).
PolyVec trajectory(const Point3& at_t0, const Point3& at_t1) {
  PolyVec x;
  for (std::size_t i = 0; i < 3; ++i) {
    const Rational a = exact(at_t0[i]), b = exact(at_t1[i]);
    x[i] = Polynomial::linear(a, b - a);
  }
  return x;
}

PolyVec operator-(const PolyVec& a, const PolyVec& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}

Polynomial dot(const PolyVec& a, const PolyVec& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

PolyVec cross(const PolyVec& a, const PolyVec& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

Condition condition(Polynomial p, Relation relation) {
  return {prepare(std::move(p)), relation};
}

/// |p - q|^2 - delta^2 <= 0.
Feature point_point(const PolyVec& p, const PolyVec& q, const Rational& delta2) {
  const PolyVec d = p - q;
  return {condition(dot(d, d) - Polynomial::constant(delta2), Relation::nonpositive)};
}

/// p projects into the segment [a, b] of positive length, within delta of its line.
Feature point_edge(const PolyVec& p, const PolyVec& a, const PolyVec& b, const Rational& delta2) {
  const PolyVec e = b - a, w = p - a;
  const Polynomial we = dot(w, e), ee = dot(e, e);
  return {condition(we, Relation::nonnegative), condition(ee - we, Relation::nonnegative),
          condition(ee, Relation::positive),
          condition(dot(w, w) * ee - we * we - delta2 * ee, Relation::nonpositive)};
}

/// v projects into the triangle (f0, f1, f2) of positive area, within delta of its plane.
Feature point_face(const PolyVec& v, const PolyVec& f0, const PolyVec& f1, const PolyVec& f2,
                   const Rational& delta2) {
  const PolyVec n = cross(f1 - f0, f2 - f0);
  const Polynomial nn = dot(n, n), height = dot(n, v - f0);
  return {condition(nn, Relation::positive),
          condition(dot(n, cross(f1 - f0, v - f0)), Relation::nonnegative),
          condition(dot(n, cross(f2 - f1, v - f1)), Relation::nonnegative),
          condition(dot(n, cross(f0 - f2, v - f2)), Relation::nonnegative),
          condition(height * height - delta2 * nn, Relation::nonpositive)};
}

/// The common perpendicular of the non-parallel segments [a0, a1], [b0, b1] has its feet
/// inside both, and length <= delta.
Feature interior_interior(const PolyVec& a0, const PolyVec& a1, const PolyVec& b0,
                          const PolyVec& b1, const Rational& delta2) {
  const PolyVec da = a1 - a0, db = b1 - b0, r = b0 - a0;
  const PolyVec w = cross(da, db);
  const Polynomial ww = dot(w, w), s = dot(cross(r, db), w), u = dot(cross(r, da), w);
  const Polynomial wr = dot(w, r);
  return {condition(ww, Relation::positive),
          condition(s, Relation::nonnegative),
          condition(ww - s, Relation::nonnegative),
          condition(u, Relation::nonnegative),
          condition(ww - u, Relation::nonnegative),
          condition(wr * wr - delta2 * ww, Relation::nonpositive)};
}

Rational squared_delta(double delta) {
  if (!std::isfinite(delta) || delta < 0) {
    throw std::invalid_argument("min separation oracle: delta must be finite and >= 0");
  }
  const Rational d(delta);
  return d * d;
}

}  // namespace

MinSeparationAnswer min_separation_oracle(const ccd::VertexFaceQuery& q, double delta) {
  const Rational delta2 = squared_delta(delta);
  const PolyVec v = trajectory(q.v_t0, q.v_t1), f0 = trajectory(q.f0_t0, q.f0_t1),
                f1 = trajectory(q.f1_t0, q.f1_t1), f2 = trajectory(q.f2_t0, q.f2_t1);
  const std::vector<Feature> features{
      point_point(v, f0, delta2),        point_point(v, f1, delta2),
      point_point(v, f2, delta2),        point_edge(v, f0, f1, delta2),
      point_edge(v, f1, f2, delta2),     point_edge(v, f2, f0, delta2),
      point_face(v, f0, f1, f2, delta2),
  };
  return earliest(features);
}

MinSeparationAnswer min_separation_oracle(const ccd::EdgeEdgeQuery& q, double delta) {
  const Rational delta2 = squared_delta(delta);
  const PolyVec a0 = trajectory(q.ea0_t0, q.ea0_t1), a1 = trajectory(q.ea1_t0, q.ea1_t1),
                b0 = trajectory(q.eb0_t0, q.eb0_t1), b1 = trajectory(q.eb1_t0, q.eb1_t1);
  const std::vector<Feature> features{
      point_point(a0, b0, delta2),
      point_point(a0, b1, delta2),
      point_point(a1, b0, delta2),
      point_point(a1, b1, delta2),
      point_edge(a0, b0, b1, delta2),
      point_edge(a1, b0, b1, delta2),
      point_edge(b0, a0, a1, delta2),
      point_edge(b1, a0, a1, delta2),
      interior_interior(a0, a1, b0, b1, delta2),
  };
  return earliest(features);
}

}  // namespace exactgeo::testing
