// Collapses whose end state intersects are refused by their motion alone. The surface
// after a collapse is not checked in place (docs/remesh.md, "Collapse", gives the
// argument: a pair that intersects after the collapse was in contact, during the
// pseudo-motion, through a vertex-face or edge-edge pair the motion check decides); here,
// random collapses of a crumpled stack to random points (the ends, lifted midpoints,
// points beyond an end) whose end state the exact self-intersection finder (a coplanar
// overlap with area counting) finds intersecting must all be refused, one by one and in
// a pass, and the applied ones must leave the stack intersection free.
//
// And under a second sheet (two_sheets.hpp, at 2^0 and 2^+-1000): a collapse to a point
// through or onto the sheet above is refused and one a step short of it applied; a
// collapse to a raised point whose end state is intersection free, but whose triangles
// sweep through a small triangle lying between, is refused naming one of its corners.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "exactgeo/mesh/check.hpp"
#include "exactgeo/mesh/self_intersection.hpp"
#include "exactgeo/remesh/operations.hpp"
#include "remesh/stacked_sheets.hpp"
#include "remesh/surface_mesh.hpp"
#include "remesh/two_sheets.hpp"
#include "support/seed.hpp"

namespace exactgeo::remesh {
namespace {

using testing::expect_intersection_free;
using testing::kInner;
using testing::kTopTriangleFirst;
using testing::Operations;
using testing::sheets;

/// The collapse of ab to `to` made without any check: b replaced by a, both at `to`, the
/// triangles of the edge removed.
Surface forced_collapse(const Surface& s, VertexIndex a, VertexIndex b, const Point3& to) {
  Surface after = s;
  after.vertices[a] = after.vertices[b] = to;
  after.triangles.clear();
  for (Triangle t : s.triangles) {
    const bool has_a = std::find(t.begin(), t.end(), a) != t.end();
    const bool has_b = std::find(t.begin(), t.end(), b) != t.end();
    if (has_a && has_b) continue;
    std::replace(t.begin(), t.end(), b, a);
    after.triangles.push_back(t);
  }
  return after;
}

bool intersects(const Surface& s) {
  return !testing::sheets_meeting(s).intersecting.empty();
}

TEST(Collapses, AnEndStateThatIntersectsIsRefusedByTheMotion) {
  auto rng = testing::seeded_engine("remesh.collapse_end_states");
  Surface surface;
  std::uniform_int_distribution<int> lift(-48, 48);  // in steps of 2^-7
  std::uniform_int_distribution<int> kind(0, 3);
  int intersecting_end_states = 0, applied = 0;
  for (int trial = 0; trial < 1500; ++trial) {
    if (trial % 100 == 0) {  // a fresh stack: collapses coarsen it quickly
      surface = testing::stack(3, 8, rng, 0.2);
      testing::crumple(surface, rng);
      ASSERT_FALSE(intersects(surface));
    }
    const std::vector<Edge> edges = surface.edges();
    const Edge e = edges[std::uniform_int_distribution<std::size_t>(0, edges.size() - 1)(rng)];
    const Point3& a = surface.vertices[e[0]];
    const Point3& b = surface.vertices[e[1]];
    const double up = std::ldexp(lift(rng), -7);
    Point3 to{};
    switch (kind(rng)) {
      case 0:  // onto one end
        to = a;
        break;
      case 1:  // a lifted midpoint
        to = {(a[0] + b[0]) / 2, (a[1] + b[1]) / 2, (a[2] + b[2]) / 2 + up};
        break;
      case 2:  // beyond b, as far again, lifted
        to = {2 * b[0] - a[0], 2 * b[1] - a[1], 2 * b[2] - a[2] + up};
        break;
      default:  // straight up or down from a
        to = {a[0], a[1], a[2] + 2 * up};
        break;
    }
    const Surface forced = forced_collapse(surface, e[0], e[1], to);
    const bool bad_end = intersects(forced);
    intersecting_end_states += bad_end ? 1 : 0;
    Surface in_pass = surface;
    const std::array<Collapse, 1> collapses{Collapse{e[0], e[1], to}};
    const Outcome pass = collapse_edges(in_pass, collapses).front();
    const Outcome one = collapse_edge(surface, e[0], e[1], to);
    EXPECT_EQ(pass.verdict, one.verdict)
        << "trial " << trial << ": " << one.reason << " / " << pass.reason;
    if (bad_end) {
      ASSERT_FALSE(one.applied()) << "trial " << trial << ": collapsing " << e[0] << "-" << e[1]
                                  << " intersects at its end, yet was applied";
    }
    if (one.applied()) {
      ++applied;
      ASSERT_FALSE(intersects(surface)) << "trial " << trial;
      ASSERT_EQ(mesh::check_mesh(mesh::mesh_of(surface)).zero_area_faces.count, 0u) << trial;
    }
  }
  std::cout << intersecting_end_states << " of 1500 collapses end intersecting, all refused; "
            << applied << " applied\n";
  EXPECT_GT(intersecting_end_states, 100);  // the test has something to refuse
  EXPECT_GT(applied, 300);
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

}  // namespace
}  // namespace exactgeo::remesh
