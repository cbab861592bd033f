// The cloth remesher's memory of unsuited collapse candidates (unsuited_edges.hpp): a vertex
// that mark_unsettled leaves unmarked after a random pass of collapses (to an end or to the
// midpoint, so that vertices move) and a random change of some sizes has the same triangles
// around it (as corners) and the same sizes and positions on its closed ring, checked by
// brute force on crumpled stacks of sheets at 2^0 and 2^+-1000; and UnsuitedEdges answers
// membership for keys asked in ascending order.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "exactgeo/remesh/operations.hpp"
#include "remesh/stacked_sheets.hpp"
#include "support/scale_names.hpp"
#include "support/seed.hpp"
#include "unsuited_edges.hpp"

namespace exactgeo::cloth {
namespace {

using remesh::Surface;
using remesh::VertexIndex;

/// The triangles around v as sorted corner triples, sorted.
std::vector<remesh::Triangle> star_corners(const Surface& s, VertexIndex v) {
  std::vector<remesh::Triangle> out;
  for (const std::size_t t : s.triangles_around(v)) {
    remesh::Triangle tri = s.triangles[t];
    std::sort(tri.begin(), tri.end());
    out.push_back(tri);
  }
  std::sort(out.begin(), out.end());
  return out;
}

class MarkUnsettledAt : public ::testing::TestWithParam<int> {};

TEST_P(MarkUnsettledAt, AnUnmarkedVertexHasTheSameStarSizesAndPositions) {
  const int exponent = GetParam();
  auto rng = testing::seeded_engine("examples.unsuited_edges." + std::to_string(exponent));
  std::bernoulli_distribution to_middle(0.3), resized(0.03), proposed(0.5);
  remesh::PassWorkspace workspace;
  remesh::TriangleChanges changes;
  std::vector<char> unsettled;
  std::size_t settled = 0, marked = 0, resized_count = 0, moved_count = 0;
  const std::size_t surfaces = testing::scaled_trials(6, 2);
  for (std::size_t k = 0; k < surfaces; ++k) {
    Surface s = testing::stack(3, 5, rng, 0.2);
    testing::crumple(s, rng);
    s = testing::times_power_of_two(std::move(s), exponent);
    std::vector<double> sizes_before(s.vertices.size());
    for (double& x : sizes_before)
      x = std::ldexp(0.25 + 0.25 * static_cast<double>(rng() % 3), exponent);
    for (int pass = 0; pass < 3; ++pass) {
      const std::string where = "2^" + std::to_string(exponent) + ", surface " + std::to_string(k) +
                                ", pass " + std::to_string(pass);
      const Surface before = s;
      std::vector<remesh::Edge> edges = s.edges();
      std::shuffle(edges.begin(), edges.end(), rng);
      std::vector<remesh::Collapse> collapses;
      for (const remesh::Edge& e : edges) {
        if (!proposed(rng)) continue;
        const Point3 &a = s.vertices[e[0]], &b = s.vertices[e[1]];
        const Point3 mid{(a[0] + b[0]) / 2, (a[1] + b[1]) / 2, (a[2] + b[2]) / 2};
        collapses.push_back({e[0], e[1], to_middle(rng) ? mid : a});
      }
      remesh::collapse_edges(s, collapses, &workspace, &changes);
      std::vector<double> sizes_after = sizes_before;
      for (double& x : sizes_after) {
        if (!resized(rng)) continue;
        x *= 0.5;
        ++resized_count;
      }
      moved_count += changes.moved.size();
      mark_unsettled(
          s, changes, sizes_before, sizes_after,
          [&](VertexIndex v) { return s.triangles_around(v); }, unsettled);
      ASSERT_EQ(unsettled.size(), s.vertices.size()) << where;
      for (VertexIndex v = 0; v < s.vertices.size(); ++v) {
        if (unsettled[v] != 0) {
          ++marked;
          continue;
        }
        ++settled;
        const std::vector<remesh::Triangle> star = star_corners(s, v);
        ASSERT_EQ(star, star_corners(before, v)) << where << ", vertex " << v;
        for (const remesh::Triangle& t : star) {
          for (const VertexIndex y : t) {
            ASSERT_EQ(sizes_after[y], sizes_before[y])
                << where << ", vertex " << v << " ring " << y;
            ASSERT_EQ(s.vertices[y], before.vertices[y])
                << where << ", vertex " << v << " ring " << y;
          }
        }
        ASSERT_EQ(sizes_after[v], sizes_before[v]) << where << ", vertex " << v;
        ASSERT_EQ(s.vertices[v], before.vertices[v]) << where << ", vertex " << v;
      }
      sizes_before = sizes_after;
    }
  }
  std::cout << "settled " << settled << ", unsettled " << marked << ", sizes changed "
            << resized_count << ", vertices moved " << moved_count << "\n";
  // Both answers were given many times, and both the sizes' and the motions' marks drove.
  EXPECT_GT(settled, 200U);
  EXPECT_GT(marked, 200U);
  EXPECT_GT(resized_count, 10U);
  EXPECT_GT(moved_count, 10U);
}

INSTANTIATE_TEST_SUITE_P(Scales, MarkUnsettledAt, ::testing::Values(0, 1000, -1000),
                         exactgeo::testing::scale_name);

TEST(UnsuitedEdges, AnswersForKeysAskedInAscendingOrder) {
  auto rng = testing::seeded_engine("examples.unsuited_edges.list");
  std::bernoulli_distribution listed(0.3);
  UnsuitedEdges memory;
  for (int trial = 0; trial < 50; ++trial) {
    std::vector<std::uint64_t> keys;
    for (VertexIndex a = 0; a < 40; ++a)
      for (VertexIndex b = a + 1; b < 40; b += 1 + static_cast<VertexIndex>(rng() % 5))
        keys.push_back(UnsuitedEdges::key(b, a));  // either order names the edge
    std::vector<std::uint64_t> last;
    memory.clear();
    for (const std::uint64_t k : keys) {
      if (!listed(rng)) continue;
      memory.add(k);
      last.push_back(k);
    }
    memory.start_pass();
    for (const std::uint64_t k : keys) {
      if (rng() % 2 == 0) continue;  // not every key is asked
      EXPECT_EQ(memory.was_unsuited(k), std::binary_search(last.begin(), last.end(), k))
          << "trial " << trial << " key " << k;
    }
    // The list made during a pass is the next pass's, and only it.
    memory.start_pass();
    for (const std::uint64_t k : keys)
      EXPECT_FALSE(memory.was_unsuited(k)) << "trial " << trial;
  }
  EXPECT_EQ(UnsuitedEdges::key(3, 7), UnsuitedEdges::key(7, 3));
  EXPECT_EQ(UnsuitedEdges::key(3, 7), (std::uint64_t{3} << 32) | 7U);
}

}  // namespace
}  // namespace exactgeo::cloth
