// The exact box: closed (touching boxes meet), exact comparisons at every magnitude.

#include "exactgeo/boxes/exact_box.hpp"

#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>

namespace exactgeo::boxes {
namespace {

TEST(ExactBox, ClosedAndExactAtEveryMagnitude) {
  for (const double s : {1.0, std::ldexp(1.0, 1000), std::ldexp(1.0, -1000), DBL_TRUE_MIN}) {
    const ExactBox a = ExactBox::of({Point3{0, 0, 0}, Point3{s, s, s}});
    EXPECT_EQ(a.lower, (Point3{0, 0, 0}));
    EXPECT_EQ(a.upper, (Point3{s, s, s}));
    EXPECT_TRUE(a.holds({s, 0, s}));                          // a corner
    EXPECT_FALSE(a.holds({std::nextafter(s, 2 * s), 0, 0}));  // one ulp out
    // Touching along a face: closed boxes meet; one ulp apart: not.
    const ExactBox touching = ExactBox::of({Point3{s, 0, 0}, Point3{2 * s, s, s}});
    EXPECT_TRUE(a.meets(touching));
    EXPECT_TRUE(touching.meets(a));
    const double gap = std::nextafter(s, 2 * s);
    EXPECT_FALSE(a.meets(ExactBox::of({Point3{gap, 0, 0}, Point3{2 * s, s, s}})));
    ExactBox grown = a;
    grown.add(touching);
    EXPECT_EQ(grown.upper, (Point3{2 * s, s, s}));
    EXPECT_TRUE(grown.holds({1.5 * s, s, 0}));
  }
  // -0 and +0 are one coordinate.
  EXPECT_TRUE(ExactBox::of(Point3{-0.0, 0, 0}).meets(ExactBox::of(Point3{0.0, 0, 0})));
  EXPECT_TRUE(ExactBox::of(Point3{DBL_MAX, -DBL_MAX, 0}).holds({DBL_MAX, -DBL_MAX, 0}));
}

}  // namespace
}  // namespace exactgeo::boxes
