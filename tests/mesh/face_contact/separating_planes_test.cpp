// Separating planes (face_contact/separating_planes.hpp, internal), the filters that prove
// two faces apart: what a set of sides says; never a separation for triangles whose
// interiors share a point (built through a common point), in either order; and, for
// triangles in two planes whose closed sets are disjoint (an exact oracle), always one:
// each one's plane or an axis across an edge of each (the separating axis theorem, whose
// candidates these are for triangles that are not coplanar). By hand: skew quads apart,
// side by side, and a skew quad beside a triangle sharing its corner.

#include "../../../mesh/src/face_contact/separating_planes.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "mesh/face_contact/face_pairs.hpp"
#include "support/seed.hpp"

namespace exactgeo::mesh::internal {
namespace {

using test_faces::face;
using test_faces::Triangle;

bool any_filter(const FaceGeometry& a, const FaceGeometry& b) {
  return separated_by_corner_plane(a, b) || separated_by_corner_plane(b, a) ||
         separated_by_edge_pair_axis(a, b);
}

TEST(SeparatingPlanes, SidesSayWhichOpenSidesAreReached) {
  Sides sides;
  EXPECT_FALSE(sides.any());
  sides.add(Sign::zero);
  EXPECT_FALSE(sides.any());
  sides.add(Sign::negative);
  EXPECT_TRUE(sides.any());
  EXPECT_FALSE(sides.both());
  EXPECT_TRUE(sides.negative && !sides.positive);
  sides.add(Sign::positive);
  EXPECT_TRUE(sides.both());
}

TEST(SeparatingPlanes, InteriorsThatShareAPointAreNeverSeparated) {
  auto rng = testing::seeded_engine("mesh.separating_planes.common_point");
  int checked = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const auto [a, b] = test_faces::through_a_common_point(rng);
    if (test_faces::collinear(a) || test_faces::collinear(b)) continue;
    const FaceGeometry fa = face(a), fb = face(b);
    ASSERT_FALSE(separated_by_corner_plane(fa, fb)) << "trial " << trial;
    ASSERT_FALSE(separated_by_corner_plane(fb, fa)) << "trial " << trial;
    ASSERT_FALSE(separated_by_edge_pair_axis(fa, fb)) << "trial " << trial;
    ASSERT_FALSE(separated_by_edge_pair_axis(fb, fa)) << "trial " << trial;
    ++checked;
  }
  EXPECT_GT(checked, 2000);
}

TEST(SeparatingPlanes, DisjointTrianglesInTwoPlanesAreAlwaysSeparated) {
  auto rng = testing::seeded_engine("mesh.separating_planes.disjoint");
  int disjoint = 0, by_axis_only = 0;
  for (int trial = 0; trial < 6000; ++trial) {
    const Triangle a = test_faces::random_triangle(rng, 3), b = test_faces::random_triangle(rng, 3);
    if (test_faces::collinear(a) || test_faces::collinear(b) || test_faces::coplanar(a, b)) {
      continue;
    }
    if (!test_faces::closed_disjoint(a, b)) continue;
    const FaceGeometry fa = face(a), fb = face(b);
    ASSERT_TRUE(any_filter(fa, fb)) << "trial " << trial;
    // The axis test is symmetric.
    EXPECT_EQ(separated_by_edge_pair_axis(fa, fb), separated_by_edge_pair_axis(fb, fa));
    ++disjoint;
    by_axis_only += !separated_by_corner_plane(fa, fb) && !separated_by_corner_plane(fb, fa);
  }
  EXPECT_GT(disjoint, 1000);
  EXPECT_GT(by_axis_only, 0);  // the edge-pair axes do work the corner planes cannot
}

TEST(SeparatingPlanes, SkewQuadsAndASharedCorner) {
  // The saddle z = x y over the unit square, and copies of it.
  const std::vector<Point3> saddle{{0, 0, 0}, {1, 0, 0}, {1, 1, 1}, {0, 1, 0}};
  std::vector<Point3> beside = saddle, above = saddle;
  for (Point3& p : beside)
    p[0] += 3;
  for (Point3& p : above)
    p[2] += 3;
  EXPECT_TRUE(any_filter(face(saddle), face(beside)));
  EXPECT_TRUE(any_filter(face(saddle), face(above)));
  // A triangle below the saddle sharing its corner (0, 0, 0): only touching, and a plane
  // through the saddle's corners shows it.
  const std::vector<Point3> below{{0, 0, 0}, {-1, 0, -1}, {0, -1, -1}};
  EXPECT_TRUE(any_filter(face(saddle), face(below)));
  // A triangle through the saddle's middle (1/2, 1/2, 1/4): no plane separates.
  const std::vector<Point3> through{{0.5, 0.5, -1}, {0.5, 0.5, 1}, {3, 0.5, 0}};
  EXPECT_FALSE(any_filter(face(saddle), face(through)));
}

}  // namespace
}  // namespace exactgeo::mesh::internal
