// Outward rounding to float (boxes/float_box.hpp): float_below(x) is the largest float <= x
// and float_above(x) the smallest float >= x, checked against the definition (the result
// is on the right side of x and its neighbour, from std::nextafter, is not) on random
// doubles of every magnitude, on floats themselves, on doubles one ulp beside them, and on
// the edges of the float range.

#include "exactgeo/boxes/float_box.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "support/generators.hpp"
#include "support/seed.hpp"

namespace exactgeo::boxes {
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr float kMaxFloat = std::numeric_limits<float>::max();

void expect_largest_float_below(double x) {
  const float f = float_below(x);
  ASSERT_LE(static_cast<double>(f), x) << x;
  if (f == kMaxFloat) return;  // x at or above the largest float
  ASSERT_GT(static_cast<double>(std::nextafter(f, kInf)), x) << x;
}

void expect_smallest_float_above(double x) {
  const float f = float_above(x);
  ASSERT_GE(static_cast<double>(f), x) << x;
  if (f == -kMaxFloat) return;
  ASSERT_LT(static_cast<double>(std::nextafter(f, -kInf)), x) << x;
}

std::vector<double> samples(testing::Rng& rng) {
  std::vector<double> xs = {0.0,
                            -0.0,
                            std::numeric_limits<float>::denorm_min(),
                            -std::numeric_limits<float>::denorm_min(),
                            std::numeric_limits<float>::min(),
                            kMaxFloat,
                            -kMaxFloat,
                            std::nextafter(static_cast<double>(kMaxFloat), 0.0),
                            std::nextafter(static_cast<double>(kMaxFloat), 1e300),
                            1e300,
                            -1e300,
                            std::numeric_limits<double>::denorm_min(),
                            -std::numeric_limits<double>::denorm_min()};
  for (int i = 0; i < 20000; ++i) {
    // Every exponent a double can have, both signs.
    xs.push_back(testing::random_magnitude(rng, -1074, 1022));
    // Floats themselves (exactly representable) and the doubles next to them.
    const auto f =
        static_cast<double>(static_cast<float>(testing::random_magnitude(rng, -149, 127)));
    for (const double y : {f, -f, std::nextafter(f, 0.0), std::nextafter(f, 2 * f + 1)})
      xs.push_back(y);
  }
  return xs;
}

TEST(FloatBox, FloatBelowAndAboveAreTheNearestFloatsOnTheirSide) {
  testing::Rng rng = testing::seeded_engine("swept-box-rounding");
  for (const double x : samples(rng)) {
    if (!std::isfinite(x)) continue;
    expect_largest_float_below(x);
    expect_smallest_float_above(x);
  }
}

TEST(FloatBox, NextFloatDownIsNextafterTowardMinusInfinity) {
  testing::Rng rng = testing::seeded_engine("swept-box-next-float");
  std::vector<float> fs = {0.0f,
                           -0.0f,
                           std::numeric_limits<float>::denorm_min(),
                           -std::numeric_limits<float>::denorm_min(),
                           std::numeric_limits<float>::min(),
                           kMaxFloat};
  for (int i = 0; i < 20000; ++i) {
    const auto bits = static_cast<std::uint32_t>(rng());
    const float f = std::bit_cast<float>(bits);
    if (std::isfinite(f) && f != -kMaxFloat) fs.push_back(f);
  }
  for (const float f : fs)
    EXPECT_EQ(std::bit_cast<std::uint32_t>(next_float_down(f)),
              std::bit_cast<std::uint32_t>(std::nextafter(f, -kInf)))
        << f;
}

}  // namespace
}  // namespace exactgeo::boxes
