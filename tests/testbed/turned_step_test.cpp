// Self-tests of the turned steps (turned_step.hpp): a rigid turn of every vertex, and
// the step at 2^+-1000 the same step, bit for bit, even for coordinates far below the
// mesh's size. No code of the library is called here.

#include "exactgeo/testbed/turned_step.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <vector>

#include "support/generators.hpp"
#include "support/seed.hpp"

namespace {

using exactgeo::testbed::turned_step;
using exactgeo::testbed::TurnedStep;

/// Random points in [-1, 1]^3, some with coordinates of 1e-12 or less.
std::vector<double> random_positions(exactgeo::testing::Rng& rng, std::size_t n) {
  std::vector<double> xyz;
  for (std::size_t v = 0; v < n; ++v) {
    for (int k = 0; k < 3; ++k) {
      const double x = exactgeo::testing::uniform(rng, -1.0, 1.0);
      xyz.push_back(v % 4 == 0 ? x * 1e-12 : x);
    }
  }
  return xyz;
}

TEST(TurnedStep, IsTheSameStepAtEveryMagnitude) {
  auto rng = exactgeo::testing::seeded_engine("testbed.turned-step.magnitudes");
  const std::vector<double> xyz = random_positions(rng, 400);
  const TurnedStep at_one = turned_step(xyz, 37.0);
  for (const int k : {1000, -1000}) {
    const TurnedStep scaled = turned_step(xyz, 37.0, k);
    for (std::size_t i = 0; i < xyz.size(); ++i) {
      ASSERT_EQ(std::ldexp(scaled.t0[i], -k), at_one.t0[i]) << "2^" << k << ", value " << i;
      ASSERT_EQ(std::ldexp(scaled.t1[i], -k), at_one.t1[i]) << "2^" << k << ", value " << i;
    }
  }
}

TEST(TurnedStep, TurnsEveryVertexAboutTheVerticalAxis) {
  auto rng = exactgeo::testing::seeded_engine("testbed.turned-step.turn");
  const std::vector<double> xyz = random_positions(rng, 400);
  const TurnedStep step = turned_step(xyz, 80.0);
  // The axis passes through the centre of the bounding box; the turn keeps each vertex's
  // height and distance to it and moves it by the chord 2 r sin(40 degrees), up to the
  // grid's 2^-40 (the largest magnitude is below 1).
  const auto middle = [&](std::size_t axis) {
    double lo = INFINITY, hi = -INFINITY;
    for (std::size_t i = axis; i < xyz.size(); i += 3) {
      lo = std::min(lo, xyz[i]);
      hi = std::max(hi, xyz[i]);
    }
    return (lo + hi) / 2;
  };
  const double cx = middle(0), cy = middle(1);
  const double tolerance = 0x1p-36;
  for (std::size_t v = 0; v < xyz.size() / 3; ++v) {
    const double* a = &step.t0[3 * v];
    const double* b = &step.t1[3 * v];
    EXPECT_EQ(a[2], b[2]) << v;
    const double r0 = std::hypot(a[0] - cx, a[1] - cy), r1 = std::hypot(b[0] - cx, b[1] - cy);
    EXPECT_NEAR(r0, r1, tolerance) << v;
    const double chord = std::hypot(b[0] - a[0], b[1] - a[1]);
    EXPECT_NEAR(chord, 2 * r0 * std::sin(40.0 * std::numbers::pi / 180.0), tolerance) << v;
  }
}

}  // namespace
