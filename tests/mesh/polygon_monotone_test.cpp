// The sweep triangulation (polygon_monotone.hpp, internal): every family of polygons the
// tests generate (convex, star-shaped, with corners inside straight edges, comb-shaped,
// with holes through bridges), from 10 to 10^4 corners, walked either way and seen along
// two axes, is triangulated without the ear clipping fallback, into n - 2 triangles that
// the certificate (polygon_certificate.hpp) accepts, with the sweep's record of the edge
// below each corner and searching its own status alike.

#include "../../mesh/src/polygon_monotone.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <optional>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "../../mesh/src/polygon_certificate.hpp"
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
          const auto order = sweep_order(walk, seen, plane);
          ScratchVector<std::uint32_t> below;
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
