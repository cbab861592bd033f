// Swept regions (swept_region.hpp), decided exactly: what meets the closed hull a flip or
// a split sweeps, whether two regions meet, whether a new triangle turns over in the old
// one's plane. Hand cases whose answer is known by construction (a vertex inside, on a
// face and one ulp outside; an edge and a triangle through the hull with every corner
// outside it; what the region shares by vertex index, and a split's partner, no
// obstacle; a flat region and a vertex one step off its plane; tetrahedra touching at a
// point, one ulp apart, crossing with no corner inside), then seeded families of small
// integer configurations (where every kind of touching happens, flat ones included)
// checked against the rational hull oracle (hull_oracle.hpp: a linear program, no
// orientation signs) and the coplanar oracle's facing test, all at 2^0 and 2^+-1000.

#include "exactgeo/remesh/swept_region.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <optional>
#include <random>
#include <span>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "remesh/hull_oracle.hpp"
#include "support/coplanar_overlap_oracle.hpp"
#include "support/rational_oracle.hpp"
#include "support/scale_names.hpp"
#include "support/seed.hpp"
#include "support/segment_triangle_oracle.hpp"

namespace exactgeo::remesh {
namespace {

using Region = std::array<RegionCorner, 4>;
using testing::collinear_oracle;
using testing::hulls_meet;
using testing::hulls_meet_beyond;
using testing::orient3d_oracle;

std::array<Point3, 4> corner_points(const Region& region) {
  return {region[0].point, region[1].point, region[2].point, region[3].point};
}

/// No three corners collinear (first_in_region's and regions_meet's precondition).
bool well_formed(const Region& region) {
  for (int skip = 0; skip < 4; ++skip) {
    std::vector<Point3> three;
    for (int i = 0; i < 4; ++i) {
      if (i != skip) three.push_back(region[i].point);
    }
    if (collinear_oracle(three[0], three[1], three[2])) return false;
  }
  return true;
}

/// first_in_region as its header states it, element by element with the hull oracle: the
/// vertices some triangle uses (by index), the edges (sorted), the triangles (in order);
/// the first that meets the region's hull outside the hull of the corners it shares with
/// it by vertex index, skipping the operation's own elements (all corners region corners)
/// and the partner's triangle abd (its corner d and edges ad and bd stay, and are tested).
std::optional<Blocker> first_in_region_oracle(const Surface& s, const Region& region,
                                              VertexIndex partner) {
  const std::array<Point3, 4> r = corner_points(region);
  const auto is_corner = [&](VertexIndex v) {
    for (const RegionCorner& c : region) {
      if (c.vertex == v) return true;
    }
    return false;
  };
  const auto of_partner_side = [&](VertexIndex v) {  // a corner of triangle abd
    return partner != kNoVertex && (v == region[0].vertex || v == region[1].vertex || v == partner);
  };
  const auto shared_mask = [&](std::span<const VertexIndex> corners) {
    unsigned mask = 0;
    for (std::size_t i = 0; i < corners.size(); ++i) {
      if (is_corner(corners[i])) mask |= 1u << i;
    }
    return mask;
  };
  std::vector<bool> used(s.vertices.size(), false);
  std::vector<Edge> edges;  // brute force: every side of every triangle, sorted, once
  for (const Triangle& t : s.triangles) {
    for (int k = 0; k < 3; ++k) {
      used[t[k]] = true;
      const Edge e = edge_of(t[k], t[(k + 1) % 3]);
      if (std::find(edges.begin(), edges.end(), e) == edges.end()) edges.push_back(e);
    }
  }
  std::sort(edges.begin(), edges.end());
  for (VertexIndex v = 0; v < s.vertices.size(); ++v) {
    if (!used[v] || is_corner(v)) continue;
    if (hulls_meet(std::array<Point3, 1>{s.vertices[v]}, r))
      return Blocker{Blocker::Kind::vertex, {v, kNoVertex, kNoVertex}};
  }
  for (const Edge& e : edges) {
    if (is_corner(e[0]) && is_corner(e[1])) continue;
    const std::array<Point3, 2> ends{s.vertices[e[0]], s.vertices[e[1]]};
    if (hulls_meet_beyond(ends, shared_mask(e), r))
      return Blocker{Blocker::Kind::edge, {e[0], e[1], kNoVertex}};
  }
  for (const Triangle& t : s.triangles) {
    if (is_corner(t[0]) && is_corner(t[1]) && is_corner(t[2])) continue;
    if (of_partner_side(t[0]) && of_partner_side(t[1]) && of_partner_side(t[2])) continue;
    const std::array<Point3, 3> corners{s.vertices[t[0]], s.vertices[t[1]], s.vertices[t[2]]};
    if (hulls_meet_beyond(corners, shared_mask(t), r)) return Blocker{Blocker::Kind::triangle, t};
  }
  return std::nullopt;
}

/// Where first_in_region and its header part, found by the family below (the family
/// compares these regions one way only, and the report of this file's tests names them).
struct Deviations {
  /// Says more than the header, never less: a flat region shared in a way a tetrahedron
  /// cannot be. (1) A vertex corner strictly inside the triangle of the other three: an
  /// edge at that corner leaving the plane meets the face opposite the corner there,
  /// tested as sharing nothing with it (swept_region.cpp, edge_meets), and is reported
  /// though it meets the region only at the shared corner. (2) Two vertex corners
  /// opposite in the quadrilateral (a diagonal), both corners of a triangle out of the
  /// plane: the other diagonal, a region edge sharing nothing with the triangle, touches
  /// it on the shared diagonal, and the triangle is reported. A flip or a split does not
  /// ask this region: (1) is a new triangle turned over (or old triangles lying on each
  /// other), refused before the region test; in (2) the triangle is on the flip's edge or
  /// its new one (refused by topology), on the split edge (the partner's, skipped), or
  /// the diagonal is a side ac or bc of the split and a new triangle turns over.
  bool reports_more = false;
};

Deviations deviations_of(const Surface& s, const Region& region) {
  Deviations found;
  const auto is_corner = [&](VertexIndex v) {
    return std::any_of(region.begin(), region.end(),
                       [v](const RegionCorner& c) { return c.vertex == v; });
  };
  const auto has = [](const Triangle& t, VertexIndex v) {
    return std::find(t.begin(), t.end(), v) != t.end();
  };
  const auto own = [&](const Triangle& t) {
    return is_corner(t[0]) && is_corner(t[1]) && is_corner(t[2]);
  };
  for (int i = 0; i < 4; ++i) {
    if (region[i].vertex == kNoVertex) continue;
    std::vector<Point3> others;
    for (int j = 0; j < 4; ++j) {
      if (j != i) others.push_back(region[j].point);
    }
    if (hulls_meet(std::array<Point3, 1>{region[i].point}, others)) found.reports_more = true;
  }
  for (int i = 0; i < 4; ++i) {
    for (int j = i + 1; j < 4; ++j) {
      const VertexIndex u = region[i].vertex, w = region[j].vertex;
      if (u == kNoVertex || w == kNoVertex) continue;
      std::vector<Point3> other_pair;
      for (int k = 0; k < 4; ++k) {
        if (k != i && k != j) other_pair.push_back(region[k].point);
      }
      const std::array<Point3, 2> pair{region[i].point, region[j].point};
      if (!hulls_meet(pair, other_pair)) continue;  // not a diagonal of a flat region
      for (const Triangle& t : s.triangles) {
        if (!has(t, u) || !has(t, w) || own(t)) continue;
        const bool out_of_plane = std::any_of(t.begin(), t.end(), [&](VertexIndex v) {
          return orient3d_oracle(region[0].point, region[1].point, region[2].point,
                                 s.vertices[v]) != Sign::zero;
        });
        if (out_of_plane) found.reports_more = true;
      }
    }
  }
  return found;
}

std::string text(const std::optional<Blocker>& b) {
  return b ? to_string(*b) : std::string("nothing");
}

std::string text(const Point3& p) {
  char buffer[96];
  std::snprintf(buffer, sizeof buffer, "(%a, %a, %a)", p[0], p[1], p[2]);
  return buffer;
}

std::string text(const Surface& s) {
  std::string out;
  for (VertexIndex v = 0; v < s.vertices.size(); ++v)
    out.append(std::to_string(v)).append("@").append(text(s.vertices[v])).append(" ");
  for (const Triangle& t : s.triangles) {
    out.append("[").append(std::to_string(t[0])).append(" ").append(std::to_string(t[1]));
    out.append(" ").append(std::to_string(t[2])).append("]");
  }
  return out;
}

class SweptRegions : public ::testing::TestWithParam<int> {
 protected:
  double scale() const { return std::ldexp(1.0, GetParam()); }
  Point3 at(double x, double y, double z) const {
    const double s = scale();
    return {s * x, s * y, s * z};
  }
  /// The flip region of the tetrahedron a = (0,0,0), b = (4,0,0), c = (0,4,0),
  /// d = (0,0,4): its triangles abc and bad (vertices 0-3), then an obstacle triangle
  /// p q r (vertices 4-6).
  Surface flip_scene(const Point3& p, const Point3& q, const Point3& r) const {
    Surface s;
    s.vertices = {at(0, 0, 0), at(4, 0, 0), at(0, 4, 0), at(0, 0, 4), p, q, r};
    s.triangles = {{0, 1, 2}, {1, 0, 3}, {4, 5, 6}};
    return s;
  }
  static Region flip_region(const Surface& s) {
    return {RegionCorner{0, s.vertices[0]}, RegionCorner{1, s.vertices[1]},
            RegionCorner{2, s.vertices[2]}, RegionCorner{3, s.vertices[3]}};
  }
  /// first_in_region and the oracle both give `expected`.
  static void expect_first(const Surface& s, const Region& region, VertexIndex partner,
                           const std::optional<Blocker>& expected, const std::string& what) {
    EXPECT_EQ(first_in_region(s, region, partner), expected)
        << what << ": found " << text(first_in_region(s, region, partner)) << ", expected "
        << text(expected);
    EXPECT_EQ(first_in_region_oracle(s, region, partner), expected) << what << " (oracle)";
  }
};

TEST(SweptRegion, BlockersAreNamedWithTheirCorners) {
  EXPECT_EQ(to_string(Blocker{Blocker::Kind::vertex, {25, kNoVertex, kNoVertex}}), "vertex 25");
  EXPECT_EQ(to_string(Blocker{Blocker::Kind::edge, {3, 7, kNoVertex}}), "edge 3 7");
  EXPECT_EQ(to_string(Blocker{Blocker::Kind::triangle, {25, 27, 26}}), "triangle 25 27 26");
}

TEST_P(SweptRegions, AVertexInTheClosedTetrahedronIsMet) {
  // The obstacle's other corners lie beyond the face x + y + z = 4, far from the region.
  const Point3 q = at(5, 5, 6), r = at(5, 6, 5);
  const Blocker vertex{Blocker::Kind::vertex, {4, kNoVertex, kNoVertex}};
  const double above_face = std::nextafter(2 * scale(), HUGE_VAL);
  for (const auto& [p, met, what] :
       {std::tuple{at(1, 1, 1), true, "inside"}, std::tuple{at(1, 1, 2), true, "on face bcd"},
        std::tuple{at(1, 1, 0), true, "on face abc"},
        std::tuple{at(4, 0, 0), true, "at corner b's place, another vertex"},
        std::tuple{Point3{scale(), scale(), above_face}, false, "one ulp beyond face bcd"}}) {
    const Surface s = flip_scene(p, q, r);
    expect_first(s, flip_region(s), kNoVertex, met ? std::optional(vertex) : std::nullopt, what);
  }
}

TEST_P(SweptRegions, AnEdgeOrATriangleThroughTheHullIsMet) {
  // An edge through the tetrahedron along x = y = 1, both ends outside.
  Surface s = flip_scene(at(1, 1, -1), at(1, 1, 5), at(-8, -8, 2));
  expect_first(s, flip_region(s), kNoVertex, Blocker{Blocker::Kind::edge, {4, 5, kNoVertex}},
               "an edge through");
  // A large triangle in z = 1 with its edges far outside: the region's edge ad pierces it.
  s = flip_scene(at(-10, -10, 1), at(30, -10, 1), at(-10, 30, 1));
  expect_first(s, flip_region(s), kNoVertex, Blocker{Blocker::Kind::triangle, {4, 5, 6}},
               "a triangle through");
  // The same triangle lifted above the tetrahedron's top corner: nothing.
  s = flip_scene(at(-10, -10, 5), at(30, -10, 5), at(-10, 30, 5));
  expect_first(s, flip_region(s), kNoVertex, std::nullopt, "a triangle above");
  // And exactly through the top corner d: touching counts (the region is closed).
  s = flip_scene(at(-10, -10, 4), at(30, -10, 4), at(-10, 30, 4));
  expect_first(s, flip_region(s), kNoVertex, Blocker{Blocker::Kind::triangle, {4, 5, 6}},
               "a triangle through corner d");
}

TEST_P(SweptRegions, WhatTheRegionSharesIsNoObstacle) {
  // The operation's own triangles only.
  Surface s = flip_scene(at(10, 10, 10), at(11, 10, 10), at(10, 11, 10));
  expect_first(s, flip_region(s), kNoVertex, std::nullopt, "its own triangles");
  // A triangle at corner c = (0, 4, 0), reaching away from the tetrahedron (y > 4).
  s.vertices[4] = at(-1, 6, 1);
  s.vertices[5] = at(1, 6, -1);
  s.triangles[2] = {2, 4, 5};
  expect_first(s, flip_region(s), kNoVertex, std::nullopt, "a neighbour at corner c");
  // The same corner, its edge to (2, -1, 1) running through the tetrahedron.
  s.vertices[4] = at(2, -1, 1);
  s.vertices[5] = at(-1, 6, 1);
  expect_first(s, flip_region(s), kNoVertex, Blocker{Blocker::Kind::edge, {2, 4, kNoVertex}},
               "a neighbour at corner c reaching in");
}

TEST_P(SweptRegions, ASplitsPartnerIsNoObstacle) {
  // Flat, in z = 0: edge ab, c above it, d below, split at m inside triangle abd. The
  // region a b c m reaches into abd: met, unless d is named as the partner.
  Surface s;
  s.vertices = {at(0, 0, 0), at(4, 0, 0), at(1, 2, 0), at(3, -2, 0)};
  s.triangles = {{0, 1, 2}, {1, 0, 3}};
  const Region region{RegionCorner{0, s.vertices[0]}, RegionCorner{1, s.vertices[1]},
                      RegionCorner{2, s.vertices[2]}, RegionCorner{kNoVertex, at(2, -1, 0)}};
  ASSERT_TRUE(well_formed(region));
  expect_first(s, region, kNoVertex, Blocker{Blocker::Kind::triangle, {1, 0, 3}}, "no partner");
  expect_first(s, region, 3, std::nullopt, "partner d");
  // A triangle a d c beside them has all its corners among a, b, c, d but is not the
  // split's: its edge c d crosses the region.
  s.triangles.push_back({0, 3, 2});
  expect_first(s, region, 3, Blocker{Blocker::Kind::edge, {2, 3, kNoVertex}}, "triangle adc");
}

TEST_P(SweptRegions, AFlatRegionIsTheQuadrilateralItself) {
  // The square a = (0,0,0), b = (4,4,0), c = (0,4,0), d = (4,0,0): a flat flip region. A
  // vertex in it is met; one step above the plane, with the rest of its triangle above,
  // nothing is.
  for (const double z : {0.0, std::nextafter(0.0, 1.0)}) {
    Surface s;
    s.vertices = {
        at(0, 0, 0), at(4, 4, 0), at(0, 4, 0), at(4, 0, 0), Point3{scale(), 2 * scale(), z},
        at(1, 2, 5), at(2, 2, 5)};
    s.triangles = {{0, 1, 2}, {1, 0, 3}, {4, 5, 6}};
    const std::optional<Blocker> expected =
        z == 0 ? std::optional(Blocker{Blocker::Kind::vertex, {4, kNoVertex, kNoVertex}})
               : std::nullopt;
    expect_first(s, flip_region(s), kNoVertex, expected, "z = " + text(s.vertices[4]));
  }
}

TEST_P(SweptRegions, AnElementAtACornerIsPassedOverOnlyBeyondAPlaneThroughThatCorner) {
  // first_in_region passes over an element whose corners all lie strictly beyond one of
  // the region's separating planes (a face of a tetrahedron; a side or the plane of a flat
  // region), a shared corner counting when it lies on that plane. A corner is on the
  // planes through it only: these elements at corner a reach through the region to
  // beyond the plane opposite a, and are met.
  // The tetrahedron: a triangle at a whose other corners lie beyond face bcd.
  Surface s = flip_scene(at(3, 3, 3), at(3, 3, 2), at(-8, -8, -8));
  s.triangles[2] = {0, 4, 5};
  expect_first(s, flip_region(s), kNoVertex, Blocker{Blocker::Kind::edge, {0, 4, kNoVertex}},
               "a triangle at corner a through face bcd");
  // Its twin beyond face acd (x < 0), a plane through a: nothing.
  s.vertices[4] = at(-1, 3, 3);
  s.vertices[5] = at(-1, 3, 2);
  expect_first(s, flip_region(s), kNoVertex, std::nullopt, "a triangle at corner a beyond acd");
  // The flat square a = (0,0,0), b = (4,4,0), c = (0,4,0), d = (4,0,0): a triangle at a in
  // its plane whose other corners lie beyond its side bd (x = 4), and its twin beyond side
  // ac (x = 0), a side through a.
  s.vertices = {at(0, 0, 0), at(4, 4, 0), at(0, 4, 0), at(4, 0, 0), at(5, 1, 0), at(5, 3, 0)};
  s.triangles = {{0, 1, 2}, {1, 0, 3}, {0, 4, 5}};
  expect_first(s, flip_region(s), kNoVertex, Blocker{Blocker::Kind::edge, {0, 4, kNoVertex}},
               "a flat triangle at corner a through side bd");
  s.vertices[4] = at(-1, 1, 0);
  s.vertices[5] = at(-1, 3, 0);
  expect_first(s, flip_region(s), kNoVertex, std::nullopt, "a flat triangle at a beyond ac");
  // Off the plane on both sides (its edges leave the square but for corner a), the
  // triangle crossing the plane along the diagonal ab: the plane separates neither side.
  s.vertices[4] = at(8, 2, 1);
  s.vertices[5] = at(2, 8, -1);
  expect_first(s, flip_region(s), kNoVertex, Blocker{Blocker::Kind::triangle, {0, 4, 5}},
               "a triangle at a across the plane");
  // The square's shadow has sides and diagonals, and only a side separates: a vertex on
  // either side of the diagonal ab is in the square.
  s.vertices.push_back(at(8, 9, 8));
  s.vertices[5] = at(8, 8, 8);
  s.triangles[2] = {4, 5, 6};
  for (const auto& [x, y] : {std::pair{1.0, 3.0}, std::pair{3.0, 1.0}}) {
    s.vertices[4] = at(x, y, 0);
    expect_first(s, flip_region(s), kNoVertex,
                 Blocker{Blocker::Kind::vertex, {4, kNoVertex, kNoVertex}},
                 "a vertex on one side of the square's diagonal ab");
  }
}

TEST_P(SweptRegions, RegionsMeetWhenTheyTouchAndNotOneUlpApart) {
  // Corners first, first + 1, ... (all kNoVertex for first = kNoVertex).
  const auto region = [&](const std::array<Point3, 4>& p, VertexIndex first) {
    Region r{};
    for (VertexIndex i = 0; i < 4; ++i)
      r[i] = {first == kNoVertex ? kNoVertex : first + i, p[i]};
    return r;
  };
  const auto shifted = [&](double dx) {
    const double s = scale();
    return std::array{Point3{dx, 0, 0}, Point3{dx + 4 * s, 0, 0}, Point3{dx, 4 * s, 0},
                      Point3{dx, 0, 4 * s}};
  };
  const Region x = region(shifted(0.0), 0);
  const double four = 4 * scale();
  for (const auto& [dx, meet] : {std::pair{5 * scale(), false}, std::pair{four, true},
                                 std::pair{std::nextafter(four, HUGE_VAL), false}}) {
    // The vertex indices do not matter: the same or other indices give the same answer.
    for (const VertexIndex first : {VertexIndex{0}, VertexIndex{10}, kNoVertex}) {
      const Region y = region(shifted(dx), first);
      EXPECT_EQ(regions_meet(x, y), meet) << "shifted by " << dx << ", first " << first;
      EXPECT_EQ(regions_meet(y, x), meet) << "shifted by " << dx << ", first " << first;
    }
    EXPECT_EQ(hulls_meet(corner_points(x), shifted(dx)), meet) << "oracle, shifted by " << dx;
  }
  // Two tetrahedra crossing with no corner in the other: only edges meet faces.
  const std::array<Point3, 4> long_x{at(-4, 0, 0), at(4, 0, 0), at(0, 1, 2), at(0, -1, 2)};
  const std::array<Point3, 4> long_y{at(0, -4, 1), at(0, 4, 1), at(1, 0, -1), at(-1, 0, -1)};
  for (const auto& [p, other] : {std::pair{long_x, long_y}, std::pair{long_y, long_x}}) {
    for (const Point3& corner : p)
      ASSERT_FALSE(hulls_meet(std::array<Point3, 1>{corner}, other)) << text(corner);
  }
  ASSERT_TRUE(hulls_meet(long_x, long_y));
  EXPECT_TRUE(regions_meet(region(long_x, 0), region(long_y, 4)));
  EXPECT_TRUE(regions_meet(region(long_y, 4), region(long_x, 0)));
  // A flat square pierced by a thin tetrahedron's edge, no corner of either in the other.
  const std::array<Point3, 4> square{at(0, 0, 0), at(4, 0, 0), at(4, 4, 0), at(0, 4, 0)};
  const std::array<Point3, 4> needle{at(2, 2, -1), at(2, 2, 1), at(9, 2, -1), at(2, 9, 1)};
  EXPECT_TRUE(regions_meet(region(square, 0), region(needle, 4)));
  // The needle moved to beside the square: apart.
  const std::array<Point3, 4> beside{at(5, 2, -1), at(5, 2, 1), at(12, 2, -1), at(5, 9, 1)};
  EXPECT_FALSE(regions_meet(region(square, 0), region(beside, 4)));
}

TEST_P(SweptRegions, TurningOverIsFacingTheOtherWayInThePlane) {
  // A triangle in z = 0, in the tilted plane z = x - 2y, and in the vertical plane x = 0
  // (each needs another coordinate plane for its shadow).
  // With each, a coordinate along which its plane's normal is not zero.
  const std::array<std::pair<std::array<Point3, 3>, int>, 3> olds{
      std::pair{std::array{at(0, 0, 0), at(4, 0, 0), at(0, 4, 0)}, 2},
      std::pair{std::array{at(0, 0, 0), at(4, 0, 4), at(0, 4, -8)}, 2},
      std::pair{std::array{at(0, 0, 0), at(0, 4, 0), at(0, 0, 4)}, 0}};
  for (const auto& [old, across] : olds) {
    const std::array<Point3, 3> same{old[1], old[2], old[0]};
    const std::array<Point3, 3> reversed{old[0], old[2], old[1]};
    EXPECT_FALSE(turns_over_in_plane(old, same));
    EXPECT_TRUE(turns_over_in_plane(old, reversed));
    // A smaller triangle inside, facing either way.
    const Point3 m{(old[0][0] + old[1][0]) / 2, (old[0][1] + old[1][1]) / 2,
                   (old[0][2] + old[1][2]) / 2};
    EXPECT_FALSE(turns_over_in_plane(old, {old[0], m, old[2]}));
    EXPECT_TRUE(turns_over_in_plane(old, {m, old[0], old[2]}));
    // Reversed, with a corner one step off the plane: not in the plane, so not turned.
    Point3 off = old[1];
    off[across] = std::nextafter(off[across], HUGE_VAL);
    EXPECT_FALSE(turns_over_in_plane(old, {old[0], old[2], off}));
  }
}

/// Points of small integer grids, in space or in one of a few planes through integer
/// directions (so that coplanar and touching configurations are frequent and exact).
class GridPoints {
 public:
  GridPoints(std::mt19937_64& rng, double scale) : rng_(rng), scale_(scale) {}

