// Dyadic rationals (the rational stage's numbers) against GMP's mpq, an independent exact
// arithmetic: conversion, sums, differences, products and signs, over the whole double
// range (subnormals, 2^±1000, zeros and exact cancellations).

#include "exactgeo/predicates/kernel/dyadic.hpp"

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "support/generators.hpp"
#include "support/seed.hpp"

namespace exactgeo::kernel {
namespace {

using testing::Rng;

mpq_class value_of(const Dyadic& d) {
  mpq_class q(mpz_class(d.significand()));
  if (d.exponent() >= 0) {
    mpq_mul_2exp(q.get_mpq_t(), q.get_mpq_t(), static_cast<mp_bitcnt_t>(d.exponent()));
  } else {
    mpq_div_2exp(q.get_mpq_t(), q.get_mpq_t(), static_cast<mp_bitcnt_t>(-d.exponent()));
  }
  return q;
}

Sign sign_of_q(const mpq_class& q) {
  return static_cast<Sign>(sgn(q));
}

/// Doubles across the range, with zeros, subnormals and both signs.
std::vector<double> samples(Rng& rng, std::size_t n) {
  std::vector<double> x{0.0,
                        -0.0,
                        1.0,
                        -1.0,
                        std::numeric_limits<double>::denorm_min(),
                        -std::numeric_limits<double>::min(),
                        std::numeric_limits<double>::max(),
                        0x1.fffffffffffffp-1};
  while (x.size() < n) {
    const double m = testing::random_magnitude(rng, -1074, 1023);
    x.push_back(testing::uniform(rng, 0, 1) < 0.5 ? -m : m);
  }
  return x;
}

TEST(Dyadic, ConvertsEveryDoubleExactly) {
  Rng rng = testing::seeded_engine("dyadic-conversion");
  for (const double x : samples(rng, 2000)) {
    EXPECT_EQ(value_of(Dyadic(x)), mpq_class(x)) << std::hexfloat << x;
    EXPECT_EQ(Dyadic(x).sign(), sign_of(x)) << std::hexfloat << x;
  }
}

TEST(Dyadic, SumsDifferencesAndProductsAreExact) {
  Rng rng = testing::seeded_engine("dyadic-arithmetic");
  const std::vector<double> x = samples(rng, 300);
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double a = x[i], b = x[(i * 7 + 3) % x.size()];
    const mpq_class qa(a), qb(b);
    EXPECT_EQ(value_of(Dyadic(a) + Dyadic(b)), qa + qb) << std::hexfloat << a << " " << b;
    EXPECT_EQ(value_of(Dyadic(a) - Dyadic(b)), qa - qb) << std::hexfloat << a << " " << b;
    EXPECT_EQ(value_of(Dyadic(b) - Dyadic(a)), qb - qa) << std::hexfloat << a << " " << b;
    EXPECT_EQ(value_of(Dyadic(a) * Dyadic(b)), qa * qb) << std::hexfloat << a << " " << b;
    EXPECT_EQ(value_of(-Dyadic(a)), -qa) << std::hexfloat << a;
  }
}

TEST(Dyadic, SumOfComponentsIsExact) {
  Rng rng = testing::seeded_engine("dyadic-sum-of");
  for (int trial = 0; trial < 500; ++trial) {
    const int count = testing::uniform_int(rng, 0, 6);
    std::vector<double> c;
    mpq_class exact = 0;
    for (int i = 0; i < count; ++i) {
      const double m =
          testing::uniform(rng, 0, 1) < 0.2 ? 0.0 : testing::random_magnitude(rng, -1074, 1023);
      c.push_back(testing::uniform(rng, 0, 1) < 0.5 ? -m : m);
      exact += mpq_class(c.back());
    }
    const Dyadic d = Dyadic::sum_of(c.data(), count);
    EXPECT_EQ(value_of(d), exact);
    EXPECT_EQ(d.sign(), sign_of_q(exact));
  }
}

/// A polynomial of degree 3 in several terms, with an exact cancellation to zero and a
/// one-ulp remainder: the sign must be that of the rationals.
TEST(Dyadic, SignsOfCancellingPolynomials) {
  Rng rng = testing::seeded_engine("dyadic-cancellation");
  for (int trial = 0; trial < 500; ++trial) {
    const double a = testing::random_magnitude(rng, -300, 300);
    const double b = testing::random_magnitude(rng, -300, 300);
    const double c = testing::random_magnitude(rng, -300, 300);
    const double nudge = testing::uniform(rng, 0, 1) < 0.5 ? 0.0 : std::nextafter(c, 2 * c) - c;
    // a b c + a b (c + nudge) - 2 a b c = a b nudge
    const Dyadic da(a), db(b), dc(c), dn(nudge), two(2.0);
    const Dyadic value = da * db * dc + da * db * (dc + dn) - two * da * db * dc;
    const mpq_class qa(a), qb(b), qc(c), qn(nudge);
    const mpq_class exact = qa * qb * qc + qa * qb * (qc + qn) - 2 * qa * qb * qc;
    EXPECT_EQ(value.sign(), sign_of_q(exact));
    EXPECT_EQ(value_of(value), exact);
  }
}

}  // namespace
}  // namespace exactgeo::kernel
