#pragma once

// A pass's swept regions as groups of points for the box queries of boxes/point_groups.hpp
// and boxes/exact_grid.hpp, and the pairs such a query finds, bucketed.

#include <array>
#include <cstddef>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include "exactgeo/boxes/exact_grid.hpp"
#include "exactgeo/boxes/point_groups.hpp"
#include "exactgeo/predicates/sign.hpp"
#include "exactgeo/remesh/swept_region.hpp"

namespace exactgeo::remesh::internal {

/// A pass's regions as groups of points of their own: region r's corners are points 4r to
/// 4r + 3, a vertex corner at its vertex's place in the surface, a new point (a split's,
/// vertex kNoVertex) where it is; for the box query of the regions against the surface's
/// triangles (the same exact boxes as the corners' on the surface, and no copy of the
/// surface's vertices to append the new points).
struct RegionPoints {
  std::vector<Point3> points;
  std::vector<std::array<VertexIndex, 4>> groups;

  /// These points and groups in place of the ones held, in the same storage.
  void assign(std::span<const Point3> vertices,
              std::span<const std::array<RegionCorner, 4>> regions) {
    points.resize(4 * regions.size());
    groups.resize(regions.size());
    for (std::size_t r = 0; r < regions.size(); ++r) {
      for (std::size_t k = 0; k < 4; ++k) {
        const RegionCorner& c = regions[r][k];
        points[4 * r + k] = c.vertex != kNoVertex ? vertices[c.vertex] : c.point;
        groups[r][k] = static_cast<VertexIndex>(4 * r + k);
      }
    }
  }
};

/// A pass's regions as groups of their corners alone: each surface vertex among them
/// once (in the order first met), then the new points; for a query of the regions against
/// each other, which needs no box of the surface's other vertices (a pass of a few
/// hundred regions on a surface of thousands of vertices). The boxes are in the scale of
/// these points, not of the whole surface: float boxes rounded outward in either scale
/// hold the exact ones, so every pair whose exact boxes meet is found in both, and the
/// pairs found in one only are apart (their exact boxes are), which the caller's exact
/// test decides.
struct CornerPoints {
  std::vector<Point3> points;
  std::vector<std::array<VertexIndex, 4>> groups;
  std::vector<VertexIndex> slot;  ///< per surface vertex: its place in `points`, or kNoVertex

  /// `vertex_count`: the surface's (every corner's vertex is below it).
  void assign(std::size_t vertex_count, std::span<const std::array<RegionCorner, 4>> regions) {
    slot.assign(vertex_count, kNoVertex);
    points.clear();
    groups.resize(regions.size());
    for (std::size_t r = 0; r < regions.size(); ++r) {
      for (std::size_t k = 0; k < 4; ++k) {
        const RegionCorner& c = regions[r][k];
        if (c.vertex == kNoVertex) continue;
        if (slot[c.vertex] == kNoVertex) {
          slot[c.vertex] = static_cast<VertexIndex>(points.size());
          points.push_back(c.point);  // a vertex's corners are all at its place
        }
        groups[r][k] = slot[c.vertex];
      }
    }
    for (std::size_t r = 0; r < regions.size(); ++r) {
      for (std::size_t k = 0; k < 4; ++k) {
        if (regions[r][k].vertex != kNoVertex) continue;
        groups[r][k] = static_cast<VertexIndex>(points.size());
        points.push_back(regions[r][k].point);
      }
    }
  }
};

/// visit(g, t) for every group g of `groups` (a collapse pass's moving triangles) and
/// triangle t of `triangles` whose boxes overlap (boxes/point_groups.hpp); the split and
/// flip passes' regions go through the exact grid instead (first_in_regions). While the
/// groups are fewer than a quarter of the triangles, the triangles are scanned down a tree
/// of the groups (no tree over the whole surface, built again each pass: the groups cluster
/// around the collapses); otherwise the two trees are walked. The same pairs either way
/// (the same float boxes), in another order. The quarter is a choice of cost only
/// (docs/remesh.md, "What a remesh costs").
template <std::size_t N, class Visit>
void groups_near_triangles(std::span<const Point3> points,
                           std::span<const std::array<VertexIndex, N>> groups,
                           std::span<const Triangle> triangles, Visit&& visit) {
  constexpr std::size_t kFewer = 4;  // triangles per group above which the scan is taken
  if (kFewer * groups.size() < triangles.size()) {
    boxes::overlapping_groups_by_scan<N, 3>(points, groups, triangles, visit);
  } else {
    boxes::overlapping_groups<N, 3>(points, groups, triangles, visit);
  }
}

/// Pairs (x, y) that a box query found, bucketed by x: the ys of x are of(x), in the order
/// found (a counting sort into one array, no vector per x).
class Buckets {
 public:
  Buckets() = default;
  Buckets(std::size_t count, std::span<const std::pair<std::size_t, std::size_t>> pairs) {
    assign(count, pairs);
  }

  /// These pairs in place of the ones held, in the same storage.
  void assign(std::size_t count, std::span<const std::pair<std::size_t, std::size_t>> pairs) {
    first_.assign(count + 1, 0);
    items_.resize(pairs.size());
    for (const auto& [x, y] : pairs)
      ++first_[x + 1];
    for (std::size_t x = 0; x < count; ++x)
      first_[x + 1] += first_[x];
    next_.assign(first_.begin(), first_.end() - 1);
    for (const auto& [x, y] : pairs)
      items_[next_[x]++] = y;
  }

  std::span<const std::size_t> of(std::size_t x) const noexcept {
    return std::span(items_).subspan(first_[x], first_[x + 1] - first_[x]);
  }

 private:
  std::vector<std::size_t> first_;
  std::vector<std::size_t> items_;
  std::vector<std::size_t> next_;  ///< assign's fill cursor per x, kept for its storage
};

/// What first_in_regions builds to find the triangles near each region, kept by a caller
/// that checks many passes (PassWorkspace): every member is filled anew before it is read.
struct RegionQuery {
  RegionPoints boxed;
  boxes::GridScratch grid;
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  Buckets near;
};

/// first_in_regions (swept_region.hpp) in `query`'s storage. `volumes`: empty, or per
/// region the sign of orient3d of its four corners in order, when the caller has asked it
/// already (a split's, split_geometry), so that the region need not ask it again.
std::vector<std::optional<Blocker>> first_in_regions(
    const Surface& surface, std::span<const std::array<RegionCorner, 4>> regions,
    std::span<const VertexIndex> partners, RegionQuery& query, std::span<const Sign> volumes = {});

}  // namespace exactgeo::remesh::internal
