// The certificate that triangles tile a polygon's projection (polygon_certificate.hpp,
// internal), in both forms (sweeps, and pair by pair for few corners), on hand-made
// triangle sets it must refuse (overlapping ears of a crossing polygon, a flipped triangle,
// a boundary chain that is not the polygon's, loops wound around twice, a figure eight for
// its triangle count, a bridge across an edge) and ones it must accept.

#include "../../mesh/src/polygon_certificate.hpp"

#include <gtest/gtest.h>

#include <array>
#include <optional>
#include <vector>

#include "../../mesh/src/polygon_monotone.hpp"
#include "../../mesh/src/polygon_sweep.hpp"
#include "../../mesh/src/polygon_walk.hpp"

namespace exactgeo::mesh::internal {
namespace {

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

}  // namespace
}  // namespace exactgeo::mesh::internal
