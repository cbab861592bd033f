// The cloth remesher's float shortcuts (examples/cloth/float_shortcuts.hpp) give the answer
// of the full computation wherever they answer: on random inputs and on inputs a relative
// 1e-16 to 1e-5 from each limit, where a margin too thin would show, at several magnitudes.

#include "float_shortcuts.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <numbers>
#include <optional>
#include <random>

#include "support/seed.hpp"

namespace exactgeo::cloth {
namespace {

using exactgeo::testing::seeded_engine;

/// Relative distances from a limit: from a few ulps to far beyond every margin.
constexpr std::array kNearness{0.0, 1e-16, 4e-16, 1e-12, 1e-9, 3e-9, 1e-7, 1e-6, 3e-6, 1e-5};
/// Magnitudes of the inputs (the shortcuts decline where squares lose precision).
constexpr std::array kScales{1.0, 0x1p-100, 0x1p+100, 0x1p-480, 0x1p+480};

double relative(std::mt19937_64& rng, double limit) {
  const double nearness =
      kNearness[std::uniform_int_distribution<std::size_t>(0, kNearness.size() - 1)(rng)];
  const double sign = std::bernoulli_distribution(0.5)(rng) ? 1.0 : -1.0;
  return limit * (1.0 + sign * nearness);
}

double pick(std::mt19937_64& rng, const auto& values) {
  return values[std::uniform_int_distribution<std::size_t>(0, values.size() - 1)(rng)];
}

/// A triangle o, o + u, o + v whose angle at o is `angle` (up to the rotation's rounding):
/// u and v in a plane turned at random, of random lengths (equal ones for an isosceles
/// triangle, whose smallest angle is then the one at o when `angle` is small), scaled and
/// moved.
std::array<Point3, 3> triangle_with_angle(std::mt19937_64& rng, double angle, double scale,
                                          bool isosceles) {
  std::uniform_real_distribution<double> unit(0.2, 1.0), turn(0.0, 2.0 * std::numbers::pi);
  const double a = unit(rng), b = isosceles ? a : unit(rng), phi = turn(rng);
  const double tilt = turn(rng), spin = turn(rng);
  // The plane z = 0 turned by `tilt` about x, then by `spin` about z.
  const auto turned = [&](double x, double y) {
    const double y1 = y * std::cos(tilt), z1 = y * std::sin(tilt);
    return Point3{x * std::cos(spin) - y1 * std::sin(spin),
                  x * std::sin(spin) + y1 * std::cos(spin), z1};
  };
  const Point3 u = turned(a * std::cos(phi), a * std::sin(phi));
  const Point3 v = turned(b * std::cos(phi + angle), b * std::sin(phi + angle));
  const Point3 o{unit(rng) * scale, unit(rng) * scale, unit(rng) * scale};
  const auto at = [&](const Point3& d) {
    return Point3{o[0] + d[0] * scale, o[1] + d[1] * scale, o[2] + d[2] * scale};
  };
  return {o, at(u), at(v)};
}

TEST(FloatShortcuts, TheFloorTestAnswersAsTheSmallestAngle) {
  std::mt19937_64 rng = seeded_engine("FloatShortcuts.Floor");
  int shortcut = 0, below = 0;
  for (int trial = 0; trial < 200000; ++trial) {
    const double scale = pick(rng, kScales);
    const bool near = trial % 2 == 0;
    const double angle =
        near ? relative(rng, kMinAngle) : std::uniform_real_distribution<double>(0.0, 1.6)(rng);
    const auto [p, q, r] = triangle_with_angle(rng, angle, scale, near);
    const double full = world_min_angle(p, q, r);
    const double to_floor = world_min_angle_to_floor(p, q, r);
    if (to_floor == kMinAngle) {
      ++shortcut;
      // It stands for an angle at or above the floor: the guard's comparisons with
      // kMinAngle and (only below it) with the old triangles' angles come out alike.
      ASSERT_GE(full, kMinAngle) << "trial " << trial << " angle " << angle;
    } else {
      ASSERT_EQ(to_floor, full) << "trial " << trial;
    }
    below += full < kMinAngle;
  }
  // Both branches were taken many times (the test would pass vacuously otherwise).
  EXPECT_GT(shortcut, 20000);
  EXPECT_GT(below, 20000);
}

TEST(FloatShortcuts, ClearlyLongerAnswersAsHypot) {
  std::mt19937_64 rng = seeded_engine("FloatShortcuts.Longer");
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  int answered = 0;
  for (int trial = 0; trial < 200000; ++trial) {
    const double scale = pick(rng, kScales);
    const double dx = unit(rng) * scale, dy = unit(rng) * scale;
    const double length = std::hypot(dx, dy);
    const double limit = trial % 2 == 0 ? relative(rng, length) : std::abs(unit(rng)) * scale;
    const std::optional<bool> longer = clearly_longer(dx, dy, limit);
    if (!longer) continue;
    ++answered;
    ASSERT_EQ(*longer, length > limit)
        << "trial " << trial << " dx " << dx << " dy " << dy << " limit " << limit;
    // Not longer is strictly shorter (the collapse pass takes it for length < limit).
    if (!*longer) {
      ASSERT_LT(length, limit) << "trial " << trial;
    }
  }
  EXPECT_GT(answered, 100000);
}

TEST(FloatShortcuts, AnAskThatCannotLowerASizeIsAtLeastTheLargest) {
  std::mt19937_64 rng = seeded_engine("FloatShortcuts.Ask");
  std::uniform_real_distribution<double> unit(-1.0, 1.0), positive(0.05, 1.0);
  constexpr double kTurn = 0.5;
  int answered = 0;
  for (int trial = 0; trial < 200000; ++trial) {
    const double scale = pick(rng, kScales);
    // Two normals at a random angle, of random lengths; the edge's length is chosen so
    // that its ask lies near max_length on every other trial.
    const double theta = std::abs(unit(rng)) * (trial % 3 == 0 ? 3.0 : 0.3);
    const Point3 n1{positive(rng) * scale, 0.0, 0.0};
    const double b = positive(rng) * scale;
    const Point3 n2{b * std::cos(theta), b * std::sin(theta), 0.0};
    const std::array<double, 3> c{n1[1] * n2[2] - n1[2] * n2[1], n1[2] * n2[0] - n1[0] * n2[2],
                                  n1[0] * n2[1] - n1[1] * n2[0]};
    const double dot = n1[0] * n2[0] + n1[1] * n2[1] + n1[2] * n2[2];
    const double max_length = positive(rng) * scale;
    const double angle = std::atan2(std::hypot(c[0], c[1], c[2]), dot);
    const double length =
        trial % 2 == 0 ? relative(rng, max_length * angle / kTurn) : positive(rng) * scale;
    if (!asks_no_less_than_max(c, dot, length * length, max_length, kTurn)) continue;
    ++answered;
    // The remesher's ask (vertex_sizes): length * turn / angle, no ask for a zero angle.
    if (!(angle > 0.0)) continue;
    ASSERT_GE(length * kTurn / angle, max_length) << "trial " << trial << " theta " << theta;
  }
  EXPECT_GT(answered, 20000);
}

TEST(FloatShortcuts, AHalfTurnIsExceededAsTheAnglesSumSays) {
  // Two corners in the plane (a quadrilateral's opposite corners c and d, as the remesher's
  // Delaunay test sees them: the cross and dot products of each corner's sides), whose
  // angles sum to near pi + slack on every other trial, near pi (a grid's right
  // triangles) or 0 or 2 pi (slivers) on some, and anything on the rest.
  std::mt19937_64 rng = seeded_engine("FloatShortcuts.HalfTurn");
  std::uniform_real_distribution<double> unit(0.05, 1.0), angle(0.0, std::numbers::pi),
      turn(0.0, 2.0 * std::numbers::pi);
  constexpr double kSlack = 1e-6;
  int answered = 0, beyond = 0;
  const auto corner = [&](double at, double scale) {
    const double a = unit(rng) * scale, b = unit(rng) * scale, phi = turn(rng);
    const double ux = a * std::cos(phi), uy = a * std::sin(phi);
    const double vx = b * std::cos(phi + at), vy = b * std::sin(phi + at);
    return std::array<double, 2>{std::abs(ux * vy - uy * vx), ux * vx + uy * vy};
  };
  for (int trial = 0; trial < 300000; ++trial) {
    const double scale = pick(rng, kScales);
    double sum = angle(rng) + angle(rng);
    if (trial % 2 == 0) sum = relative(rng, std::numbers::pi + kSlack) - std::numbers::pi;
    if (trial % 2 == 0 && trial % 3 == 0) sum = relative(rng, 1.0) * 1e-300;  // below pi
    sum = trial % 10 == 1 ? relative(rng, std::numbers::pi) - std::numbers::pi : sum;
    sum = trial % 10 == 3 ? relative(rng, 1e-3) : sum;
    sum = trial % 10 == 5 ? relative(rng, 2.0 * std::numbers::pi - 1e-3) : sum;
    if (trial % 2 == 0 && trial % 3 != 0) sum += std::numbers::pi;
    const double first = std::clamp(sum - angle(rng), std::max(0.0, sum - std::numbers::pi),
                                    std::min(sum, std::numbers::pi));
    const auto [cross1, dot1] = corner(first, scale);
    const auto [cross2, dot2] = corner(sum - first, scale);
    const std::optional<bool> clear =
        clearly_beyond_half_turn(cross1, dot1, cross2, dot2, std::tan(kSlack));
    const bool full =
        std::atan2(cross1, dot1) + std::atan2(cross2, dot2) > std::numbers::pi + kSlack;
    beyond += full;
    if (!clear) continue;
    ++answered;
    ASSERT_EQ(*clear, full) << "trial " << trial << " sum " << sum << " scale " << scale;
  }
  std::cout << answered << " of 300000 answered, " << beyond << " beyond a half turn\n";
  EXPECT_GT(answered, 100000);  // every scale but the two whose products overflow or underflow
  EXPECT_GT(beyond, 50000);
  EXPECT_LT(beyond, 250000);
}

}  // namespace
}  // namespace exactgeo::cloth
