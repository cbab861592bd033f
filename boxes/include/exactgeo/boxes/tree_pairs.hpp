#pragma once

// The pairs of overlapping primitive boxes between two box trees, or within one, found by
// walking both trees at once.
//
// A pair of nodes whose boxes are disjoint, or below which every vertex moves by one and
// the same exact vector (standing still included, box_tree.hpp), holds no pair and is
// dropped whole. Otherwise the larger node (by half-perimeter) is opened, until two
// leaves meet and their primitives are compared, eight at a time (packet.hpp). Within one
// tree, a node paired with itself opens into its two children each with itself, plus the
// children with each other, so every unordered pair is met once. Against one query per
// primitive this drops whole groups of pairs at once and walks each tree path once per
// group instead of once per primitive.
//
// Which overlapping pairs count is the walk's rule: for collisions, pairs that share a
// corner (adjacent primitives) and pairs that both stand still are skipped; for
// intersections at rest, every overlapping pair counts.
//
// For threads, the walk is first opened breadth first into a fixed number of node pairs
// (split_pairs); each is then walked on its own. The split does not depend on the thread
// count, so neither does the order in which pairs come out.

#include <bit>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "exactgeo/boxes/box_tree.hpp"

namespace exactgeo::boxes {

/// Node a of the first tree with node b of the second; with one tree, a == b stands for
/// the pairs within node a.
struct NodePair {
  std::uint32_t a;
  std::uint32_t b;
};

/// Whether primitives that share a corner are paired.
enum class SharedCorners : std::uint8_t {
  skip,  ///< collisions: adjacent primitives touch by construction
  keep,  ///< intersections: adjacent faces may still cross
};

/// The two trees of a walk (the same tree twice for a walk of a tree with itself), the
/// vertices' boxes they were fitted to, and the rule for adjacent primitives.
template <std::size_t NA, std::size_t NB>
struct Walk {
  const BoxTree<NA>& a;
  const BoxTree<NB>& b;
  const VertexBoxes& vertices;
  SharedCorners shared = SharedCorners::skip;

  /// Whether p stands for the pairs within one node of a tree walked with itself.
  bool within(NodePair p) const noexcept {
    if constexpr (NA == NB) {
      return &a == &b && p.a == p.b;
    } else {
      return false;
    }
  }
};

/// Whether node pair p can hold a pair of primitives at all: with one tree and a == b,
/// unless everything below moves together; else when the boxes overlap, unless both
/// sides move together.
template <std::size_t NA, std::size_t NB>
bool holds_pairs(const Walk<NA, NB>& w, NodePair p) {
  const auto& a = w.a.node(p.a);
  if (w.within(p)) return a.together == kNoVertex;
  const auto& b = w.b.node(p.b);
  if (!overlap(a.box, b.box)) return false;
  return a.together == kNoVertex || b.together == kNoVertex ||
         !w.vertices.move_together(a.together, b.together);
}

/// For a pair that holds_pairs: true when both nodes are leaves, whose primitives are then
/// to be compared; otherwise calls push(q) for each smaller pair q that holds pairs (the
/// children are tested here, next to their parent in memory) and returns false.
template <std::size_t NA, std::size_t NB, class Push>
bool open_pair(const Walk<NA, NB>& w, NodePair p, Push&& push) {
  const auto& a = w.a.node(p.a);
  const auto& b = w.b.node(p.b);
  const auto push_live = [&](NodePair q) {
    if (holds_pairs(w, q)) push(q);
  };
  if (a.is_leaf() && b.is_leaf()) return true;
  if (w.within(p)) {
    const std::uint32_t left = p.a + 1, right = a.first;
    push_live({left, left});
    push_live({right, right});
    push_live({left, right});
  } else if (!a.is_leaf() && (b.is_leaf() || a.extent >= b.extent)) {
    push_live({p.a + 1, p.b});
    push_live({a.first, p.b});
  } else {
    push_live({p.a, p.b + 1});
    push_live({p.a, b.first});
  }
  return false;
}

/// The root pair opened breadth first until there are at least `wanted` pairs or nothing
/// left to open; pairs that hold nothing are dropped.
template <std::size_t NA, std::size_t NB>
std::vector<NodePair> split_pairs(const Walk<NA, NB>& w, std::size_t wanted) {
  std::vector<NodePair> pairs;
  if (w.a.empty() || w.b.empty() || !holds_pairs(w, {0, 0})) return pairs;
  pairs.push_back({0, 0});
  bool opened_any = true;
  while (pairs.size() < wanted && opened_any) {
    opened_any = false;
    std::vector<NodePair> next;
    next.reserve(3 * pairs.size());
    for (const NodePair p : pairs) {
      if (open_pair(w, p, [&](NodePair q) { next.push_back(q); }))
        next.push_back(p);
      else
        opened_any = true;
    }
    pairs = std::move(next);
  }
  return pairs;
}

/// Calls visit(leaf_a, i, leaf_b, j) for every pair of primitives below `start` (a pair
/// that holds_pairs; lane i of a leaf of the first tree, lane j of one of the second) whose
/// boxes overlap, of which at least one may move, and which share no corner unless the
/// walk keeps those; with one tree, each unordered pair once.
template <std::size_t NA, std::size_t NB, class Visit>
void overlapping_pairs(const Walk<NA, NB>& w, NodePair start, std::vector<NodePair>& stack,
                       Visit&& visit) {
  stack.assign(1, start);
  while (!stack.empty()) {
    const NodePair p = stack.back();
    stack.pop_back();
    if (!open_pair(w, p, [&](NodePair q) { stack.push_back(q); })) continue;
    const auto& la = w.a.leaf(w.a.node(p.a));
    const auto& b = w.b.node(p.b);
    const auto& lb = w.b.leaf(b);
    const bool within = w.within(p);
    // Only the lanes of a whose box meets b's leaf box can meet one of b's boxes.
    for (unsigned lanes = overlap_mask(b.box, la); lanes != 0; lanes &= lanes - 1) {
      const auto i = static_cast<std::size_t>(std::countr_zero(lanes));
      unsigned hits = overlap_mask(la.box(i), lb);
      if (w.shared == SharedCorners::skip) hits &= ~shared_corner_mask(la.corners(i), lb);
      if ((la.moving >> i & 1) == 0) hits &= lb.moving;
      if (within) hits &= ~((2u << i) - 1);  // each pair once: lanes after i only
      for (; hits != 0; hits &= hits - 1)
        visit(la, i, lb, static_cast<std::size_t>(std::countr_zero(hits)));
    }
  }
}

}  // namespace exactgeo::boxes
