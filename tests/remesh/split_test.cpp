// Splits in flat sheets at points of the sheet's plane: a split off its edge must not turn
// a new triangle over or lay one half over another. A boundary edge (one triangle) and an
// inner edge (two) of integer triangles in two planes, at 2^0 and 2^+-1000, split at every
// point of a half-integer grid around them: applied exactly when the rational oracle finds
// the split surface without overlap, zero area or a turned triangle (or the point lies
// strictly inside the edge, where nothing moves), as a single split and in a pass.
//
// And under a second sheet (two_sheets.hpp, at 2^0 and 2^+-1000): a split point lifted
// through or onto the sheet is refused and one just under it applied; a rounded midpoint a
// hair off the edge, inside its other triangle, is applied (alone, lifted and in a pass);
// a split whose new triangle passes through a neighbour with all its corners among the
// split's is refused.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "exactgeo/remesh/operations.hpp"
#include "remesh/flat_sheet.hpp"
#include "remesh/sheets_oracle.hpp"
#include "remesh/two_sheets.hpp"
#include "support/rational_oracle.hpp"
#include "support/seed.hpp"
#include "support/segment_triangle_oracle.hpp"

namespace exactgeo::remesh {
namespace {

using testing::expect_intersection_free;
using testing::facing_oracle;
using testing::flat_overlap;
using testing::kInner;
using testing::Operations;
using testing::points_of;
using testing::sheets;
using testing::TrianglePoints;

/// The split of edge ab (vertices 0 and 1) at `at` made without any check: each triangle
/// x y c walking x -> y along the edge becomes x m c and m y c.
Surface forced_split(const Surface& s, const Point3& at) {
  Surface split = s;
  const auto m = static_cast<VertexIndex>(s.vertices.size());
  split.vertices.push_back(at);
  split.triangles.clear();
  for (const Triangle& t : s.triangles) {
    const VertexIndex c = third_corner(t, 0, 1);
    const VertexIndex x = walks(t, 0, 1) ? 0 : 1, y = 1 - x;
    split.triangles.push_back({x, m, c});
    split.triangles.push_back({m, y, c});
  }
  return split;
}

/// Why the forced split is wrong by the oracle, or nullopt.
std::optional<std::string> split_fault(const Surface& s, const Point3& at) {
  const Surface split = forced_split(s, at);
  if (auto fault = flat_overlap(split)) return fault;
  for (std::size_t i = 0; i < split.triangles.size(); ++i) {
    const TrianglePoints old = points_of(s, s.triangles[i / 2]);
    if (facing_oracle(old, points_of(split, split.triangles[i])) != Sign::positive)
      return "new triangle " + std::to_string(i) + " turns over";
  }
  return std::nullopt;
}

/// Strictly inside segment ab (exactly: collinear by the oracle's plane test, in the box).
bool inside_edge(const Point3& a, const Point3& b, const Point3& m) {
  if (m == a || m == b) return false;
  for (int k = 0; k < 3; ++k) {
    if (m[k] < std::min(a[k], b[k]) || m[k] > std::max(a[k], b[k])) return false;
  }
  // Collinear: the cross product of b - a and m - a vanishes, checked on a grid point
  // where these small multiples are exact.
  const double ux = b[0] - a[0], uy = b[1] - a[1], uz = b[2] - a[2];
  const double vx = m[0] - a[0], vy = m[1] - a[1], vz = m[2] - a[2];
  return uy * vz - uz * vy == 0 && uz * vx - ux * vz == 0 && ux * vy - uy * vx == 0;
}

struct SplitCase {
  const char* name;
  std::vector<std::array<double, 2>> corners;  // a, b, then the opposite corners
  std::vector<Triangle> triangles;
};

class FlatSplits : public ::testing::TestWithParam<std::tuple<int, bool>> {};

TEST_P(FlatSplits, AppliedExactlyWhenTheHalvesTileTheirTriangles) {
  const auto [exponent, tilted] = GetParam();
  const testing::FlatPlane plane = testing::flat_plane(tilted, exponent);
  const std::vector<SplitCase> cases = {
      {"boundary edge", {{0, 0}, {4, 0}, {1, 2}}, {{0, 1, 2}}},
      {"inner edge", {{0, 0}, {4, 0}, {1, 2}, {3, -2}}, {{0, 1, 2}, {1, 0, 3}}},
      {"inner edge, obtuse", {{0, 0}, {4, 0}, {-1, 1}, {5, -1}}, {{0, 1, 2}, {1, 0, 3}}},
  };
  for (const SplitCase& c : cases) {
    Surface surface;
    for (const auto& [x, y] : c.corners)
      surface.vertices.push_back(plane(x, y));
    surface.triangles = c.triangles;
    ASSERT_FALSE(flat_overlap(surface).has_value()) << c.name;
    int applied = 0, refused = 0;
    for (double x = -4; x <= 8; x += 0.5) {
      for (double y = -4; y <= 4; y += 0.5) {
        const Point3 at = plane(x, y);
        const std::string what = std::string(c.name) + " at (" + std::to_string(x) + ", " +
                                 std::to_string(y) + "), scale 2^" + std::to_string(exponent);
        const bool on_edge = inside_edge(surface.vertices[0], surface.vertices[1], at);
        const std::optional<std::string> fault = on_edge ? std::nullopt : split_fault(surface, at);
        Surface single = surface;
        const Outcome one = split_edge(single, 0, 1, at);
        Surface pass = surface;
        const std::array<Split, 1> splits{Split{0, 1, at}};
        const Outcome in_pass = split_edges(pass, splits).front();
        EXPECT_EQ(one.applied(), !fault) << what << ": " << (fault ? *fault : one.reason);
        EXPECT_EQ(in_pass.verdict, one.verdict) << what;
        if (one.applied()) {
          ++applied;
          EXPECT_FALSE(flat_overlap(single).has_value()) << what;
        } else {
          ++refused;
        }
      }
    }
    EXPECT_GT(applied, 5) << c.name;
    EXPECT_GT(refused, 100) << c.name;
  }
}

TEST(FlatSplits, APointBeyondTheOppositeCornerIsRefusedNamingIt) {
  // A boundary edge's triangle a b c split at m beyond c: both halves turn over.
  Surface s;
  s.vertices = {{0, 0, 0}, {4, 0, 0}, {1, 1, 0}};
  s.triangles = {{0, 1, 2}};
  const Outcome split = split_edge(s, 0, 1, {1, 3, 0});
  EXPECT_EQ(split.verdict, Verdict::refused_collision);
  ASSERT_TRUE(split.blocker.has_value());
  EXPECT_EQ(split.blocker->corners[0], 2u) << split.reason;
  EXPECT_NE(split.reason.find("over, flat in the plane of the triangle it replaces"),
            std::string::npos)
      << split.reason;
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

TEST_P(Operations, TheTwoSidesFoldIntoEachOtherOnlyWithBothCornersOnOneSideOfPlaneABM) {
  // Random splits of an inner edge ab, a = (0,0,0) and b = (4,0,0), with opposite corners
  // c and d and the new point m of small integers (the two triangles apart but for their
  // edge): every applied split leaves the two
  // triangles' four new ones intersection free by an oracle written from the definition
  // (sheets_oracle.hpp: GMP, a touch or a flat overlap counting), which shares no code
  // with the split's checks or the library's finder (which must agree with it). With c and d
  // strictly on opposite sides of the plane of a, b and m, the split takes the sides as apart
  // without testing their new triangles against each other (split.cpp, sides_apart); with both on
  // one side, a fold of the sides into each other happens, and is refused.
  const double s = scale();
  auto rng = testing::seeded_engine("remesh.split.sides");
  std::uniform_int_distribution<int> coordinate(-4, 4);
  const auto point = [&] {
    return Point3{s * coordinate(rng), s * coordinate(rng), s * coordinate(rng)};
  };
  int apart_applied = 0;  // c and d on opposite sides of plane abm, applied
  int folds_refused = 0;  // on one side, refused as a fold of the sides
  // 3000 trials at full effort (tests/support/seed.hpp); the counts of both kinds below
  // are asked of the same share of them.
  const int trials = static_cast<int>(testing::scaled_trials(3000));
  for (int trial = 0; trial < trials; ++trial) {
    Surface surface;
    surface.vertices = {Point3{0, 0, 0}, Point3{4 * s, 0, 0}, point(), point()};
    surface.triangles = {{0, 1, 2}, {1, 0, 3}};
    const Point3 m = point();
    const auto& p = surface.vertices;
    if (testing::collinear_oracle(p[0], p[1], p[2]) || testing::collinear_oracle(p[0], p[1], p[3]))
      continue;
    if (testing::sheets_meet_oracle(surface)) continue;  // folded already
    const Sign c_side = testing::orient3d_oracle(p[0], p[1], m, p[2]);
    const Sign d_side = testing::orient3d_oracle(p[0], p[1], m, p[3]);
    Surface split = surface;
    const Outcome outcome = split_edge(split, 0, 1, m);
    const Surface forced = forced_split(surface, m);
    const bool zero_area =
        std::any_of(forced.triangles.begin(), forced.triangles.end(), [&](const Triangle& t) {
          const auto& q = forced.vertices;
          return testing::collinear_oracle(q[t[0]], q[t[1]], q[t[2]]);
        });
    if (zero_area) {  // m on a line through a corner: a new triangle of zero area
      EXPECT_FALSE(outcome.applied()) << "trial " << trial << ": applied with zero area";
      continue;
    }
    const bool intersecting = testing::sheets_meet_oracle(forced);
    EXPECT_EQ(intersecting, !testing::sheets_meeting(forced).intersecting.empty())
        << "trial " << trial << ": the finder and the oracle disagree";
    if (outcome.applied()) {
      EXPECT_FALSE(intersecting) << "trial " << trial << ": applied, and intersecting";
      apart_applied += c_side != Sign::zero && d_side == -c_side ? 1 : 0;
    } else if (outcome.reason.find("fold its two sides") != std::string::npos) {
      EXPECT_TRUE(intersecting) << "trial " << trial << ": " << outcome.reason;
      EXPECT_FALSE(c_side != Sign::zero && d_side == -c_side) << "trial " << trial;
      ++folds_refused;
    }
  }
  EXPECT_GT(apart_applied, 200 * trials / 3000);
  EXPECT_GT(folds_refused, 200 * trials / 3000);
}

INSTANTIATE_TEST_SUITE_P(Planes, FlatSplits,
                         ::testing::Combine(::testing::Values(0, 1000, -1000), ::testing::Bool()),
                         [](const auto& param_info) {
                           const int k = std::get<0>(param_info.param);
                           return (k < 0 ? "scale_2m" : "scale_2p") + std::to_string(std::abs(k)) +
                                  (std::get<1>(param_info.param) ? "_tilted" : "_flat");
                         });

}  // namespace
}  // namespace exactgeo::remesh
