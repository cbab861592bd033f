// Ray-triangle classification: every outcome by hand, then against the independent
// rational oracle on generic, dense dyadic (exactly degenerate) and scaled inputs.

#include "exactgeo/predicates/ray_triangle.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "support/generators.hpp"
#include "support/rational_oracle.hpp"
#include "support/seed.hpp"

namespace exactgeo {
namespace {

using testing::Rng;

const Point3 kA{0, 0, 0}, kB{4, 0, 0}, kC{0, 4, 0};  // in the plane z = 0, normal +z

RayTriangleHit hit(const Point3& o, const Vector3& d) {
  return classify_ray_triangle(o, d, kA, kB, kC);
}

void expect_hit(const RayTriangleHit& h, RayTriangle kind, int feature = 0,
                Sign turn = Sign::zero) {
  EXPECT_EQ(h.kind, kind);
  EXPECT_EQ(h.feature, feature);
  EXPECT_EQ(h.turn, turn);
}

TEST(RayTriangle, TransversalOutcomes) {
  expect_hit(hit({1, 1, -1}, {0, 0, 1}), RayTriangle::interior, 0, Sign::positive);
  expect_hit(hit({1, 1, 1}, {0, 0, -1}), RayTriangle::interior, 0, Sign::negative);
  expect_hit(hit({1, 1, 1}, {0, 0, 1}), RayTriangle::miss);                      // pointing away
  expect_hit(hit({9, 9, -1}, {0, 0, 1}), RayTriangle::miss);                     // beside
  expect_hit(hit({2, 0, -1}, {0, 0, 1}), RayTriangle::edge, 0, Sign::positive);  // ab
  expect_hit(hit({2, 2, -1}, {0, 0, 1}), RayTriangle::edge, 1, Sign::positive);  // bc
  expect_hit(hit({0, 2, -1}, {0, 0, 1}), RayTriangle::edge, 2, Sign::positive);  // ca
  expect_hit(hit({0, 0, -1}, {0, 0, 1}), RayTriangle::vertex, 0, Sign::positive);
  expect_hit(hit({4, 0, -1}, {0, 0, 1}), RayTriangle::vertex, 1, Sign::positive);
  expect_hit(hit({0, 4, 1}, {0, 0, -1}), RayTriangle::vertex, 2, Sign::negative);
  expect_hit(hit({-1, 1, -1}, {1, 0, 1}), RayTriangle::edge, 2, Sign::positive);  // slanted
}

TEST(RayTriangle, OriginOnTheTriangle) {
  expect_hit(hit({1, 1, 0}, {0, 0, 1}), RayTriangle::origin_on);
  expect_hit(hit({2, 0, 0}, {0, 0, -1}), RayTriangle::origin_on);  // on an edge
  expect_hit(hit({4, 0, 0}, {1, 2, 3}), RayTriangle::origin_on);   // on a vertex
  expect_hit(hit({1, 1, 0}, {1, 0, 0}), RayTriangle::origin_on);   // and the ray in the plane
}

TEST(RayTriangle, RayInThePlane) {
  expect_hit(hit({-1, 1, 0}, {1, 0, 0}), RayTriangle::coplanar);   // enters through ca
  expect_hit(hit({-1, 1, 0}, {-1, 0, 0}), RayTriangle::miss);      // away from it
  expect_hit(hit({-1, -1, 0}, {1, 1, 0}), RayTriangle::coplanar);  // through vertex a
  expect_hit(hit({-1, 0, 0}, {1, 0, 0}), RayTriangle::coplanar);   // along edge ab
  expect_hit(hit({5, 5, 0}, {1, 0, 0}), RayTriangle::miss);
  expect_hit(hit({1, 1, 1}, {1, 0, 0}), RayTriangle::miss);  // parallel, off the plane
}

TEST(RayTriangle, DegenerateTriangles) {
  const Point3 p{0, 0, 0}, q{2, 0, 0}, r{4, 0, 0};  // collinear
  EXPECT_EQ(classify_ray_triangle({1, 0, -1}, {0, 0, 1}, p, q, r).kind, RayTriangle::coplanar);
  EXPECT_EQ(classify_ray_triangle({1, 1, -1}, {0, 0, 1}, p, q, r).kind, RayTriangle::miss);
  EXPECT_EQ(classify_ray_triangle({3, 0, 0}, {0, 0, 1}, p, q, r).kind, RayTriangle::origin_on);
  EXPECT_EQ(classify_ray_triangle({5, 0, 0}, {1, 0, 0}, p, q, r).kind, RayTriangle::miss);
  EXPECT_EQ(classify_ray_triangle({5, 0, 0}, {-1, 0, 0}, p, q, r).kind, RayTriangle::coplanar);
  EXPECT_EQ(classify_ray_triangle({1, 1, 1}, {0, -1, -1}, p, p, p).kind, RayTriangle::miss);
  EXPECT_EQ(classify_ray_triangle({1, 1, 1}, {-1, -1, -1}, p, p, p).kind, RayTriangle::coplanar);
  EXPECT_EQ(classify_ray_triangle(p, {-1, -1, -1}, p, p, p).kind, RayTriangle::origin_on);
}

std::string describe(const Point3& o, const Vector3& d, const Point3& a, const Point3& b,
                     const Point3& c) {
  char buf[512];
  std::snprintf(buf, sizeof buf, "o=(%a,%a,%a) d=(%a,%a,%a) a=(%a,%a,%a) b=(%a,%a,%a) c=(%a,%a,%a)",
                o[0], o[1], o[2], d[0], d[1], d[2], a[0], a[1], a[2], b[0], b[1], b[2], c[0], c[1],
                c[2]);
  return buf;
}

void expect_matches_oracle(const Point3& o, const Vector3& d, const Point3& a, const Point3& b,
                           const Point3& c) {
  const RayTriangleHit expected = testing::ray_triangle_oracle(o, d, a, b, c);
  for (const Arithmetic arithmetic : {Arithmetic::exact, Arithmetic::rational}) {
    const RayTriangleHit got = classify_ray_triangle(o, d, a, b, c, arithmetic);
    ASSERT_EQ(got.kind, expected.kind) << describe(o, d, a, b, c);
    ASSERT_EQ(got.feature, expected.feature) << describe(o, d, a, b, c);
    ASSERT_EQ(got.turn, expected.turn) << describe(o, d, a, b, c);
  }
}

TEST(RayTriangle, GenericInputsAgreeWithOracle) {
  Rng rng = testing::seeded_engine("ray-triangle-generic");
  for (int i = 0; i < 5000; ++i) {
    expect_matches_oracle(testing::random_point(rng), testing::random_point(rng),
                          testing::random_point(rng), testing::random_point(rng),
                          testing::random_point(rng));
  }
}

/// Small integers make exact degeneracies common: rays through edges and vertices, rays in
/// the plane, origins on the triangle, degenerate triangles.
TEST(RayTriangle, DenseDyadicInputsAgreeWithOracle) {
  Rng rng = testing::seeded_engine("ray-triangle-dyadic");
  int counts[6] = {};
  for (int i = 0; i < 60000; ++i) {
    const Point3 o = testing::integer_point(rng, 2);
    const Vector3 d = testing::nonzero_integer_direction(rng, 2);
    const Point3 a = testing::integer_point(rng, 2), b = testing::integer_point(rng, 2),
                 c = testing::integer_point(rng, 2);
    expect_matches_oracle(o, d, a, b, c);
    ++counts[static_cast<int>(classify_ray_triangle(o, d, a, b, c).kind)];
  }
  for (int k = 0; k < 6; ++k)
    EXPECT_GT(counts[k], 100) << "outcome " << k << " barely exercised";
}

TEST(RayTriangle, ScalingByPowersOfTwoChangesNothing) {
  Rng rng = testing::seeded_engine("ray-triangle-scaled");
  for (int i = 0; i < 3000; ++i) {
    const Point3 o = testing::integer_point(rng, 3), a = testing::integer_point(rng, 3),
                 b = testing::integer_point(rng, 3), c = testing::integer_point(rng, 3);
    const Vector3 d = testing::nonzero_integer_direction(rng, 3);
    const RayTriangleHit reference = classify_ray_triangle(o, d, a, b, c);
    const int k = testing::uniform_int(rng, -1070, 1018);
    const int kd = testing::uniform_int(rng, -1070, 1018);  // the direction scales freely
    const RayTriangleHit s =
        classify_ray_triangle(testing::scaled(o, k), testing::scaled(d, kd), testing::scaled(a, k),
                              testing::scaled(b, k), testing::scaled(c, k));
    ASSERT_EQ(s.kind, reference.kind) << "k=" << k << " kd=" << kd;
    ASSERT_EQ(s.feature, reference.feature);
    ASSERT_EQ(s.turn, reference.turn);
  }
}

TEST(RayTriangle, RelabellingTheCornersRelabelsTheAnswer) {
  Rng rng = testing::seeded_engine("ray-triangle-relabel");
  for (int i = 0; i < 5000; ++i) {
    const Point3 o = testing::integer_point(rng, 2), a = testing::integer_point(rng, 2),
                 b = testing::integer_point(rng, 2), c = testing::integer_point(rng, 2);
    const Vector3 d = testing::nonzero_integer_direction(rng, 2);
    const RayTriangleHit h = classify_ray_triangle(o, d, a, b, c);
    // Cyclic shift (b, c, a): features shift by one, turn unchanged.
    const RayTriangleHit shifted = classify_ray_triangle(o, d, b, c, a);
    EXPECT_EQ(shifted.kind, h.kind);
    EXPECT_EQ(shifted.turn, h.turn);
    if (h.kind == RayTriangle::edge || h.kind == RayTriangle::vertex) {
      EXPECT_EQ(shifted.feature, (h.feature + 2) % 3);
    }
    // Reversed orientation (a, c, b): turn flips.
    const RayTriangleHit reversed = classify_ray_triangle(o, d, a, c, b);
    EXPECT_EQ(reversed.kind, h.kind);
    EXPECT_EQ(reversed.turn, -h.turn);
  }
}

}  // namespace
}  // namespace exactgeo
