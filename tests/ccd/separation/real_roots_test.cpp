// Exact real roots (separation/internal/real_roots.hpp): the polynomial arithmetic against
// hand-computed polynomials and the division identity; roots of polynomials built from
// known rational and irrational roots (a + b sqrt 2), clustered ones 2^-200
// apart, roots at the ends and at the midpoints of the intervals: every root isolated once,
// in order, with valid isolating intervals, halving keeps it; the Tarski queries and the
// sign at a root against signs computed at the known roots (a + b sqrt 2 decided exactly).

#include "exactgeo/ccd/separation/internal/real_roots.hpp"

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <optional>
#include <string>
#include <vector>

#include "support/generators.hpp"
#include "support/seed.hpp"

namespace exactgeo::ccd::internal {
namespace {

using testing::Rng;
using Poly = RationalPolynomial;

/// num / den in lowest terms (GMP works on canonical fractions only).
mpq_class fraction(long num, long den = 1) {
  mpq_class r(num, den);
  r.canonicalize();
  return r;
}

Rational q(long num, long den = 1) {
  return Rational(fraction(num, den));
}

/// 2^k as a rational.
Rational two_to(int k) {
  return Rational(std::ldexp(1.0, k));
}

Poly poly(std::vector<Rational> c) {
  return Poly(std::move(c));
}

/// t - r.
Poly linear(const Rational& r) {
  return poly({-r, q(1)});
}

std::string show(const Poly& p) {
  std::string s;
  for (int k = 0; k <= p.degree(); ++k)
    s += (k ? " + " : "") + p.coefficients()[k].value().get_str() + " t^" + std::to_string(k);
  return p.is_zero() ? "0" : s;
}

::testing::AssertionResult same(const Poly& a, const Poly& b) {
  if (a.coefficients() == b.coefficients()) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << show(a) << " is not " << show(b);
}

TEST(RealRoots, ConstructionTrimsAndEvaluates) {
  const Poly zero = poly({q(0), q(0)});
  EXPECT_TRUE(zero.is_zero());
  EXPECT_EQ(zero.degree(), -1);
  EXPECT_EQ(Poly().degree(), -1);
  EXPECT_EQ(zero(q(7)), q(0));
  EXPECT_EQ(zero.sign_at(q(7)), Sign::zero);
  const Poly p = poly({q(1), q(-3), q(2), q(0), q(0)});  // 1 - 3t + 2t^2 = (1 - t)(1 - 2t)
  EXPECT_EQ(p.degree(), 2);
  EXPECT_EQ(p(q(2)), q(3));
  EXPECT_EQ(p(q(1, 2)), q(0));
  EXPECT_EQ(p(q(3, 4)), q(-1, 8));
  EXPECT_EQ(p.sign_at(q(3, 4)), Sign::negative);
  EXPECT_EQ(p.sign_at(q(1)), Sign::zero);
  EXPECT_EQ(p.sign_at(q(-1, 3)), Sign::positive);
}

TEST(RealRoots, ProductDerivativeAndHomogeneousForm) {
  EXPECT_TRUE(same(poly({q(1), q(1)}) * poly({q(1), q(-1)}), poly({q(1), q(0), q(-1)})));
  // (t - 1/2)(t^2 + 2) = t^3 - t^2/2 + 2t - 1
  EXPECT_TRUE(
      same(linear(q(1, 2)) * poly({q(2), q(0), q(1)}), poly({q(-1), q(2), q(-1, 2), q(1)})));
  EXPECT_TRUE((poly({q(3)}) * Poly()).is_zero());
  EXPECT_TRUE(same(poly({q(1), q(2), q(3), q(4)}).derivative(), poly({q(2), q(6), q(12)})));
  EXPECT_TRUE(poly({q(5)}).derivative().is_zero());
  EXPECT_TRUE(Poly().derivative().is_zero());
  // sum_k d_k (1 - t)^(n - k) t^k
  EXPECT_TRUE(same(Poly::from_homogeneous({q(1), q(0), q(0)}), poly({q(1), q(-2), q(1)})));
  EXPECT_TRUE(same(Poly::from_homogeneous({q(0), q(1), q(0)}), poly({q(0), q(1), q(-1)})));
  EXPECT_TRUE(same(Poly::from_homogeneous({q(2), q(3), q(5)}), poly({q(2), q(-1), q(4)})));
  EXPECT_TRUE(same(Poly::from_homogeneous({q(7)}), poly({q(7)})));
  EXPECT_TRUE(Poly::from_homogeneous({q(0), q(0), q(0), q(0)}).is_zero());
  // (1 - t)^3 + t^3 = 1 - 3t + 3t^2
  EXPECT_TRUE(same(Poly::from_homogeneous({q(1), q(0), q(0), q(1)}), poly({q(1), q(-3), q(3)})));
}

TEST(RealRoots, DivisionByHand) {
  // t^3 - 2t + 5 = (t - 1)(t^2 + t - 1) + 4
  const Poly a = poly({q(5), q(-2), q(0), q(1)});
  EXPECT_TRUE(same(a / linear(q(1)), poly({q(-1), q(1), q(1)})));
  EXPECT_TRUE(same(a % linear(q(1)), poly({q(4)})));
  // By a constant: exact quotient, zero remainder.
  EXPECT_TRUE(same(poly({q(6), q(0), q(3)}) / poly({q(3)}), poly({q(2), q(0), q(1)})));
  EXPECT_TRUE((poly({q(6), q(0), q(3)}) % poly({q(3)})).is_zero());
  // By a polynomial of higher degree: quotient 0, remainder the dividend.
  EXPECT_TRUE((poly({q(1), q(1)}) / poly({q(1), q(0), q(1)})).is_zero());
  EXPECT_TRUE(same(poly({q(1), q(1)}) % poly({q(1), q(0), q(1)}), poly({q(1), q(1)})));
  // 2t^4 + 3t^3 - t + 7 by 2t^2 - 1: quotient t^2 + 3t/2 + 1/2, remainder t/2 + 15/2.
  const Poly b = poly({q(7), q(-1), q(0), q(3), q(2)});
  const Poly d = poly({q(-1), q(0), q(2)});
  EXPECT_TRUE(same(b / d, poly({q(1, 2), q(3, 2), q(1)})));
  EXPECT_TRUE(same(b % d, poly({q(15, 2), q(1, 2)})));
}

Poly random_poly(Rng& rng, int degree) {
  std::vector<Rational> c;
  for (int k = 0; k <= degree; ++k)
    c.push_back(q(testing::uniform_int(rng, -9, 9), testing::uniform_int(rng, 1, 6)));
  if (c.back().is_zero()) c.back() = q(1);
  return poly(c);
}

TEST(RealRoots, DivisionIdentityOnRandomPolynomials) {
  Rng rng = testing::seeded_engine("real-roots-division");
  for (int i = 0; i < 300; ++i) {
    const Poly a = random_poly(rng, testing::uniform_int(rng, 0, 7));
    const Poly b = random_poly(rng, testing::uniform_int(rng, 0, 4));
    const Poly quotient = a / b, remainder = a % b;
    std::vector<Rational> sum = (quotient * b).coefficients();
    sum.resize(std::max<std::size_t>(sum.size(), remainder.coefficients().size()), q(0));
    for (std::size_t k = 0; k < remainder.coefficients().size(); ++k)
      sum[k] += remainder.coefficients()[k];
    ASSERT_TRUE(same(poly(sum), a)) << show(a) << " by " << show(b);
    ASSERT_LT(remainder.degree(), b.degree()) << show(a) << " by " << show(b);
  }
}

TEST(RealRoots, GcdAndSquarefreePart) {
  const Poly p = linear(q(1)) * linear(q(2)) * linear(q(-3));
  const Poly r = linear(q(2)) * linear(q(-3)) * linear(q(5)) * poly({q(7)});
  EXPECT_TRUE(same(gcd(p, r), poly({q(-6), q(1), q(1)})));  // (t - 2)(t + 3), monic
  EXPECT_TRUE(same(gcd(r, p), poly({q(-6), q(1), q(1)})));
  EXPECT_TRUE(same(gcd(p, linear(q(4))), poly({q(1)})));  // coprime
  EXPECT_TRUE(same(gcd(poly({q(2), q(4)}), Poly()), poly({q(1, 2), q(1)})));
  EXPECT_TRUE(gcd(Poly(), Poly()).is_zero());
  // (t - 1)^2 (t + 2)^3 (t - 1/3) 5 -> a multiple of (t - 1)(t + 2)(t - 1/3).
  const Poly repeated = linear(q(1)) * linear(q(1)) * linear(q(-2)) * linear(q(-2)) *
                        linear(q(-2)) * linear(q(1, 3)) * poly({q(5)});
  const Poly simple = linear(q(1)) * linear(q(-2)) * linear(q(1, 3));
  const Poly sf = squarefree_part(repeated);
  ASSERT_EQ(sf.degree(), 3);
  const Rational scale = sf.coefficients().back();
  EXPECT_TRUE(same(sf, simple * poly({scale})));
  EXPECT_TRUE(same(squarefree_part(simple), simple));
  EXPECT_TRUE(same(squarefree_part(poly({q(-4)})), poly({q(-4)})));
  // (t^2 - 2)^2: sqrt 2 and -sqrt 2, each once.
  const Poly two = poly({q(-2), q(0), q(1)});
  const Poly sf2 = squarefree_part(two * two);
  EXPECT_TRUE(same(sf2, two * poly({sf2.coefficients().back()})));
}

// ---------------------------------------------------------------------------------------
// Roots known exactly: rationals, and a + b sqrt 2 (the roots of t^2 - 2 and its shifts).

/// a + b sqrt 2.
struct Known {
  mpq_class a;
  mpq_class b;
};

/// The sign of a + b sqrt 2, exactly.
int sign_of(const Known& x) {
  const int sa = sgn(x.a), sb = sgn(x.b);
  if (sb == 0) return sa;
  if (sa == 0 || sa == sb) return sb;
  // Opposite signs: compare a^2 with 2 b^2.
  const int c = cmp(x.a * x.a, 2 * x.b * x.b);
  return c == 0 ? 0 : (c > 0 ? sa : sb);
}

/// x < y.
bool less(const Known& x, const Known& y) {
  return sign_of({y.a - x.a, y.b - x.b}) > 0;
}

/// The sign of p at a + b sqrt 2 (Horner in Q(sqrt 2)).
int sign_at(const Poly& p, const Known& x) {
  Known value{0, 0};
  for (int k = p.degree(); k >= 0; --k) {
    value = {value.a * x.a + 2 * value.b * x.b + p.coefficients()[k].value(),
             value.a * x.b + value.b * x.a};
  }
  return sign_of(value);
}

/// The monic polynomial with these roots (each a rational, or a pair a +- b sqrt 2 given
/// as its + member, which brings its conjugate).
Poly with_roots(const std::vector<Known>& roots, std::vector<Known>& all) {
  Poly p = poly({q(1)});
  for (const Known& r : roots) {
    if (sgn(r.b) == 0) {
      p = p * linear(Rational(r.a));
      all.push_back(r);
    } else {
      // (t - a)^2 - 2 b^2
      p = p * poly({Rational(mpq_class(r.a * r.a - 2 * r.b * r.b)), Rational(mpq_class(-2 * r.a)),
                    q(1)});
      all.push_back(r);
      all.push_back({r.a, -r.b});
    }
  }
  std::sort(all.begin(), all.end(), less);
  return p;
}

/// roots_between(p, lo, hi) finds exactly the known roots strictly inside, in order, each
/// in a valid isolating interval (or exact), and halving keeps it.
void expect_roots(const std::vector<Known>& given, const Rational& lo, const Rational& hi,
                  const std::string& what) {
  std::vector<Known> all;
  const Poly p = with_roots(given, all);
  const Known klo{lo.value(), 0}, khi{hi.value(), 0};
  std::vector<Known> inside;
  for (const Known& r : all) {
    if (less(klo, r) && less(r, khi)) inside.push_back(r);
  }
  const std::vector<IsolatedRoot> found = roots_between(p, lo, hi);
  ASSERT_EQ(found.size(), inside.size()) << what;
  std::optional<Rational> previous_hi;
  for (std::size_t i = 0; i < found.size(); ++i) {
    IsolatedRoot root = found[i];
    const Known& r = inside[i];
    if (root.exact) {
      EXPECT_EQ(sgn(r.b), 0) << what << ": an irrational root reported exact";
      EXPECT_EQ(root.exact->value(), r.a) << what;
      EXPECT_EQ(root.lo, *root.exact);
      EXPECT_EQ(root.hi, *root.exact);
    } else {
      EXPECT_LT(root.lo, root.hi) << what;
      EXPECT_NE(p.sign_at(root.lo), Sign::zero) << what;
      EXPECT_NE(p.sign_at(root.hi), Sign::zero) << what;
      EXPECT_TRUE(less({root.lo.value(), 0}, r) && less(r, {root.hi.value(), 0}))
          << what << ": root " << i << " outside its interval";
      for (std::size_t j = 0; j < inside.size(); ++j) {
        if (j != i) {
          EXPECT_FALSE(less({root.lo.value(), 0}, inside[j]) &&
                       less(inside[j], {root.hi.value(), 0}))
              << what << ": two roots in one interval";
        }
      }
    }
    EXPECT_TRUE(root.lo >= lo && root.hi <= hi) << what;
    if (previous_hi) {
      EXPECT_LE(*previous_hi, root.lo) << what << ": out of order";
    }
    previous_hi = root.hi;
    // Halving keeps the root until a midpoint is the root itself.
    for (int h = 0; h < 80 && !root.exact; ++h) {
      const Rational width = root.hi - root.lo;
      halve_isolating_interval(p, root);
      if (root.exact) {
        EXPECT_EQ(sgn(r.b), 0) << what;
        EXPECT_EQ(root.exact->value(), r.a) << what;
        break;
      }
      ASSERT_EQ(root.hi - root.lo, width / Rational(2)) << what;
      ASSERT_TRUE(less({root.lo.value(), 0}, r) && less(r, {root.hi.value(), 0}))
          << what << ": halving lost the root";
    }
  }
}

Known rational(long num, long den = 1) {
  return {fraction(num, den), 0};
}

TEST(RealRoots, RootsOfPolynomialsWithKnownRoots) {
  const Known sqrt2{0, 1};                                // +- sqrt 2
  const Known shifted{mpq_class(1, 3), mpq_class(1, 5)};  // 1/3 +- sqrt(2)/5
  expect_roots({rational(1, 3), rational(2, 3)}, q(0), q(1), "thirds");
  expect_roots({rational(1, 2)}, q(0), q(1), "a root at the first midpoint");
  expect_roots({rational(1, 4), rational(3, 4), rational(1, 2)}, q(0), q(1), "dyadic roots");
  expect_roots({sqrt2}, q(-2), q(2), "sqrt 2");
  expect_roots({sqrt2}, q(0), q(2), "sqrt 2, the positive one");
  expect_roots({sqrt2, rational(7, 5), rational(-1)}, q(-3), q(3), "sqrt 2 next to 7/5");
  expect_roots({shifted, rational(1, 3)}, q(0), q(1), "1/3 between its neighbours");
  expect_roots({rational(0), rational(1)}, q(0), q(1), "roots at both ends: not inside");
  expect_roots({rational(0), rational(1), rational(1, 7)}, q(0), q(1), "ends and 1/7");
  expect_roots({rational(5)}, q(0), q(1), "none inside");
  expect_roots({}, q(0), q(1), "a constant");
  // Clusters: 2^-100 and 2^-100 + 2^-200, and two irrational ones about 2^-60 apart.
  const mpq_class tiny = two_to(-100).value();
  expect_roots({{tiny, 0}, {tiny + two_to(-200).value(), 0}, rational(1, 2)}, q(0), q(1),
               "a cluster 2^-200 wide");
  expect_roots({{mpq_class(1, 3), two_to(-60).value()}, rational(1, 3)}, q(0), q(1),
               "1/3 and 1/3 +- 2^-60 sqrt 2");
  // Far from 1: roots near 2^1000 and 2^-1000.
  expect_roots({{two_to(1000).value(), 0}, {two_to(1000).value(), two_to(900).value()}}, q(0),
               two_to(1001), "near 2^1000");
  expect_roots({{two_to(-1000).value(), two_to(-1010).value()}, rational(1)}, q(0), q(2),
               "near 2^-1000");
}

TEST(RealRoots, RootsOfRandomProducts) {
  Rng rng = testing::seeded_engine("real-roots-random");
  for (int i = 0; i < 60; ++i) {
    std::vector<Known> roots;
    const int n = testing::uniform_int(rng, 0, 5);
    std::vector<mpq_class> used;
    for (int k = 0; k < n; ++k) {
      const mpq_class r =
          fraction(testing::uniform_int(rng, -20, 20), testing::uniform_int(rng, 1, 12));
      if (std::find(used.begin(), used.end(), r) != used.end()) continue;
      used.push_back(r);
      roots.push_back({r, 0});
    }
    if (i % 2)
      roots.push_back({fraction(testing::uniform_int(rng, -3, 3), 4),
                       mpq_class(1, testing::uniform_int(rng, 1, 9))});
    const mpq_class lo =
        fraction(testing::uniform_int(rng, -25, 0), testing::uniform_int(rng, 1, 8));
    const mpq_class hi =
        fraction(testing::uniform_int(rng, 1, 25), testing::uniform_int(rng, 1, 8));
    expect_roots(roots, Rational(lo), Rational(hi), "random #" + std::to_string(i));
    if (::testing::Test::HasFatalFailure()) return;
  }
}

/// The Tarski queries and sign_at_root against the signs at the known roots: q_i > 0 minus
/// q_i < 0 over the roots in random intervals, and the sign at each isolated root, for
/// conditions that vanish at some roots, change sign between close ones, or are constant.
TEST(RealRoots, TarskiQueriesAndSignsAtRoots) {
  Rng rng = testing::seeded_engine("real-roots-tarski");
  const Known s{mpq_class(1, 2), mpq_class(1, 4)};  // 1/2 +- sqrt(2)/4: 0.146..., 0.853...
  std::vector<Known> roots;
  const Poly p =
      with_roots({rational(1, 5), rational(1, 2), s, rational(9, 10), rational(-1, 3)}, roots);
  const std::vector<Poly> qs{
      linear(q(1, 2)),                                 // zero at 1/2
      linear(q(3, 5)),                                 // changes sign between roots
      poly({q(-2), q(0), q(1)}),                       // t^2 - 2: negative at all of them
      poly({q(-1, 8), q(0), q(1)}) * linear(q(1, 5)),  // zero at 1/5, t^2 - 1/8 near s-
      poly({q(-3)}),                                   // a negative constant
      Poly(),                                          // zero
      poly({q(1, 8), q(-1), q(1)}),  // (t - 1/2)^2 - 1/8: zero at both irrational roots
      poly({Rational(mpq_class(1, 8) + two_to(-100).value()), q(-1), q(1)}),  // 2^-100 above
  };
  const TarskiQueries tarski(p, qs);
  const std::vector<IsolatedRoot> isolated = roots_between(p, q(-1), q(2));
  ASSERT_EQ(isolated.size(), roots.size());
  for (std::size_t i = 0; i < qs.size(); ++i) {
    for (std::size_t r = 0; r < roots.size(); ++r) {
      const int expected = sign_at(qs[i], roots[r]);
      EXPECT_EQ(static_cast<int>(sign_at_root(qs[i], p, isolated[r])), expected)
          << "q" << i << " at root " << r;
    }
  }
  int nonzero_queries = 0;
  for (int trial = 0; trial < 300; ++trial) {
    mpq_class lo = fraction(testing::uniform_int(rng, -40, 40), testing::uniform_int(rng, 1, 40));
    mpq_class hi = fraction(testing::uniform_int(rng, -40, 40), testing::uniform_int(rng, 1, 40));
    if (hi < lo) std::swap(lo, hi);
    if (p.sign_at(Rational(lo)) == Sign::zero || p.sign_at(Rational(hi)) == Sign::zero) continue;
    int count = 0;
    std::vector<int> expected(qs.size(), 0);
    for (const Known& r : roots) {
      if (!(less({lo, 0}, r) && less(r, {hi, 0}))) continue;
      ++count;
      for (std::size_t i = 0; i < qs.size(); ++i)
        expected[i] += sign_at(qs[i], r);
    }
    EXPECT_EQ(tarski.count(Rational(lo), Rational(hi)), count);
    for (std::size_t i = 0; i < qs.size(); ++i) {
      EXPECT_EQ(tarski.query(i, Rational(lo), Rational(hi)), expected[i])
          << "q" << i << " on (" << lo.get_str() << ", " << hi.get_str() << ")";
      nonzero_queries += expected[i] != 0;
    }
  }
  EXPECT_GT(nonzero_queries, 100);
}

}  // namespace
}  // namespace exactgeo::ccd::internal
