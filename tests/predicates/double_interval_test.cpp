// DoubleInterval's one-ulp moves (predicates/src/double_interval.hpp), computed from the
// bits, against std::nextafter: the special values (zeros, subnormals, the largest and
// smallest normals, infinities, NaN) and random bit patterns of every exponent, both ways.

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <ios>
#include <limits>
#include <random>
#include <vector>

#include "../../predicates/src/double_interval.hpp"
#include "support/seed.hpp"

namespace exactgeo::double_interval_test {
namespace {

using internal::DoubleInterval;

void expect_nextafter(double x) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  const double up = DoubleInterval::up(x), down = DoubleInterval::down(x);
  const double want_up = std::nextafter(x, kInf), want_down = std::nextafter(x, -kInf);
  if (std::isnan(x)) {
    EXPECT_TRUE(std::isnan(up) && std::isnan(down));
    return;
  }
  // Bit for bit: -0 and +0 told apart.
  EXPECT_EQ(std::bit_cast<std::uint64_t>(up), std::bit_cast<std::uint64_t>(want_up))
      << std::hexfloat << x;
  EXPECT_EQ(std::bit_cast<std::uint64_t>(down), std::bit_cast<std::uint64_t>(want_down))
      << std::hexfloat << x;
}

TEST(DoubleInterval, UpAndDownAreNextafter) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  constexpr double kMax = std::numeric_limits<double>::max();
  constexpr double kMin = std::numeric_limits<double>::min();
  constexpr double kTiny = std::numeric_limits<double>::denorm_min();
  for (const double x :
       {0.0, -0.0, kTiny, -kTiny, 2 * kTiny, kMin, -kMin, kMin - kTiny, -(kMin - kTiny), 1.0, -1.0,
        0x1.fffffffffffffp-1, kMax, -kMax, kInf, -kInf, std::numeric_limits<double>::quiet_NaN()}) {
    expect_nextafter(x);
  }
  auto rng = testing::seeded_engine("predicates.double_interval.nextafter");
  std::uniform_int_distribution<std::uint64_t> bits;
  for (int i = 0; i < 100000; ++i)
    expect_nextafter(std::bit_cast<double>(bits(rng)));
}

}  // namespace
}  // namespace exactgeo::double_interval_test
