// A polygon's walk as the sweeps read it (polygon_walk.hpp, internal): its distinct corners
// in ascending order with local numbers, and its edges as a 1-chain with net coefficients
// (a bridge walked there and back has coefficient 0), against a map kept by hand over
// random walks of numbers in one run and scattered; repeats next to themselves dropped
// cyclically; chains of uses in any order; and the sweep order of the projected points.

#include "../../mesh/src/polygon_walk.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <map>
#include <random>
#include <utility>
#include <vector>

#include "support/seed.hpp"

namespace exactgeo::mesh::internal {
namespace {

TEST(PolygonWalk, ABridgeWalkedBothWaysHasCoefficientZero) {
  // A square 10 11 12 13 with a hole 20 21 22, joined by the bridge 10-20.
  const std::vector<VertexIndex> corners{10, 11, 12, 13, 10, 20, 22, 21, 20};
  const PolygonWalk walk = walk_of(corners);
  EXPECT_EQ(walk.corners, 9u);
  EXPECT_EQ(walk.vertices, (ScratchVector<VertexIndex>{10, 11, 12, 13, 20, 21, 22}));
  EXPECT_EQ(local_number(walk, 20), 4u);
  EXPECT_EQ(local_number(walk, 14), std::nullopt);
  EXPECT_EQ(local_number(walk, 9), std::nullopt);
  EXPECT_EQ(local_number(walk, 23), std::nullopt);
  // Local numbers: 10 11 12 13 20 21 22 are 0 1 2 3 4 5 6.
  EXPECT_EQ(walk.edges, (ScratchVector<ChainEdge>{{0, 1, 1},
                                                {0, 3, -1},
                                                {0, 4, 0},
                                                {1, 2, 1},
                                                {2, 3, 1},
                                                {4, 5, -1},
                                                {4, 6, 1},
                                                {5, 6, -1}}));
}

TEST(PolygonWalk, RepeatsNextToThemselvesAreDroppedCyclically) {
  EXPECT_EQ(without_repeats(std::vector<VertexIndex>{1, 1, 2, 3, 3, 1}),
            (ScratchVector<VertexIndex>{2, 3, 1}));
  EXPECT_EQ(without_repeats(std::vector<VertexIndex>{4, 5, 6}),
            (ScratchVector<VertexIndex>{4, 5, 6}));
  // The last corner is next to the first.
  EXPECT_EQ(without_repeats(std::vector<VertexIndex>{4, 5, 4}), (ScratchVector<VertexIndex>{5, 4}));
  EXPECT_TRUE(without_repeats(std::vector<VertexIndex>{7, 7, 7}).empty());
}

/// The walk by hand: distinct corners sorted, and per pair of local numbers the times
/// walked up minus the times walked down.
std::pair<std::vector<VertexIndex>, std::map<std::pair<std::uint32_t, std::uint32_t>, int>>
walk_by_hand(const std::vector<VertexIndex>& corners) {
  std::vector<VertexIndex> sorted = corners;
  std::sort(sorted.begin(), sorted.end());
  sorted.erase(std::unique(sorted.begin(), sorted.end()), sorted.end());
  const auto local = [&](VertexIndex v) {
    return static_cast<std::uint32_t>(std::lower_bound(sorted.begin(), sorted.end(), v) -
                                      sorted.begin());
  };
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> net;
  for (std::size_t k = 0; k < corners.size(); ++k) {
    const std::uint32_t a = local(corners[k]), b = local(corners[(k + 1) % corners.size()]);
    net[{std::min(a, b), std::max(a, b)}] += a < b ? 1 : -1;
  }
  return {sorted, net};
}

TEST(PolygonWalk, RandomWalksAgreeWithTheWalkByHand) {
  auto rng = testing::seeded_engine("mesh.polygon_walk");
  for (int trial = 0; trial < 500; ++trial) {
    // Half the walks on numbers in one run from 1000, half scattered up to 10^6.
    const bool run = trial % 2 == 0;
    const int distinct = 3 + trial % 12;
    std::vector<VertexIndex> pool;
    for (int k = 0; k < distinct; ++k) {
      pool.push_back(run ? static_cast<VertexIndex>(1000 + k)
                         : std::uniform_int_distribution<VertexIndex>(0, 1000000)(rng));
    }
    std::uniform_int_distribution<std::size_t> pick(0, pool.size() - 1);
    std::vector<VertexIndex> corners;
    const int length = 3 + trial % 30;
    while (static_cast<int>(corners.size()) < length) {
      const VertexIndex c = pool[pick(rng)];
      if (corners.empty() || c != corners.back()) corners.push_back(c);
    }
    if (corners.back() == corners.front()) corners.pop_back();
    if (corners.size() < 3) continue;
    const auto [sorted, net] = walk_by_hand(corners);
    const PolygonWalk walk = walk_of(corners);
    EXPECT_EQ(walk.corners, corners.size());
    ASSERT_TRUE(std::ranges::equal(walk.vertices, sorted));
    ScratchVector<ChainEdge> expected;
    for (const auto& [pair, coefficient] : net)
      expected.push_back({pair.first, pair.second, coefficient});
    ASSERT_EQ(walk.edges, expected) << "trial " << trial;
    for (std::uint32_t k = 0; k < sorted.size(); ++k)
      EXPECT_EQ(local_number(walk, sorted[k]), k);
    // The same chain from the uses in reverse order.
    std::vector<ChainUse> uses;
    for (std::size_t k = corners.size(); k-- > 0;) {
      uses.push_back({*local_number(walk, corners[k]),
                      *local_number(walk, corners[(k + 1) % corners.size()])});
    }
    EXPECT_EQ(chain_of(uses, sorted.size()), expected);
  }
}

TEST(PolygonWalk, TheSweepOrderIsLexicographicInTheProjection) {
  auto rng = testing::seeded_engine("mesh.polygon_walk.sweep");
  std::uniform_int_distribution<int> small(-3, 3);
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<Point3> vertices(40);
    for (Point3& p : vertices)
      p = {double(small(rng)), double(small(rng)), double(small(rng))};
    std::vector<VertexIndex> corners;
    for (VertexIndex v = 0; v < 40; v += 1 + static_cast<VertexIndex>(trial % 3))
      corners.push_back(v);
    const PolygonWalk walk = walk_of(corners);
    for (const int axis : {0, 1, 2}) {
      const Projection plane(axis);
      const auto order = sweep_order(walk, vertices, plane);
      ASSERT_EQ(order.size(), walk.vertices.size());
      std::vector<std::uint32_t> sorted(order.begin(), order.end());
      std::sort(sorted.begin(), sorted.end());
      for (std::uint32_t k = 0; k < sorted.size(); ++k)
        ASSERT_EQ(sorted[k], k);  // a permutation of the local numbers
      const int u = (axis + 1) % 3, v = (axis + 2) % 3;
      for (std::size_t k = 1; k < order.size(); ++k) {
        const Point3& a = vertices[walk.vertices[order[k - 1]]];
        const Point3& b = vertices[walk.vertices[order[k]]];
        EXPECT_TRUE(a[u] < b[u] || (a[u] == b[u] && a[v] <= b[v])) << "axis " << axis;
      }
    }
  }
}

}  // namespace
}  // namespace exactgeo::mesh::internal
