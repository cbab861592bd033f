// Collision-safe operations on crafted near-degenerate cases: a flat sheet (a grid of
// triangles in z = 0) under a second sheet (one large triangle at height h). Each
// operation that would make the sheets meet is refused, naming the element it would
// meet, and its twin one step of the coordinates away (one ulp, or a step short of the
// other sheet) is applied; the same at 2^0 and 2^+-1000. After every applied operation
// the exact self-intersection finder reports no intersecting pair.

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "exactgeo/mesh/self_intersection.hpp"
#include "exactgeo/remesh/operations.hpp"
#include "remesh/surface_mesh.hpp"

namespace exactgeo::remesh {
namespace {


/// n x n squares of side 1 in z = 0 (vertex (i, j) is i + (n + 1) j), each split along
/// its diagonal (i, j)-(i+1, j+1), turning counter-clockwise seen from +z; then a large
/// triangle over it at height h, facing down. Every coordinate times `scale`.
Surface sheets(int n, double h, double scale) {
  Surface s;
  const auto index = [n](int i, int j) { return static_cast<VertexIndex>(i + (n + 1) * j); };
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i)
      s.vertices.push_back({scale * i, scale * j, 0.0});
  }
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      s.triangles.push_back({index(i, j), index(i + 1, j), index(i + 1, j + 1)});
      s.triangles.push_back({index(i, j), index(i + 1, j + 1), index(i, j + 1)});
    }
  }
  const auto top = static_cast<VertexIndex>(s.vertices.size());
  s.vertices.push_back({-scale * n, -scale * n, scale * h});
  s.vertices.push_back({scale * 2 * n, scale * n / 2, scale * h});
  s.vertices.push_back({-scale * n, scale * 2 * n, scale * h});
  s.triangles.push_back({top, top + 2, top + 1});
  return s;
}

void expect_intersection_free(const Surface& s, const std::string& after) {
  const mesh::SelfIntersections found = testing::sheets_meeting(s);
  EXPECT_TRUE(found.intersecting.empty()) << "after " << after;
}

constexpr VertexIndex kInner = 1 + 5 * 1;      // vertex (1, 1) of the 4 x 4 grid
constexpr VertexIndex kTopTriangleFirst = 25;  // the upper sheet's corners: 25, 26, 27

class Operations : public ::testing::TestWithParam<int> {
 protected:
  double scale() const { return std::ldexp(1.0, GetParam()); }
  /// One step below height h (scaled): the largest double under it.
  double just_below(double h) const { return std::nextafter(scale() * h, 0.0); }
};

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

TEST_P(Operations, CollapseStopsAtTheSheetAbove) {
  const double s = scale();
  Surface surface = sheets(4, 1.0, s);
  const VertexIndex a = kInner, b = kInner + 1;  // (1, 1) and (2, 1), both inner
  const Point3 through{1.5 * s, s, 1.5 * s};
  const Outcome refused = collapse_edge(surface, a, b, through);
  EXPECT_EQ(refused.verdict, Verdict::refused_collision) << refused.reason;
  EXPECT_EQ(surface.triangles.size(), 33u);
  const Outcome touching = collapse_edge(surface, a, b, {1.5 * s, s, s});
  EXPECT_EQ(touching.verdict, Verdict::refused_collision) << touching.reason;
  const Outcome applied = collapse_edge(surface, a, b, {1.5 * s, s, just_below(1.0)});
  ASSERT_TRUE(applied.applied()) << applied.reason;
  EXPECT_EQ(surface.triangles.size(), 31u);  // the edge's two triangles gone
  EXPECT_TRUE(surface.triangles_around(b).empty());
  expect_intersection_free(surface, "the collapse");
}

