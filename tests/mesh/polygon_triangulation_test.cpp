// A file's polygon made into triangles (polygon_triangulation.hpp, internal), called
// directly: planar polygons of every generator in a plane of no axis (z = x + y), small
// (ear clipping, certified pair by pair) and large (the sweeps), become n - 2 triangles
// that tile them (exact oracles, polygon_tiling.hpp), turning as the polygon is walked;
// a polygon with one corner lifted is split over its projection; corners on one line give
// a fan of zero-area triangles; a pentagram is self-crossing and nothing is appended; the
// fan is (c0, c[i], c[i+1]). Triangles are appended to what `out` holds.

#include "../../mesh/src/polygon_triangulation.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "mesh/polygon_tiling.hpp"
#include "support/polygon_oracle.hpp"
#include "support/seed.hpp"
#include "support/segment_triangle_oracle.hpp"

namespace exactgeo::mesh::internal {
namespace {

using test_polygons::expect_tiles;
using testing::Polygon2;

/// The polygon's points at (x, y, x + y) (exact for the generators' integers), or at z = 0.
std::vector<Point3> embedded(const Polygon2& polygon, bool tilted) {
  std::vector<Point3> vertices;
  for (const auto& [x, y] : polygon.points)
    vertices.push_back({x, y, tilted ? x + y : 0.0});
  return vertices;
}

std::vector<std::array<std::uint32_t, 3>> triples(const std::vector<Face>& faces,
                                                  std::size_t from = 0) {
  std::vector<std::array<std::uint32_t, 3>> t;
  for (std::size_t f = from; f < faces.size(); ++f) {
    EXPECT_TRUE(faces[f].is_triangle());
    t.push_back({faces[f].corners[0], faces[f].corners[1], faces[f].corners[2]});
  }
  return t;
}

PolygonForm triangulate(const Polygon2& polygon, const std::vector<Point3>& vertices,
                        std::vector<Face>& out) {
  const std::vector<VertexIndex> corners(polygon.cycle.begin(), polygon.cycle.end());
  return triangulate_polygon(corners, vertices, out);
}

TEST(PolygonTriangulation, PlanarPolygonsAreTiledInAnyPlane) {
  auto rng = testing::seeded_engine("mesh.polygon_triangulation.planar");
  std::vector<std::pair<std::string, Polygon2>> polygons = {
      {"keyhole", testing::keyhole_polygon(false)},
      {"keyhole with an L-shaped hole", testing::keyhole_polygon(true)}};
  for (const int n : {5, 12, 16, 17, 60, 2000}) {
    const std::string size = " of " + std::to_string(n);
    polygons.emplace_back("star" + size, testing::star_polygon(rng, n, true));
    polygons.emplace_back("convex" + size, testing::convex_polygon(rng, n));
    polygons.emplace_back("holed star" + size, testing::holed_star_polygon(rng, n));
    polygons.emplace_back("comb" + size, testing::comb_polygon(rng, std::max(2, n / 4)));
  }
  for (const auto& [name, polygon] : polygons) {
    for (const bool tilted : {false, true}) {
      const std::string what = name + (tilted ? " in z = x + y" : " in z = 0");
      std::vector<Face> out{make_triangle(9, 9, 9)};  // kept: triangles are appended
      ASSERT_EQ(triangulate(polygon, embedded(polygon, tilted), out), PolygonForm::planar) << what;
      EXPECT_TRUE(out.front() == make_triangle(9, 9, 9));
      expect_tiles(polygon, triples(out, 1), rng, what, 100);
    }
  }
}

TEST(PolygonTriangulation, WalkedClockwiseTheTrianglesTurnClockwise) {
  auto rng = testing::seeded_engine("mesh.polygon_triangulation.clockwise");
  for (const int n : {7, 300}) {
    const Polygon2 polygon = testing::star_polygon(rng, n, false);
    Polygon2 backwards = polygon;
    std::reverse(backwards.cycle.begin(), backwards.cycle.end());
    std::vector<Face> out;
    ASSERT_EQ(triangulate(backwards, embedded(polygon, true), out), PolygonForm::planar);
    for (Face& f : out)
      std::swap(f.corners[1], f.corners[2]);  // the mirror images tile it counter-clockwise
    expect_tiles(polygon, triples(out), rng, "star of " + std::to_string(n), 100);
  }
}

TEST(PolygonTriangulation, ALiftedCornerIsSplitOverTheProjection) {
  auto rng = testing::seeded_engine("mesh.polygon_triangulation.lifted");
  for (const int n : {6, 40}) {
    const Polygon2 polygon = testing::star_polygon(rng, n, false);
    std::vector<Point3> vertices = embedded(polygon, false);
    vertices[polygon.cycle[1]][2] = 1.0;  // off the plane z = 0; the projection along z stays
    std::vector<Face> out;
    ASSERT_EQ(triangulate(polygon, vertices, out), PolygonForm::non_planar);
    expect_tiles(polygon, triples(out), rng, "lifted star of " + std::to_string(n), 100);
  }
}

TEST(PolygonTriangulation, CollinearCornersGiveAFanOfZeroAreaTriangles) {
  const std::vector<Point3> vertices{{0, 0, 0}, {1, 2, 3}, {2, 4, 6}, {5, 10, 15}, {3, 6, 9}};
  const std::vector<VertexIndex> corners{0, 1, 2, 3, 4};
  std::vector<Face> out;
  ASSERT_EQ(triangulate_polygon(corners, vertices, out), PolygonForm::zero_area);
  ASSERT_EQ(out.size(), 3u);
  for (const Face& f : out) {
    EXPECT_TRUE(f.is_triangle());
    EXPECT_TRUE(testing::collinear_oracle(vertices[f.corners[0]], vertices[f.corners[1]],
                                          vertices[f.corners[2]]));
  }
}

TEST(PolygonTriangulation, APentagramIsSelfCrossingAndNothingIsAppended) {
  Polygon2 pentagram;
  pentagram.points = {{0, 10}, {6, -8}, {-10, 3}, {10, 3}, {-6, -8}};
  pentagram.cycle = {0, 1, 2, 3, 4};
  for (const bool tilted : {false, true}) {
    std::vector<Face> out{make_triangle(1, 2, 3)};
    EXPECT_EQ(triangulate(pentagram, embedded(pentagram, tilted), out), PolygonForm::self_crossing);
    ASSERT_EQ(out.size(), 1u);
    EXPECT_TRUE(out.front() == make_triangle(1, 2, 3));
  }
}

TEST(PolygonTriangulation, TheFanIsFromTheFirstCorner) {
  const std::vector<VertexIndex> corners{7, 3, 9, 4, 11};
  std::vector<Face> out{make_quad(0, 1, 2, 3)};
  append_fan(corners, out);
  EXPECT_EQ(out, (std::vector<Face>{make_quad(0, 1, 2, 3), make_triangle(7, 3, 9),
                                    make_triangle(7, 9, 4), make_triangle(7, 4, 11)}));
}

}  // namespace
}  // namespace exactgeo::mesh::internal
