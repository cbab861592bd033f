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
#include <iostream>
#include <random>
#include <span>
#include <stdexcept>
#include <utility>
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

TEST(CollapsePass, ProposingOnlyWhatCouldGoAheadMakesTheSameCollapses) {
  // Passes over a crumpled stack proposing every edge in a random order (to an end or to a
  // lifted midpoint): the pass that proposes only the collapses could_go_ahead allows must
  // apply the same collapses with the same outcomes and leave the same surface as
  // collapse_edges given all of them, and every collapse could_go_ahead refuses must be
  // deferred there (or refused for its topology, which is checked first) (at 2^0 and 2^+-1000: the
  // schedule's boxes are exact at every scale).
  auto rng = testing::seeded_engine("remesh.collapse_pass.could_go_ahead");
  std::uniform_int_distribution<int> lift(-40, 40);  // in steps of 2^-7
  int skipped = 0, applied = 0;
  for (const int exponent : {0, 1000, -1000}) {
    Surface all = testing::stack(3, 8, rng, 0.2);
    testing::crumple(all, rng);
    all = testing::times_power_of_two(std::move(all), exponent);
    Surface some = all;
    for (int pass = 0; pass < 6; ++pass) {
      std::vector<Edge> edges = all.edges();
      std::shuffle(edges.begin(), edges.end(), rng);
      std::vector<Collapse> collapses;
      for (const Edge& e : edges) {
        const Point3& a = all.vertices[e[0]];
        const Point3& b = all.vertices[e[1]];
        const double up = std::ldexp(lift(rng), exponent - 7);
        collapses.push_back(
            {e[0], e[1],
             pass % 2 == 0 ? a
                           : Point3{(a[0] + b[0]) / 2, (a[1] + b[1]) / 2, (a[2] + b[2]) / 2 + up}});
      }
      const std::vector<Outcome> every = collapse_edges(all, collapses);
      CollapsePass proposed(some);
      // Its table of the triangles around each vertex is the surface's, through the pass.
      for (VertexIndex v = 0; v < some.vertices.size(); ++v) {
        const std::span<const std::size_t> around = proposed.triangles_around(v);
        ASSERT_EQ(std::vector<std::size_t>(around.begin(), around.end()), some.triangles_around(v))
            << "vertex " << v << ", pass " << pass;
      }
      std::vector<std::size_t> asked;  // the collapses proposed, in order
      for (std::size_t i = 0; i < collapses.size(); ++i) {
        if (!proposed.could_go_ahead(collapses[i].a, collapses[i].b)) {
          EXPECT_TRUE(every[i].verdict == Verdict::deferred ||
                      every[i].verdict == Verdict::refused_topology)
              << "collapse " << i << ", pass " << pass << ": " << every[i].reason;
          ++skipped;
          continue;
        }
        proposed.propose(collapses[i]);
        asked.push_back(i);
        if (i % 7 == 0) {  // and stays so while collapses are proposed
          const std::span<const std::size_t> around = proposed.triangles_around(collapses[i].a);
          ASSERT_EQ(std::vector<std::size_t>(around.begin(), around.end()),
                    some.triangles_around(collapses[i].a));
        }
      }
      const std::vector<Outcome> fewer = proposed.finish(some);
      ASSERT_EQ(fewer.size(), asked.size());
      std::size_t applied_in_all = 0;
      for (const Outcome& o : every)
        applied_in_all += o.applied() ? 1 : 0;
      std::size_t applied_in_some = 0;
      for (std::size_t k = 0; k < asked.size(); ++k) {
        const Outcome& o = every[asked[k]];
        EXPECT_EQ(fewer[k].verdict, o.verdict) << fewer[k].reason << " / " << o.reason;
        EXPECT_EQ(fewer[k].blocker, o.blocker) << fewer[k].reason;
        applied_in_some += fewer[k].applied() ? 1 : 0;
      }
      EXPECT_EQ(applied_in_some, applied_in_all) << "pass " << pass;
      applied += static_cast<int>(applied_in_some);
      ASSERT_EQ(some.vertices, all.vertices) << "pass " << pass;
      ASSERT_EQ(some.triangles, all.triangles) << "pass " << pass;
    }
    // A pass is finished once.
    CollapsePass used(some);
    EXPECT_TRUE(used.finish(some).empty());
    EXPECT_THROW(static_cast<void>(used.could_go_ahead(0, 1)), std::logic_error);
    EXPECT_THROW(used.propose({0, 1, Point3{}}), std::logic_error);
    EXPECT_THROW(static_cast<void>(used.triangles_around(0)), std::logic_error);
  }
  std::cout << skipped << " collapses left unproposed, " << applied << " applied\n";
  EXPECT_GT(skipped, 500);
  EXPECT_GT(applied, 100);
}

}  // namespace
}  // namespace exactgeo::remesh
