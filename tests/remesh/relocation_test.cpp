// Relocations under a second sheet (two_sheets.hpp: a flat grid in z = 0 under one large
// triangle, at 2^0 and 2^+-1000): a vertex moved onto or through the sheet above is
// refused, naming the triangle it would meet, and one step short of it is applied; a move
// whose vertex passes beside the sheet but whose edge meets the sheet's edge is refused
// naming that edge; in a smoothing pass (relocate_vertices) only the colliding moves and
// a vertex's second move are refused. After every applied relocation the exact
// self-intersection finder reports no intersecting pair.

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "exactgeo/remesh/operations.hpp"
#include "remesh/two_sheets.hpp"

namespace exactgeo::remesh {
namespace {

using testing::expect_intersection_free;
using testing::kInner;
using testing::kTopTriangleFirst;
using testing::Operations;
using testing::sheets;

TEST_P(Operations, RelocationStopsAtTheSheetAbove) {
  const double s = scale();
  Surface surface = sheets(4, 1.0, s);
  const Point3 onto{s, s, s};  // touching the upper sheet
  Outcome refused = relocate_vertex(surface, kInner, onto);
  EXPECT_EQ(refused.verdict, Verdict::refused_collision) << refused.reason;
  ASSERT_TRUE(refused.blocker.has_value());
  EXPECT_EQ(refused.blocker->kind, Blocker::Kind::triangle);
  EXPECT_EQ(refused.blocker->corners[0], kTopTriangleFirst);
  EXPECT_EQ(surface.vertices[kInner], (Point3{s, s, 0.0}));  // unchanged
  EXPECT_EQ(relocate_vertex(surface, kInner, {s, s, 2 * s}).verdict, Verdict::refused_collision);
  const Outcome applied = relocate_vertex(surface, kInner, {s, s, just_below(1.0)});
  EXPECT_TRUE(applied.applied()) << applied.reason;
  EXPECT_EQ(surface.vertices[kInner], (Point3{s, s, just_below(1.0)}));
  expect_intersection_free(surface, "the relocation");
}

TEST_P(Operations, AMovingEdgeMeetsAStandingEdge) {
  const double s = scale();
  // The upper sheet is a sliver at height 1 over the strip 1.4 < y < 1.45: not over the
  // inner vertex (1, 1), but over its edge to (1, 2). Lifting the vertex through height 1
  // brings no vertex to a triangle; only that edge meets the sliver's long edge.
  Surface surface = sheets(4, 1.0, s);
  surface.vertices[kTopTriangleFirst] = {-8 * s, 1.4 * s, s};
  surface.vertices[kTopTriangleFirst + 1] = {8 * s, 1.4 * s, s};
  surface.vertices[kTopTriangleFirst + 2] = {8 * s, 1.45 * s, s};
  const Outcome refused = relocate_vertex(surface, kInner, {s, s, 2 * s});
  EXPECT_EQ(refused.verdict, Verdict::refused_collision) << refused.reason;
  ASSERT_TRUE(refused.blocker.has_value());
  EXPECT_EQ(refused.blocker->kind, Blocker::Kind::edge) << refused.reason;
  EXPECT_TRUE(relocate_vertex(surface, kInner, {s, s, just_below(1.0)}).applied());
}

TEST_P(Operations, ASmoothingPassRefusesOnlyTheMovesThatCollide) {
  const double s = scale();
  Surface surface = sheets(4, 1.0, s);
  const VertexIndex through = kInner, up = kInner + 2, under = 18, twice = 12;
  const std::vector<Move> moves{{through, {s, s, 1.5 * s}},
                                {up, {3 * s, s, 0.5 * s}},
                                {under, {3 * s, 3 * s, just_below(1.0)}},
                                {twice, {2 * s, 2 * s, 0.25 * s}},
                                {twice, {2 * s, 2 * s, 0.5 * s}}};
  const std::vector<Outcome> done = relocate_vertices(surface, moves);
  ASSERT_EQ(done.size(), moves.size());
  EXPECT_EQ(done[0].verdict, Verdict::refused_collision) << done[0].reason;
  ASSERT_TRUE(done[0].blocker.has_value());
  EXPECT_EQ(*done[0].blocker, (Blocker{Blocker::Kind::triangle, {25, 27, 26}}));
  EXPECT_NE(done[0].reason.find("would meet triangle 25 27 26"), std::string::npos)
      << done[0].reason;
  EXPECT_TRUE(done[1].applied()) << done[1].reason;
  EXPECT_TRUE(done[2].applied()) << done[2].reason;
  EXPECT_TRUE(done[3].applied()) << done[3].reason;
  EXPECT_EQ(done[4].verdict, Verdict::refused_topology);
  EXPECT_EQ(surface.vertices[through], (Point3{s, s, 0.0}));
  EXPECT_EQ(surface.vertices[up], (Point3{3 * s, s, 0.5 * s}));
  EXPECT_EQ(surface.vertices[under], (Point3{3 * s, 3 * s, just_below(1.0)}));
  EXPECT_EQ(surface.vertices[twice], (Point3{2 * s, 2 * s, 0.25 * s}));
  expect_intersection_free(surface, "the smoothing pass");
}

}  // namespace
}  // namespace exactgeo::remesh
