// The lane masks of box tree leaves (boxes/packet.hpp) against the scalar tests
// they replace (and the SSE2 lane bits against the portable ones): overlap_mask bit j is overlap(a,
// box j) for closed boxes (touching, equal, nested, disjoint by one float ulp on one axis), unused
// lanes never overlap, and shared_corner_mask bit j says whether lane j's primitive has one of the
// given corners.

#include "exactgeo/boxes/packet.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "support/generators.hpp"
#include "support/seed.hpp"

namespace exactgeo::boxes {
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();

/// Coordinates from a small grid, so touching and equal bounds are common, sometimes
/// moved by one ulp.
float coordinate(testing::Rng& rng) {
  const auto x = static_cast<float>(testing::uniform_int(rng, -4, 4)) / 4;
  switch (testing::uniform_int(rng, 0, 3)) {
    case 0:
      return std::nextafter(x, kInf);
    case 1:
      return std::nextafter(x, -kInf);
    default:
      return x;
  }
}

FloatBox random_box(testing::Rng& rng) {
  FloatBox b{};
  for (int k = 0; k < 3; ++k) {
    const float x = coordinate(rng), y = coordinate(rng);
    b.lo[k] = std::min(x, y);
    b.hi[k] = std::max(x, y);
  }
  return b;
}

TEST(BoxPacket, LaneBitsAreTheSameOnEveryPath) {
  // The SSE2 movemask (when compiled in) and the portable shuffles, on every mask.
  for (unsigned expected = 0; expected < 16; ++expected) {
    lanes::Int4 in{};
    for (int j = 0; j < 4; ++j)
      in[j] = (expected >> j & 1) != 0 ? -1 : 0;
    EXPECT_EQ(lanes::portable_bits(in), expected);
    EXPECT_EQ(lanes::bits(in), expected);
  }
}

TEST(BoxPacket, OverlapMaskIsTheScalarTestLaneByLane) {
  testing::Rng rng = testing::seeded_engine("box-packet-overlap");
  for (int round = 0; round < 5000; ++round) {
    Packet<2> p{};
    const std::size_t used = static_cast<std::size_t>(testing::uniform_int(rng, 0, kPacketLanes));
    for (std::size_t j = 0; j < kPacketLanes; ++j)
      p.set_box(j, j < used ? random_box(rng) : kNoBox);
    const FloatBox a = testing::uniform_int(rng, 0, 9) == 0 ? p.box(0) : random_box(rng);
    const unsigned mask = overlap_mask(a, p);
    for (std::size_t j = 0; j < kPacketLanes; ++j) {
      const bool expected = j < used && overlap(a, p.box(j));
      EXPECT_EQ((mask >> j & 1) != 0, expected) << "round " << round << " lane " << j;
    }
    EXPECT_EQ(mask >> kPacketLanes, 0u);
  }
}

TEST(BoxPacket, SharedCornerMaskFindsEveryCommonCorner) {
  testing::Rng rng = testing::seeded_engine("box-packet-corners");
  for (int round = 0; round < 5000; ++round) {
    Packet<3> p{};
    for (std::size_t j = 0; j < kPacketLanes; ++j) {
      for (std::size_t k = 0; k < 3; ++k)
        p.corner[k][j] = testing::uniform_int(rng, 0, 9) == 0
                             ? kNoVertex
                             : static_cast<VertexIndex>(testing::uniform_int(rng, 0, 20));
    }
    const std::array<VertexIndex, 2> edge = {
        static_cast<VertexIndex>(testing::uniform_int(rng, 0, 20)),
        static_cast<VertexIndex>(testing::uniform_int(rng, 0, 20))};
    const unsigned mask = shared_corner_mask(edge, p);
    for (std::size_t j = 0; j < kPacketLanes; ++j) {
      bool expected = false;
      for (const VertexIndex v : edge)
        for (std::size_t k = 0; k < 3; ++k)
          expected = expected || p.corner[k][j] == v;
      EXPECT_EQ((mask >> j & 1) != 0, expected) << "round " << round << " lane " << j;
    }
  }
}

}  // namespace
}  // namespace exactgeo::boxes
