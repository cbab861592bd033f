// A polygon seen along one coordinate axis (polygon_projection.hpp, internal): the two
// coordinates kept in cyclic order, orientations against an oracle in rationals (GMP) on
// random points of a small grid in every projection, the sweep order and equal
// projections, the flat copy seen along z alike, and points in the closed triangle as the
// oracle's three orientations say.

#include "../../mesh/src/polygon_projection.hpp"

#include <gtest/gtest.h>

#include <random>

#include "support/polygon_oracle.hpp"
#include "support/seed.hpp"

namespace exactgeo::mesh::internal {
namespace {

using testing::Point2;

TEST(PolygonProjection, TheKeptCoordinatesAreInCyclicOrder) {
  const Point3 p{1, 2, 3};
  const Projection x(0), y(1), z(2);
  EXPECT_EQ(x.axis(), 0);
  EXPECT_EQ(x.u(p), 2);
  EXPECT_EQ(x.v(p), 3);
  EXPECT_EQ(y.u(p), 3);
  EXPECT_EQ(y.v(p), 1);
  EXPECT_EQ(z.u(p), 1);
  EXPECT_EQ(z.v(p), 2);
  EXPECT_EQ(y.flat(p), (Point3{3, 1, 0}));
  // Counter-clockwise in (y, z) seen along x: the triangle of the unit vectors' ends.
  EXPECT_EQ(x.orientation({0, 0, 0}, {0, 1, 0}, {0, 0, 1}), Sign::positive);
  EXPECT_EQ(y.orientation({0, 0, 0}, {0, 1, 0}, {0, 0, 1}), Sign::zero);
  EXPECT_EQ(z.orientation({0, 0, 0}, {0, 1, 0}, {1, 0, 0}), Sign::negative);
}

TEST(PolygonProjection, RandomPointsAgreeWithTheOracle) {
  auto rng = testing::seeded_engine("mesh.polygon_projection");
  std::uniform_int_distribution<int> small(-3, 3);
  const auto point = [&] {
    return Point3{double(small(rng)), double(small(rng)), double(small(rng))};
  };
  int inside = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const Point3 a = point(), b = point(), c = point(), q = point();
    for (const int axis : {0, 1, 2}) {
      const Projection plane(axis);
      const auto seen = [&](const Point3& p) { return Point2{plane.u(p), plane.v(p)}; };
      const Sign turn = testing::orientation_oracle(seen(a), seen(b), seen(c));
      ASSERT_EQ(plane.orientation(a, b, c), turn) << "axis " << axis;
      // The flat copies, seen along z, turn alike and sort alike.
      EXPECT_EQ(Projection(2).orientation(plane.flat(a), plane.flat(b), plane.flat(c)), turn);
      EXPECT_EQ(plane.before(a, q), Projection(2).before(plane.flat(a), plane.flat(q)));
      const Point2 sa = seen(a), sq = seen(q);
      EXPECT_EQ(plane.before(a, q), sa < sq);  // lexicographic
      EXPECT_EQ(plane.same(a, q), sa == sq);
      if (turn == Sign::zero) continue;
      const bool want = testing::orientation_oracle(seen(a), seen(b), sq) != -turn &&
                        testing::orientation_oracle(seen(b), seen(c), sq) != -turn &&
                        testing::orientation_oracle(seen(c), seen(a), sq) != -turn;
      ASSERT_EQ(plane.in_triangle(a, b, c, turn, q), want) << "axis " << axis;
      inside += want;
    }
  }
  EXPECT_GT(inside, 500);
}

}  // namespace
}  // namespace exactgeo::mesh::internal