TEST_P(Operations, ACollapseCannotSweepOverATriangle) {
  const double s = scale();
  // A small triangle lies flat just above the grid, at height 1/8. Collapsing the inner
  // edge (1, 1)-(2, 1) to the raised point (1.5, 1, 1/2) makes a tent over it: the end
  // state is intersection free (the triangle sits in the gap under the tent), but the
  // triangles rising from the grid to the tent sweep through it.
  Surface surface = sheets(4, 1.0, s);
  surface.vertices[kTopTriangleFirst] = {1.5 * s, 1.25 * s, 0.125 * s};
  surface.vertices[kTopTriangleFirst + 1] = {1.5625 * s, 1.25 * s, 0.125 * s};
  surface.vertices[kTopTriangleFirst + 2] = {1.5 * s, 1.3125 * s, 0.125 * s};
  const Outcome refused = collapse_edge(surface, kInner, kInner + 1, {1.5 * s, s, 0.5 * s});
  EXPECT_EQ(refused.verdict, Verdict::refused_collision) << refused.reason;
  ASSERT_TRUE(refused.blocker.has_value());
  EXPECT_EQ(refused.blocker->kind, Blocker::Kind::vertex) << refused.reason;
  EXPECT_GE(refused.blocker->corners[0], kTopTriangleFirst);
  // The same collapse to a point in the grid's plane moves nothing over the triangle.
  const Outcome flat = collapse_edge(surface, kInner, kInner + 1, {1.5 * s, s, 0.0});
  EXPECT_TRUE(flat.applied()) << flat.reason;
  expect_intersection_free(surface, "the flat collapse");
}

TEST_P(Operations, SplitPokingThroughTheSheetIsRefused) {
  const double s = scale();
  // The upper sheet one unit in 2^20 above the grid: a split point lifted more pokes
  // through it.
  const double h = std::ldexp(1.0, -20);
  Surface surface = sheets(4, h, s);
  const VertexIndex a = kInner, b = kInner + 6;  // the diagonal (1, 1)-(2, 2)
  const Point3 mid{1.5 * s, 1.5 * s, 0.0};
  const Outcome poking = split_edge(surface, a, b, {mid[0], mid[1], 2 * h * s});
  EXPECT_EQ(poking.verdict, Verdict::refused_collision) << poking.reason;
  ASSERT_TRUE(poking.blocker.has_value());
  EXPECT_EQ(poking.blocker->kind, Blocker::Kind::triangle);
  const Outcome touching = split_edge(surface, a, b, {mid[0], mid[1], h * s});
  EXPECT_EQ(touching.verdict, Verdict::refused_collision) << touching.reason;
  // Just under the sheet: the thin region between the old and the new triangles is empty.
  Surface lifted = surface;
  const Outcome under = split_edge(lifted, a, b, {mid[0], mid[1], just_below(h)});
  ASSERT_TRUE(under.applied()) << under.reason;
  EXPECT_EQ(lifted.triangles.size(), 35u);
  expect_intersection_free(lifted, "the lifted split");
  // Exactly on the edge: nothing moves.
  const Outcome on_edge = split_edge(surface, a, b, mid);
  ASSERT_TRUE(on_edge.applied()) << on_edge.reason;
  ASSERT_TRUE(on_edge.new_vertex.has_value());
  EXPECT_EQ(surface.vertices[*on_edge.new_vertex], mid);
  expect_intersection_free(surface, "the split on the edge");
}

TEST_P(Operations, SplitOffTheEdgeIntoItsOtherTriangleIsApplied) {
  // A rounded midpoint a hair off the diagonal (1, 1)-(2, 2), inside the triangle with
  // corner (2, 1): the other triangle's region reaches into that triangle, which the
  // split replaces too, so it is no obstacle (the partner corner), and the four new
  // triangles tile the old two.
  const double s = scale();
  Surface surface = sheets(4, 1.0, s);
  const VertexIndex a = kInner, b = kInner + 6;
  const Point3 off{1.5 * s, std::nextafter(1.5 * s, 0.0), 0.0};
  const Outcome split = split_edge(surface, a, b, off);
  ASSERT_TRUE(split.applied()) << split.reason;
  EXPECT_EQ(surface.triangles.size(), 35u);
  expect_intersection_free(surface, "the split off the edge");
  // Lifted by one ulp of the height as well: still inside the thin space under the sheet.
  Surface lifted = sheets(4, 1.0, s);
  const Outcome up = split_edge(lifted, a, b, {off[0], off[1], std::ldexp(s, -60)});
  ASSERT_TRUE(up.applied()) << up.reason;
  expect_intersection_free(lifted, "the lifted split off the edge");
  // And in a pass.
  Surface passed = sheets(4, 1.0, s);
  const std::vector<Outcome> outcomes = split_edges(passed, std::array{Split{a, b, off}});
  ASSERT_TRUE(outcomes.front().applied()) << outcomes.front().reason;
  EXPECT_EQ(passed.triangles, surface.triangles);
}

