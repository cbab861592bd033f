// The float frame (internal/float_frame.hpp): the map x -> (x - c) 2^-e that brings a box
// into Embree's floats. Every mapped point of the box lies within 2 of 0 and the box's
// largest half-extent maps into [1/2, 1]; the float bounds enclose the mapped value with
// the padding and the origin is the nearest float; the map is the same at every power of
// two (dyadic boxes and points on a grid, where every step is exact, at 2^-900 to 2^900);
// a box wider than DBL_MAX, a flat box and a point box map too.

#include "exactgeo/inside/internal/float_frame.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <random>

#include "support/seed.hpp"

namespace exactgeo::inside {
namespace {

using internal::FloatFrame;

TEST(FloatFrame, BoundsEncloseTheMappedValueWithPadding) {
  auto rng = testing::seeded_engine("inside.float_frame");
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(-1070, 1020);
  for (int trial = 0; trial < 2000; ++trial) {
    const int e = exponent(rng);
    const double x = std::ldexp(unit(rng), e), y = std::ldexp(unit(rng), e);
    const Point3 lower{std::min(x, y), -1, 0}, upper{std::max(x, y), 1, 0};
    const internal::FloatFrame frame(lower, upper);
    for (const double v : {x, y, lower[0] / 2 + upper[0] / 2}) {
      const double mapped = frame.map(0, v);
      EXPECT_LT(std::fabs(mapped), 2.0) << std::hexfloat << v;
      EXPECT_LE(static_cast<double>(frame.lower_bound(0, v)), mapped - internal::FloatFrame::kPad);
      EXPECT_GE(static_cast<double>(frame.upper_bound(0, v)), mapped + internal::FloatFrame::kPad);
      EXPECT_LE(std::fabs(static_cast<double>(frame.origin(0, v)) - mapped), 0x1p-24);
    }
  }
  // A box spanning more than DBL_MAX still maps into [-2, 2].
  const double big = 0x1.fffffffffffffp+1023;
  const internal::FloatFrame huge({-big, 0, 0}, {big, 0, 0});
  EXPECT_LT(std::fabs(huge.map(0, big)), 2.0);
  EXPECT_LT(std::fabs(huge.map(0, -big)), 2.0);
}

TEST(FloatFrame, TheLargestHalfExtentMapsIntoHalfToOne) {
  auto rng = testing::seeded_engine("inside.float_frame.extent");
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(-1000, 1000);
  for (int trial = 0; trial < 2000; ++trial) {
    const int e = exponent(rng);
    Point3 lower, upper;
    for (int i = 0; i < 3; ++i) {
      // Axes of different widths, and a centre away from 0.
      const double a = std::ldexp(unit(rng), e - i), b = std::ldexp(unit(rng), e - i);
      const double shift = std::ldexp(unit(rng), e + 2);
      lower[i] = std::min(a, b) + shift;
      upper[i] = std::max(a, b) + shift;
    }
    const FloatFrame frame(lower, upper);
    double largest = 0.0;
    for (int i = 0; i < 3; ++i) {
      // The bounds map to either side of 0 (the centre lies between them).
      EXPECT_LE(frame.map(i, lower[i]), 0.0);
      EXPECT_GE(frame.map(i, upper[i]), 0.0);
      largest = std::max({largest, -frame.map(i, lower[i]), frame.map(i, upper[i])});
    }
    // The half-extent h lies in [2^(e'-1), 2^e'): mapped, in [1/2, 1), up to the one
    // rounding of x - c (relative 2^-53) and of the centre's halves.
    EXPECT_GE(largest, 0.5 * (1 - 0x1p-50));
    EXPECT_LE(largest, 1 + 0x1p-50);
  }
}

TEST(FloatFrame, TheMapIsTheSameAtEveryPowerOfTwo) {
  // Boxes and points on a grid of 2^-20 within [-2^10, 2^10]: every subtraction, halving
  // and scaling is exact, so the frame of the box scaled by 2^k maps the scaled points to
  // the very values the frame at scale 1 does, and those are (x - c) 2^-e exactly.
  auto rng = testing::seeded_engine("inside.float_frame.scale");
  std::uniform_int_distribution<std::int64_t> grid(-(std::int64_t{1} << 30), std::int64_t{1} << 30);
  const auto on_grid = [&] { return std::ldexp(static_cast<double>(grid(rng)), -20); };
  for (int trial = 0; trial < 500; ++trial) {
    Point3 lower, upper;
    for (int i = 0; i < 3; ++i) {
      const double a = on_grid(), b = on_grid();
      lower[i] = std::min(a, b);
      upper[i] = std::max(a, b);
    }
    Point3 p;
    for (int i = 0; i < 3; ++i)
      p[i] = lower[i] + std::ldexp(upper[i] - lower[i], -3) * (trial % 9);  // in the box
    const FloatFrame one(lower, upper);
    for (const int k : {-900, -300, 1, 300, 900}) {
      const auto up = [k](const Point3& q) {
        return Point3{std::ldexp(q[0], k), std::ldexp(q[1], k), std::ldexp(q[2], k)};
      };
      const FloatFrame scaled(up(lower), up(upper));
      const Point3 q = up(p);
      for (int i = 0; i < 3; ++i) {
        EXPECT_EQ(std::bit_cast<std::uint64_t>(scaled.map(i, q[i])),
                  std::bit_cast<std::uint64_t>(one.map(i, p[i])))
            << "k = " << k << ", axis " << i;
        EXPECT_EQ(scaled.lower_bound(i, q[i]), one.lower_bound(i, p[i]));
        EXPECT_EQ(scaled.upper_bound(i, q[i]), one.upper_bound(i, p[i]));
        EXPECT_EQ(scaled.origin(i, q[i]), one.origin(i, p[i]));
      }
    }
  }
}

TEST(FloatFrame, FlatAndPointBoxes) {
  // A box flat along z: z maps to 0, the other axes as for the square.
  const FloatFrame flat({-4, -4, 7}, {4, 4, 7});
  EXPECT_EQ(flat.map(2, 7), 0.0);
  EXPECT_EQ(flat.map(0, 4), 0.5);  // half-extent 4 = 2^2 lies in [2^2, 2^3): times 2^-3
  EXPECT_EQ(flat.map(1, -4), -0.5);
  // A box that is one point: a translation alone, and the bounds still pad it.
  const FloatFrame point({1.5, -2, 3}, {1.5, -2, 3});
  for (int i = 0; i < 3; ++i) {
    const double x = i == 0 ? 1.5 : (i == 1 ? -2 : 3);
    EXPECT_EQ(point.map(i, x), 0.0);
    EXPECT_EQ(point.origin(i, x), 0.0f);
    EXPECT_LE(static_cast<double>(point.lower_bound(i, x)), -FloatFrame::kPad);
    EXPECT_GE(static_cast<double>(point.upper_bound(i, x)), FloatFrame::kPad);
  }
}

}  // namespace
}  // namespace exactgeo::inside
