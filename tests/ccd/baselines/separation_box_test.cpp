// The minimum-separation baseline (baselines/separation_box.hpp), the per-axis box test
// in plain doubles: conservative against the exact method, and wrong by design up to
// sqrt(3) δ.

#include "exactgeo/ccd/baselines/separation_box.hpp"

#include <gtest/gtest.h>

#include "ccd/query_transforms.hpp"
#include "ccd/run_query.hpp"
#include "ccd/separation/sampled_distance.hpp"
#include "exactgeo/ccd/ccd.hpp"
#include "support/generators.hpp"
#include "support/seed.hpp"

namespace exactgeo::ccd {
namespace {

using testing::Rng;

/// The baseline box test is conservative: every pair within δ is a yes. It also says yes
/// for a pair up to sqrt(3) δ apart (the cube's corner), which the exact method rejects.
TEST(SeparationBoxBaseline, NeverMissesAndSeesTheCubesCorners) {
  Rng rng = testing::seeded_engine("min-separation-box-test");
  int within = 0;
  // 100 at full effort (tests/support/seed.hpp), at least one of each five kinds; more
  // pairs within δ than queries, as at full effort.
  const auto queries = static_cast<int>(testing::scaled_trials(100, 5));
  for (int i = 0; i < queries; ++i) {
    const auto vf = varied_query<VertexFaceQuery>(rng, i);
    const auto ee = varied_query<EdgeEdgeQuery>(rng, i);
    for (const double delta : deltas_for(vf, rng)) {
      if (separated(vf, delta).collision) {
        ++within;
        EXPECT_TRUE(vertex_face_separation_box_baseline(vf, delta)) << "vf #" << i << " " << delta;
      }
    }
    for (const double delta : deltas_for(ee, rng)) {
      if (separated(ee, delta).collision) {
        ++within;
        EXPECT_TRUE(edge_edge_separation_box_baseline(ee, delta)) << "ee #" << i << " " << delta;
      }
    }
  }
  EXPECT_GT(within, 100 * queries / 100);
  // A vertex standing 0.75 delta from a face corner along each axis: 1.3 delta away.
  const double d = 0.5;
  const Point3 v{-0.375, -0.375, 0.375};
  const VertexFaceQuery corner{v, {0, 0, 0}, {1, 0, 0}, {0, 1, 0},
                               v, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  EXPECT_TRUE(vertex_face_separation_box_baseline(corner, d));
  EXPECT_FALSE(separated(corner, d).collision);
  EXPECT_TRUE(separated(corner, 0.65).collision);  // |v| = 0.6495...
}

}  // namespace
}  // namespace exactgeo::ccd