TEST_P(Operations, SplitThroughANeighbourOfBothOppositeCornersIsRefused) {
  // Found by the random operations (seed 101): edge ab = 4-5 with opposite corners c = 0
  // and d = 3, and a triangle a d c beside it. The lifted midpoint's new triangle b m c
  // passes through a d c; only its corners are all among a, b, c, d, and it is not the
  // split's own: its region must test it.
  const double s = scale();
  Surface surface;
  for (const Point3& p :
       {Point3{0x1.9p-2, 0x1.74p+0, 0x1.2p-3}, Point3{0x1.b8p-2, 0x1.76p+0, 0x1.2p-3},
        Point3{0x1.8p-1, 0x1.8p+0, 0x1.1p-2}, Point3{0x1.24p-1, 0x1.7ap+0, 0x1.38p-2},
        Point3{0x1.48p-2, 0x1.7ap+0, 0x1.18p-2}, Point3{0x1p-1, 0x1.78p+0, 0x1.88p-3}}) {
    surface.vertices.push_back({s * p[0], s * p[1], s * p[2]});
  }
  surface.triangles = {{0, 4, 5}, {3, 5, 4}, {1, 5, 2}, {4, 0, 3}, {5, 1, 0}, {5, 3, 2}};
  expect_intersection_free(surface, "setting up");
  const Point3 m{s * 0x1.a4p-2, s * 0x1.79p+0, s * 0x1.56p-2};
  const Outcome split = split_edge(surface, 4, 5, m);
  EXPECT_EQ(split.verdict, Verdict::refused_collision) << split.reason;
  ASSERT_TRUE(split.blocker.has_value());
  Surface forced = surface;  // what the split would have made
  forced.vertices.push_back(m);
  forced.triangles[0] = {0, 4, 6};
  forced.triangles.push_back({0, 6, 5});
  forced.triangles[1] = {3, 5, 6};
  forced.triangles.push_back({3, 6, 4});
  EXPECT_FALSE(testing::sheets_meeting(forced).intersecting.empty())
      << "the refused split would have made an intersection";
}

