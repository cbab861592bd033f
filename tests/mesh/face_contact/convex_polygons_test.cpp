// Two convex polygons (face_contact/convex_polygons.hpp, internal), called directly, past
// the filters that would settle most pairs first: triangles in one plane (z = 0, and
// z = x + 2 y) against the rational clipping oracle (support/coplanar_overlap_oracle.hpp):
// they intersect when they overlap with area and face the same way, or either way under
// CoplanarOverlap::intersecting; triangles in two planes whose interiors share a point
// (built through it) intersect, closed triangles that are disjoint (exact oracle) are
// apart, and a corner resting on the other's interior only touches; convex quads by hand.
// Every answer is the same with the faces swapped.

#include "../../../mesh/src/face_contact/convex_polygons.hpp"

#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

#include "mesh/face_contact/face_pairs.hpp"
#include "support/coplanar_overlap_oracle.hpp"
#include "support/seed.hpp"

namespace exactgeo::mesh::internal {
namespace {

using test_faces::face;
using test_faces::Triangle;

/// The answer, the same both ways round.
FaceContact contact(const FaceGeometry& a, const FaceGeometry& b, CoplanarOverlap coplanar) {
  const FaceContact ab = convex_polygons_contact(a, b, coplanar);
  EXPECT_EQ(convex_polygons_contact(b, a, coplanar), ab);
  return ab;
}

TEST(ConvexPolygons, CoplanarTrianglesAgainstTheClippingOracle) {
  auto rng = testing::seeded_engine("mesh.convex_polygons.coplanar");
  std::uniform_int_distribution<int> grid(0, 4);
  int overlapping = 0, opposite = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    const bool tilted = trial % 2 == 1;
    const auto point = [&] {
      const double x = grid(rng), y = grid(rng);
      return Point3{x, y, tilted ? x + 2 * y : 0.0};
    };
    const Triangle a{point(), point(), point()}, b{point(), point(), point()};
    if (test_faces::collinear(a) || test_faces::collinear(b)) continue;
    const bool overlap = testing::coplanar_overlap_oracle(a, b);
    const bool same_way = testing::facing_oracle(a, b) == Sign::positive;
    const FaceGeometry fa = face(a), fb = face(b);
    const std::string what = "trial " + std::to_string(trial);
    ASSERT_EQ(contact(fa, fb, CoplanarOverlap::touching),
              overlap && same_way ? FaceContact::intersecting : FaceContact::apart)
        << what;
    ASSERT_EQ(contact(fa, fb, CoplanarOverlap::intersecting),
              overlap ? FaceContact::intersecting : FaceContact::apart)
        << what;
    overlapping += overlap;
    opposite += overlap && !same_way;
  }
  EXPECT_GT(overlapping, 300);
  EXPECT_GT(opposite, 100);
}

TEST(ConvexPolygons, TrianglesInTwoPlanes) {
  auto rng = testing::seeded_engine("mesh.convex_polygons.crossing");
  int through = 0, disjoint = 0, resting = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    // Interiors sharing a point: intersecting, under either rule.
    const auto [a, b] = test_faces::through_a_common_point(rng);
    if (!test_faces::collinear(a) && !test_faces::collinear(b) && !test_faces::coplanar(b, a)) {
      for (const CoplanarOverlap rule : {CoplanarOverlap::touching, CoplanarOverlap::intersecting})
        ASSERT_EQ(contact(face(a), face(b), rule), FaceContact::intersecting) << "trial " << trial;
      ++through;
      // a's corner a0 moved onto m, the others pushed off b's plane to one side: a corner
      // resting on b's interior, which only touches.
      Triangle rest = a;
      const Point3 m = {(a[0][0] + a[1][0] + a[2][0]) / 3, (a[0][1] + a[1][1] + a[2][1]) / 3,
                        (a[0][2] + a[1][2] + a[2][2]) / 3};  // exact: a's centroid is m
      rest[0] = m;
      const Sign s1 = testing::orient3d_oracle(b[0], b[1], b[2], rest[1]);
      const Sign s2 = testing::orient3d_oracle(b[0], b[1], b[2], rest[2]);
      if (s1 != Sign::zero && s1 == s2 && !test_faces::collinear(rest)) {
        ASSERT_EQ(contact(face(rest), face(b), CoplanarOverlap::touching), FaceContact::apart)
            << "trial " << trial;
        ++resting;
      }
    }
    // Random triangles whose closed sets are disjoint: apart.
    const Triangle c = test_faces::random_triangle(rng, 3), d = test_faces::random_triangle(rng, 3);
    if (test_faces::collinear(c) || test_faces::collinear(d) || test_faces::coplanar(c, d))
      continue;
    if (!test_faces::closed_disjoint(c, d)) continue;
    ASSERT_EQ(contact(face(c), face(d), CoplanarOverlap::intersecting), FaceContact::apart)
        << "trial " << trial;
    ++disjoint;
  }
  EXPECT_GT(through, 1500);
  EXPECT_GT(disjoint, 500);
  EXPECT_GT(resting, 100);
}

TEST(ConvexPolygons, ConvexQuadsByHand) {
  const std::vector<Point3> square{{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}};
  const std::vector<Point3> turned{{0, 0, 0}, {0, 2, 0}, {2, 2, 0}, {2, 0, 0}};
  const std::vector<Point3> shifted{{1, 1, 0}, {3, 1, 0}, {3, 3, 0}, {1, 3, 0}};
  const std::vector<Point3> beside{{2, 0, 0}, {4, 0, 0}, {4, 2, 0}, {2, 2, 0}};  // an edge
  const std::vector<Point3> wall{{1, 1, -1}, {1, 1, 1}, {1, 3, 1}, {1, 3, -1}};  // x = 1
  const std::vector<Point3> stand{{1, 1, 0}, {1, 3, 0}, {1, 3, 2}, {1, 1, 2}};   // on it
  ASSERT_EQ(face(square).shape, Shape::convex);
  const auto both = [&](const std::vector<Point3>& a, const std::vector<Point3>& b,
                        FaceContact touching, FaceContact intersecting) {
    EXPECT_EQ(contact(face(a), face(b), CoplanarOverlap::touching), touching);
    EXPECT_EQ(contact(face(a), face(b), CoplanarOverlap::intersecting), intersecting);
  };
  const FaceContact apart = FaceContact::apart, meet = FaceContact::intersecting;
  both(square, shifted, meet, meet);   // overlapping, facing the same way
  both(turned, shifted, apart, meet);  // overlapping, facing opposite ways
  both(square, beside, apart, apart);  // sharing an edge only
  both(square, wall, meet, meet);      // the wall's interior crosses the square's
  both(square, stand, apart, apart);   // standing on it: an edge on the square
}

}  // namespace
}  // namespace exactgeo::mesh::internal
