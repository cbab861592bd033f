// Segments against triangles, exactly (predicates/segment_triangle.hpp), against the
// rational oracle that solves for the meeting point instead of reading orientation signs
// (tests/support/segment_triangle_oracle.hpp): random configurations of small integers
// (where every kind of touching happens), random doubles, segments and triangles in one
// plane, exact contacts (through a corner, along an edge) and each of them moved by one
// ulp, all at 2^0, 2^+-1000 and at subnormal scale.

#include "exactgeo/predicates/segment_triangle.hpp"
#include "exactgeo/predicates/orient3d.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>
#include <random>
#include <string>

#include "support/seed.hpp"
#include "support/segment_triangle_oracle.hpp"

namespace exactgeo {
namespace {

using testing::collinear_oracle;
using testing::segment_meets_triangle_beyond_oracle;
using testing::segment_meets_triangle_oracle;

/// Five points: a segment x y and a triangle p q r.
using Case = std::array<Point3, 5>;

std::string text(const Case& c) {
  std::string s;
  char buffer[80];
  for (const Point3& p : c) {
    std::snprintf(buffer, sizeof buffer, "(%a, %a, %a) ", p[0], p[1], p[2]);
    s += buffer;
  }
  return s;
}

Case scaled(Case c, double s) {
  for (Point3& p : c) {
    for (double& x : p)
      x *= s;
  }
  return c;
}

/// Every predicate of the header on one case against the oracle; counts the meetings.
void expect_agrees(const Case& c, int& meetings) {
  const auto& [x, y, p, q, r] = c;
  ASSERT_EQ(collinear(p, q, r), collinear_oracle(p, q, r)) << text(c);
  ASSERT_EQ(collinear(x, y, p), collinear_oracle(x, y, p)) << text(c);
  if (collinear_oracle(p, q, r)) {
    EXPECT_FALSE(shadow_axis(p, q, r).has_value()) << text(c);
    return;
  }
  ASSERT_TRUE(shadow_axis(p, q, r).has_value()) << text(c);
  const bool meets = segment_meets_triangle_oracle(x, y, p, q, r);
  meetings += meets ? 1 : 0;
  ASSERT_EQ(segment_meets_triangle(x, y, p, q, r), meets) << text(c);
  ASSERT_EQ(segment_meets_triangle(y, x, q, r, p), meets) << text(c);  // same sets
  // The segment from corner p to x.
  ASSERT_EQ(segment_meets_triangle_beyond(p, x, q, r),
            segment_meets_triangle_beyond_oracle(p, x, q, r))
      << text(c);
}

/// Every case at 2^0, 2^+-1000 and 2^-1060 (subnormal coordinates for small integers).
void expect_agrees_at_every_scale(const Case& c, int& meetings) {
  for (const int e : {0, 1000, -1000, -1060}) {
    int unused = 0;
    expect_agrees(scaled(c, std::ldexp(1.0, e)), e == 0 ? meetings : unused);
  }
}

TEST(SegmentTriangle, SmallIntegersMeetInEveryWay) {
  std::mt19937_64 rng = testing::seeded_engine("SegmentTriangle.integers");
  std::uniform_int_distribution<int> coordinate(-3, 3);
  int meetings = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    Case c;
    for (Point3& p : c) {
      for (double& x : p)
        x = coordinate(rng);
    }
    expect_agrees_at_every_scale(c, meetings);
    if (::testing::Test::HasFatalFailure()) return;
  }
  EXPECT_GT(meetings, 400);
}

TEST(SegmentTriangle, InOnePlane) {
  // Every point in the plane z = x - 2y (exact for small integers): segments and
  // triangles that share the plane, the case decided in a shadow.
  std::mt19937_64 rng = testing::seeded_engine("SegmentTriangle.plane");
  std::uniform_int_distribution<int> coordinate(-4, 4);
  int meetings = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    Case c;
    for (Point3& p : c) {
      p[0] = coordinate(rng);
      p[1] = coordinate(rng);
      p[2] = p[0] - 2 * p[1];
    }
    expect_agrees_at_every_scale(c, meetings);
    if (::testing::Test::HasFatalFailure()) return;
  }
  EXPECT_GT(meetings, 800);
}

TEST(SegmentTriangle, ExactContactsAndOneUlpAway) {
  // A segment through a corner or through an edge's midpoint of the triangle, exactly (the
  // points are dyadic), then each coordinate of its far end moved one ulp either way.
  std::mt19937_64 rng = testing::seeded_engine("SegmentTriangle.contacts");
  std::uniform_int_distribution<int> coordinate(-64, 64);
  int meetings = 0;
  for (int trial = 0; trial < 600; ++trial) {
    Point3 p, q, r, below;
    for (Point3* v : {&p, &q, &r, &below}) {
      for (double& x : *v)
        x = coordinate(rng) / 8.0;
    }
    const Point3 mid{(q[0] + r[0]) / 2, (q[1] + r[1]) / 2, (q[2] + r[2]) / 2};
    for (const Point3& contact : {p, mid}) {
      // From `below` through the contact and as far again: the far end is 2 contact - below.
      const Point3 far{2 * contact[0] - below[0], 2 * contact[1] - below[1],
                       2 * contact[2] - below[2]};
      for (int k = 0; k < 3; ++k) {
        for (const double direction : {-HUGE_VAL, 0.0, HUGE_VAL}) {
          Point3 moved = far;
          if (direction != 0.0) moved[k] = std::nextafter(moved[k], direction);
          expect_agrees_at_every_scale({below, moved, p, q, r}, meetings);
          expect_agrees_at_every_scale({below, contact, p, q, r}, meetings);  // ends on it
          if (::testing::Test::HasFatalFailure()) return;
        }
      }
    }
  }
  EXPECT_GT(meetings, 1000);
}

TEST(SegmentTriangle, RandomDoubles) {
  std::mt19937_64 rng = testing::seeded_engine("SegmentTriangle.doubles");
  std::uniform_real_distribution<double> coordinate(-1.0, 1.0);
  int meetings = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    Case c;
    for (Point3& p : c) {
      for (double& x : p)
        x = coordinate(rng);
    }
    expect_agrees_at_every_scale(c, meetings);
    if (::testing::Test::HasFatalFailure()) return;
  }
  EXPECT_GT(meetings, 50);
}

}  // namespace
}  // namespace exactgeo
