// A vertex's swept box (ccd/mesh/internal/swept_box.hpp) contains both of its positions in
// the step's scale, at every magnitude.

#include "exactgeo/ccd/mesh/internal/swept_box.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "support/generators.hpp"
#include "support/seed.hpp"

namespace exactgeo::ccd::internal {
namespace {

TEST(SweptBox, VertexBoxContainsBothPositionsInTheStepsScale) {
  testing::Rng rng = testing::seeded_engine("swept-box-vertex");
  for (int i = 0; i < 2000; ++i) {
    const int e = testing::uniform_int(rng, -1000, 1000);
    std::vector<double> t0(3), t1(3);
    for (int k = 0; k < 3; ++k) {
      t0[k] = testing::uniform(rng, -1, 1) * std::ldexp(1.0, e);
      t1[k] = testing::uniform(rng, -1, 1) * std::ldexp(1.0, e);
    }
    const boxes::Scale scale(std::max(
        std::max(std::fabs(t0[0]), std::fabs(t0[1])),
        std::max({std::fabs(t0[2]), std::fabs(t1[0]), std::fabs(t1[1]), std::fabs(t1[2])})));
    const FloatBox box = vertex_swept_box(t0.data(), t1.data(), 0, scale);
    for (int k = 0; k < 3; ++k) {
      for (const double x : {t0[k], t1[k]}) {
        EXPECT_LE(static_cast<double>(box.lo[k]), scale(x));
        EXPECT_GE(static_cast<double>(box.hi[k]), scale(x));
      }
      // In the step's scale every coordinate is below 1 in magnitude, far inside floats.
      EXPECT_LE(std::fabs(box.lo[k]), 1.0f);
      EXPECT_LE(std::fabs(box.hi[k]), 1.0f);
    }
  }
}

}  // namespace
}  // namespace exactgeo::ccd::internal
