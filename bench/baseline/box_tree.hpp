#pragma once

// Kept unchanged as the baseline that ccd_mesh_bench measures the library's broad phase
// against in the same run (docs/ccd.md): the broad phase before refitted trees and
// dual-tree traversal, which builds a tree over the moving primitives every step and
// queries it once per primitive box.
//
// A bounding-volume hierarchy over swept boxes, queried one box at a time (a QueryTree,
// apart from the box trees of exactgeo::boxes, which are walked against each other).
//
// Built top down: the boxes of a node are split at the median of their centres along the
// axis where the centres spread the most, down to leaves of at most kLeafSize boxes. A
// query visits every node whose box overlaps the query box and reports every stored box
// that overlaps it (closed boxes: touching counts), so it finds exactly the overlapping
// boxes, in an order fixed by the tree, which depends only on the input boxes.
//

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "baseline/swept_box.hpp"

namespace exactgeo::ccd::bench::baseline {

class QueryTree {
 public:
  QueryTree() = default;
  /// Takes the boxes (their order is not kept).
  explicit QueryTree(std::vector<SweptBox> boxes) : boxes_(std::move(boxes)) {
    if (boxes_.empty()) return;
    nodes_.reserve(2 * boxes_.size() / kLeafSize + 1);
    build_all();
  }

  bool empty() const noexcept { return boxes_.empty(); }
  std::size_t size() const noexcept { return boxes_.size(); }
  /// The stored boxes in the tree's leaf order: neighbours in space are mostly neighbours
  /// here, so querying in this order keeps the nodes a query visits in cache for the next.
  std::span<const SweptBox> boxes() const noexcept { return boxes_; }

  /// Calls visit(id) for every stored box overlapping `query`.
  template <class Visit>
  void query(const SweptBox& query, Visit&& visit) const {
    if (nodes_.empty()) return;
    // Depth is at most log2(n / kLeafSize) + 1 < 64 for any n that fits in memory.
    std::array<std::uint32_t, 64> stack;
    std::size_t top = 0;
    stack[top++] = 0;
    while (top > 0) {
      const Node& node = nodes_[stack[--top]];
      if (!overlap(node.bounds, query)) continue;
      if (node.count > 0) {
        for (std::uint32_t i = node.first; i < node.first + node.count; ++i) {
          if (overlap(boxes_[i], query)) visit(boxes_[i].id);
        }
        continue;
      }
      const auto self = static_cast<std::uint32_t>(&node - nodes_.data());
      stack[top++] = node.first;  // right child
      stack[top++] = self + 1;    // left child, stored right after its parent
    }
  }

 private:
  static constexpr std::size_t kLeafSize = 4;

  struct Node {
    SweptBox bounds;          ///< bounds.id unused
    std::uint32_t first = 0;  ///< leaf: first box; inner node: the right child
    std::uint32_t count = 0;  ///< boxes in a leaf; 0 for an inner node
  };

  /// A box with its centre (twice the centre, finite even for boxes reaching infinity,
  /// so the median split always sees a strict weak order).
  struct Item {
    SweptBox box;
    std::array<float, 3> centre;
  };

  static Item item(const SweptBox& b) noexcept {
    constexpr float kMax = std::numeric_limits<float>::max() / 2;
    Item it{b, {}};
    for (int k = 0; k < 3; ++k)
      it.centre[k] = std::clamp(b.lo[k], -kMax, kMax) + std::clamp(b.hi[k], -kMax, kMax);
    return it;
  }

  void build_all() {
    std::vector<Item> items(boxes_.size());
    for (std::size_t i = 0; i < boxes_.size(); ++i)
      items[i] = item(boxes_[i]);
    build(items, 0, items.size());
    for (std::size_t i = 0; i < items.size(); ++i)
      boxes_[i] = items[i].box;
  }

  std::uint32_t build(std::vector<Item>& items, std::size_t begin, std::size_t end) {
    const auto index = static_cast<std::uint32_t>(nodes_.size());
    nodes_.push_back({});
    SweptBox bounds = items[begin].box;
    std::array<float, 3> lo = items[begin].centre, hi = lo;
    for (std::size_t i = begin; i < end; ++i) {
      for (int k = 0; k < 3; ++k) {
        bounds.lo[k] = std::min(bounds.lo[k], items[i].box.lo[k]);
        bounds.hi[k] = std::max(bounds.hi[k], items[i].box.hi[k]);
        lo[k] = std::min(lo[k], items[i].centre[k]);
        hi[k] = std::max(hi[k], items[i].centre[k]);
      }
    }
    nodes_[index].bounds = bounds;
    if (end - begin <= kLeafSize) {
      nodes_[index].first = static_cast<std::uint32_t>(begin);
      nodes_[index].count = static_cast<std::uint32_t>(end - begin);
      return index;
    }
    int axis = 0;
    for (int k = 1; k < 3; ++k) {
      if (hi[k] - lo[k] > hi[axis] - lo[axis]) axis = k;
    }
    const std::size_t middle = begin + (end - begin) / 2;
    const auto by_centre = [axis](const Item& a, const Item& b) {
      return a.centre[axis] != b.centre[axis] ? a.centre[axis] < b.centre[axis]
                                              : a.box.id < b.box.id;
    };
    std::nth_element(items.begin() + static_cast<std::ptrdiff_t>(begin),
                     items.begin() + static_cast<std::ptrdiff_t>(middle),
                     items.begin() + static_cast<std::ptrdiff_t>(end), by_centre);
    build(items, begin, middle);  // the left child is index + 1
    nodes_[index].first = build(items, middle, end);
    return index;
  }

  std::vector<SweptBox> boxes_;
  std::vector<Node> nodes_;
};

}  // namespace exactgeo::ccd::bench::baseline