TEST_P(Operations, FlipSweepsTheTetrahedronOfItsCorners) {
  const double s = scale();
  // Lift the grid's vertex (2, 1) so that flipping the diagonal (1, 1)-(2, 2) sweeps a
  // tetrahedron, and put a vertex of the upper sheet's triangle on its new face, one ulp
  // inside it and one ulp outside it.
  const VertexIndex a = kInner, b = kInner + 6, c = kInner + 1, d = kInner + 5;
  for (const int nudge : {0, -1, +1}) {
    Surface surface = sheets(4, 1.0, s);
    surface.vertices[c][2] = s;  // (2, 1, 1): triangle a b c rises
    // The new face (c, a, d) spans c = (2, 1, 1), a = (1, 1, 0), d = (1, 2, 0): the plane
    // z = x - 1 + ... ; the tetrahedron's fourth corner b = (2, 2, 0) lies below it.
    // Its centroid (4/3, 4/3, 1/3) is not a double: take the point at weights (1/4,
    // 1/2, 1/4) of c, a, d: (1.25, 1.25, 0.25), exactly on the face.
    Point3 x{1.25 * s, 1.25 * s, 0.25 * s};
    if (nudge != 0) x[2] = std::nextafter(x[2], nudge < 0 ? 0.0 : HUGE_VAL);
    // The upper triangle's first corner moves down to x; the triangle stays above the grid.
    surface.vertices[kTopTriangleFirst] = x;
    surface.vertices[kTopTriangleFirst + 1] = {4 * s, 8 * s, 4 * s};
    surface.vertices[kTopTriangleFirst + 2] = {-4 * s, 2 * s, 4 * s};
    expect_intersection_free(surface, "setting up");
    const Outcome flip = flip_edge(surface, a, b);
    if (nudge <= 0) {  // on the new face, or inside the tetrahedron
      EXPECT_EQ(flip.verdict, Verdict::refused_collision) << "nudge " << nudge;
      ASSERT_TRUE(flip.blocker.has_value());
      EXPECT_EQ(flip.blocker->kind, Blocker::Kind::vertex) << flip.reason;
      EXPECT_EQ(flip.blocker->corners[0], kTopTriangleFirst);
    } else {
      ASSERT_TRUE(flip.applied()) << flip.reason;
      EXPECT_FALSE(surface.triangles_on_edge(c, d).empty());
      expect_intersection_free(surface, "the flip");
    }
  }
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

TEST_P(Operations, AnEdgeThroughTheFlipsTetrahedronIsMet) {
  const double s = scale();
  // The tetrahedron of FlipSweepsTheTetrahedronOfItsCorners; an edge of the upper
  // triangle runs through it from face to new face, (1, 1, 1/4) to (2, 2, 1/4), both ends
  // outside it and above the grid.
  Surface surface = sheets(4, 1.0, s);
  surface.vertices[kInner + 1][2] = s;
  surface.vertices[kTopTriangleFirst] = {s, s, 0.25 * s};
  surface.vertices[kTopTriangleFirst + 1] = {1.5 * s, 4 * s, 4 * s};
  surface.vertices[kTopTriangleFirst + 2] = {2 * s, 2 * s, 0.25 * s};
  expect_intersection_free(surface, "setting up");
  const Outcome flip = flip_edge(surface, kInner, kInner + 6);
  EXPECT_EQ(flip.verdict, Verdict::refused_collision) << flip.reason;
  ASSERT_TRUE(flip.blocker.has_value());
  EXPECT_EQ(flip.blocker->kind, Blocker::Kind::edge) << flip.reason;
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

TEST(OperationsTopology, RefusalsSayWhy) {
  Surface surface = sheets(4, 1.0, 1.0);
  // A boundary edge cannot be flipped; a boundary vertex's inner edge cannot collapse.
  EXPECT_EQ(flip_edge(surface, 0, 1).verdict, Verdict::refused_topology);
  const Outcome pinch = collapse_edge(surface, 1, 6, {1, 1, 0});
  EXPECT_EQ(pinch.verdict, Verdict::refused_topology);
  EXPECT_NE(pinch.reason.find("pinch"), std::string::npos) << pinch.reason;
  // No such edge; a fixed vertex.
  EXPECT_EQ(split_edge(surface, 0, 24, {1, 1, 0}).verdict, Verdict::refused_topology);
  surface.fixed.assign(surface.vertices.size(), false);
  surface.fixed[kInner] = true;
  const Outcome fixed = relocate_vertex(surface, kInner, {1, 1, 0.5});
  EXPECT_EQ(fixed.verdict, Verdict::refused_topology);
  EXPECT_NE(fixed.reason.find("fixed"), std::string::npos) << fixed.reason;
  // Flipping the diagonal of a flat square twice gives it back.
  surface.fixed.clear();
  ASSERT_TRUE(flip_edge(surface, kInner, kInner + 6).applied());
  ASSERT_TRUE(flip_edge(surface, kInner + 1, kInner + 5).applied());
  EXPECT_FALSE(surface.triangles_on_edge(kInner, kInner + 6).empty());
  // A split point on the edge's line but beyond its end is refused.
  EXPECT_EQ(split_edge(surface, kInner, kInner + 1, {3, 1, 0}).verdict, Verdict::refused_topology);
}

INSTANTIATE_TEST_SUITE_P(Scales, Operations, ::testing::Values(0, 1000, -1000),
                         [](const ::testing::TestParamInfo<int>& param_info) {
                           const int k = param_info.param;
                           return (k < 0 ? "scale_2m" : "scale_2p") + std::to_string(std::abs(k));
                         });

}  // namespace
}  // namespace exactgeo::remesh
