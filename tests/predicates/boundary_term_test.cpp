// The certified boundary term of the generalized winding number (boundary_term.hpp),
// against the definition: for one triangle, w(p) = Omega(p) / 4 pi computed in 512-bit
// MPFR from the solid angle alone (support/solid_angle_oracle.hpp), and the ray's signed
// crossing S from the rational ray-triangle oracle. At every precision that encloses
// the term, the enclosure must hold w - S. Inputs: random, points near the triangle's
// edges and one ulp off them, points a subnormal step off the face (w one part in 2^1074
// from +-1/2), rays that pass near a boundary edge (the branch cut), at scales 2^0 and
// 2^+-1000; and the cases with an exact answer: a ray through a boundary edge, a point on
// one, and a point of w exactly 1/2, which no precision may decide.

#include "exactgeo/predicates/boundary_term.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "exactgeo/predicates/ray_directions.hpp"
#include "support/generators.hpp"
#include "support/rational_oracle.hpp"
#include "support/scale_names.hpp"
#include "support/seed.hpp"
#include "support/solid_angle_oracle.hpp"

namespace exactgeo {
namespace {

using testing::Triangle;

std::string hex(const Point3& p) {
  char buf[160];
  std::snprintf(buf, sizeof buf, "(%a, %a, %a)", p[0], p[1], p[2]);
  return buf;
}

constexpr std::array<BoundaryEdge, 3> kTriangleBoundary{
    BoundaryEdge{0, 1, 1}, BoundaryEdge{1, 2, 1}, BoundaryEdge{2, 0, 1}};

/// The signed crossing count of the first ray of the sequence that meets the triangle
/// transversally or not at all, by the rational oracle, and that ray; nullopt when the
/// point lies on the triangle.
struct Ray {
  Vector3 direction;
  std::int64_t crossings;
};
std::optional<Ray> first_clean_ray(const Point3& p, const Triangle& t) {
  for (std::size_t k = 0;; ++k) {
    const Vector3 r = ray_direction(k);
    const RayTriangleHit hit = testing::ray_triangle_oracle(p, r, t[0], t[1], t[2]);
    switch (hit.kind) {
      case RayTriangle::miss:
        return Ray{r, 0};
      case RayTriangle::interior:
        return Ray{r, to_int(hit.turn)};
      case RayTriangle::origin_on:
        return std::nullopt;
      default:
        break;  // through an edge or a vertex, or in the plane: the next ray
    }
  }
}

struct Tally {
  std::size_t cases = 0;
  std::size_t by_doubles = 0;  ///< enclosed by the double stage
  std::size_t by_mpfr = 0;     ///< enclosed first by an MPFR stage
  std::size_t never = 0;       ///< enclosed by no stage
};

/// Every stage that encloses the term holds the definition's w - S.
void expect_certified(const Point3& p, const Triangle& t, Tally& tally) {
  const auto ray = first_clean_ray(p, t);
  if (!ray) return;
  const double truth =
      testing::generalized_winding_oracle(p, std::span(&t, 1), static_cast<double>(ray->crossings));
  ++tally.cases;
  bool enclosed_before = false;
  for (const unsigned bits : kBoundaryTermPrecisions) {
    const BoundaryTerm term = boundary_term(p, ray->direction, t, kTriangleBoundary, bits);
    ASSERT_NE(term.kind, BoundaryTermKind::ray_on_edge) << hex(p);
    ASSERT_NE(term.kind, BoundaryTermKind::point_on_edge) << hex(p);
    if (term.kind != BoundaryTermKind::enclosed) continue;
    // The oracle's double is within half an ulp of w - S.
    ASSERT_LE(term.turns.lower, std::nextafter(truth, 1.0))
        << "point " << hex(p) << ", " << bits << " bits, S " << ray->crossings;
    ASSERT_GE(term.turns.upper, std::nextafter(truth, -1.0))
        << "point " << hex(p) << ", " << bits << " bits, S " << ray->crossings;
    if (!enclosed_before) (bits == 53 ? tally.by_doubles : tally.by_mpfr) += 1;
    enclosed_before = true;
  }
  tally.never += !enclosed_before;
}

Triangle scaled(const Triangle& t, int k) {
  return {testing::scaled(t[0], k), testing::scaled(t[1], k), testing::scaled(t[2], k)};
}

/// Corners of small integer coordinates, scaled by 2^k: exactly degenerate cases come easily.
Triangle integer_triangle(testing::Rng& rng, int k) {
  return scaled({testing::integer_point(rng, 8), testing::integer_point(rng, 8),
                 testing::integer_point(rng, 8)},
                k);
}

class BoundaryTermScales : public ::testing::TestWithParam<int> {};

TEST_P(BoundaryTermScales, RandomPointsAndTriangles) {
  const int k = GetParam();
  auto rng = testing::seeded_engine("predicates.boundary_term.random." + std::to_string(k));
  Tally tally;
  for (int i = 0; i < 400; ++i) {
    const Triangle t = scaled(
        {testing::random_point(rng), testing::random_point(rng), testing::random_point(rng)}, k);
    expect_certified(testing::scaled(testing::random_point(rng, 2.0), k), t, tally);
    ASSERT_FALSE(HasFatalFailure());
  }
  EXPECT_GT(tally.cases, 350u);
  EXPECT_GE(tally.by_doubles, tally.cases * 95 / 100) << "doubles enclose the term far from edges";
}

TEST_P(BoundaryTermScales, PointsNearTheEdgesAndOneUlpOff) {
  const int k = GetParam();
  auto rng = testing::seeded_engine("predicates.boundary_term.edges." + std::to_string(k));
  Tally tally;
  for (int i = 0; i < 200; ++i) {
    const Triangle t = integer_triangle(rng, k);
    const int e = testing::uniform_int(rng, 0, 2);
    const Point3& a = t[e];
    const Point3& b = t[(e + 1) % 3];
    // A point of the edge's line (rounded), moved by whole ulps or by 2^-m of the size.
    const double s = testing::uniform(rng, -0.5, 1.5);
    Point3 p = testing::rounded_affine(a, b, b, s, 0.0);
    if (i % 2 == 0) {
      p = testing::ulp_step(p, testing::uniform_int(rng, 0, 2), testing::uniform_int(rng, -2, 2));
    } else {
      for (double& x : p)
        x += std::ldexp(testing::uniform(rng, -1, 1), k - testing::uniform_int(rng, 10, 50));
    }
    expect_certified(p, t, tally);
    ASSERT_FALSE(HasFatalFailure());
  }
  EXPECT_GT(tally.cases, 150u);
  EXPECT_GT(tally.by_mpfr, 0u) << "some points near an edge need more than doubles";
}

TEST_P(BoundaryTermScales, PointsASubnormalStepOffTheFace) {
  // The triangle in the plane z = 0 and p above an interior point by 2^-1074 (2^-74 at
  // scale 2^1000): w = +-1/2 minus a part in 2^1074, which only the last stage resolves.
  const int k = GetParam();
  auto rng = testing::seeded_engine("predicates.boundary_term.face." + std::to_string(k));
  Tally tally;
  for (int i = 0; i < 40; ++i) {
    const Triangle t = scaled({Point3{0, 0, 0}, Point3{4, 0, 0}, Point3{0, 4, 0}}, k);
    const double z =
        (i % 2 ? 1 : -1) * std::ldexp(testing::uniform_int(rng, 1, 4), -1074 + std::max(k, 0));
    const Point3 p{std::ldexp(testing::uniform(rng, 0.1, 1.5), k),
                   std::ldexp(testing::uniform(rng, 0.1, 1.5), k), z};
    expect_certified(p, t, tally);
    ASSERT_FALSE(HasFatalFailure());
    // |w| < 1/2 (the point is off the face): the last stage is precise enough to say so.
    // Below the face (z < 0) w = 1/2 - delta, above it -1/2 + delta; delta is 2^-1074 of
    // w at scales 2^0 and 2^1000, 2^-74 at 2^-1000.
    const auto ray = first_clean_ray(p, t);
    ASSERT_TRUE(ray);
    const auto s = static_cast<double>(ray->crossings);
    const BoundaryTerm last =
        boundary_term(p, ray->direction, t, kTriangleBoundary,
                      std::end(kBoundaryTermPrecisions)[-1], {-0.5 - s, 0.5 - s});
    ASSERT_EQ(last.kind, BoundaryTermKind::enclosed) << hex(p);
    EXPECT_EQ(last.versus[0], Versus::above) << hex(p);
    EXPECT_EQ(last.versus[1], Versus::below) << hex(p);
    // The double stage cannot see it, and says so.
    const BoundaryTerm first =
        boundary_term(p, ray->direction, t, kTriangleBoundary, 53, {-0.5 - s, 0.5 - s});
    EXPECT_EQ(first.versus[z < 0 ? 1 : 0], Versus::unsure) << hex(p);
  }
  EXPECT_EQ(tally.cases, 40u);
}

TEST_P(BoundaryTermScales, RaysNearABoundaryEdge) {
  // p = m - s r + tiny, m on an edge: the ray passes just beside the edge, where the
  // half angle is near its branch cut (the exact sign of det[a - p, b - p, -r] decides).
  const int k = GetParam();
  auto rng = testing::seeded_engine("predicates.boundary_term.cut." + std::to_string(k));
  Tally tally;
  for (int i = 0; i < 200; ++i) {
    const Triangle t = integer_triangle(rng, k);
    const int e = testing::uniform_int(rng, 0, 2);
    const Point3 m = testing::rounded_affine(t[e], t[(e + 1) % 3], t[e], 0.5, 0.0);
    const Vector3 r = ray_direction(0);
    const double s = std::ldexp(testing::uniform(rng, 0.1, 4.0), k);
    Point3 p{m[0] - s * r[0], m[1] - s * r[1], m[2] - s * r[2]};
    p = testing::ulp_step(p, testing::uniform_int(rng, 0, 2), testing::uniform_int(rng, -3, 3));
    expect_certified(p, t, tally);
    ASSERT_FALSE(HasFatalFailure());
  }
  EXPECT_GT(tally.cases, 150u);
}

/// Rays through an end of a boundary edge (a dyadic step along the ray, so the end lies on
/// it exactly), the edge's other end anywhere: every term along it is 0/0 at that edge, a
/// ray that meets the edge, never a precision to refine (once: undecided after 2048 bits,
/// where the edges of a dropped zero-area face left the ray unflagged). The next ray of
/// the sequence is enclosed, and holds the solid-angle oracle's w - S.
TEST_P(BoundaryTermScales, RaysThroughAnEndOfAnEdgeMeetTheEdge) {
  const int k = GetParam();
  testing::Rng rng = testing::seeded_engine("boundary-term-ray-through-end");
  Tally tally;
  for (int i = 0; i < 200; ++i) {
    const std::size_t ray = static_cast<std::size_t>(testing::uniform_int(rng, 0, 3));
    const Vector3 r = ray_direction(ray);
    const Point3 p = testing::integer_point(rng, 8);
    const double s = testing::uniform_int(rng, 1, 64) / 4.0;
    const Point3 on_ray{p[0] + s * r[0], p[1] + s * r[1], p[2] + s * r[2]};  // exact
    Triangle t{on_ray, testing::integer_point(rng, 8), testing::integer_point(rng, 8)};
    std::rotate(t.begin(), t.begin() + i % 3, t.end());  // the end at every corner
    const Triangle scaled_t = scaled(t, k);
    const Point3 scaled_p = testing::scaled(p, k);
    for (const unsigned bits : kBoundaryTermPrecisions) {
      const BoundaryTerm term = boundary_term(scaled_p, r, scaled_t, kTriangleBoundary, bits);
      // p on the face's plane is possible, on an edge only where the point is on it.
      ASSERT_TRUE(term.kind == BoundaryTermKind::ray_on_edge ||
                  term.kind == BoundaryTermKind::point_on_edge)
          << hex(scaled_p) << " ray " << ray << ", " << bits << " bits";
    }
    expect_certified(scaled_p, scaled_t, tally);
  }
  EXPECT_GT(tally.cases, 150u);
  EXPECT_EQ(tally.never, 0u);
}

/// The reproducer: an open triangle and, apart from it, a collinear (zero-area) triangle
/// whose edges are in the boundary chain, the first ray from (1, 1, 1) passing exactly
/// through its corner (9, 5/2, 41/32).
TEST(BoundaryTerm, ARayThroughTheCornerOfACollinearTriangleMeetsItsEdge) {
  const std::vector<Point3> v{{0, 0, 0},         {4, 0, 0},          {0, 4, 0},
                              {9, 2.5, 1.28125}, {10, 2.5, 1.28125}, {11, 2.5, 1.28125}};
  const std::vector<BoundaryEdge> chain{{0, 1, 1}, {1, 2, 1}, {2, 0, 1},
                                        {3, 4, 1}, {4, 5, 1}, {5, 3, 1}};
  const Point3 p{1, 1, 1};
  for (const unsigned bits : kBoundaryTermPrecisions) {
    EXPECT_EQ(boundary_term(p, ray_direction(0), v, chain, bits).kind,
              BoundaryTermKind::ray_on_edge)
        << bits << " bits";
  }
  // Along the next ray the collinear loop adds nothing: w - S is the open triangle's.
  const Vector3 r = ray_direction(1);
  const BoundaryTerm next = boundary_term(p, r, v, chain, 53);
  ASSERT_EQ(next.kind, BoundaryTermKind::enclosed);
  const Triangle t{v[0], v[1], v[2]};
  const RayTriangleHit hit = testing::ray_triangle_oracle(p, r, t[0], t[1], t[2]);
  ASSERT_TRUE(hit.kind == RayTriangle::miss || hit.kind == RayTriangle::interior);
  const double crossings = hit.kind == RayTriangle::interior ? to_int(hit.turn) : 0;
  const double w_minus_s = testing::generalized_winding_oracle(p, std::span(&t, 1), crossings);
  EXPECT_LE(next.turns.lower, std::nextafter(w_minus_s, 1.0));
  EXPECT_GE(next.turns.upper, std::nextafter(w_minus_s, -1.0));
}

INSTANTIATE_TEST_SUITE_P(Scales, BoundaryTermScales, ::testing::Values(0, 1000, -1000),
                         exactgeo::testing::scale_name);

TEST(BoundaryTerm, ARayThroughABoundaryEdgeIsNamed) {
  // The ray from p along r = (1, 3/16, 9/256) reaches the edge's midpoint m exactly.
  const Triangle t{Point3{0, 0, 0}, Point3{4, 2, 6}, Point3{-2, 8, 2}};
  const Point3 m{2, 1, 3};
  const Vector3 r = ray_direction(0);
  const Point3 p{m[0] - 256 * r[0], m[1] - 256 * r[1], m[2] - 256 * r[2]};
  for (const unsigned bits : kBoundaryTermPrecisions) {
    EXPECT_EQ(boundary_term(p, r, t, kTriangleBoundary, bits).kind, BoundaryTermKind::ray_on_edge)
        << bits << " bits";
  }
  // The same point seen along the next ray is enclosed.
  EXPECT_EQ(boundary_term(p, ray_direction(1), t, kTriangleBoundary, 53).kind,
            BoundaryTermKind::enclosed);
}

TEST(BoundaryTerm, APointOnABoundaryEdgeIsNamed) {
  const Triangle t{Point3{0, 0, 0}, Point3{4, 2, 6}, Point3{-2, 8, 2}};
  for (const Point3& p : {Point3{2, 1, 3}, t[1], Point3{-1, 4, 1}}) {
    for (const unsigned bits : kBoundaryTermPrecisions) {
      EXPECT_EQ(boundary_term(p, ray_direction(0), t, kTriangleBoundary, bits).kind,
                BoundaryTermKind::point_on_edge)
          << hex(p) << ", " << bits << " bits";
    }
  }
}

TEST(BoundaryTerm, AWindingNumberOfExactlyOneHalfIsNeverDecided) {
  // Three faces of the cube [-1, 1]^3 meeting at the corner (-1, -1, -1), as six
  // triangles; from the centre each covers a sixth of the sphere: w = +-1/2 exactly.
  const std::vector<Point3> v{{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                              {-1, -1, 1},  {1, -1, 1},  {-1, 1, 1}};
  // z = -1: 0 3 2 1; y = -1: 0 1 5 4; x = -1: 0 4 6 3 (each turning the same way about
  // the centre); the boundary loop 1 2 3 6 4 5 runs the other way round the corner.
  const std::vector<Triangle> triangles{{v[0], v[3], v[2]}, {v[0], v[2], v[1]}, {v[0], v[1], v[5]},
                                        {v[0], v[5], v[4]}, {v[0], v[4], v[6]}, {v[0], v[6], v[3]}};
  const std::vector<BoundaryEdge> loop{{3, 2, 1}, {2, 1, 1}, {1, 5, 1},
                                       {5, 4, 1}, {4, 6, 1}, {6, 3, 1}};
  const Point3 centre{0, 0, 0};
  const double w = testing::generalized_winding_oracle(centre, triangles);
  ASSERT_EQ(std::abs(w), 0.5);
  for (std::size_t k = 0; k < 4; ++k) {
    const Vector3 r = ray_direction(k);
    std::int64_t s = 0;
    for (const Triangle& t : triangles) {
      const RayTriangleHit hit = testing::ray_triangle_oracle(centre, r, t[0], t[1], t[2]);
      ASSERT_TRUE(hit.kind == RayTriangle::miss || hit.kind == RayTriangle::interior);
      s += hit.kind == RayTriangle::interior ? to_int(hit.turn) : 0;
    }
    for (const unsigned bits : kBoundaryTermPrecisions) {
      const BoundaryTerm term = boundary_term(centre, r, v, loop, bits);
      ASSERT_EQ(term.kind, BoundaryTermKind::enclosed) << bits << " bits";
      EXPECT_LE(term.turns.lower, w - static_cast<double>(s)) << bits << " bits, ray " << k;
      EXPECT_GE(term.turns.upper, w - static_cast<double>(s)) << bits << " bits, ray " << k;
      EXPECT_LT(term.turns.upper - term.turns.lower,
                std::max(std::ldexp(1.0, 40 - int(bits)), 0x1p-50));
    }
  }
}

}  // namespace
}  // namespace exactgeo
