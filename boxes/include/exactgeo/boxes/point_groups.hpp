#pragma once

// The pairs of groups of points (a triangle's corners, a swept region's) whose closed
// boxes overlap, found by box trees (box_tree.hpp, tree_pairs.hpp) at rest: one walk for
// a set of queries against a set of primitives, or within one set, not a search per
// query. The float boxes are rounded outward, so every pair whose exact boxes meet is
// found (and a few whose boxes only come within a float's rounding, which the caller's
// exact tests then decide).

#include <algorithm>
#include <array>
#include <cmath>
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
