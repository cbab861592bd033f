// Pseudo-motions (pseudo_motion.hpp): what a collapse or a move would hit as its vertices
// move on straight lines while the rest stands. Hand cases whose answer is known by
// construction, at 2^0 and 2^+-1000: a collapse whose end passes through a standing
// triangle hits it (named), one that stays under it, or ends one step under it, does
// not, and one that ends on it does; the collapsing edge's ends meet at the end of the
// step, which is no contact when the edge is named as merged and is one when it is not; a
// triangle rising over a standing vertex names the vertex; an edge rising through a
// standing sliver's edge names that edge. Every named contact is confirmed by the exact
// distance oracle of the CCD tests (min_separation_oracle with distance 0, which shares no
// code with exact CCD).

#include "exactgeo/remesh/pseudo_motion.hpp"

#include <gtest/gtest.h>

#include "support/scale_names.hpp"

#include <array>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "ccd/separation/min_separation_oracle.hpp"

namespace exactgeo::remesh {
namespace {

/// The positions at both ends of the step.
struct Ends {
  std::vector<Point3> t0, t1;
  Ends(const Surface& s, std::span<const Move> moves) : t0(s.vertices), t1(s.vertices) {
    for (const Move& m : moves)
      t1[m.vertex] = m.to;
  }
};

/// Vertex v and triangle f come into contact during the step, by the distance oracle.
bool vertex_face_contact(const Ends& e, VertexIndex v, const Triangle& f) {
  const ccd::VertexFaceQuery q{e.t0[v], e.t0[f[0]], e.t0[f[1]], e.t0[f[2]],
                               e.t1[v], e.t1[f[0]], e.t1[f[1]], e.t1[f[2]]};
  return testing::min_separation_oracle(q, 0.0).within;
}

bool edge_edge_contact(const Ends& e, const Edge& a, const Edge& b) {
  const ccd::EdgeEdgeQuery q{e.t0[a[0]], e.t0[a[1]], e.t0[b[0]], e.t0[b[1]],
                             e.t1[a[0]], e.t1[a[1]], e.t1[b[0]], e.t1[b[1]]};
  return testing::min_separation_oracle(q, 0.0).within;
}

std::string blocker_text(const std::optional<Blocker>& b) {
  return b ? to_string(*b) : std::string("nothing");
}

class PseudoMotions : public ::testing::TestWithParam<int> {
 protected:
  double scale() const { return std::ldexp(1.0, GetParam()); }
  Point3 at(double x, double y, double z) const {
    const double s = scale();
    return {s * x, s * y, s * z};
  }
  /// Edge ab = (0,0,0)-(2,0,0) (vertices 0, 1) between triangles abc and bad, c = (1,2,0)
  /// and d = (1,-2,0) (vertices 2, 3), in z = 0; then a triangle p q r (vertices 4-6).
  Surface scene(const Point3& p, const Point3& q, const Point3& r) const {
    Surface s;
    s.vertices = {at(0, 0, 0), at(2, 0, 0), at(1, 2, 0), at(1, -2, 0), p, q, r};
    s.triangles = {{0, 1, 2}, {1, 0, 3}, {4, 5, 6}};
    return s;
  }
  /// The collapse of ab to `to`: both ends move there, merged.
  static std::optional<Blocker> collapse(const Surface& s, const Point3& to) {
    const std::array<Move, 2> moves{Move{0, to}, Move{1, to}};
    return first_collision(s, moves, Edge{0, 1});
  }
};

TEST_P(PseudoMotions, ACollapseWhoseEndPassesThroughAStandingTriangleHitsIt) {
  // A large triangle at height 2 covering 4 < x < 8 on the line y = 0. Collapsing ab to
  // (7, 0, 4), b passes height 2 at x = 4.5 (through it), a at x = 3.5 (beside it).
  const Surface s = scene(at(2, -8, 2), at(10, -8, 2), at(6, 8, 2));
  const Point3 to = at(7, 0, 4);
  const std::optional<Blocker> hit = collapse(s, to);
  ASSERT_TRUE(hit.has_value());
  EXPECT_EQ(*hit, (Blocker{Blocker::Kind::triangle, {4, 5, 6}})) << blocker_text(hit);
  const std::array<Move, 2> moves{Move{0, to}, Move{1, to}};
  const Ends ends(s, moves);
  EXPECT_TRUE(vertex_face_contact(ends, 1, s.triangles[2]));
  EXPECT_FALSE(vertex_face_contact(ends, 0, s.triangles[2]));
  // Moving b alone there hits it too.
  EXPECT_EQ(first_collision(s, std::array{Move{1, to}}), hit) << "b alone";
}

TEST_P(PseudoMotions, ACollapseThatStaysUnderTheTriangleHitsNothing) {
  const Surface s = scene(at(2, -8, 2), at(10, -8, 2), at(6, 8, 2));
  EXPECT_EQ(collapse(s, at(7, 0, 1)), std::nullopt);
  EXPECT_EQ(collapse(s, at(1, 0, 1)), std::nullopt);
  // One step under the triangle's plane at the end: nothing; on it: a contact at the end.
  EXPECT_EQ(collapse(s, {7 * scale(), 0.0, std::nextafter(2 * scale(), 0.0)}), std::nullopt);
  EXPECT_EQ(collapse(s, at(7, 0, 2)), (Blocker{Blocker::Kind::triangle, {4, 5, 6}}));
}

TEST_P(PseudoMotions, TheCollapsingEdgesEndsCountAsOneVertex) {
  // Collapsed to its midpoint, nothing moves off the plane and nothing else is near; but
  // a and b meet at the end of the step, so edges at a and at b that share no vertex (ad
  // and bc, say) touch there: a contact, unless the edge is named as merged.
  const Surface s = scene(at(10, 10, 10), at(11, 10, 10), at(10, 11, 10));
  const Point3 mid = at(1, 0, 0);
  const std::array<Move, 2> moves{Move{0, mid}, Move{1, mid}};
  EXPECT_EQ(first_collision(s, moves, Edge{0, 1}), std::nullopt);
  const std::optional<Blocker> unmerged = first_collision(s, moves);
  ASSERT_TRUE(unmerged.has_value());
  ASSERT_EQ(unmerged->kind, Blocker::Kind::edge) << blocker_text(unmerged);
  const Edge named{unmerged->corners[0], unmerged->corners[1]};
  EXPECT_LT(named[1], 4u) << "an edge of the collapse's own triangles: " << blocker_text(unmerged);
  // Some moving edge that shares no vertex with the named one touches it.
  const Ends ends(s, moves);
  bool confirmed = false;
  for (const Edge& e : s.edges()) {
    if ((e[0] == 0 || e[0] == 1 || e[1] == 0 || e[1] == 1) && e[0] != named[0] &&
        e[0] != named[1] && e[1] != named[0] && e[1] != named[1]) {
      confirmed = confirmed || edge_edge_contact(ends, e, named);
    }
  }
  EXPECT_TRUE(confirmed) << blocker_text(unmerged);
}

TEST_P(PseudoMotions, ATriangleRisingOverAStandingVertexNamesIt) {
  // Collapsing ab to (1, 0, 1), triangle abc rises as a tent; the standing point
  // (1, 1/4, 1/4) lies in it at time 2/7. The standing triangle's other corners are high
  // above, at y = 1/4 (a plane no moving vertex crosses).
  const Surface s = scene(at(1, 0.25, 0.25), at(1, 0.25, 3), at(1.5, 0.25, 3));
  const Point3 to = at(1, 0, 1);
  const std::optional<Blocker> hit = collapse(s, to);
  EXPECT_EQ(hit, (Blocker{Blocker::Kind::vertex, {4, kNoVertex, kNoVertex}})) << blocker_text(hit);
  const std::array<Move, 2> moves{Move{0, to}, Move{1, to}};
  EXPECT_TRUE(vertex_face_contact(Ends(s, moves), 4, s.triangles[0]));
  // The same triangle lifted so that its lowest corner is above the tent's top: nothing.
  const Surface above = scene(at(1, 0.25, 1.5), at(1, 0.25, 3), at(1.5, 0.25, 3));
  EXPECT_EQ(collapse(above, to), std::nullopt);
}

TEST_P(PseudoMotions, AnEdgeRisingThroughAStandingEdgeNamesIt) {
  // A sliver at height 1 over the strip 1 < y < 1.0625: c = (1, 2, 0) rising to
  // (1, 2, 4) passes beside it, but its edges to a and b rise through the sliver's edges.
  const Surface s = scene(at(-8, 1, 1), at(8, 1, 1), at(8, 1.0625, 1));
  const std::array<Move, 1> up{Move{2, at(1, 2, 4)}};
  const std::optional<Blocker> hit = first_collision(s, up);
  ASSERT_TRUE(hit.has_value());
  ASSERT_EQ(hit->kind, Blocker::Kind::edge) << blocker_text(hit);
  const Edge named{hit->corners[0], hit->corners[1]};
  EXPECT_GE(named[0], 4u) << "an edge of the sliver: " << blocker_text(hit);
  const Ends ends(s, up);
  EXPECT_TRUE(edge_edge_contact(ends, Edge{0, 2}, named) ||
              edge_edge_contact(ends, Edge{1, 2}, named))
      << blocker_text(hit);
  // Rising to 1.5 only, the edges stay under the sliver (below 0.8 over the strip).
  EXPECT_EQ(first_collision(s, std::array{Move{2, at(1, 2, 1.5)}}), std::nullopt);
}

INSTANTIATE_TEST_SUITE_P(Scales, PseudoMotions, ::testing::Values(0, 1000, -1000),
                         exactgeo::testing::scale_name);

}  // namespace
}  // namespace exactgeo::remesh