  /// Picks the next configuration's frame: space (half the time) or a plane.
  void choose_frame() {
    const int kind = std::uniform_int_distribution<int>(0, 7)(rng_);
    static constexpr std::array<std::array<std::array<int, 3>, 2>, 4> planes{{
        {{{1, 0, 0}, {0, 1, 0}}},   // z = 0
        {{{1, 0, 1}, {0, 1, -2}}},  // z = x - 2y
        {{{1, 1, 0}, {0, 0, 1}}},   // vertical
        {{{2, 1, 1}, {1, -1, 3}}},
    }};
    flat_ = kind < 4;
    if (flat_) plane_ = planes[static_cast<std::size_t>(kind)];
  }
  bool flat() const { return flat_; }

  Point3 point(int range) {
    std::uniform_int_distribution<int> c(-range, range);
    if (!flat_) return {scale_ * c(rng_), scale_ * c(rng_), scale_ * c(rng_)};
    const int u = c(rng_), v = c(rng_);
    Point3 p{};
    for (int k = 0; k < 3; ++k)
      p[k] = scale_ * (u * plane_[0][k] + v * plane_[1][k]);
    return p;
  }

 private:
  std::mt19937_64& rng_;
  double scale_;
  bool flat_ = false;
  std::array<std::array<int, 3>, 2> plane_{};
};

TEST_P(SweptRegions, RegionsMeetAgreesWithTheHullOracle) {
  auto rng = testing::seeded_engine("remesh.swept_region.regions_meet");
  GridPoints grid(rng, scale());
  int meet = 0, apart = 0, flat = 0;
  // 400 at full effort (tests/support/seed.hpp); each kind asked of the same share.
  const auto trials = static_cast<int>(testing::scaled_trials(400));
  for (int trial = 0; trial < trials; ++trial) {
    grid.choose_frame();
    Region x{}, y{};
    for (RegionCorner& c : x)
      c.point = grid.point(3);
    for (RegionCorner& c : y)
      c.point = grid.point(3);
    // Shift y along one grid direction so that apart pairs are as common as meeting ones.
    const Point3 shift = grid.point(3);
    for (RegionCorner& c : y) {
      for (int k = 0; k < 3; ++k)
        c.point[k] += shift[k];
    }
    if (!well_formed(x) || !well_formed(y)) continue;
    const bool expected = hulls_meet(corner_points(x), corner_points(y));
    std::string what = "trial " + std::to_string(trial) + ":";
    for (const Region* r : {&x, &y}) {
      for (const RegionCorner& c : *r)
        what.append(" ").append(text(c.point));
      what += " /";
    }
    EXPECT_EQ(regions_meet(x, y), expected) << what;
    EXPECT_EQ(regions_meet(y, x), expected) << what;
    (expected ? meet : apart) += 1;
    flat += grid.flat() ? 1 : 0;
  }
  EXPECT_GT(meet, 60 * trials / 400);
  EXPECT_GT(apart, 60 * trials / 400);
  EXPECT_GT(flat, 60 * trials / 400);
}

TEST_P(SweptRegions, TurnsOverInPlaneAgreesWithTheFacingOracle) {
  auto rng = testing::seeded_engine("remesh.swept_region.turns_over");
  GridPoints grid(rng, scale());
  std::uniform_int_distribution<int> lift(0, 5);
  int turned = 0, not_turned = 0, off_plane = 0;
  for (int trial = 0; trial < 1000; ++trial) {
    do {
      grid.choose_frame();
    } while (!grid.flat());
    const std::array<Point3, 3> old{grid.point(4), grid.point(4), grid.point(4)};
    if (collinear_oracle(old[0], old[1], old[2])) continue;
    std::array<Point3, 3> made{grid.point(4), grid.point(4), grid.point(4)};
    if (lift(rng) == 0) made[1][2] += scale();  // off the plane (by one grid step in z)
    const bool in_plane = testing::coplanar_oracle(old, made);
    const Sign facing = testing::facing_oracle(old, made);
    if (in_plane && facing == Sign::zero) continue;  // a made triangle of zero area
    const bool expected = in_plane && facing == Sign::negative;
    EXPECT_EQ(turns_over_in_plane(old, made), expected)
        << "trial " << trial << ": " << text(old[0]) << text(old[1]) << text(old[2]) << " / "
        << text(made[0]) << text(made[1]) << text(made[2]);
    (expected ? turned : not_turned) += 1;
    off_plane += in_plane ? 0 : 1;
  }
  EXPECT_GT(turned, 200);
  EXPECT_GT(not_turned, 200);
  EXPECT_GT(off_plane, 50);
}

TEST_P(SweptRegions, FirstInRegionAgreesWithTheHullOracle) {
  auto rng = testing::seeded_engine("remesh.swept_region.first_in_region");
  GridPoints grid(rng, scale());
  std::uniform_int_distribution<int> coin(0, 1);
  int found[4] = {};  // vertex, edge, triangle, nothing
  int partnered = 0;
  int deviating = 0;  // left out of the comparison (Deviations)
  for (int trial = 0; trial < 150; ++trial) {
    grid.choose_frame();
    Surface s;
    constexpr VertexIndex kVertices = 10;
    while (s.vertices.size() < kVertices) {
      const Point3 p = grid.point(4);
      if (std::find(s.vertices.begin(), s.vertices.end(), p) == s.vertices.end())
        s.vertices.push_back(p);
    }
    std::uniform_int_distribution<VertexIndex> vertex(0, kVertices - 1);
    while (s.triangles.size() < 5) {
      const Triangle t{vertex(rng), vertex(rng), vertex(rng)};
      if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) continue;
      if (collinear_oracle(s.vertices[t[0]], s.vertices[t[1]], s.vertices[t[2]])) continue;
      s.triangles.push_back(t);
    }
    // A few regions on this surface: four of its vertices (a flip's), or three and a new
    // point (a split's), whose first two are sometimes those of a triangle a b d, d the
    // partner.
    std::vector<Region> regions;
    std::vector<VertexIndex> partners;
    std::uniform_int_distribution<std::size_t> triangle(0, s.triangles.size() - 1);
    for (int attempt = 0; attempt < 12 && regions.size() < 4; ++attempt) {
      std::vector<VertexIndex> picked;
      VertexIndex partner = kNoVertex;
      const bool split = coin(rng) == 1;
      if (split && coin(rng) == 1) {
        const Triangle& t = s.triangles[triangle(rng)];
        picked = {t[0], t[1]};
        partner = t[2];
      }
      while (picked.size() < 4) {
        const VertexIndex v = vertex(rng);
        if (std::find(picked.begin(), picked.end(), v) == picked.end() && v != partner)
          picked.push_back(v);
      }
      Region region{};
      for (int i = 0; i < 4; ++i)
        region[i] = {picked[i], s.vertices[picked[i]]};
      if (split) region[3] = {kNoVertex, grid.point(3)};
      if (!well_formed(region)) continue;
      regions.push_back(region);
      partners.push_back(partner);
    }
    const std::vector<std::optional<Blocker>> in_one_walk = first_in_regions(s, regions, partners);
    ASSERT_EQ(in_one_walk.size(), regions.size());
    for (std::size_t i = 0; i < regions.size(); ++i) {
      const std::optional<Blocker> expected = first_in_region_oracle(s, regions[i], partners[i]);
      const std::optional<Blocker> one = first_in_region(s, regions[i], partners[i]);
      std::string what = "trial " + std::to_string(trial) + ", region " + std::to_string(i) + ":";
      for (const RegionCorner& c : regions[i]) {
        what.append(" ").append(c.vertex == kNoVertex ? "new" : std::to_string(c.vertex));
        what.append("@").append(text(c.point));
      }
      what += ", partner " + std::to_string(partners[i]);
      EXPECT_EQ(in_one_walk[i], one) << what;
      const Deviations deviations = deviations_of(s, regions[i]);
      if (deviations.reports_more) {
        ++deviating;
        // Says no less than the header.
        EXPECT_TRUE(one.has_value() || !expected.has_value())
            << what << ": missed " << text(expected) << "; surface " << text(s);
        continue;
      }
      EXPECT_EQ(one, expected) << what << ": found " << text(one) << ", the oracle "
                               << text(expected) << "; surface " << text(s);
      ++found[expected ? static_cast<int>(expected->kind) : 3];
      partnered += partners[i] != kNoVertex ? 1 : 0;
    }
  }
  EXPECT_GT(found[0] + found[1] + found[2] + found[3], deviating);  // most compared exactly
  EXPECT_GT(found[0], 20);                                          // a vertex
  EXPECT_GT(found[1], 20);                                          // an edge
  EXPECT_GT(found[2], 5);                                           // a triangle
  EXPECT_GT(found[3], 20);                                          // nothing
  EXPECT_GT(partnered, 10);  // compared exactly with a partner
}

/// A point nudged by `steps` doubles (up or down) in one coordinate.
Point3 nudged(Point3 p, int axis, int steps) {
  for (int i = 0; i < std::abs(steps); ++i)
    p[axis] = std::nextafter(p[axis], steps > 0 ? HUGE_VAL : -HUGE_VAL);
  return p;
}

TEST_P(SweptRegions, ThinSplitRegionsAgreeWithTheHullOracle) {
  // A split's region a b c m with m a double or two off the midpoint of ab (a rounded
  // midpoint: a, b and m all but collinear), among elements around its corners (their
  // stars' links, on both sides of a corner: what the region test's own lines in the
  // shadow and its three faces of four decide) and points a few doubles off the edge's
  // line; first_in_region against the rational hull oracle.
  auto rng = testing::seeded_engine("remesh.swept_region.thin_split");
  GridPoints grid(rng, scale());
  std::uniform_int_distribution<int> coin(0, 1), axis(0, 2), steps(-2, 2), kind(0, 3);
  std::uniform_int_distribution<int> quarter(-2, 6);
  int found[4] = {};  // vertex, edge, triangle, nothing
  int deviating = 0;
  // 300 at full effort (tests/support/seed.hpp); each kind asked of the same share.
  const auto trials = static_cast<int>(testing::scaled_trials(300));
  for (int trial = 0; trial < trials; ++trial) {
    grid.choose_frame();
    Surface s;
    const auto add = [&](const Point3& p) {
      if (std::find(s.vertices.begin(), s.vertices.end(), p) != s.vertices.end()) return false;
      s.vertices.push_back(p);
      return true;
    };
    while (s.vertices.size() < 4)  // a, b, c and d, the partner
      add(grid.point(4));
    const Point3 a = s.vertices[0], b = s.vertices[1];
    const auto on_line = [&](int q) {  // a + (q / 4)(b - a), exact on the grid's scale
      Point3 p{};
      for (int k = 0; k < 3; ++k)
        p[k] = a[k] + (b[k] - a[k]) * (q / 4.0);
      return p;
    };
    while (s.vertices.size() < 11) {
      switch (kind(rng)) {
        case 0:  // a few doubles off the edge's line
          add(nudged(on_line(quarter(rng)), axis(rng), steps(rng)));
          break;
        case 1:  // near a or b
          add(nudged(s.vertices[static_cast<std::size_t>(coin(rng))], axis(rng), steps(rng)));
          break;
        default:
          add(grid.point(4));
      }
    }
    const Point3 midpoint = on_line(2);
    Point3 m = nudged(midpoint, axis(rng), steps(rng));
    if (coin(rng) == 1) m = nudged(m, axis(rng), steps(rng));
    const Region region{RegionCorner{0, a}, RegionCorner{1, b}, RegionCorner{2, s.vertices[2]},
                        RegionCorner{kNoVertex, m}};
    if (!well_formed(region)) continue;
    // Triangles: abc and abd (the split's), and random ones, most at a corner of the
    // region (fans around a, b and c, whose far edges pass around the corner).
    s.triangles = {{0, 1, 2}, {1, 0, 3}};
    std::uniform_int_distribution<VertexIndex> vertex(0, 10), corner(0, 2);
    const std::size_t triangles = std::uniform_int_distribution<std::size_t>(3, 9)(rng);
    while (s.triangles.size() < triangles) {
      const Triangle t{coin(rng) == 1 ? corner(rng) : vertex(rng), vertex(rng), vertex(rng)};
      if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) continue;
      if (collinear_oracle(s.vertices[t[0]], s.vertices[t[1]], s.vertices[t[2]])) continue;
      s.triangles.push_back(t);
    }
    const VertexIndex partner = coin(rng) == 1 ? 3 : kNoVertex;
    const std::optional<Blocker> one = first_in_region(s, region, partner);
    const std::optional<Blocker> expected = first_in_region_oracle(s, region, partner);
    const std::string what = "trial " + std::to_string(trial) + ": new point " + text(m) +
                             ", partner " + std::to_string(partner) + "; surface " + text(s);
    if (deviations_of(s, region).reports_more) {
      ++deviating;
      EXPECT_TRUE(one.has_value() || !expected.has_value()) << what;
      continue;
    }
    EXPECT_EQ(one, expected) << what << ": found " << text(one) << ", the oracle "
                             << text(expected);
    ++found[expected ? static_cast<int>(expected->kind) : 3];
  }
  EXPECT_GT(found[0] + found[1] + found[2] + found[3], 4 * deviating);
  EXPECT_GT(found[0], 10 * trials / 300);  // a vertex
  EXPECT_GT(found[1], 10 * trials / 300);  // an edge
  EXPECT_GT(found[2], 5 * trials / 300);   // a triangle
  EXPECT_GT(found[3], 20 * trials / 300);  // nothing
  std::printf("thin split regions: %d vertex, %d edge, %d triangle, %d nothing, %d deviating\n",
              found[0], found[1], found[2], found[3], deviating);
}

