// The shared triangle surface's tables (surface/triangle_surface.hpp) against brute force
// on random triangle sets: the edges each once and sorted, the triangles at an edge, the
// triangles around a vertex, each in triangle order; an edge table and a vertex table
// assigned new triangles in the storage of old ones as ones made fresh; an edge table of the
// triangles around marked vertices only as the whole one for every edge with a marked end.
#include "exactgeo/surface/triangle_surface.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <random>
#include <set>
#include <vector>

#include "support/seed.hpp"

namespace exactgeo {
namespace {

/// `count` triangles of three distinct corners among `vertices` vertices (some vertices
/// used by none, edges shared by any number of triangles).
std::vector<Triangle> random_triangles(std::mt19937_64& rng, std::size_t count,
                                       VertexIndex vertices) {
  std::uniform_int_distribution<VertexIndex> corner(0, vertices - 1);
  std::vector<Triangle> triangles;
  while (triangles.size() < count) {
    const Triangle t{corner(rng), corner(rng), corner(rng)};
    if (t[0] != t[1] && t[1] != t[2] && t[0] != t[2]) triangles.push_back(t);
  }
  return triangles;
}

TEST(TriangleSurface, TablesAgreeWithBruteForce) {
  auto rng = testing::seeded_engine("surface.tables");
  EdgeTriangles reused;  // assigned each round's triangles, in the storage of the last's
  VertexTriangles reused_around;
  for (int round = 0; round < 50; ++round) {
    const VertexIndex n = 3 + static_cast<VertexIndex>(rng() % 40);
    const std::vector<Triangle> triangles = random_triangles(rng, 1 + rng() % 60, n);

    std::set<Edge> expected_edges;
    for (const Triangle& t : triangles) {
      for (int k = 0; k < 3; ++k)
        expected_edges.insert(edge_of(t[k], t[(k + 1) % 3]));
    }
    const std::vector<Edge> edges = edges_of(triangles, n);
    EXPECT_EQ(edges, std::vector<Edge>(expected_edges.begin(), expected_edges.end()));

    const EdgeTriangles at_edge(triangles, n);
    reused.assign(triangles, n);
    const VertexTriangles around(triangles, n);
    reused_around.assign(triangles, n);
    for (VertexIndex a = 0; a < n; ++a) {
      std::vector<std::size_t> expected_around;
      for (std::size_t t = 0; t < triangles.size(); ++t) {
        const Triangle& c = triangles[t];
        if (std::find(c.begin(), c.end(), a) != c.end()) expected_around.push_back(t);
      }
      const auto got = around[a];
      EXPECT_EQ(std::vector<std::size_t>(got.begin(), got.end()), expected_around) << a;
      const auto again = reused_around[a];
      EXPECT_EQ(std::vector<std::size_t>(again.begin(), again.end()), expected_around)
          << a << ", assigned";
      for (VertexIndex b = 0; b < n; ++b) {
        std::vector<std::size_t> expected_at;
        for (const std::size_t t : expected_around) {
          const Triangle& c = triangles[t];
          if (a != b && std::find(c.begin(), c.end(), b) != c.end()) expected_at.push_back(t);
        }
        EXPECT_EQ(at_edge.on(a, b), expected_at) << a << "-" << b;
        EXPECT_EQ(reused.on(a, b), expected_at) << a << "-" << b << ", assigned";
        EXPECT_EQ(reused.has(a, b), !expected_at.empty()) << a << "-" << b << ", assigned";
      }
    }
  }
}

TEST(TriangleSurface, AMarkedTableAnswersAsTheWholeOneForEdgesWithAMarkedEnd) {
  auto rng = testing::seeded_engine("surface.marked_table");
  EdgeTriangles marked_table;  // assigned each round, in the storage of the last round's
  for (int round = 0; round < 200; ++round) {
    const VertexIndex n = 3 + static_cast<VertexIndex>(rng() % 40);
    const std::vector<Triangle> triangles = random_triangles(rng, 1 + rng() % 80, n);
    // From none to every vertex marked, a tenth to a half of them most rounds.
    std::vector<std::uint8_t> marked(n, 0);
    const std::uint64_t in_ten = round == 0 ? 0 : round == 1 ? 10 : 1 + rng() % 5;
    for (std::uint8_t& m : marked)
      m = rng() % 10 < in_ten ? 1 : 0;
    const EdgeTriangles whole(triangles, n);
    marked_table.assign_marked(triangles, n, marked);
    for (VertexIndex a = 0; a < n; ++a) {
      for (VertexIndex b = 0; b < n + 2; ++b) {  // ends out of range too
        if (marked[a] == 0 && (b >= n || marked[b] == 0)) continue;
        EXPECT_EQ(marked_table.on(a, b), whole.on(a, b)) << round << ": " << a << "-" << b;
        EXPECT_EQ(marked_table.on(b, a), whole.on(b, a)) << round << ": " << b << "-" << a;
        EXPECT_EQ(marked_table.has(a, b), whole.has(a, b)) << round << ": " << a << "-" << b;
      }
    }
  }
}

TEST(TriangleSurface, ThirdCornerAndWalkingOrder) {
  const Triangle t{4, 7, 9};
  EXPECT_EQ(third_corner(t, 4, 7), 9u);
  EXPECT_EQ(third_corner(t, 9, 4), 7u);
  EXPECT_TRUE(walks(t, 4, 7));
  EXPECT_TRUE(walks(t, 9, 4));
  EXPECT_FALSE(walks(t, 7, 4));
  EXPECT_EQ(edge_of(9, 4), (Edge{4, 9}));
}

}  // namespace
}  // namespace exactgeo
