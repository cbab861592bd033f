// Bringing coordinates to magnitude 1 (predicates/kernel/unit_magnitude.hpp): the largest
// magnitude, which values are left alone, and the scaling itself against GMP: every value
// multiplied by one and the same power of two, the largest landing in [1/2, 1), exactly
// (scaling back gives the input), and refused exactly when some value would lose bits below
// the normal range.

#include "exactgeo/predicates/kernel/unit_magnitude.hpp"

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "support/generators.hpp"
#include "support/seed.hpp"

namespace exactgeo::kernel {
namespace {

using testing::Rng;

/// x 2^k, exactly.
mpq_class times_power_of_two(const mpq_class& x, int k) {
  mpq_class r;
  if (k >= 0) {
    mpq_mul_2exp(r.get_mpq_t(), x.get_mpq_t(), static_cast<mp_bitcnt_t>(k));
  } else {
    mpq_div_2exp(r.get_mpq_t(), x.get_mpq_t(), static_cast<mp_bitcnt_t>(-k));
  }
  return r;
}

/// The k with largest 2^-k in [1/2, 1) (largest > 0), checked exactly.
int expected_unit_exponent(double largest) {
  const int k = std::ilogb(largest) + 1;
  const mpq_class scaled = times_power_of_two(mpq_class(largest), -k);
  EXPECT_TRUE(scaled >= mpq_class(1, 2) && scaled < 1) << largest;
  return k;
}

/// Whether x 2^-k is a double (finite, no bit lost below the normal range).
bool exactly_scalable(double x, int k) {
  const double y = std::ldexp(x, -k);
  return std::isfinite(y) && mpq_class(y) == times_power_of_two(mpq_class(x), -k);
}

std::string show(const std::vector<double>& v) {
  std::string s;
  for (const double x : v)
    s += std::to_string(std::ilogb(x == 0.0 ? 1.0 : x)) + (x == 0.0 ? "(zero) " : " ");
  return "exponents " + s;
}

/// Scales a copy of `values` and checks it against the exact expectation.
void expect_scaled_as_exact(const std::vector<double>& values) {
  std::vector<double> scaled = values;
  const double largest = largest_magnitude(values);
  const bool did = scale_to_unit_magnitude(scaled);
  if (near_unit_magnitude(largest)) {
    EXPECT_FALSE(did) << show(values);
    EXPECT_EQ(scaled, values) << "values near magnitude 1 are left alone";
    return;
  }
  const int k = expected_unit_exponent(largest);
  EXPECT_EQ(unit_exponent(largest), k) << largest;
  bool exact = true;
  for (const double x : values)
    exact = exact && exactly_scalable(x, k);
  ASSERT_EQ(did, exact) << show(values);
  if (!did) return;
  double scaled_largest = 0;
  for (std::size_t i = 0; i < values.size(); ++i) {
    ASSERT_EQ(mpq_class(scaled[i]), times_power_of_two(mpq_class(values[i]), -k)) << i;
    ASSERT_EQ(std::signbit(scaled[i]), std::signbit(values[i])) << i;
    EXPECT_EQ(std::ldexp(scaled[i], k), values[i]) << "scaling back gives the input";
    scaled_largest = std::max(scaled_largest, std::fabs(scaled[i]));
  }
  EXPECT_GE(scaled_largest, 0.5);
  EXPECT_LT(scaled_largest, 1.0);
  EXPECT_EQ(scaled_largest, largest_magnitude(scaled));
}

TEST(UnitMagnitude, LargestMagnitudeIsTheLargestAbsoluteValue) {
  EXPECT_EQ(largest_magnitude(std::vector<double>{}), 0.0);
  EXPECT_EQ(largest_magnitude(std::vector<double>{-0.0, 0.0}), 0.0);
  EXPECT_EQ(largest_magnitude(std::vector<double>{1.5, -3.0, 2.0}), 3.0);
  EXPECT_EQ(largest_magnitude(std::vector<double>{-std::numeric_limits<double>::max(), 1.0}),
            std::numeric_limits<double>::max());
  EXPECT_EQ(largest_magnitude(std::vector<double>{-std::numeric_limits<double>::denorm_min()}),
            std::numeric_limits<double>::denorm_min());
}

/// The exponent that brings a magnitude to [1/2, 1), at the ends of the range; an infinite
/// extent (a box wider than the largest double) lies above every finite one.
TEST(UnitMagnitude, UnitExponentBringsTheLargestToOneHalfOrAbove) {
  EXPECT_EQ(unit_exponent(1.0), 1);
  EXPECT_EQ(unit_exponent(0.5), 0);
  EXPECT_EQ(unit_exponent(std::nextafter(1.0, 0.0)), 0);
  EXPECT_EQ(unit_exponent(std::numeric_limits<double>::max()), 1024);
  EXPECT_EQ(unit_exponent(std::numeric_limits<double>::denorm_min()), -1073);
  EXPECT_EQ(unit_exponent(INFINITY), 1025);
  EXPECT_EQ(kUnitWindowLow, 0x1p-64);
  EXPECT_EQ(kUnitWindowHigh, 0x1p64);
}

TEST(UnitMagnitude, ValuesNearOneAreLeftAlone) {
  EXPECT_TRUE(near_unit_magnitude(0.0));
  EXPECT_TRUE(near_unit_magnitude(0x1p-64));
  EXPECT_TRUE(near_unit_magnitude(0x1p64));
  EXPECT_TRUE(near_unit_magnitude(1.0));
  EXPECT_FALSE(near_unit_magnitude(std::nextafter(0x1p-64, 0.0)));
  EXPECT_FALSE(near_unit_magnitude(std::nextafter(0x1p64, INFINITY)));
  for (const std::vector<double>& v :
       {std::vector<double>{0.0, -0.0}, std::vector<double>{0x1p64, -3.0, 0x1p-1074},
        std::vector<double>{-0x1p-64, 0x1p-100}, std::vector<double>{0.75, -1e-300}}) {
    std::vector<double> copy = v;
    EXPECT_FALSE(scale_to_unit_magnitude(copy));
    EXPECT_EQ(copy, v);
  }
}

/// Both ends of the double range, each value exact in GMP.
TEST(UnitMagnitude, ExtremeMagnitudesAreScaledExactly) {
  const double max = std::numeric_limits<double>::max();
  const double tiny = std::numeric_limits<double>::denorm_min();
  for (const std::vector<double>& v : {
           std::vector<double>{max, -max, 0.0},
           std::vector<double>{max, 0x1p-50, -1.0},
           std::vector<double>{0x1p1000, -0x1.8p999, 0x1p-20},
           std::vector<double>{tiny},
           std::vector<double>{-tiny, 3 * tiny, 0.0},
           std::vector<double>{0x1p-1000, -0x1.fffffffffffffp-1001, 0x1p-1074},
           std::vector<double>{0x1p-1022, std::nextafter(0x1p-1022, 0.0)},
           std::vector<double>{std::nextafter(0x1p64, INFINITY)},
           std::vector<double>{std::nextafter(0x1p-64, 0.0), 0x1p-1074},
       }) {
    expect_scaled_as_exact(v);
  }
}

/// A large value next to one with low bits: scaling down pushes the small one below the
/// normal range. Refused exactly when a bit would be lost, accepted when none is.
TEST(UnitMagnitude, RefusedExactlyWhenABitWouldBeLost) {
  std::vector<double> lost{0x1p1000, 0x1.0000000000001p-60};  // -> 2^-1061 (1 + 2^-52)
  EXPECT_FALSE(scale_to_unit_magnitude(lost));
  std::vector<double> kept{0x1p1000, 0x1p-60};  // -> 2^-1061, a subnormal, exact
  EXPECT_TRUE(scale_to_unit_magnitude(kept));
  EXPECT_EQ(kept[1], 0x1p-1061);
  std::vector<double> lowest{0x1.8p1000, 0x1p-73};  // 2^-1074 after scaling: the last bit
  EXPECT_TRUE(scale_to_unit_magnitude(lowest));
  EXPECT_EQ(lowest[1], 0x1p-1074);
  std::vector<double> below{0x1.8p1000, 0x1p-75};  // 2^-1076: gone
  EXPECT_FALSE(scale_to_unit_magnitude(below));
  expect_scaled_as_exact({0x1p1000, 0x1.0000000000001p-60});
  expect_scaled_as_exact({-0x1p700, 0x1.8p-350, 0x1.0000000000001p-320});
}

/// Random values: one magnitude, mixed magnitudes (often refused), near the bounds of
/// [2^-64, 2^64], at both ends of the range.
TEST(UnitMagnitude, RandomValuesAgreeWithGmp) {
  Rng rng = testing::seeded_engine("unit-magnitude-random");
  int scaled = 0, refused = 0;
  for (int i = 0; i < 3000; ++i) {
    const int top = testing::uniform_int(rng, -1074, 1023);
    const int spread = i % 3 == 0 ? 2000 : testing::uniform_int(rng, 0, 120);
    std::vector<double> v(static_cast<std::size_t>(testing::uniform_int(rng, 1, 25)));
    for (double& x : v) {
      x = i % 11 == 0 && &x != v.data()
              ? 0.0
              : testing::random_magnitude(rng, std::max(top - spread, -1100), top);
    }
    std::vector<double> copy = v;
    const bool near = near_unit_magnitude(largest_magnitude(v));
    const bool did = scale_to_unit_magnitude(copy);
    scaled += did;
    refused += !did && !near;
    expect_scaled_as_exact(v);
    if (::testing::Test::HasFatalFailure()) return;
  }
  EXPECT_GT(scaled, 1000);
  EXPECT_GT(refused, 100);
}

}  // namespace
}  // namespace exactgeo::kernel
