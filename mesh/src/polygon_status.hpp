#pragma once

// The status of a plane sweep: the items across the sweep line in their order, bottom to
// top, as a treap (a binary search tree balanced by random priorities, expected depth
// O(log n)) whose nodes sit in one array, 64 bytes each, recycled as items leave. It is
// what std::set does for the sweeps, with the memory a sweep over a million edges can
// afford to walk: a descent reads one cache line per level, and the nodes stay together.
// Each node also knows its neighbours below and above (a threaded tree), so that stepping
// to a neighbour, which the sweeps do at every corner, reads the node it reaches instead
// of climbing the tree; the links share the node's cache line (an item of at most 44
// bytes keeps a node at 64). Items are compared only by `Below` (strict: a
// below b), only at insertion, and only with items already there.

#include <cstdint>
#include <limits>
#include <vector>

#include "scratch_vector.hpp"

namespace exactgeo::mesh::internal {

template <class Item, class Below>
class SweepStatus {
 public:
  using Handle = std::uint32_t;
  static constexpr Handle kNone = std::numeric_limits<Handle>::max();

  explicit SweepStatus(Below below) : below_(below) {}

  bool empty() const { return root_ == kNone; }
  const Item& operator[](Handle h) const { return nodes_[h].item; }
  Item& operator[](Handle h) { return nodes_[h].item; }

  /// The top item, or kNone.
  Handle last() const { return top_; }

  /// The item just below h, or kNone.
  Handle previous(Handle h) const { return nodes_[h].neighbour[0]; }

  /// The item just above h, or kNone.
  Handle next(Handle h) const { return nodes_[h].neighbour[1]; }

  /// Inserts the item where `Below` puts it, searching from the root.
  Handle insert(const Item& item) {
    const Handle h = allocate(item);
    if (root_ == kNone) {
      root_ = h;
      top_ = h;
      return h;
    }
    Handle at = root_;
    for (;;) {
      const int side = below_(item, nodes_[at].item) ? 0 : 1;
      if (nodes_[at].child[side] == kNone) {
        attach(h, at, side);
        return h;
      }
      at = nodes_[at].child[side];
    }
  }

  /// Inserts the item just below `above` (kNone: at the top) when `Below` agrees with
  /// that place (two comparisons), else where a search puts it.
  Handle insert_below(const Item& item, Handle above) {
    const Handle h = try_insert_below(item, above);
    return h == kNone ? insert(item) : h;
  }

  /// Inserts the item just below `above` (kNone: at the top) when `Below` agrees with
  /// that place (two comparisons); else inserts nothing and returns kNone.
  Handle try_insert_below(const Item& item, Handle above) {
    if (root_ == kNone) return above == kNone ? insert(item) : kNone;
    const Handle under = above == kNone ? top_ : previous(above);
    if ((above != kNone && !below_(item, nodes_[above].item)) ||
        (under != kNone && !below_(nodes_[under].item, item))) {
      return kNone;
    }
    const Handle h = allocate(item);
    // Just below `above`: its left child when it has none, else right of its predecessor.
    if (above != kNone && nodes_[above].child[0] == kNone) {
      attach(h, above, 0);
    } else {
      attach(h, under, 1);
    }
    return h;
  }

  /// Removes h; returns the item that was just above it (kNone: none).
  Handle erase(Handle h) {
    const Handle under = nodes_[h].neighbour[0];
    const Handle above = nodes_[h].neighbour[1];
    if (under != kNone) nodes_[under].neighbour[1] = above;
    if (above != kNone) nodes_[above].neighbour[0] = under;
    if (top_ == h) top_ = under;
    // Rotate h down until it is a leaf, the child of higher priority up each time.
    for (;;) {
      const Node& n = nodes_[h];
      if (n.child[0] == kNone && n.child[1] == kNone) break;
      const int side = n.child[0] == kNone                                         ? 1
                       : n.child[1] == kNone                                       ? 0
                       : nodes_[n.child[0]].priority > nodes_[n.child[1]].priority ? 0
                                                                                   : 1;
      rotate_up(n.child[side]);
    }
    const Handle parent = nodes_[h].parent;
    if (parent == kNone) {
      root_ = kNone;
    } else {
      nodes_[parent].child[nodes_[parent].child[0] == h ? 0 : 1] = kNone;
    }
    free_.push_back(h);
    return above;
  }

 private:
  struct alignas(64) Node {
    Item item;
    Handle child[2];
    Handle parent;
    std::uint32_t priority;
    Handle neighbour[2];  ///< the items just below and just above
  };

  Handle allocate(const Item& item) {
    // A fixed sequence of priorities (xorshift): the same tree on every run.
    seed_ ^= seed_ << 13;
    seed_ ^= seed_ >> 7;
    seed_ ^= seed_ << 17;
    const Node node{
        item, {kNone, kNone}, kNone, static_cast<std::uint32_t>(seed_ >> 32), {kNone, kNone}};
    if (free_.empty()) {
      nodes_.push_back(node);
      return static_cast<Handle>(nodes_.size() - 1);
    }
    const Handle h = free_.back();
    free_.pop_back();
    nodes_[h] = node;
    return h;
  }

  /// h (new, a leaf) as parent's child on `side`, then up while its priority is higher.
  /// A new leaf left of its parent lies just below it, between it and the parent's old
  /// neighbour below (right of it: just above it); rotations keep the order.
  void attach(Handle h, Handle parent, int side) {
    nodes_[parent].child[side] = h;
    nodes_[h].parent = parent;
    const Handle beyond = nodes_[parent].neighbour[side];  // the parent's old one that side
    nodes_[h].neighbour[side] = beyond;
    nodes_[h].neighbour[1 - side] = parent;
    nodes_[parent].neighbour[side] = h;
    if (beyond != kNone) nodes_[beyond].neighbour[1 - side] = h;
    if (top_ == parent && side == 1) top_ = h;
    while (nodes_[h].parent != kNone && nodes_[nodes_[h].parent].priority < nodes_[h].priority)
      rotate_up(h);
  }

  /// h takes its parent's place, the parent becoming its child.
  void rotate_up(Handle h) {
    const Handle p = nodes_[h].parent;
    const Handle g = nodes_[p].parent;
    const int side = nodes_[p].child[0] == h ? 0 : 1;
    const Handle moved = nodes_[h].child[1 - side];
    nodes_[p].child[side] = moved;
    if (moved != kNone) nodes_[moved].parent = p;
    nodes_[h].child[1 - side] = p;
    nodes_[p].parent = h;
    nodes_[h].parent = g;
    if (g == kNone) {
      root_ = h;
    } else {
      nodes_[g].child[nodes_[g].child[0] == p ? 0 : 1] = h;
    }
  }

  Below below_;
  ScratchVector<Node> nodes_;
  ScratchVector<Handle> free_;
  Handle root_ = kNone;
  Handle top_ = kNone;
  std::uint64_t seed_ = 0x9e3779b97f4a7c15ull;
};

}  // namespace exactgeo::mesh::internal
