// The coplanar overlap oracle on hand cases whose answer is plain, in three planes and at
// 2^0 and 2^+-1000: overlap with area counts whichever way the triangles face; a shared
// edge, a shared corner or a touching edge is no area.

#include "support/coplanar_overlap_oracle.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <stdexcept>

namespace exactgeo::testing {
namespace {

using Plane = std::function<Point3(double, double)>;

TEST(CoplanarOverlapOracle, HandCasesInThreePlanesAtEveryScale) {
  for (const int e : {0, 1000, -1000}) {
    const double s = std::ldexp(1.0, e);
    const Plane planes[] = {
        [s](double x, double y) {
          return Point3{s * x, s * y, 0.0};
        },
        [s](double x, double y) {
          return Point3{s * y, 0.0, s * x};
        },
        [s](double x, double y) {
          return Point3{s * x, s * y, s * (x - 2 * y)};
        },
    };
    for (const Plane& p : planes) {
      const auto t = [&](double ax, double ay, double bx, double by, double cx, double cy) {
        return TrianglePoints{p(ax, ay), p(bx, by), p(cx, cy)};
      };
      const TrianglePoints base = t(0, 0, 4, 0, 0, 4);
      EXPECT_TRUE(coplanar_overlap_oracle(base, base));
      EXPECT_TRUE(coplanar_overlap_oracle(base, t(0, 0, 0, 4, 4, 0)));    // facing the other way
      EXPECT_TRUE(coplanar_overlap_oracle(base, t(1, 1, 2, 1, 1, 2)));    // inside
      EXPECT_TRUE(coplanar_overlap_oracle(t(1, 1, 1, 2, 2, 1), base));    // inside, turned
      EXPECT_TRUE(coplanar_overlap_oracle(base, t(0, 0, 4, 0, 1, 1)));    // shared edge, same side
      EXPECT_FALSE(coplanar_overlap_oracle(base, t(4, 0, 0, 0, 1, -1)));  // the other side
      EXPECT_FALSE(coplanar_overlap_oracle(base, t(4, 0, 5, 0, 4, 1)));   // a shared corner
      EXPECT_FALSE(coplanar_overlap_oracle(base, t(2, 2, 4, 4, 0, 4)));   // touching the edge
      EXPECT_FALSE(coplanar_overlap_oracle(base, t(5, 5, 6, 5, 5, 6)));   // apart
      EXPECT_TRUE(coplanar_overlap_oracle(base, t(2, 2, -1, 2, 2, -1)));  // crossing edges
      EXPECT_EQ(facing_oracle(base, t(1, 1, 2, 1, 1, 2)), Sign::positive);
      EXPECT_EQ(facing_oracle(base, t(1, 1, 1, 2, 2, 1)), Sign::negative);
      EXPECT_THROW((void)coplanar_overlap_oracle(base, {p(0, 0), p(1, 0), Point3{s, s, s}}),
                   std::invalid_argument);
    }
  }
}

}  // namespace
}  // namespace exactgeo::testing
