// Ear clipping in a projection (polygon_ears.hpp, internal), the fallback of the
// triangulation: polygons of the generators (star-shaped with and without corners inside
// straight edges, convex, keyholes with a square and an L-shaped hole, whose bridge ends
// repeat) become n - 2 triangles that tile them, checked against exact oracles
// (polygon_tiling.hpp); walked clockwise with the turn negative they are the same
// triangles' mirror images; a pentagram, whose edges cross, runs out of ears; a square
// seen along an axis in which it is a segment has none.

#include "../../mesh/src/polygon_ears.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "mesh/polygon_tiling.hpp"
#include "support/polygon_oracle.hpp"
#include "support/seed.hpp"

namespace exactgeo::mesh::internal {
namespace {

using test_polygons::expect_tiles;
using testing::Polygon2;

/// clip_ears along z on the polygon's cycle (its points at z = 0, vertex k = point k).
bool clip(const Polygon2& polygon, std::vector<std::uint32_t> cycle, Sign turn,
          std::vector<Face>& out) {
  std::vector<Point3> corner_points;
  for (const std::uint32_t c : cycle)
    corner_points.push_back({polygon.points[c][0], polygon.points[c][1], 0.0});
  const std::vector<VertexIndex> corners(cycle.begin(), cycle.end());
  return clip_ears(corners, corner_points, Projection(2), turn, out);
}

std::vector<std::array<std::uint32_t, 3>> triples(const std::vector<Face>& faces) {
  std::vector<std::array<std::uint32_t, 3>> t;
  for (const Face& f : faces) {
    EXPECT_TRUE(f.is_triangle());
    t.push_back({f.corners[0], f.corners[1], f.corners[2]});
  }
  return t;
}

TEST(PolygonEars, PolygonsOfEveryGeneratorAreTiledBothWaysRound) {
  auto rng = testing::seeded_engine("mesh.polygon_ears");
  std::vector<std::pair<std::string, Polygon2>> polygons = {
      {"keyhole", testing::keyhole_polygon(false)},
      {"keyhole with an L-shaped hole", testing::keyhole_polygon(true)}};
  for (const int n : {3, 5, 8, 17, 40, 150}) {
    polygons.emplace_back("random star of " + std::to_string(n),
                          testing::random_star_polygon(rng, n, false));
    polygons.emplace_back("random star with corners inside edges, " + std::to_string(n),
                          testing::random_star_polygon(rng, n, true));
    polygons.emplace_back("convex " + std::to_string(n), testing::convex_polygon(rng, n));
  }
  for (const auto& [name, polygon] : polygons) {
    std::vector<Face> out{make_quad(7, 7, 7, 7)};  // kept: triangles are appended
    ASSERT_TRUE(clip(polygon, polygon.cycle, Sign::positive, out)) << name;
    EXPECT_TRUE(out.front() == make_quad(7, 7, 7, 7));
    out.erase(out.begin());
    expect_tiles(polygon, triples(out), rng, name, 100);
    // Clockwise: triangles turning clockwise, each the mirror of one that tiles.
    std::vector<std::uint32_t> backwards(polygon.cycle.rbegin(), polygon.cycle.rend());
    std::vector<Face> mirrored;
    ASSERT_TRUE(clip(polygon, backwards, Sign::negative, mirrored)) << name;
    for (Face& f : mirrored)
      std::swap(f.corners[1], f.corners[2]);
    expect_tiles(polygon, triples(mirrored), rng, name + ", walked clockwise", 100);
    // And no ear turns the wrong way.
    std::vector<Face> none;
    EXPECT_FALSE(clip(polygon, polygon.cycle, Sign::negative, none)) << name;
  }
}

TEST(PolygonEars, APentagramRunsOutOfEarsAndASegmentHasNone) {
  Polygon2 pentagram;
  pentagram.points = {{0, 10}, {6, -8}, {-10, 3}, {10, 3}, {-6, -8}};
  pentagram.cycle = {0, 1, 2, 3, 4};
  for (const Sign turn : {Sign::positive, Sign::negative}) {
    std::vector<Face> out;
    EXPECT_FALSE(clip(pentagram, pentagram.cycle, turn, out));
  }
  // The unit square in the plane y = 0: seen along y, (u, v) = (z, x), it runs clockwise
  // and has two ears; seen along z it is a segment, and has none.
  const std::vector<Point3> square{{0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {0, 0, 1}};
  const std::vector<VertexIndex> corners{0, 1, 2, 3};
  std::vector<Face> out;
  EXPECT_TRUE(clip_ears(corners, square, Projection(1), Sign::negative, out));
  EXPECT_EQ(out.size(), 2u);
  for (const Sign turn : {Sign::positive, Sign::negative}) {
    std::vector<Face> flat;
    EXPECT_FALSE(clip_ears(corners, square, Projection(2), turn, flat));
  }
}

}  // namespace
}  // namespace exactgeo::mesh::internal
