// Welding (weld.hpp): vertices at exactly the same position become one, +0 and -0 alike,
// the first occurrence keeping its coordinates and its place; faces re-indexed, degenerate
// ones kept; a reader welds on request before it splits polygons. merge_equal_positions
// against a quadratic search for each position's first occurrence, on random vertices
// drawn from few positions (signed zeros, subnormals, one ulp apart); and the face soup's
// test, vertices_welding_closes, on a cube stored as a soup, whole and open.

#include "exactgeo/mesh/weld.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "mesh/mesh_io.hpp"
#include "support/hexahedron.hpp"
#include "support/seed.hpp"

namespace exactgeo::mesh {
namespace {

using namespace test_io;  // the readers' shared helpers (mesh_io.hpp)

// ---------------------------------------------------------------------------------------
// Welding in the readers, and weld_vertices

TEST_F(mesh_io, WeldingTurnsAQuadSoupIntoSharedVertices) {
  // A cube stored as six quads with four vertices each.
  const int quads[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                           {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
  auto corner = [](int v) {
    return Point3{static_cast<double>(v & 1 ? 1 : 0) * 0.1, v & 2 ? 1e-300 : 0.0,
                  v & 4 ? -3.0 : 0.0};
  };
  std::string off = "OFF\n24 6 0\n";
  for (const auto& q : quads) {
    for (const int v : q) {
      const Point3 p = corner(v);
      off.append(cat(decimal(p[0]), " ", decimal(p[1]), " ", decimal(p[2]), "\n"));
    }
  }
  for (int f = 0; f < 6; ++f) {
    off.append("4");
    for (int c = 0; c < 4; ++c)
      off.append(cat(" ", std::to_string(4 * f + c)));
    off.append("\n");
  }
  const LoadedMesh soup = load("soup.off", off);
  EXPECT_EQ(soup.mesh.vertices.size(), 24u);
  EXPECT_EQ(soup.welded_vertices, 0u);

  const LoadedMesh welded = load("soup.off", off, {.weld = true});
  EXPECT_EQ(welded.mesh.vertices.size(), 8u);
  EXPECT_EQ(welded.welded_vertices, 16u);
  ASSERT_EQ(welded.mesh.faces.size(), 6u);
  for (std::size_t f = 0; f < 6; ++f) {
    EXPECT_FALSE(welded.mesh.faces[f].is_triangle());
    for (std::size_t c = 0; c < 4; ++c) {
      // Same corner positions as before, now shared.
      EXPECT_EQ(welded.mesh.vertices[welded.mesh.faces[f].corners[c]],
                soup.mesh.vertices[soup.mesh.faces[f].corners[c]]);
    }
  }
  // First-occurrence order: the first face's corners are vertices 0..3.
  EXPECT_TRUE(welded.mesh.faces[0] == make_quad(0, 1, 2, 3));
}

TEST_F(mesh_io, WeldingComesBeforePolygonsAreSplit) {
  // A pentagon whose first corner is written again as vertex 6 at the same place: without
  // welding the polygon touches itself there (refused in every reader, for want of
  // --split-polygons); welded, it is the pentagon, split exactly.
  const std::string vertices = "v 0 0 0\nv 2 0 0\nv 3 1 0\nv 1 2 0\nv -1 1 0\nv 0 0 0\n";
  const std::string faces = "f 1 2 3 4 5 6\n";
  EXPECT_MESSAGE_HAS(load_error("touch.obj", vertices + faces), "touch.obj:7:", "face 1",
                     "--split-polygons");
  const LoadedMesh welded = load("touch.obj", vertices + faces, {.weld = true});
  EXPECT_EQ(welded.welded_vertices, 1u);
  EXPECT_EQ(welded.mesh.vertices.size(), 5u);
  EXPECT_EQ(welded.mesh.faces.size(), 3u);
  EXPECT_EQ(welded.split_polygons, 1u);
  for (const Face& f : welded.mesh.faces) {
    EXPECT_TRUE(f.is_triangle());
    for (std::size_t c = 0; c < 3; ++c)
      EXPECT_LT(f.corners[c], 5u);
  }
  // The same in OFF and PLY.
  const std::string off = "OFF\n6 1 0\n0 0 0\n2 0 0\n3 1 0\n1 2 0\n-1 1 0\n0 0 0\n6 0 1 2 3 4 5\n";
  EXPECT_MESSAGE_HAS(load_error("touch.off", off), "touch.off:9:", "--split-polygons");
  EXPECT_EQ(load("touch.off", off, {.weld = true}).mesh.faces.size(), 3u);
  const std::string ply =
      "ply\nformat ascii 1.0\nelement vertex 6\nproperty float x\nproperty float y\n"
      "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
      "0 0 0\n2 0 0\n3 1 0\n1 2 0\n-1 1 0\n0 0 0\n6 0 1 2 3 4 5\n";
  EXPECT_MESSAGE_HAS(load_error("touch.ply", ply), "touch.ply", "--split-polygons");
  EXPECT_EQ(load("touch.ply", ply, {.weld = true}).mesh.faces.size(), 3u);
}

TEST(mesh_io_weld, SignedZerosMergeAndFirstOccurrenceWins) {
  Mesh mesh;
  mesh.vertices = {{-0.0, 0.0, 1.0},    // 0
                   {5.0, 5.0, 5.0},     // 1: unreferenced, kept
                   {0.0, -0.0, 1.0},    // 2 == 0
                   {2.0, 0.0, 0.0},     // 3
                   {0.0, 0.0, 1.0},     // 4 == 0
                   {2.0, -0.0, -0.0}};  // 5 == 3
  mesh.faces = {make_triangle(2, 3, 4), make_quad(5, 0, 2, 3)};
  EXPECT_EQ(weld_vertices(mesh), 3u);
  ASSERT_EQ(mesh.vertices.size(), 3u);
  EXPECT_TRUE(std::signbit(mesh.vertices[0][0]));  // the first occurrence's coordinates
  EXPECT_EQ(mesh.vertices[1], (Point3{5, 5, 5}));
  EXPECT_EQ(mesh.vertices[2], (Point3{2, 0, 0}));
  EXPECT_TRUE(mesh.faces == (std::vector<Face>{make_triangle(0, 2, 0), make_quad(2, 0, 0, 2)}));

  Mesh distinct;
  distinct.vertices = {{0, 0, 0}, {0, 0, std::numeric_limits<double>::denorm_min()}};
  distinct.faces = {make_triangle(0, 1, 1)};
  EXPECT_EQ(weld_vertices(distinct), 0u);
  EXPECT_EQ(distinct.vertices.size(), 2u);
}

// ---------------------------------------------------------------------------------------
// Merging positions, and the face soup's test

/// The new index of each vertex by a quadratic search: the number of distinct positions
/// (compared as doubles: +0 == -0) before its position's first occurrence.
std::vector<VertexIndex> first_occurrences(const std::vector<Point3>& vertices,
                                           std::vector<Point3>& kept) {
  std::vector<VertexIndex> index;
  kept.clear();
  for (const Point3& p : vertices) {
    std::size_t k = 0;
    while (k < kept.size() && !(kept[k] == p))
      ++k;
    if (k == kept.size()) kept.push_back(p);
    index.push_back(static_cast<VertexIndex>(k));
  }
  return index;
}

TEST(Weld, MergeEqualPositionsKeepsEachFirstOccurrence) {
  auto rng = exactgeo::testing::seeded_engine("mesh.weld.merge");
  const double tiny = std::numeric_limits<double>::denorm_min();
  const std::vector<double> values = {0.0, -0.0,  tiny, -tiny, 1.0, std::nextafter(1.0, 2.0),
                                      0.1, -1e300};
  std::uniform_int_distribution<std::size_t> pick(0, values.size() - 1);
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<Point3> vertices(static_cast<std::size_t>(1 + trial % 40));
    for (Point3& p : vertices)
      p = {values[pick(rng)], values[pick(rng) % 3], values[pick(rng)]};
    std::vector<Point3> kept;
    const std::vector<VertexIndex> expected = first_occurrences(vertices, kept);
    std::vector<Point3> merged = vertices;
    const std::vector<VertexIndex> index = merge_equal_positions(merged);
    if (kept.size() == vertices.size()) {
      EXPECT_TRUE(index.empty());
      EXPECT_EQ(merged, vertices);  // unchanged
      continue;
    }
    ASSERT_EQ(index, expected) << "trial " << trial;
    ASSERT_EQ(merged.size(), kept.size());
    for (std::size_t k = 0; k < kept.size(); ++k) {
      for (int i = 0; i < 3; ++i)  // the first occurrence's coordinates, the sign of 0 too
        EXPECT_EQ(std::signbit(merged[k][i]), std::signbit(kept[k][i])) << "trial " << trial;
    }
  }
}

/// The unit cube as a soup: six quads with four vertices each, 24 in all.
Mesh cube_soup() {
  Mesh soup;
  const auto corners = exactgeo::testing::unit_cube_corners();
  for (const auto& q : exactgeo::testing::kHexahedronFaces) {
    const auto base = static_cast<VertexIndex>(soup.vertices.size());
    for (const VertexIndex c : q)
      soup.vertices.push_back(corners[c]);
    soup.faces.push_back(make_quad(base, base + 1, base + 2, base + 3));
  }
  return soup;
}

TEST(Weld, AFaceSoupIsClosedByWeldingItsRepeatedVertices) {
  Mesh soup = cube_soup();
  EXPECT_EQ(vertices_welding_closes(soup), std::optional<std::size_t>(16));
  // Closed already, once welded: nothing to say.
  Mesh welded = soup;
  EXPECT_EQ(weld_vertices(welded), 16u);
  EXPECT_EQ(vertices_welding_closes(welded), std::nullopt);
  // Without a face, welding leaves it open: not a soup's problem.
  soup.faces.pop_back();
  EXPECT_EQ(vertices_welding_closes(soup), std::nullopt);
  // Nothing repeats in a lone triangle: open, and welding merges nothing.
  Mesh triangle;
  triangle.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  triangle.faces = {make_triangle(0, 1, 2)};
  EXPECT_EQ(vertices_welding_closes(triangle), std::nullopt);
}

}  // namespace
}  // namespace exactgeo::mesh
