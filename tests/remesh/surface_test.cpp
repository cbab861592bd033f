// The surface the operations change (surface.hpp): its adjacency queries against a
// brute-force reading of the triangle list (every pair of vertices, every vertex), on hand
// cases (an empty surface, two triangles on an edge, an edge of three triangles, a vertex
// no triangle uses) and on seeded random triangle lists, with corners in any order and
// vertices left unused; and its fixed flags, none when the list is empty.

#include "exactgeo/remesh/surface.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "support/seed.hpp"

namespace exactgeo::remesh {
namespace {

bool has_corner(const Triangle& t, VertexIndex v) {
  return std::count(t.begin(), t.end(), v) > 0;
}

/// The triangles with both corners, in order, by reading every triangle.
std::vector<std::size_t> on_edge_by_reading(const Surface& s, VertexIndex a, VertexIndex b) {
  std::vector<std::size_t> found;
  for (std::size_t t = 0; t < s.triangles.size(); ++t) {
    if (has_corner(s.triangles[t], a) && has_corner(s.triangles[t], b)) found.push_back(t);
  }
  return found;
}

std::vector<std::size_t> around_by_reading(const Surface& s, VertexIndex v) {
  std::vector<std::size_t> found;
  for (std::size_t t = 0; t < s.triangles.size(); ++t) {
    if (has_corner(s.triangles[t], v)) found.push_back(t);
  }
  return found;
}

/// Every side of every triangle, smaller end first, each once, sorted (a std::set).
std::vector<Edge> edges_by_reading(const Surface& s) {
  std::set<std::pair<VertexIndex, VertexIndex>> sides;
  for (const Triangle& t : s.triangles) {
    for (int k = 0; k < 3; ++k) {
      const VertexIndex u = t[k], w = t[(k + 1) % 3];
      sides.insert({std::min(u, w), std::max(u, w)});
    }
  }
  std::vector<Edge> edges;
  for (const auto& [u, w] : sides)
    edges.push_back({u, w});
  return edges;
}

/// Every query of the surface agrees with the reading of its triangle list.
void expect_adjacency_as_read(const Surface& s, const std::string& what) {
  const auto n = static_cast<VertexIndex>(s.vertices.size());
  for (VertexIndex a = 0; a < n; ++a) {
    EXPECT_EQ(s.triangles_around(a), around_by_reading(s, a)) << what << ": around " << a;
    for (VertexIndex b = 0; b < n; ++b) {
      if (a == b) continue;
      EXPECT_EQ(s.triangles_on_edge(a, b), on_edge_by_reading(s, a, b))
          << what << ": edge " << a << "-" << b;
    }
  }
  EXPECT_EQ(s.edges(), edges_by_reading(s)) << what;
}

TEST(RemeshSurface, AnEmptySurfaceHasNoEdgesAndNoNeighbours) {
  const Surface empty;
  EXPECT_TRUE(empty.edges().empty());
  Surface unused;  // vertices, no triangles
  unused.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  EXPECT_TRUE(unused.edges().empty());
  EXPECT_TRUE(unused.triangles_around(0).empty());
  EXPECT_TRUE(unused.triangles_on_edge(0, 1).empty());
}

TEST(RemeshSurface, TwoTrianglesOnAnEdge) {
  // abc and bad on edge ab (0, 1); c = 2, d = 3; vertex 4 used by no triangle.
  const std::vector<Point3> vertices{{0, 0, 0}, {2, 0, 0}, {1, 1, 0}, {1, -1, 0}, {5, 5, 5}};
  const std::vector<Triangle> triangles{{0, 1, 2}, {1, 0, 3}};
  Surface s{vertices, triangles};
  EXPECT_EQ(s.triangles_on_edge(0, 1), (std::vector<std::size_t>{0, 1}));
  EXPECT_EQ(s.triangles_on_edge(1, 0), (std::vector<std::size_t>{0, 1}));  // either order
  EXPECT_EQ(s.triangles_on_edge(2, 1), (std::vector<std::size_t>{0}));     // a boundary edge
  EXPECT_TRUE(s.triangles_on_edge(2, 3).empty());                          // not an edge
  EXPECT_TRUE(s.triangles_on_edge(0, 4).empty());
  EXPECT_EQ(s.triangles_around(0), (std::vector<std::size_t>{0, 1}));
  EXPECT_EQ(s.triangles_around(3), (std::vector<std::size_t>{1}));
  EXPECT_TRUE(s.triangles_around(4).empty());
  EXPECT_EQ(s.edges(), (std::vector<Edge>{{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}}));
  expect_adjacency_as_read(s, "two triangles");
  // A third triangle on ab (three sheets meeting at an edge), listed before the others'
  // smaller edges: the queries keep triangle order, the edges stay sorted and single.
  s.triangles.push_back({4, 1, 0});
  EXPECT_EQ(s.triangles_on_edge(0, 1), (std::vector<std::size_t>{0, 1, 2}));
  EXPECT_EQ(s.edges(), (std::vector<Edge>{{0, 1}, {0, 2}, {0, 3}, {0, 4}, {1, 2}, {1, 3}, {1, 4}}));
  expect_adjacency_as_read(s, "three triangles on an edge");
}

TEST(RemeshSurface, AdjacencyAgreesWithReadingTheTriangles) {
  auto rng = testing::seeded_engine("remesh.surface.adjacency");
  std::uniform_int_distribution<int> vertex_count(3, 24);
  std::uniform_int_distribution<int> triangle_count(0, 40);
  int surfaces_with_shared_edges = 0;
  for (int trial = 0; trial < 200; ++trial) {
    Surface s;
    const int n = vertex_count(rng);
    for (int v = 0; v < n; ++v)
      s.vertices.push_back({1.0 * v, 0.5 * v, -0.25 * v});  // positions play no part
    std::uniform_int_distribution<VertexIndex> corner(0, static_cast<VertexIndex>(n - 1));
    const int m = triangle_count(rng);
    while (static_cast<int>(s.triangles.size()) < m) {
      const Triangle t{corner(rng), corner(rng), corner(rng)};
      if (t[0] != t[1] && t[1] != t[2] && t[0] != t[2]) s.triangles.push_back(t);
    }
    const std::vector<Edge> edges = edges_by_reading(s);
    surfaces_with_shared_edges += edges.size() < 3 * s.triangles.size() ? 1 : 0;
    expect_adjacency_as_read(s, "trial " + std::to_string(trial));
    if (::testing::Test::HasFailure()) break;  // one surface's report is enough
  }
  EXPECT_GT(surfaces_with_shared_edges, 100);  // triangles do meet at edges
}

TEST(RemeshSurface, FixedFlags) {
  const std::vector<Point3> vertices{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
  const std::vector<Triangle> triangles{{0, 1, 2}, {2, 1, 3}};
  Surface s{vertices, triangles};
  for (VertexIndex v = 0; v < 4; ++v)
    EXPECT_FALSE(s.is_fixed(v)) << v;  // no flags: none fixed
  s.fixed = {false, true, false, true};
  for (VertexIndex v = 0; v < 4; ++v)
    EXPECT_EQ(s.is_fixed(v), v % 2 == 1) << v;
  // Written like the surface it is, with the flags last.
  const Surface written{vertices, triangles, {true, false, false, false}};
  EXPECT_TRUE(written.is_fixed(0));
  EXPECT_FALSE(written.is_fixed(3));
  EXPECT_EQ(written.edges(), s.edges());
}

}  // namespace
}  // namespace exactgeo::remesh
