#pragma once

// The mesh broad phase's pairs in the order of their operator<=> (lexicographic in their
// 32-bit indices), which the collapse pass reads them in (collapse.cpp), by a radix sort:
// a pass sorts tens of thousands, and comparing four indices a pair was most of it.

#include <array>
#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <utility>
#include <vector>

#include "exactgeo/ccd/mesh/mesh_ccd.hpp"

namespace exactgeo::remesh::internal {

/// Sorts `items` by key(item), W 32-bit words compared lexicographically, the first one
/// most significant: a least-significant-digit radix sort of 11-bit digits, each pass
/// stable, so the items end in the order of their keys; a digit that is the same in every
/// item is skipped (it would keep the order), and one that is 0 in every item is known so
/// before it is counted (a pass's indices are small). Items with equal keys are equal here
/// (the key is all of an item), so the result is std::sort's.
template <std::size_t W, class T, class Key>
void radix_sort(std::vector<T>& items, const Key& key) {
  constexpr int kBits = 11;
  constexpr std::uint32_t kDigits = 1u << kBits;
  if (items.size() < 2) return;
  // Per word, the bits set in some item.
  std::array<std::uint32_t, W> set{};
  for (const T& x : items) {
    const std::array<std::uint32_t, W> k = key(x);
    for (std::size_t w = 0; w < W; ++w)
      set[w] |= k[w];
  }
  std::vector<T> sorted(items.size());
  std::vector<std::size_t> count(kDigits);
  for (std::size_t w = W; w-- > 0;) {
    for (int shift = 0; shift < 32; shift += kBits) {
      if (((set[w] >> shift) & (kDigits - 1)) == 0) continue;
      const auto digit = [&](const T& x) { return (key(x)[w] >> shift) & (kDigits - 1); };
      std::fill(count.begin(), count.end(), 0);
      for (const T& x : items)
        ++count[digit(x)];
      if (count[digit(items.front())] == items.size()) continue;
      std::size_t start = 0;
      for (std::size_t& c : count)
        start += std::exchange(c, start);
      for (const T& x : items)
        sorted[count[digit(x)]++] = x;
      items.swap(sorted);
    }
  }
}

/// The candidates as std::sort would order them.
inline void sort_pairs(ccd::MeshCcdCandidates& candidates) {
  static_assert(std::is_same_v<VertexIndex, std::uint32_t> &&
                std::is_same_v<FaceIndex, std::uint32_t>);
  radix_sort<2>(candidates.vertex_face, [](const ccd::VertexFacePair& p) {
    return std::array<std::uint32_t, 2>{p.vertex, p.face};
  });
  radix_sort<4>(candidates.edge_edge, [](const ccd::EdgeEdgePair& p) {
    return std::array<std::uint32_t, 4>{p.a[0], p.a[1], p.b[0], p.b[1]};
  });
}

}  // namespace exactgeo::remesh::internal
