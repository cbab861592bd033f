// The parts of a polygon's triangulation, tested directly (mesh/src/, internal): the
// certificate that triangles tile a polygon's projection, in both forms (sweeps, and pair
// by pair for few corners), on hand-made triangle sets it must refuse (overlapping ears
// of a crossing polygon, a flipped triangle, a boundary chain that is not the polygon's,
// loops wound around twice, a bridge across an edge) and ones it must accept; the
// sweep that finds a walk's region and its turn; and the sweep triangulation, which must
// take every family of polygons the tests generate without the ear clipping fallback.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "../../mesh/src/polygon_certificate.hpp"
#include "../../mesh/src/polygon_monotone.hpp"
#include "../../mesh/src/polygon_sweep.hpp"
#include "../../mesh/src/polygon_walk.hpp"
#include "support/polygon_oracle.hpp"
#include "support/seed.hpp"

namespace exactgeo::mesh::internal {
namespace {

using testing::Polygon2;

/// Points of the (x, y) plane at z = 0, seen along z (axis 2).
std::vector<Point3> in_plane(const std::vector<std::array<double, 2>>& points) {
  std::vector<Point3> vertices;
  for (const auto& [x, y] : points)
    vertices.push_back({x, y, 0.0});
  return vertices;
}

std::vector<Face> triangles(const std::vector<std::array<VertexIndex, 3>>& corners) {
  std::vector<Face> faces;
  for (const auto& [a, b, c] : corners)
    faces.push_back(make_triangle(a, b, c));
  return faces;
}

/// region_turn for these corners along z.
std::optional<Sign> turn_of(const std::vector<VertexIndex>& corners,
                            const std::vector<Point3>& vertices) {
  const PolygonWalk walk = walk_of(corners);
  const Projection plane(2);
  return region_turn(walk, sweep_order(walk, vertices, plane), vertices, plane);
}

TEST(PolygonCertificate, OverlappingEarsOfACrossingPolygonAreRefused) {
  // The polygon of Polygons.EarsThatOverlapAreCaught: every triangle turns alike, the
  // boundary chain is the polygon's, and (1, 2, 3) overlaps (0, 1, 3); its edges cross.
  const std::vector<Point3> v = in_plane({{0, 0}, {20, 17}, {0, 12}, {6, 13}, {0, 16}});
  const std::vector<VertexIndex> corners{0, 1, 2, 3, 4};
  EXPECT_FALSE(triangles_tile_polygon(corners, triangles({{1, 2, 3}, {0, 1, 3}, {0, 3, 4}}), v, 2));
  EXPECT_EQ(turn_of(corners, v), std::nullopt);
}

TEST(PolygonCertificate, ATilingIsAcceptedAndAFlippedTriangleRefused) {
  // A dart: corner 3 is reflex. The fan from corner 0 has the boundary chain and the
  // count right, but (0, 2, 3) turns the other way.
  const std::vector<Point3> v = in_plane({{0, 0}, {4, 0}, {4, 4}, {2, 1}, {0, 4}});
  const std::vector<VertexIndex> corners{0, 1, 2, 3, 4};
  EXPECT_TRUE(triangles_tile_polygon(corners, triangles({{1, 2, 3}, {0, 1, 3}, {0, 3, 4}}), v, 2));
  EXPECT_FALSE(triangles_tile_polygon(corners, triangles({{0, 1, 2}, {0, 2, 3}, {0, 3, 4}}), v, 2));
  // Walked the other way round: the same triangles reversed, turning clockwise.
  const std::vector<VertexIndex> backwards{4, 3, 2, 1, 0};
  EXPECT_EQ(turn_of(backwards, v), Sign::negative);
  EXPECT_TRUE(
      triangles_tile_polygon(backwards, triangles({{3, 2, 1}, {3, 1, 0}, {4, 3, 0}}), v, 2));
  EXPECT_FALSE(
      triangles_tile_polygon(backwards, triangles({{1, 2, 3}, {0, 1, 3}, {0, 3, 4}}), v, 2));
  // Seen along x the dart is a segment: no region.
  EXPECT_FALSE(triangles_tile_polygon(corners, triangles({{1, 2, 3}, {0, 1, 3}, {0, 3, 4}}), v, 0));
}

TEST(PolygonCertificate, ABoundaryChainThatIsNotThePolygonsIsRefused) {
  const std::vector<Point3> v = in_plane({{0, 0}, {4, 0}, {4, 4}, {2, 1}, {0, 4}, {0, 4}});
  const std::vector<VertexIndex> corners{0, 1, 2, 3, 4};
  // Vertex 5 lies where corner 4 does: the same tiling in the plane, but its boundary
  // runs through a vertex that is not the polygon's.
  EXPECT_FALSE(triangles_tile_polygon(corners, triangles({{1, 2, 3}, {0, 1, 3}, {0, 3, 5}}), v, 2));
  // Two triangles over one diagonal and a third over the other: the chains differ.
  EXPECT_FALSE(triangles_tile_polygon(corners, triangles({{1, 2, 3}, {0, 1, 3}, {0, 1, 3}}), v, 2));
  // One triangle too few, though each is fine.
  EXPECT_FALSE(triangles_tile_polygon(corners, triangles({{1, 2, 3}, {0, 1, 3}}), v, 2));
}

TEST(PolygonCertificate, LoopsWoundAroundTwiceAreRefused) {
  // The square [0, 8]^2 and a triangle inside it turning the same way, joined at corner
  // 0. The fan from corner 4 over the square and the inner triangle: n - 2 triangles,
  // each counter-clockwise, whose boundary is the walk's; but the inner triangle is
  // covered twice, where the walk winds around twice.
  const std::vector<Point3> v = in_plane({{0, 0}, {8, 0}, {8, 8}, {0, 8}, {4, 2}, {2, 4}});
  const std::vector<VertexIndex> nested{0, 1, 2, 3, 0, 4, 5};
  EXPECT_EQ(turn_of(nested, v), std::nullopt);
  EXPECT_FALSE(triangles_tile_polygon(
      nested, triangles({{0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}, {0, 4, 5}}), v, 2));
  // The inner loop turned round is a hole touching the outside at corner 0: tiled.
  const std::vector<VertexIndex> notched{0, 1, 2, 3, 0, 5, 4};
  EXPECT_EQ(turn_of(notched, v), Sign::positive);
  EXPECT_TRUE(triangles_tile_polygon(
      notched, triangles({{0, 1, 4}, {1, 2, 4}, {2, 5, 4}, {2, 3, 5}, {3, 0, 5}}), v, 2));
}

TEST(PolygonCertificate, AFigureEightIsRefusedForItsTriangleCount) {
  // A square and a triangle beside it, joined at corner 2: three triangles tile it, two
  // fewer than n - 2, which ear clipping (and so every reader so far) never makes.
  const std::vector<Point3> v = in_plane({{0, 0}, {8, 0}, {8, 8}, {0, 8}, {16, 8}, {8, 16}});
  const std::vector<VertexIndex> corners{0, 1, 2, 4, 5, 2, 3};
  EXPECT_EQ(turn_of(corners, v), Sign::positive);
  EXPECT_FALSE(triangles_tile_polygon(corners, triangles({{0, 1, 2}, {0, 2, 3}, {2, 4, 5}}), v, 2));
  // The sweep triangulation declines it (corner 2 has two ways in and two out).
  const PolygonWalk walk = walk_of(corners);
  const Projection plane(2);
  std::vector<Face> out;
  EXPECT_FALSE(
      triangulate_by_sweep(walk, sweep_order(walk, v, plane), v, plane, Sign::positive, {}, out));
  EXPECT_TRUE(out.empty());
}

TEST(PolygonCertificate, BothFormsRefuseABridgeThatCrossesAnEdge) {
  // The square [0, 8]^2 less the hole [3, 5] x [2, 5], tiled by 8 triangles, none of them
  // on a bridge. As a keyhole with its bridge from (0, 0) to (3, 2) the walk is tiled by
  // them; with its bridge to (5, 5), across the hole's edge at (3, 3), it is refused by
  // the sweep and by the pairwise form alike, though the triangles still tile the region.
  const std::vector<Point3> v =
      in_plane({{0, 0}, {8, 0}, {8, 8}, {0, 8}, {3, 2}, {3, 5}, {5, 5}, {5, 2}});
  const std::vector<Face> tiling = triangles(
      {{0, 1, 7}, {0, 7, 4}, {1, 2, 6}, {1, 6, 7}, {2, 3, 5}, {2, 5, 6}, {3, 0, 4}, {3, 4, 5}});
  const Projection plane(2);
  const std::vector<VertexIndex> beside{0, 1, 2, 3, 0, 4, 5, 6, 7, 4};
  const std::vector<VertexIndex> across{0, 1, 2, 3, 0, 6, 7, 4, 5, 6};
  EXPECT_TRUE(triangles_tile_polygon(beside, tiling, v, 2));
  EXPECT_TRUE(few_triangles_tile(beside, tiling, v, plane, Sign::positive));
  EXPECT_FALSE(triangles_tile_polygon(across, tiling, v, 2));
  EXPECT_FALSE(few_triangles_tile(across, tiling, v, plane, Sign::positive));
  // The pairwise form refuses what the sweep form refuses in the other tests, too.
  const std::vector<Point3> dart = in_plane({{0, 0}, {4, 0}, {4, 4}, {2, 1}, {0, 4}});
  const std::vector<VertexIndex> corners{0, 1, 2, 3, 4};
  EXPECT_TRUE(few_triangles_tile(corners, triangles({{1, 2, 3}, {0, 1, 3}, {0, 3, 4}}), dart, plane,
                                 Sign::positive));
  EXPECT_FALSE(few_triangles_tile(corners, triangles({{0, 1, 2}, {0, 2, 3}, {0, 3, 4}}), dart,
                                  plane, Sign::positive));
  EXPECT_FALSE(few_triangles_tile(corners, triangles({{1, 2, 3}, {0, 1, 3}, {0, 1, 3}}), dart,
                                  plane, Sign::positive));
  const std::vector<Point3> square = in_plane({{0, 0}, {8, 0}, {8, 8}, {0, 8}, {4, 2}, {2, 4}});
  EXPECT_FALSE(
      few_triangles_tile(std::vector<VertexIndex>{0, 1, 2, 3, 0, 4, 5},
                         triangles({{0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}, {0, 4, 5}}), square,
                         plane, Sign::positive));
}

TEST(PolygonSweep, EdgesThatTouchOrOverlapAreRefused) {
  const std::vector<Point3> v = in_plane(
      {{0, 0}, {8, 0}, {8, 8}, {0, 8}, {3, 3}, {3, 5}, {5, 5}, {5, 3}, {4, 0}, {4, 4}, {8, 0}});
  // A keyhole, and the same with its bridge across the hole (through its corner (3, 3)).
  EXPECT_EQ(turn_of({0, 1, 2, 3, 0, 4, 5, 6, 7, 4}, v), Sign::positive);
  EXPECT_EQ(turn_of({0, 1, 2, 3, 0, 6, 7, 4, 5, 6}, v), std::nullopt);
  // A spike from the bottom edge's middle up to (4, 4), where the bottom edge is not
  // split: the spike's foot lies inside the edge (0, 1).
  EXPECT_EQ(turn_of({0, 1, 2, 3, 8, 9}, v), std::nullopt);
  // The same with the edge split at the foot: a spike walked there and back bounds
  // nothing, and touches the rest only at its foot.
  EXPECT_EQ(turn_of({0, 8, 9, 8, 1, 2, 3}, v), Sign::positive);
  // Two edges on one line that overlap: (0, 1) and (8, 10), 10 a copy of corner 1.
  EXPECT_EQ(turn_of({0, 1, 2, 10, 8, 3}, v), std::nullopt);
  // A keyhole whose bridge crosses an edge of the hole inside it, at (3, 3): every winding
  // number is still 0 or 1 (the bridge bounds nothing), only the crossing is wrong.
  const std::vector<Point3> w =
      in_plane({{0, 0}, {8, 0}, {8, 8}, {0, 8}, {3, 2}, {3, 5}, {5, 5}, {5, 2}});
  EXPECT_EQ(turn_of({0, 1, 2, 3, 0, 4, 5, 6, 7, 4}, w), Sign::positive);
  EXPECT_EQ(turn_of({0, 1, 2, 3, 0, 6, 7, 4, 5, 6}, w), std::nullopt);
  // Two holes whose bridges cross each other at (4, 4): on both sides of each bridge the
  // winding number is the same, so only the test of the two edges finds it.
  const std::vector<Point3> x = in_plane({{0, 0},
                                          {8, 0},
                                          {8, 8},
                                          {0, 8},  // outside
                                          {5, 5},
                                          {5, 6},
                                          {6, 6},
                                          {6, 5},  // hole A
                                          {3, 5},
                                          {2, 5},
                                          {2, 6},
                                          {3, 6}});  // hole B
  EXPECT_EQ(turn_of({0, 1, 8, 9, 10, 11, 8, 1, 2, 3, 0, 4, 5, 6, 7, 4}, x), std::nullopt);
  EXPECT_EQ(turn_of({0, 1, 2, 3, 10, 11, 8, 9, 10, 3, 0, 4, 5, 6, 7, 4}, x), Sign::positive);
}

/// Every family of polygons the tests generate, of about n corners.
std::vector<std::pair<std::string, Polygon2>> family_polygons(std::mt19937_64& rng, int n) {
  return {{"convex", testing::convex_polygon(rng, n)},
          {"star", testing::star_polygon(rng, n, false)},
          {"star with corners inside edges", testing::star_polygon(rng, n, true)},
          {"comb", testing::comb_polygon(rng, std::max(2, n / 4))},
          {"star with holes", testing::holed_star_polygon(rng, n)}};
}

TEST(PolygonSweep, EveryFamilyIsTriangulatedWithoutTheFallback) {
  std::mt19937_64 rng =
      testing::seeded_engine("PolygonSweep.EveryFamilyIsTriangulatedWithoutTheFallback");
  // (Polygons.LargePolygonsOfEveryFamilyBecomeTrianglesThatTileThem loads them up to 10^5
  // corners, where the quadratic fallback would take minutes.)
  for (const int n : {10, 1000, 10000}) {
    for (const auto& [name, polygon] : family_polygons(rng, n)) {
      const std::vector<Point3> v = in_plane(polygon.points);
      for (const bool backwards : {false, true}) {
        // Along z in the plane z = 0; along x in the plane x = 0 with y and z taking x
        // and y swapped: a mirror image, which turns the other way.
        for (const int axis : {2, 0}) {
          std::vector<Point3> seen = v;
          if (axis == 0) {
            for (Point3& p : seen)
              p = {0.0, p[1], p[0]};  // seen along x: (u, v) = (y, z)
          }
          const bool clockwise = backwards != (axis == 0);
          std::vector<VertexIndex> corners(polygon.cycle.begin(), polygon.cycle.end());
          if (backwards) std::reverse(corners.begin(), corners.end());
          const std::string what = name + " of " + std::to_string(corners.size()) +
                                   " corners along axis " + std::to_string(axis) +
                                   (backwards ? ", walked backwards" : "");
          const PolygonWalk walk = walk_of(corners);
          const Projection plane(axis);
          const std::vector<std::uint32_t> order = sweep_order(walk, seen, plane);
          std::vector<std::uint32_t> below;
          const std::optional<Sign> turn = region_turn(walk, order, seen, plane, &below);
          ASSERT_EQ(turn, clockwise ? Sign::negative : Sign::positive) << what;
          // With the certificate's record of the edge below each corner, as the reader
          // runs it, and searching its own status.
          std::vector<Face> recorded;
          ASSERT_TRUE(triangulate_by_sweep(walk, order, seen, plane, *turn, below, recorded))
              << what;
          EXPECT_EQ(recorded.size() + 2, corners.size()) << what;
          EXPECT_TRUE(triangles_tile_polygon(corners, recorded, seen, axis)) << what;
          std::vector<Face> searched;
          ASSERT_TRUE(triangulate_by_sweep(walk, order, seen, plane, *turn, {}, searched)) << what;
          EXPECT_TRUE(triangles_fit(walk, searched, seen, plane, *turn)) << what;
        }
      }
    }
  }
}

}  // namespace
}  // namespace exactgeo::mesh::internal
