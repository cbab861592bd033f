// The coplanarity-cubic baseline: right where the answer is clear, wrong by design within
// its tolerance, and measured against exact root parity.

#include "exactgeo/ccd/baselines/cubic.hpp"

#include <gtest/gtest.h>

#include <cstdio>

#include "exactgeo/ccd/root_parity.hpp"
#include "support/generators.hpp"
#include "support/seed.hpp"

namespace exactgeo::ccd {
namespace {

VertexFaceQuery vertex_falling_to(double x, double y, double end) {
  return {{x, y, 1}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {x, y, end}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
}

TEST(Cubic, ClearCases) {
  EXPECT_TRUE(vertex_face_cubic(vertex_falling_to(0.2, 0.2, -1)));
  EXPECT_FALSE(vertex_face_cubic(vertex_falling_to(2, 2, -1)));
  EXPECT_TRUE(vertex_face_cubic(vertex_falling_to(0.2, 0.2, 0)));  // lands on it
  const EdgeEdgeQuery through{{0, 0, 1},  {1, 1, 1},  {1, 0, 0}, {0, 1, 0},
                              {0, 0, -1}, {1, 1, -1}, {1, 0, 0}, {0, 1, 0}};
  EXPECT_TRUE(edge_edge_cubic(through));
  EdgeEdgeQuery beside = through;
  beside.eb0_t0 = beside.eb0_t1 = {3, 0, 0};
  beside.eb1_t0 = beside.eb1_t1 = {4, 1, 0};
  EXPECT_FALSE(edge_edge_cubic(beside));
}

TEST(Cubic, ToleranceMakesNearMissesCollisions) {
  // Ending 1e-9 above the face is a miss, but within the default tolerance of 1e-6 the
  // cubic method calls it a collision: the false positive simulators accept as thickness.
  EXPECT_EQ(vertex_face_root_parity(vertex_falling_to(0.25, 0.25, 1e-9)).parity, RootParity::even);
  EXPECT_TRUE(vertex_face_cubic(vertex_falling_to(0.25, 0.25, 1e-9)));
  EXPECT_FALSE(vertex_face_cubic(vertex_falling_to(0.25, 0.25, 1e-9), {.tolerance = 1e-12}));
}

TEST(Cubic, AgreesWithExactParityOnWellSeparatedMotions) {
  // Random motions of unit size: roots, when there are any, are far from the tolerance.
  testing::Rng rng = testing::seeded_engine("cubic-random");
  int cases = 0, positives = 0, missed = 0, extra = 0;
  for (int i = 0; i < 3000; ++i) {
    VertexFaceQuery q;
    for (Point3* p :
         {&q.v_t0, &q.f0_t0, &q.f1_t0, &q.f2_t0, &q.v_t1, &q.f0_t1, &q.f1_t1, &q.f2_t1}) {
      *p = testing::random_point(rng);
    }
    const bool exact = vertex_face_root_parity(q).collision();
    const bool cubic = vertex_face_cubic(q);
    ++cases;
    positives += exact;
    missed += exact && !cubic;
    // Parity cannot see two roots, so some of these may be real (two-root) collisions.
    extra += !exact && cubic;
  }
  std::printf("[ info     ] %d cases, %d parity collisions, cubic missed %d, added %d\n", cases,
              positives, missed, extra);
  EXPECT_GT(positives, 100);
  EXPECT_LE(missed, positives / 100);
  EXPECT_LE(extra, cases / 20);
}

}  // namespace
}  // namespace exactgeo::ccd
