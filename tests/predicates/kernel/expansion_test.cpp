// Error-free transformations and expansion arithmetic against GMP rationals.

#include "exactgeo/predicates/kernel/expansion.hpp"

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "support/generators.hpp"
#include "support/seed.hpp"

namespace exactgeo::kernel {
namespace {

using testing::Rng;

template <int N>
mpq_class value_of(const Expansion<N>& e) {
  mpq_class sum = 0;
  for (int i = 0; i < e.size(); ++i)
    sum += mpq_class(e.data()[i]);
  return sum;
}

/// Components nonzero, increasing in magnitude, and (a consequence of nonoverlapping that
/// is cheap to check) each below the leading power of two of the next.
template <int N>
void expect_well_formed(const Expansion<N>& e) {
  for (int i = 0; i < e.size(); ++i)
    ASSERT_NE(e.data()[i], 0.0);
  for (int i = 1; i < e.size(); ++i) {
    const double lower = std::fabs(e.data()[i - 1]);
    const double upper = std::fabs(e.data()[i]);
    ASSERT_LT(lower, upper);
    // Nonoverlapping: |lower| is below the last set bit of upper, hence below 2^ilogb(upper).
    ASSERT_LT(lower, std::ldexp(1.0, std::ilogb(upper)));
  }
}

double wide(Rng& rng) {
  return testing::random_magnitude(rng, -300, 300);
}

TEST(ErrorFree, TwoSumTwoDiffTwoProductAreExact) {
  Rng rng = testing::seeded_engine("error-free");
  for (int i = 0; i < 20000; ++i) {
    const double a = wide(rng), b = i % 4 == 0 ? a * 0x1p-30 : wide(rng);
    const TwoTerm s = two_sum(a, b);
    EXPECT_EQ(mpq_class(s.head) + mpq_class(s.tail), mpq_class(a) + mpq_class(b));
    EXPECT_EQ(s.head, a + b);
    const TwoTerm d = two_diff(a, b);
    EXPECT_EQ(mpq_class(d.head) + mpq_class(d.tail), mpq_class(a) - mpq_class(b));
    const TwoTerm p = two_product(a, b);
    EXPECT_EQ(mpq_class(p.head) + mpq_class(p.tail), mpq_class(a) * mpq_class(b));
    EXPECT_EQ(p.head, a * b);
  }
}

TEST(ErrorFree, SplitHalvesFitIn26Bits) {
  Rng rng = testing::seeded_engine("split");
  for (int i = 0; i < 10000; ++i) {
    const double a = wide(rng);
    const TwoTerm s = split(a);
    EXPECT_EQ(s.head + s.tail, a);
    // hi has at most 26 significant bits: hi * 2^(25 - ilogb(hi)) is an integer.
    const double scaled_hi = std::ldexp(s.head, 25 - std::ilogb(s.head));
    EXPECT_EQ(scaled_hi, std::trunc(scaled_hi));
  }
}

/// A random expansion: the exact sum of a few random doubles of spread-out magnitudes.
Expansion<8> random_expansion(Rng& rng) {
  Expansion<8> e;
  const int terms = testing::uniform_int(rng, 0, 4);
  for (int i = 0; i < terms; ++i) {
    e = (e + Expansion<1>(testing::random_magnitude(rng, -200, 200))).narrow<8>().value();
    e.compress();
  }
  return e;
}

TEST(Expansion, SumDifferenceProductAreExactAndWellFormed) {
  Rng rng = testing::seeded_engine("expansion-arithmetic");
  for (int i = 0; i < 5000; ++i) {
    const Expansion<8> a = random_expansion(rng);
    const Expansion<8> b = random_expansion(rng);
    const auto sum = a + b;
    expect_well_formed(sum);
    EXPECT_EQ(value_of(sum), value_of(a) + value_of(b));
    const auto difference = a - b;
    expect_well_formed(difference);
    EXPECT_EQ(value_of(difference), value_of(a) - value_of(b));
    const auto product = a * b;
    expect_well_formed(product);
    EXPECT_EQ(value_of(product), value_of(a) * value_of(b));
    const double factor = wide(rng);
    const auto scaled_e = scale(a, factor);
    expect_well_formed(scaled_e);
    EXPECT_EQ(value_of(scaled_e), value_of(a) * mpq_class(factor));
  }
}

TEST(Expansion, SignIsTheSignOfTheValue) {
  Rng rng = testing::seeded_engine("expansion-sign");
  for (int i = 0; i < 5000; ++i) {
    const auto e = random_expansion(rng) - random_expansion(rng);
    EXPECT_EQ(e.sign(), sign_of(sgn(value_of(e))));
  }
  const auto zero = Expansion<2>::difference(0.1, 0.1);
  EXPECT_TRUE(zero.is_zero());
  EXPECT_EQ(zero.sign(), Sign::zero);
  // A value whose head alone cancels: (1 + 2^-60) - 1 = 2^-60 > 0.
  const auto tiny = (Expansion<1>(1.0) + Expansion<1>(0x1p-60)) - Expansion<1>(1.0);
  EXPECT_EQ(tiny.sign(), Sign::positive);
}

TEST(Expansion, CompressKeepsTheValueAndPutsItInTheHead) {
  Rng rng = testing::seeded_engine("expansion-compress");
  for (int i = 0; i < 5000; ++i) {
    auto e = random_expansion(rng) * random_expansion(rng);
    const mpq_class before = value_of(e);
    e.compress();
    expect_well_formed(e);
    EXPECT_EQ(value_of(e), before);
    if (!e.is_zero()) {
      // The head is within one ulp of the value.
      const mpq_class error = abs(before - mpq_class(e.head()));
      const double ulp = std::nextafter(std::fabs(e.head()), INFINITY) - std::fabs(e.head());
      EXPECT_LE(error, mpq_class(ulp));
    }
  }
}

TEST(Expansion, NarrowFitsOrSaysSo) {
  const auto three = (Expansion<1>(1.0) + Expansion<1>(0x1p-80)) + Expansion<1>(0x1p-200);
  ASSERT_EQ(three.size(), 3);
  EXPECT_TRUE(three.narrow<3>().has_value());
  EXPECT_FALSE(three.narrow<2>().has_value());
  EXPECT_EQ(value_of(*three.narrow<3>()), value_of(three));
}

}  // namespace
}  // namespace exactgeo::kernel
