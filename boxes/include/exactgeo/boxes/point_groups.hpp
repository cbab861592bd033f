#pragma once

// The pairs of groups of points (a triangle's corners, a swept region's) whose closed
// boxes overlap, found by box trees (box_tree.hpp, tree_pairs.hpp) at rest: one walk for
// a set of queries against a set of primitives, or within one set, not a search per
// query. The float boxes are rounded outward, so every pair whose exact boxes meet is
// found (and a few whose boxes only come within a float's rounding, which the caller's
// exact tests then decide).

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

#include "exactgeo/boxes/box_tree.hpp"
#include "exactgeo/boxes/tree_pairs.hpp"

namespace exactgeo::boxes {

/// The boxes of `points` (finite), at rest, in one scale for all.
inline VertexBoxes point_boxes(std::span<const Point3> points) {
  double largest = 0.0;
  for (const Point3& p : points) {
    for (const double x : p)
      largest = std::max(largest, std::fabs(x));
  }
  const Scale scale(largest);
  std::vector<FloatBox> b(points.size());
  for (std::size_t i = 0; i < points.size(); ++i)
    b[i] = point_box(points[i], scale);
  return VertexBoxes::at_rest(std::move(b));
}

/// visit(i, j) for every group i of `a` and j of `b` (groups of indices into `points`)
/// whose boxes overlap, each pair once.
template <std::size_t NA, std::size_t NB, class Visit>
void overlapping_groups(std::span<const Point3> points,
                        std::span<const std::array<VertexIndex, NA>> a,
                        std::span<const std::array<VertexIndex, NB>> b, Visit&& visit) {
  if (a.empty() || b.empty()) return;
  const VertexBoxes at_rest = point_boxes(points);
  const BoxTree<NA> tree_a(a, at_rest);
  const BoxTree<NB> tree_b(b, at_rest);
  const Walk<NA, NB> walk{tree_a, tree_b, at_rest, SharedCorners::keep};
  std::vector<NodePair> stack;
  overlapping_pairs(walk, {0, 0}, stack,
                    [&](const Packet<NA>& pa, std::size_t i, const Packet<NB>& pb, std::size_t j) {
                      visit(pa.id[i], pb.id[j]);
                    });
}

/// overlapping_groups(points, a, b, visit) for a few groups `a` against many `b`: a tree of
/// `a` only, and each group of `b` walked down it with its box, so that nothing is built
/// over `b` (a remesh pass checks tens of regions against every triangle of the surface).
/// The same float boxes and the same overlap test as the two trees' walk: the same pairs,
/// each once, in another order.
template <std::size_t NA, std::size_t NB, class Visit>
void overlapping_groups_by_scan(std::span<const Point3> points,
                                std::span<const std::array<VertexIndex, NA>> a,
                                std::span<const std::array<VertexIndex, NB>> b, Visit&& visit) {
  if (a.empty() || b.empty()) return;
  const VertexBoxes at_rest = point_boxes(points);
  const BoxTree<NA> tree_a(a, at_rest);
  const FloatBox root = tree_a.node(0).box;
  // Per point, the sides of the root's box its box lies strictly beyond: bit k below it
  // along axis k, bit 3 + k above it. A group's box (the union of its points') misses the
  // root's exactly when, along some axis, every point's box lies below it or every one
  // above it: when the points' bits have one in common. Most of `b` is far from every
  // group of `a`, and is passed over with no box made.
  std::vector<std::uint8_t> beyond(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const FloatBox& box = at_rest.box[i];
    unsigned bits = 0;
    for (int k = 0; k < 3; ++k) {
      bits |= box.hi[k] < root.lo[k] ? 1u << k : 0u;
      bits |= root.hi[k] < box.lo[k] ? 8u << k : 0u;
    }
    beyond[i] = static_cast<std::uint8_t>(bits);
  }
  std::vector<std::uint32_t> stack;
  for (std::size_t j = 0; j < b.size(); ++j) {
    unsigned common = beyond[b[j][0]];
    for (std::size_t c = 1; c < NB; ++c)
      common &= beyond[b[j][c]];
    if (common != 0) continue;  // the box misses the root's
    FloatBox box = at_rest.box[b[j][0]];
    for (std::size_t c = 1; c < NB; ++c)
      box = united(box, at_rest.box[b[j][c]]);
    stack.assign(1, 0);
    while (!stack.empty()) {
      const auto& node = tree_a.node(stack.back());
      const std::uint32_t index = stack.back();
      stack.pop_back();
      if (!overlap(box, node.box)) continue;
      if (!node.is_leaf()) {
        stack.push_back(node.first);  // the right child
        stack.push_back(index + 1);   // the left child
        continue;
      }
      const auto& leaf = tree_a.leaf(node);
      for (unsigned hits = overlap_mask(box, leaf); hits != 0; hits &= hits - 1)
        visit(static_cast<std::size_t>(leaf.id[static_cast<std::size_t>(std::countr_zero(hits))]),
              j);
    }
  }
}

/// visit(i, j), i < j, for every two groups of `groups` whose boxes overlap.
template <std::size_t N, class Visit>
void overlapping_groups(std::span<const Point3> points,
                        std::span<const std::array<VertexIndex, N>> groups, Visit&& visit) {
  if (groups.empty()) return;
  const VertexBoxes at_rest = point_boxes(points);
  const BoxTree<N> tree(groups, at_rest);
  const Walk<N, N> walk{tree, tree, at_rest, SharedCorners::keep};
  std::vector<NodePair> stack;
  overlapping_pairs(walk, {0, 0}, stack,
                    [&](const Packet<N>& pa, std::size_t i, const Packet<N>& pb, std::size_t j) {
                      const std::size_t x = pa.id[i], y = pb.id[j];
                      visit(std::min(x, y), std::max(x, y));
                    });
}

}  // namespace exactgeo::boxes
