// Self-tests of the exact minimum-separation oracle: hand-computed motions with known
// closest distances and earliest times (rational and irrational), degenerate primitives,
// and randomized consistency checks against exact static distances at rational times.
// Nothing of the library under test is called here, only its query types.

#include "ccd/separation/min_separation_oracle.hpp"
#include "ccd/separation/static_distance.hpp"

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>

#include "exactgeo/ccd/queries.hpp"
#include "support/generators.hpp"
#include "support/seed.hpp"

namespace {

using exactgeo::Point3;
using exactgeo::ccd::EdgeEdgeQuery;
using exactgeo::ccd::VertexFaceQuery;
using exactgeo::testing::distance2_at;
using exactgeo::testing::min_separation_oracle;
using exactgeo::testing::MinSeparationAnswer;
using exactgeo::testing::Rng;
using Rational = mpq_class;

Rational squared(double x) {
  const Rational r(x);
  return r * r;
}

double below(double x) {
  return std::nextafter(x, 0.0);
}

// ---------------------------------------------------------------------------------------
// Expectations.

void expect_within_at(const MinSeparationAnswer& a, const Rational& t) {
  EXPECT_TRUE(a.within);
  EXPECT_EQ(a.earliest_lo, t) << "earliest interval [" << a.earliest_lo.get_str() << ", "
                              << a.earliest_hi.get_str() << "], expected " << t.get_str();
  EXPECT_EQ(a.earliest_hi, t);
}

void expect_not_within(const MinSeparationAnswer& a) {
  EXPECT_FALSE(a.within);
}

/// t* = (8 - 2 sqrt 7) / 25, the smaller root of 625 t^2 - 400 t + 36, lies in the closed
/// [lo, hi]: 8 - 25 lo >= 2 sqrt 7 and 8 - 25 hi <= 2 sqrt 7 (squares compared with 28).
void expect_brackets_eight_minus_two_root_seven_over_25(const MinSeparationAnswer& a) {
  ASSERT_TRUE(a.within);
  EXPECT_LT(a.earliest_lo, a.earliest_hi) << "an irrational time cannot be exact";
  const Rational width_bound = Rational(1) / Rational(mpz_class(1) << 80);
  EXPECT_LE(a.earliest_hi - a.earliest_lo, width_bound);
  const Rational left = 8 - 25 * a.earliest_lo, right = 8 - 25 * a.earliest_hi;
  EXPECT_TRUE(left >= 0 && left * left >= 28);
  EXPECT_TRUE(right < 0 || right * right <= 28);
  EXPECT_NEAR(a.earliest_lo.get_d(), (8.0 - 2.0 * std::sqrt(7.0)) / 25.0, 1e-15);
}

VertexFaceQuery static_triangle(const Point3& v0, const Point3& v1, const Point3& f0,
                                const Point3& f1, const Point3& f2) {
  return {v0, f0, f1, f2, v1, f0, f1, f2};
}

EdgeEdgeQuery static_first_edge(const Point3& a0, const Point3& a1, const Point3& b0_t0,
                                const Point3& b1_t0, const Point3& b0_t1, const Point3& b1_t1) {
  return {a0, a1, b0_t0, b1_t0, a0, a1, b0_t1, b1_t1};
}

// ---------------------------------------------------------------------------------------
// Vertex-face, hand-computed.

// The vertex slides at height h = 3/4 over the triangle (0,0,0), (4,0,0), (0,4,0) along
// y = 1, x(t) = -3 + 8t: distance sqrt(x^2 + h^2) to the edge x = 0 while x < 0, h above
// the interior. It reaches h at x = 0 (t = 3/8), and 5/4 at x = -1 (t = 1/4).
TEST(MinSeparationOracle, VertexSlidingOverTriangleInterior) {
  const double h = 0.75;
  const VertexFaceQuery q = static_triangle({-3, 1, h}, {5, 1, h}, {0, 0, 0}, {4, 0, 0}, {0, 4, 0});
  expect_within_at(min_separation_oracle(q, h), Rational(3, 8));
  expect_not_within(min_separation_oracle(q, below(h)));
  expect_not_within(min_separation_oracle(q, 0.0));
  expect_within_at(min_separation_oracle(q, 1.25), Rational(1, 4));
  expect_within_at(min_separation_oracle(q, 4.0), Rational(0));
}

// The vertex falls through the interior, z(t) = 2 - 4t: touches at t = 1/2, and is within
// 1/2 from z = 1/2 on (t = 3/8).
TEST(MinSeparationOracle, VertexFallingThroughTriangle) {
  const VertexFaceQuery q = static_triangle({1, 1, 2}, {1, 1, -2}, {0, 0, 0}, {4, 0, 0}, {0, 4, 0});
  expect_within_at(min_separation_oracle(q, 0.0), Rational(1, 2));
  expect_within_at(min_separation_oracle(q, 0.5), Rational(3, 8));
  // z(t) = 1 - 3t reaches 3/4 at t = 1/12: a root of the squarefree quadratic
  // (1 - 3t)^2 - 9/16 isolated by bisection, then recognized as rational.
  const VertexFaceQuery thirds =
      static_triangle({1, 1, 1}, {1, 1, -2}, {0, 0, 0}, {4, 0, 0}, {0, 4, 0});
  expect_within_at(min_separation_oracle(thirds, 0.75), Rational(1, 12));
}

TEST(MinSeparationOracle, TouchingExactlyAtTheEnds) {
  const VertexFaceQuery at_end =
      static_triangle({1, 1, 2}, {1, 1, 0}, {0, 0, 0}, {4, 0, 0}, {0, 4, 0});
  expect_within_at(min_separation_oracle(at_end, 0.0), Rational(1));
  expect_within_at(min_separation_oracle(at_end, 0.5), Rational(3, 4));
  // Stopping at height 1/2: within 1/2 only at t = 1.
  const VertexFaceQuery stops_above =
      static_triangle({1, 1, 2}, {1, 1, 0.5}, {0, 0, 0}, {4, 0, 0}, {0, 4, 0});
  expect_within_at(min_separation_oracle(stops_above, 0.5), Rational(1));
  expect_not_within(min_separation_oracle(stops_above, below(0.5)));
  const VertexFaceQuery from_start =
      static_triangle({1, 1, 0}, {1, 1, 2}, {0, 0, 0}, {4, 0, 0}, {0, 4, 0});
  expect_within_at(min_separation_oracle(from_start, 0.0), Rational(0));
}

// The triangle (0,0,0), (4,0,0), (2,-4,0) lies in z = 0, y <= 0. The vertex moves in the
// plane x = 2 from (y, z) = (5/4, 0) to (-5/4, 15/8), on the line 3y + 4z = 15/4 at
// distance 3/4 from the edge y = z = 0. While y >= 0 the closest point is on that edge,
// with squared distance y^2 + z^2 = (625 t^2 - 400 t + 100) / 64, least (9/16) at t = 8/25;
// for y < 0 the vertex is above the interior at height z > 15/16.
VertexFaceQuery vertex_past_edge() {
  return static_triangle({2, 1.25, 0}, {2, -1.25, 1.875}, {0, 0, 0}, {4, 0, 0}, {2, -4, 0});
}

TEST(MinSeparationOracle, VertexPassingAnEdgeAtThreeQuarters) {
  const VertexFaceQuery q = vertex_past_edge();
  expect_within_at(min_separation_oracle(q, 0.75), Rational(8, 25));
  expect_not_within(min_separation_oracle(q, below(0.75)));
  expect_within_at(min_separation_oracle(q, 1.25), Rational(0));
}

// Distance 1 is first reached at the smaller root of 625 t^2 - 400 t + 36 = 0, the
// irrational t = (8 - 2 sqrt 7) / 25.
TEST(MinSeparationOracle, IrrationalEarliestTime) {
  expect_brackets_eight_minus_two_root_seven_over_25(
      min_separation_oracle(vertex_past_edge(), 1.0));
}

// The same relative motion against a triangle collapsed to the point (2, 0, 0).
TEST(MinSeparationOracle, TriangleCollapsedToAPoint) {
  const Point3 p{2, 0, 0};
  const VertexFaceQuery q = static_triangle({2, 1.25, 0}, {2, -1.25, 1.875}, p, p, p);
  expect_within_at(min_separation_oracle(q, 0.75), Rational(8, 25));
  expect_not_within(min_separation_oracle(q, below(0.75)));
  expect_brackets_eight_minus_two_root_seven_over_25(min_separation_oracle(q, 1.0));
}

// A triangle with collinear corners (one in the middle, in either position, or two equal)
// is the segment [0, 4] of the x axis, its longest edge. The vertex slides at height 3/4
// as in the first test.
TEST(MinSeparationOracle, TriangleWithCollinearCorners) {
  const Point3 v0{-3, 0, 0.75}, v1{5, 0, 0.75};
  for (const VertexFaceQuery& q : {static_triangle(v0, v1, {0, 0, 0}, {2, 0, 0}, {4, 0, 0}),
                                   static_triangle(v0, v1, {0, 0, 0}, {4, 0, 0}, {2, 0, 0}),
                                   static_triangle(v0, v1, {4, 0, 0}, {0, 0, 0}, {4, 0, 0})}) {
    expect_within_at(min_separation_oracle(q, 0.75), Rational(3, 8));
    expect_within_at(min_separation_oracle(q, 1.25), Rational(1, 4));
    expect_not_within(min_separation_oracle(q, below(0.75)));
  }
}

// The corner f2 moves from (0, 4, 0) to (0, -4, 0): the triangle flattens at t = 1/2 and
// then covers y < 0. The static vertex (1, -1, 0) is reached by the edge f1 f2 when
// 1/4 + 1 / |y2| = 1, y2 = 4 - 8t = -4/3, t = 2/3.
TEST(MinSeparationOracle, TriangleFlatteningOverTime) {
  const VertexFaceQuery q{{1, -1, 0}, {0, 0, 0}, {4, 0, 0}, {0, 4, 0},
                          {1, -1, 0}, {0, 0, 0}, {4, 0, 0}, {0, -4, 0}};
  expect_within_at(min_separation_oracle(q, 0.0), Rational(2, 3));
  // Distance 1 at t = 0 already (the vertex is 1 below the edge f0 f1).
  expect_within_at(min_separation_oracle(q, 1.0), Rational(0));
}

// ---------------------------------------------------------------------------------------
// Edge-edge, hand-computed.

// Edge b, parallel to edge a = [0, 4] x {0} x {0} at distance 3/4, slides from x in
// [6, 8] to [-2, 0]: the x ranges meet at t = 1/4; the gap is 1 (distance 5/4) at t = 1/8.
TEST(MinSeparationOracle, ParallelEdges) {
  const EdgeEdgeQuery q = static_first_edge({0, 0, 0}, {4, 0, 0}, {6, 0.75, 0}, {8, 0.75, 0},
                                            {-2, 0.75, 0}, {0, 0.75, 0});
  expect_within_at(min_separation_oracle(q, 0.75), Rational(1, 4));
  expect_within_at(min_separation_oracle(q, 1.25), Rational(1, 8));
  expect_not_within(min_separation_oracle(q, below(0.75)));
  // Collinear: the same slide on the x axis touches at t = 1/4.
  const EdgeEdgeQuery collinear =
      static_first_edge({0, 0, 0}, {4, 0, 0}, {6, 0, 0}, {8, 0, 0}, {-2, 0, 0}, {0, 0, 0});
  expect_within_at(min_separation_oracle(collinear, 0.0), Rational(1, 4));
}

// Edge a = [-2, 2] on the x axis; edge b along y (y in [-2, 2]) at x = 0, descending
// z = 1 - 2t: the interiors cross at t = 1/2, and are 1/4 apart at t = 3/8.
TEST(MinSeparationOracle, CrossingSkewEdges) {
  const EdgeEdgeQuery q =
      static_first_edge({-2, 0, 0}, {2, 0, 0}, {0, -2, 1}, {0, 2, 1}, {0, -2, -1}, {0, 2, -1});
  expect_within_at(min_separation_oracle(q, 0.0), Rational(1, 2));
  expect_within_at(min_separation_oracle(q, 0.25), Rational(3, 8));
  expect_within_at(min_separation_oracle(q, 1.0), Rational(0));
}

// Edge b at height 3/4, perpendicular to a, slides along x from -5 to 3: distance 3/4
// once x >= -2, i.e. t >= 3/8.
TEST(MinSeparationOracle, SkewEdgesPassingAtConstantHeight) {
  const EdgeEdgeQuery q = static_first_edge({-2, 0, 0}, {2, 0, 0}, {-5, -2, 0.75}, {-5, 2, 0.75},
                                            {3, -2, 0.75}, {3, 2, 0.75});
  expect_within_at(min_separation_oracle(q, 0.75), Rational(3, 8));
  expect_not_within(min_separation_oracle(q, below(0.75)));
}

// Edge b (along y, y in [-2, 2]) at x = c(t) = -13/4 + 5t/2, z = 15t/8, passes the end
// (-2, 0, 0) of a: squared distance (c + 2)^2 + z^2 while c <= -2, least 9/16 at t = 8/25,
// and z >= 15/16 afterwards.
TEST(MinSeparationOracle, SkewEdgesPassingAnEndpoint) {
  const EdgeEdgeQuery q = static_first_edge({-2, 0, 0}, {2, 0, 0}, {-3.25, -2, 0}, {-3.25, 2, 0},
                                            {-0.75, -2, 1.875}, {-0.75, 2, 1.875});
  expect_within_at(min_separation_oracle(q, 0.75), Rational(8, 25));
  expect_not_within(min_separation_oracle(q, below(0.75)));
  expect_brackets_eight_minus_two_root_seven_over_25(min_separation_oracle(q, 1.0));
}

// Zero-length edges: a point moving from (5/4, 0, 0) to (-5/4, 0, 15/8) against the origin
// (a zero-length edge) and against the segment [(0,-2,0), (0,2,0)].
TEST(MinSeparationOracle, ZeroLengthEdges) {
  const Point3 p0{1.25, 0, 0}, p1{-1.25, 0, 1.875}, o{0, 0, 0};
  const EdgeEdgeQuery points{p0, p0, o, o, p1, p1, o, o};
  expect_within_at(min_separation_oracle(points, 0.75), Rational(8, 25));
  expect_not_within(min_separation_oracle(points, below(0.75)));
  const EdgeEdgeQuery point_segment{p0, p0, {0, -2, 0}, {0, 2, 0}, p1, p1, {0, -2, 0}, {0, 2, 0}};
  expect_within_at(min_separation_oracle(point_segment, 0.75), Rational(8, 25));
  expect_not_within(min_separation_oracle(point_segment, below(0.75)));
  expect_brackets_eight_minus_two_root_seven_over_25(min_separation_oracle(point_segment, 1.0));
}

// Edge a = [-2, 2] on the x axis; edge b in the plane x = 0 from (y, z) = (-1 - t, 1 - 2t)
// to (1, 1 - 3t). Both edges can only meet at the origin, which is on b iff
// y0 z1 - y1 z0 = 3t^2 + 4t - 2 = 0 (b crosses y = 0 between its ends since y0 < 0 < y1):
// the distance 0 is attained only at the irrational t = (sqrt(10) - 2) / 3.
TEST(MinSeparationOracle, TouchingAtAnIrrationalTime) {
  const EdgeEdgeQuery q =
      static_first_edge({-2, 0, 0}, {2, 0, 0}, {0, -1, 1}, {0, 1, 1}, {0, -2, -1}, {0, 1, -2});
  const MinSeparationAnswer a = min_separation_oracle(q, 0.0);
  ASSERT_TRUE(a.within);
  EXPECT_LT(a.earliest_lo, a.earliest_hi);
  EXPECT_LE(a.earliest_hi - a.earliest_lo, Rational(1) / Rational(mpz_class(1) << 80));
  // lo <= (sqrt(10) - 2) / 3 <= hi  <=>  (3 lo + 2)^2 <= 10 <= (3 hi + 2)^2.
  const Rational left = 3 * a.earliest_lo + 2, right = 3 * a.earliest_hi + 2;
  EXPECT_LE(left * left, 10);
  EXPECT_GE(right * right, 10);
  EXPECT_NEAR(a.earliest_lo.get_d(), (std::sqrt(10.0) - 2.0) / 3.0, 1e-15);
}

// Scaling every coordinate and delta by 2^k, or translating by a large dyadic vector, is
// exact in double and leaves the set S unchanged.
TEST(MinSeparationOracle, ExactUnderScalingAndTranslation) {
  const VertexFaceQuery base = vertex_past_edge();
  for (const int k : {-600, -60, -20, 20, 60, 600}) {
    SCOPED_TRACE(::testing::Message() << "scale 2^" << k);
    auto scale = [k](const Point3& p) { return exactgeo::testing::scaled(p, k); };
    const VertexFaceQuery q{scale(base.v_t0),  scale(base.f0_t0), scale(base.f1_t0),
                            scale(base.f2_t0), scale(base.v_t1),  scale(base.f0_t1),
                            scale(base.f1_t1), scale(base.f2_t1)};
    expect_within_at(min_separation_oracle(q, std::ldexp(0.75, k)), Rational(8, 25));
    expect_not_within(min_separation_oracle(q, below(std::ldexp(0.75, k))));
    expect_brackets_eight_minus_two_root_seven_over_25(
        min_separation_oracle(q, std::ldexp(1.0, k)));
  }
  auto shift = [](const Point3& p) {
    return Point3{p[0] + 1048576.0, p[1] - 4096.0, p[2] + 65536.0};
  };
  const VertexFaceQuery moved{shift(base.v_t0),  shift(base.f0_t0), shift(base.f1_t0),
                              shift(base.f2_t0), shift(base.v_t1),  shift(base.f0_t1),
                              shift(base.f1_t1), shift(base.f2_t1)};
  expect_within_at(min_separation_oracle(moved, 0.75), Rational(8, 25));
  expect_not_within(min_separation_oracle(moved, below(0.75)));
  expect_brackets_eight_minus_two_root_seven_over_25(min_separation_oracle(moved, 1.0));
}

TEST(MinSeparationOracle, RejectsInvalidInput) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const VertexFaceQuery vf = vertex_past_edge();
  EXPECT_THROW(min_separation_oracle(vf, -1.0), std::invalid_argument);
  EXPECT_THROW(min_separation_oracle(vf, nan), std::invalid_argument);
  EXPECT_THROW(min_separation_oracle(vf, inf), std::invalid_argument);
  VertexFaceQuery bad = vf;
  bad.f2_t1[1] = nan;
  EXPECT_THROW(min_separation_oracle(bad, 1.0), std::invalid_argument);
  EdgeEdgeQuery ee =
      static_first_edge({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {0, 1, 0}, {1, 1, 0});
  EXPECT_NO_THROW(min_separation_oracle(ee, 0.0));
  EXPECT_THROW(min_separation_oracle(ee, -inf), std::invalid_argument);
  ee.eb0_t0[2] = inf;
  EXPECT_THROW(min_separation_oracle(ee, 1.0), std::invalid_argument);
}

// ---------------------------------------------------------------------------------------
// Randomized consistency.

/// Small-integer points, with some coincident, collinear or static ones.
Point3 random_small_point(Rng& rng) {
  return exactgeo::testing::integer_point(rng, 3);
}

VertexFaceQuery random_vertex_face(Rng& rng) {
  VertexFaceQuery q{};
  std::array<Point3*, 8> points{&q.v_t0, &q.f0_t0, &q.f1_t0, &q.f2_t0,
                                &q.v_t1, &q.f0_t1, &q.f1_t1, &q.f2_t1};
  for (Point3* p : points)
    *p = random_small_point(rng);
  switch (exactgeo::testing::uniform_int(rng, 0, 5)) {
    case 0:  // f0 = f1 throughout
      q.f1_t0 = q.f0_t0, q.f1_t1 = q.f0_t1;
      break;
    case 1:  // a static triangle
      q.f0_t1 = q.f0_t0, q.f1_t1 = q.f1_t0, q.f2_t1 = q.f2_t0;
      break;
    case 2:  // f2 the midpoint of f0 f1 at t = 0 (collinear then)
      for (std::size_t i = 0; i < 3; ++i)
        q.f2_t0[i] = (q.f0_t0[i] + q.f1_t0[i]) / 2;
      break;
    default:
      break;
  }
  return q;
}

EdgeEdgeQuery random_edge_edge(Rng& rng) {
  EdgeEdgeQuery q{};
  std::array<Point3*, 8> points{&q.ea0_t0, &q.ea1_t0, &q.eb0_t0, &q.eb1_t0,
                                &q.ea0_t1, &q.ea1_t1, &q.eb0_t1, &q.eb1_t1};
  for (Point3* p : points)
    *p = random_small_point(rng);
  switch (exactgeo::testing::uniform_int(rng, 0, 5)) {
    case 0:  // edge a of zero length throughout
      q.ea1_t0 = q.ea0_t0, q.ea1_t1 = q.ea0_t1;
      break;
    case 1:  // parallel edges at t = 0 and t = 1
      for (std::size_t i = 0; i < 3; ++i) {
        q.eb1_t0[i] = q.eb0_t0[i] + (q.ea1_t0[i] - q.ea0_t0[i]);
        q.eb1_t1[i] = q.eb0_t1[i] - (q.ea1_t1[i] - q.ea0_t1[i]);
      }
      break;
    case 2:  // edge b static
      q.eb0_t1 = q.eb0_t0, q.eb1_t1 = q.eb1_t0;
      break;
    default:
      break;
  }
  return q;
}

/// The sum of the L1 lengths of all displacements x_t1 - x_t0: a Lipschitz constant of
/// the distance in t (every point of either primitive moves at most as far as the
/// farthest-moving of its corners, and the Euclidean length is at most the L1 length).
Rational lipschitz_bound(const std::array<Point3, 8>& t0, const std::array<Point3, 8>& t1) {
  Rational sum = 0;
  for (std::size_t i = 0; i < 8; ++i) {
    for (std::size_t j = 0; j < 3; ++j)
      sum += abs(Rational(t1[i][j]) - Rational(t0[i][j]));
  }
  return sum;
}
Rational lipschitz_bound(const VertexFaceQuery& q) {
  return lipschitz_bound({q.v_t0, q.f0_t0, q.f1_t0, q.f2_t0, q.v_t0, q.f0_t0, q.f1_t0, q.f2_t0},
                         {q.v_t1, q.f0_t1, q.f1_t1, q.f2_t1, q.v_t0, q.f0_t0, q.f1_t0, q.f2_t0});
}
Rational lipschitz_bound(const EdgeEdgeQuery& q) {
  return lipschitz_bound(
      {q.ea0_t0, q.ea1_t0, q.eb0_t0, q.eb1_t0, q.ea0_t0, q.ea1_t0, q.eb0_t0, q.eb1_t0},
      {q.ea0_t1, q.ea1_t1, q.eb0_t1, q.eb1_t1, q.ea0_t0, q.ea1_t0, q.eb0_t0, q.eb1_t0});
}

/// Checks an answer against exact distances at the times k/64: a time within delta must
/// be in S (so within, and not below earliest_lo), a time below earliest_lo must not be.
/// Conversely, an exact earliest time must be within delta, and an isolating interval
/// must have dist(lo) <= delta + L (hi - lo) for the Lipschitz constant L above.
template <class Query>
void check_against_samples(const Query& q, double delta, const MinSeparationAnswer& a) {
  const Rational delta2 = squared(delta);
  for (int k = 0; k <= 64; ++k) {
    const Rational t(k, 64);
    const bool close = distance2_at(q, t) <= delta2;
    if (close) {
      ASSERT_TRUE(a.within) << "t = " << t.get_str() << " is within delta " << delta;
    }
    if (a.within && t < a.earliest_lo) {
      ASSERT_FALSE(close) << "t = " << t.get_str() << " is within delta " << delta
                          << " before the earliest time " << a.earliest_lo.get_str();
    }
  }
  if (a.within) {
    ASSERT_LE(a.earliest_lo, a.earliest_hi);
    ASSERT_GE(a.earliest_lo, 0);
    ASSERT_LE(a.earliest_hi, 1);
    if (a.earliest_lo == a.earliest_hi) {
      ASSERT_LE(distance2_at(q, a.earliest_lo), delta2)
          << "exact earliest time " << a.earliest_lo.get_str();
    } else {
      const Rational width = a.earliest_hi - a.earliest_lo;
      ASSERT_LE(width, Rational(1) / Rational(mpz_class(1) << 80));
      const Rational reach = Rational(delta) + lipschitz_bound(q) * width;
      ASSERT_LE(distance2_at(q, a.earliest_lo), reach * reach)
          << "earliest interval starting at " << a.earliest_lo.get_str();
    }
  }
}

/// Two answers for the same set S (a relabelled query): the same decision and overlapping
/// earliest brackets.
void expect_same_set(const MinSeparationAnswer& a, const MinSeparationAnswer& b) {
  ASSERT_EQ(a.within, b.within);
  if (!a.within) return;
  EXPECT_LE(a.earliest_lo, b.earliest_hi);
  EXPECT_LE(b.earliest_lo, a.earliest_hi);
}

/// delta <= larger: S(delta) is a subset of S(larger).
void expect_monotone(const MinSeparationAnswer& smaller, const MinSeparationAnswer& larger) {
  if (!smaller.within) return;
  ASSERT_TRUE(larger.within);
  EXPECT_LE(larger.earliest_lo, smaller.earliest_hi);
}

double random_delta(Rng& rng) {
  return exactgeo::testing::uniform_int(rng, 0, 12) / 4.0;
}

TEST(MinSeparationOracle, RandomVertexFaceConsistency) {
  Rng rng = exactgeo::testing::seeded_engine("min_separation_oracle");
  const auto iterations = static_cast<int>(exactgeo::testing::scaled_trials(120));
  for (int iteration = 0; iteration < iterations; ++iteration) {
    const VertexFaceQuery q = random_vertex_face(rng);
    const double delta = random_delta(rng), larger = delta + random_delta(rng) + 0.25;
    const MinSeparationAnswer a = min_separation_oracle(q, delta);
    SCOPED_TRACE(::testing::Message() << "iteration " << iteration << ", delta " << delta);
    check_against_samples(q, delta, a);
    const MinSeparationAnswer b = min_separation_oracle(q, larger);
    check_against_samples(q, larger, b);
    expect_monotone(a, b);
    // Relabelling the triangle's corners does not change the point set.
    const VertexFaceQuery rotated{q.v_t0, q.f1_t0, q.f2_t0, q.f0_t0,
                                  q.v_t1, q.f1_t1, q.f2_t1, q.f0_t1};
    const VertexFaceQuery mirrored{q.v_t0, q.f0_t0, q.f2_t0, q.f1_t0,
                                   q.v_t1, q.f0_t1, q.f2_t1, q.f1_t1};
    expect_same_set(a, min_separation_oracle(rotated, delta));
    expect_same_set(a, min_separation_oracle(mirrored, delta));
  }
}

TEST(MinSeparationOracle, RandomEdgeEdgeConsistency) {
  Rng rng = exactgeo::testing::seeded_engine("min_separation_oracle.edge_edge");
  const auto iterations = static_cast<int>(exactgeo::testing::scaled_trials(120));
  for (int iteration = 0; iteration < iterations; ++iteration) {
    const EdgeEdgeQuery q = random_edge_edge(rng);
    const double delta = random_delta(rng), larger = delta + random_delta(rng) + 0.25;
    const MinSeparationAnswer a = min_separation_oracle(q, delta);
    SCOPED_TRACE(::testing::Message() << "iteration " << iteration << ", delta " << delta);
    check_against_samples(q, delta, a);
    const MinSeparationAnswer b = min_separation_oracle(q, larger);
    check_against_samples(q, larger, b);
    expect_monotone(a, b);
    // Swapping the edges, or the ends of an edge, does not change the point sets.
    const EdgeEdgeQuery swapped{q.eb0_t0, q.eb1_t0, q.ea0_t0, q.ea1_t0,
                                q.eb0_t1, q.eb1_t1, q.ea0_t1, q.ea1_t1};
    const EdgeEdgeQuery reversed{q.ea1_t0, q.ea0_t0, q.eb0_t0, q.eb1_t0,
                                 q.ea1_t1, q.ea0_t1, q.eb0_t1, q.eb1_t1};
    expect_same_set(a, min_separation_oracle(swapped, delta));
    expect_same_set(a, min_separation_oracle(reversed, delta));
  }
}

// All points translate by the same vector: the distance is constant, so the answer is the
// static distance at t = 0, first reached at t = 0.
TEST(MinSeparationOracle, RigidTranslationKeepsTheStaticDistance) {
  Rng rng = exactgeo::testing::seeded_engine("min_separation_oracle.translation");
  auto moved = [](const Point3& p, const Point3& d) {
    return Point3{p[0] + d[0], p[1] + d[1], p[2] + d[2]};
  };
  for (int iteration = 0; iteration < 100; ++iteration) {
    SCOPED_TRACE(::testing::Message() << "iteration " << iteration);
    const Point3 d = random_small_point(rng);
    const double delta = random_delta(rng);
    const VertexFaceQuery base = random_vertex_face(rng);
    const VertexFaceQuery vf{
        base.v_t0,           base.f0_t0,           base.f1_t0,           base.f2_t0,
        moved(base.v_t0, d), moved(base.f0_t0, d), moved(base.f1_t0, d), moved(base.f2_t0, d)};
    const MinSeparationAnswer a = min_separation_oracle(vf, delta);
    ASSERT_EQ(a.within, distance2_at(vf, 0) <= squared(delta));
    if (a.within) expect_within_at(a, Rational(0));

    const EdgeEdgeQuery e = random_edge_edge(rng);
    const EdgeEdgeQuery ee{e.ea0_t0,           e.ea1_t0,           e.eb0_t0,
                           e.eb1_t0,           moved(e.ea0_t0, d), moved(e.ea1_t0, d),
                           moved(e.eb0_t0, d), moved(e.eb1_t0, d)};
    const MinSeparationAnswer b = min_separation_oracle(ee, delta);
    ASSERT_EQ(b.within, distance2_at(ee, 0) <= squared(delta));
    if (b.within) expect_within_at(b, Rational(0));
  }
}

// Arbitrary doubles (long dyadic fractions): the answer still agrees with the samples.
TEST(MinSeparationOracle, RandomDoublesAgreeWithSamples) {
  Rng rng = exactgeo::testing::seeded_engine("min_separation_oracle.doubles");
  const auto iterations = static_cast<int>(exactgeo::testing::scaled_trials(30));
  for (int iteration = 0; iteration < iterations; ++iteration) {
    SCOPED_TRACE(::testing::Message() << "iteration " << iteration);
    const double delta = exactgeo::testing::uniform(rng, 0.0, 1.0);
    const VertexFaceQuery vf{
        exactgeo::testing::random_point(rng), exactgeo::testing::random_point(rng),
        exactgeo::testing::random_point(rng), exactgeo::testing::random_point(rng),
        exactgeo::testing::random_point(rng), exactgeo::testing::random_point(rng),
        exactgeo::testing::random_point(rng), exactgeo::testing::random_point(rng)};
    check_against_samples(vf, delta, min_separation_oracle(vf, delta));
    const EdgeEdgeQuery ee{
        exactgeo::testing::random_point(rng), exactgeo::testing::random_point(rng),
        exactgeo::testing::random_point(rng), exactgeo::testing::random_point(rng),
        exactgeo::testing::random_point(rng), exactgeo::testing::random_point(rng),
        exactgeo::testing::random_point(rng), exactgeo::testing::random_point(rng)};
    check_against_samples(ee, delta, min_separation_oracle(ee, delta));
  }
}

}  // namespace
