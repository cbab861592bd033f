// The collapse pass's order of the broad phase's pairs (remesh/src/pair_order.hpp): the
// radix sort leaves them as std::sort does, on random pairs with repeats, indices small
// (most digits the same in every pair, passes skipped) and across all 32 bits.

#include "../../remesh/src/pair_order.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <vector>

#include "support/seed.hpp"

namespace exactgeo::remesh::internal {
namespace {

TEST(PairOrder, TheRadixSortOrdersThePairsAsStdSort) {
  std::mt19937_64 rng = testing::seeded_engine("PairOrder.std_sort");
  for (const std::uint32_t largest : {3u, 200u, 70000u, 0xFFFFFFFFu}) {
    std::uniform_int_distribution<std::uint32_t> index(0, largest);
    for (const std::size_t n : {0u, 1u, 2u, 17u, 5000u}) {
      ccd::MeshCcdCandidates candidates;
      for (std::size_t i = 0; i < n; ++i) {
        candidates.vertex_face.push_back({index(rng), index(rng)});
        candidates.edge_edge.push_back({{index(rng), index(rng)}, {index(rng), index(rng)}});
        if (i % 7 == 0) {  // repeats
          candidates.vertex_face.push_back(candidates.vertex_face.back());
          candidates.edge_edge.push_back(candidates.edge_edge.back());
        }
      }
      std::shuffle(candidates.vertex_face.begin(), candidates.vertex_face.end(), rng);
      std::shuffle(candidates.edge_edge.begin(), candidates.edge_edge.end(), rng);
      ccd::MeshCcdCandidates expected = candidates;
      std::sort(expected.vertex_face.begin(), expected.vertex_face.end());
      std::sort(expected.edge_edge.begin(), expected.edge_edge.end());
      sort_pairs(candidates);
      EXPECT_EQ(candidates.vertex_face, expected.vertex_face) << largest << " " << n;
      EXPECT_EQ(candidates.edge_edge, expected.edge_edge) << largest << " " << n;
    }
  }
}

}  // namespace
}  // namespace exactgeo::remesh::internal