TEST(SweptRegion, TheHullOracleAgreesWithTheSegmentTriangleOracle) {
  // The hull oracle's linear program against the support oracle's clipping, on segments
  // and triangles of small integers (the check of the oracle the tests above rely on).
  auto rng = testing::seeded_engine("remesh.swept_region.hull_oracle");
  std::uniform_int_distribution<int> c(-2, 2);
  const auto point = [&] { return Point3{1.0 * c(rng), 1.0 * c(rng), 1.0 * c(rng)}; };
  int meet = 0, apart = 0;
  for (int trial = 0; trial < 600; ++trial) {
    const std::array<Point3, 2> seg{point(), point()};
    const std::array<Point3, 3> tri{point(), point(), point()};
    if (collinear_oracle(tri[0], tri[1], tri[2])) continue;
    const bool expected =
        testing::segment_meets_triangle_oracle(seg[0], seg[1], tri[0], tri[1], tri[2]);
    EXPECT_EQ(hulls_meet(seg, tri), expected)
        << text(seg[0]) << text(seg[1]) << " / " << text(tri[0]) << text(tri[1]) << text(tri[2]);
    // Beyond a shared corner: the segment from tri[0].
    const bool beyond_expected =
        testing::segment_meets_triangle_beyond_oracle(tri[0], seg[1], tri[1], tri[2]);
    if (seg[1] != tri[0]) {
      EXPECT_EQ(hulls_meet_beyond(std::array{tri[0], seg[1]}, 1u, tri), beyond_expected)
          << text(tri[0]) << text(seg[1]) << " / " << text(tri[1]) << text(tri[2]);
    }
    (expected ? meet : apart) += 1;
  }
  EXPECT_GT(meet, 50);
  EXPECT_GT(apart, 100);
}

INSTANTIATE_TEST_SUITE_P(Scales, SweptRegions, ::testing::Values(0, 1000, -1000),
                         exactgeo::testing::scale_name);

}  // namespace
}  // namespace exactgeo::remesh
