#pragma once

// Morton (Z-order) codes, kMortonBits bits per axis, and their stable sort: the order in
// which the box tree lays out its primitives (box_tree.hpp) and in which a batch of points
// is visited (inside/batch.cpp). A cost only wherever it is used: any order gives the same
// answers there.

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace exactgeo::boxes {

/// Bits per axis of a Morton code: 2^10 cells per axis, 30 bits in all.
inline constexpr int kMortonBits = 10;

/// x's low kMortonBits bits spread out to every third bit (bit i to bit 3 i); a code is
/// spread(x) | spread(y) << 1 | spread(z) << 2.
constexpr std::uint32_t morton_spread(std::uint32_t x) noexcept {
  x = (x | (x << 16)) & 0x030000FFu;
  x = (x | (x << 8)) & 0x0300F00Fu;
  x = (x | (x << 4)) & 0x030C30C3u;
  x = (x | (x << 2)) & 0x09249249u;
  return x;
}

/// Sorts keys (code << 32 | index) by their codes, stably: keys made in index order stay
/// in index order among equal codes. Three radix passes of kMortonBits bits.
inline void sort_morton_keys(std::vector<std::uint64_t>& keys) {
  constexpr std::uint64_t kDigit = (1u << kMortonBits) - 1;
  std::vector<std::uint64_t> other(keys.size());
  for (int shift = 32; shift < 32 + 3 * kMortonBits; shift += kMortonBits) {
    std::array<std::size_t, (1u << kMortonBits) + 1> start{};
    for (const std::uint64_t key : keys)
      ++start[(key >> shift & kDigit) + 1];
    for (std::size_t d = 1; d < start.size(); ++d)
      start[d] += start[d - 1];
    for (const std::uint64_t key : keys)
      other[start[key >> shift & kDigit]++] = key;
    keys.swap(other);
  }
}

}  // namespace exactgeo::boxes
