// Flips in flat sheets: the new triangles of a flip whose four corners lie in one plane
// must tile the quadrilateral, never lie one over the other. Random quadrilaterals of
// integer points in two planes (z = 0 and z = x - 2y), at 2^0 and 2^+-1000, with corners
// exactly on the line of the new diagonal and one ulp either side of it: a flip is applied
// exactly when the rational oracle (coplanar_overlap_oracle.hpp) finds the flipped pair
// apart and facing as before, as a single flip and in a pass. The quadrilateral's corner
// a is a sheet corner: the operation's own edges are its only ones, so no region test
// can see it lying inside the other new triangle.
//
// And under a second sheet (two_sheets.hpp, at 2^0 and 2^+-1000): a flip sweeps the
// closed tetrahedron of its four corners, so a vertex of the sheet on its new face or one
// ulp inside refuses it (named) and one ulp outside does not; an edge running through the
// tetrahedron, both ends outside it, refuses it too.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "exactgeo/remesh/operations.hpp"
#include "remesh/flat_sheet.hpp"
#include "remesh/two_sheets.hpp"
#include "support/seed.hpp"

namespace exactgeo::remesh {
namespace {

using testing::expect_intersection_free;
using testing::facing_oracle;
using testing::flat_overlap;
using testing::kInner;
using testing::kTopTriangleFirst;
using testing::Operations;
using testing::points_of;
using testing::sheets;

/// Two triangles abc and bad on edge ab (vertices 0, 1; c = 2, d = 3).
Surface two_triangles(const Point3& a, const Point3& b, const Point3& c, const Point3& d) {
  Surface s;
  s.vertices = {a, b, c, d};
  s.triangles = {{0, 1, 2}, {1, 0, 3}};
  return s;
}

/// The flip made without any check: cad and dbc.
Surface forced_flip(const Surface& s) {
  Surface flipped = s;
  flipped.triangles = {{2, 0, 3}, {3, 1, 2}};
  return flipped;
}

/// Why the flipped pair is wrong by the oracle (overlap, zero area, or a new triangle
/// facing the other way from abc), or nullopt.
std::optional<std::string> flip_fault(const Surface& s) {
  const Surface flipped = forced_flip(s);
  if (auto fault = flat_overlap(flipped)) return fault;
  for (const Triangle& t : flipped.triangles) {
    if (facing_oracle(points_of(s, s.triangles[0]), points_of(flipped, t)) != Sign::positive)
      return "a new triangle turns over";
  }
  return std::nullopt;
}

struct Tally {
  int applied = 0;
  int refused = 0;
};

/// One case: flip_edge and flip_edges agree with the oracle, and an applied flip leaves a
/// surface the oracle finds clean.
void check_flip(const Surface& s, const std::string& what, Tally& tally) {
  ASSERT_FALSE(flat_overlap(s).has_value()) << what << ": the set-up overlaps";
  const std::optional<std::string> fault = flip_fault(s);
  Surface single = s;
  const Outcome one = flip_edge(single, 0, 1);
  Surface pass = s;
  const std::array<Edge, 1> edges{Edge{0, 1}};
  const Outcome in_pass = flip_edges(pass, edges).front();
  EXPECT_EQ(one.applied(), !fault) << what << ": " << (fault ? *fault : one.reason);
  EXPECT_EQ(in_pass.verdict, one.verdict) << what << ": " << in_pass.reason;
  if (one.applied()) {
    ++tally.applied;
    EXPECT_FALSE(flat_overlap(single).has_value()) << what;
    EXPECT_EQ(single.triangles, pass.triangles) << what;
  } else {
    ++tally.refused;
    EXPECT_EQ(single.triangles, s.triangles) << what << ": refused, but changed";
  }
}

class FlatFlips : public ::testing::TestWithParam<std::tuple<int, bool>> {};

TEST_P(FlatFlips, AppliedExactlyWhenTheNewTrianglesTileTheQuadrilateral) {
  const auto [exponent, tilted] = GetParam();
  const testing::FlatPlane plane = testing::flat_plane(tilted, exponent);
  std::mt19937_64 rng = testing::seeded_engine("FlatFlips.random");
  std::uniform_int_distribution<int> coordinate(-8, 8);
  Tally tally;
  // 3000 at full effort (tests/support/seed.hpp); both kinds asked of the same share.
  const auto trials = static_cast<int>(testing::scaled_trials(3000));
  for (int trial = 0; trial < trials; ++trial) {
    const std::array<double, 2> a{0, 0}, b{static_cast<double>(coordinate(rng) % 4 + 5), 0};
    const double cx = coordinate(rng), cy = std::abs(coordinate(rng)) + 1;   // left of ab
    const double dx = coordinate(rng), dy = -std::abs(coordinate(rng)) - 1;  // right of it
    const Surface s =
        two_triangles(plane(a[0], a[1]), plane(b[0], b[1]), plane(cx, cy), plane(dx, dy));
    check_flip(s, "trial " + std::to_string(trial), tally);
  }
  // Both kinds occur: convex quadrilaterals, and ones reflex at a or b.
  EXPECT_GT(tally.applied, 300 * trials / 3000);
  EXPECT_GT(tally.refused, 300 * trials / 3000);
}

TEST(FlatFlips, ACornerOnTheNewDiagonalAndOneUlpEitherSide) {
  // c = (-2, 2), d = (2, -2): the new diagonal passes through a = (0, 0) exactly. d moved
  // by one ulp in x turns a to either side of it: convex (applied) or reflex at a. (In
  // z = 0 only: an ulp off the grid is not exact in the tilted plane.)
  for (const int exponent : {0, 1000, -1000}) {
    const testing::FlatPlane plane = testing::flat_plane(false, exponent);
    Tally tally;
    for (const double dx : {std::nextafter(2.0, 0.0), 2.0, std::nextafter(2.0, 4.0)}) {
      const Surface s = two_triangles(plane(0, 0), plane(4, 0), plane(-2, 2), plane(dx, -2));
      check_flip(s, "d.x = " + std::to_string(dx) + " at 2^" + std::to_string(exponent), tally);
    }
    EXPECT_EQ(tally.applied, 1);  // the ulp that makes the quadrilateral convex at a
    EXPECT_EQ(tally.refused, 2);  // zero area on the diagonal, a fold one ulp beyond
  }
}

TEST(FlatFlips, TheRefusalNamesTheReflexCorner) {
  // The sheet: a b c d in z = 0, reflex at a, so that cad would lie inside dbc.
  Surface s = two_triangles({0, 0, 0}, {4, 0, 0}, {-3, 1, 0}, {-3, -1, 0});
  const Outcome flip = flip_edge(s, 0, 1);
  EXPECT_EQ(flip.verdict, Verdict::refused_collision);
  ASSERT_TRUE(flip.blocker.has_value());
  EXPECT_EQ(flip.blocker->kind, Blocker::Kind::vertex);
  EXPECT_EQ(flip.blocker->corners[0], 0u) << flip.reason;
  EXPECT_NE(flip.reason.find("would turn new triangle 2 0 3 over"), std::string::npos)
      << flip.reason;
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

INSTANTIATE_TEST_SUITE_P(Planes, FlatFlips,
                         ::testing::Combine(::testing::Values(0, 1000, -1000), ::testing::Bool()),
                         [](const auto& param_info) {
                           const int k = std::get<0>(param_info.param);
                           return (k < 0 ? "scale_2m" : "scale_2p") + std::to_string(std::abs(k)) +
                                  (std::get<1>(param_info.param) ? "_tilted" : "_flat");
                         });

}  // namespace
}  // namespace exactgeo::remesh
