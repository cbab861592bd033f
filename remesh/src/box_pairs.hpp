#pragma once

// The pairs of point groups whose closed boxes overlap, found by box trees (boxes/): a
// pass's swept regions against the surface's triangles, or against each other. The float
// boxes are rounded outward, so every pair whose exact boxes meet is found (and a few
// whose boxes only come within a float's rounding, which the exact tests then decide).

#include <algorithm>
#include <array>
#include <cmath>
#include <span>
#include <vector>

#include "exactgeo/boxes/box_tree.hpp"
#include "exactgeo/boxes/tree_pairs.hpp"
#include "exactgeo/remesh/swept_region.hpp"

namespace exactgeo::remesh::internal {

/// The boxes of `points` (finite), at rest, in one scale for all.
inline boxes::VertexBoxes point_boxes(std::span<const Point3> points) {
  double largest = 0.0;
  for (const Point3& p : points) {
    for (const double x : p)
      largest = std::max(largest, std::fabs(x));
  }
  const boxes::Scale scale(largest);
  std::vector<boxes::FloatBox> b(points.size());
  for (std::size_t i = 0; i < points.size(); ++i)
    b[i] = boxes::point_box(points[i], scale);
  return boxes::VertexBoxes::at_rest(std::move(b));
}

/// visit(i, j) for every group i of `a` and j of `b` (groups of indices into `points`)
/// whose boxes overlap, each pair once.
template <std::size_t NA, std::size_t NB, class Visit>
void overlapping_groups(std::span<const Point3> points,
                        std::span<const std::array<VertexIndex, NA>> a,
                        std::span<const std::array<VertexIndex, NB>> b, Visit&& visit) {
  if (a.empty() || b.empty()) return;
  const boxes::VertexBoxes at_rest = point_boxes(points);
  const boxes::BoxTree<NA> tree_a(a, at_rest);
  const boxes::BoxTree<NB> tree_b(b, at_rest);
  const boxes::Walk<NA, NB> walk{tree_a, tree_b, at_rest, boxes::SharedCorners::keep};
  std::vector<boxes::NodePair> stack;
  boxes::overlapping_pairs(
      walk, {0, 0}, stack,
      [&](const boxes::Packet<NA>& pa, std::size_t i, const boxes::Packet<NB>& pb, std::size_t j) {
        visit(pa.id[i], pb.id[j]);
      });
}

/// visit(i, j), i < j, for every two groups of `groups` whose boxes overlap.
template <std::size_t N, class Visit>
void overlapping_groups(std::span<const Point3> points,
                        std::span<const std::array<VertexIndex, N>> groups, Visit&& visit) {
  if (groups.empty()) return;
  const boxes::VertexBoxes at_rest = point_boxes(points);
  const boxes::BoxTree<N> tree(groups, at_rest);
  const boxes::Walk<N, N> walk{tree, tree, at_rest, boxes::SharedCorners::keep};
  std::vector<boxes::NodePair> stack;
  boxes::overlapping_pairs(
      walk, {0, 0}, stack,
      [&](const boxes::Packet<N>& pa, std::size_t i, const boxes::Packet<N>& pb, std::size_t j) {
        const std::size_t x = pa.id[i], y = pb.id[j];
        visit(std::min(x, y), std::max(x, y));
      });
}

/// Regions as groups of points for overlapping_groups: `points` starts with the surface's
/// vertices, and a region's new point (vertex kNoVertex) is appended after them.
struct RegionPoints {
  std::vector<Point3> points;
  std::vector<std::array<VertexIndex, 4>> groups;

  RegionPoints(std::span<const Point3> vertices,
               std::span<const std::array<RegionCorner, 4>> regions)
      : points(vertices.begin(), vertices.end()), groups(regions.size()) {
    for (std::size_t r = 0; r < regions.size(); ++r) {
      for (std::size_t k = 0; k < 4; ++k) {
        if (regions[r][k].vertex != kNoVertex) {
          groups[r][k] = regions[r][k].vertex;
        } else {
          groups[r][k] = static_cast<VertexIndex>(points.size());
          points.push_back(regions[r][k].point);
        }
      }
    }
  }
};

}  // namespace exactgeo::remesh::internal
