#pragma once

// The broad phase of find_self_intersections: a box tree over the faces, traversed
// against itself, reports every pair of faces whose closed bounding boxes overlap. Any
// other pair is apart: a face lies in the box of its corners (a bilinear patch is a convex
// combination of them), so faces with disjoint boxes share no point. The boxes are the
// corners' exact coordinate minima and maxima, and touching boxes count as overlapping,
// so no pair is lost to rounding. Nothing here decides a pair; that is face_contact's.

#include <cstddef>
#include <utility>
#include <vector>

#include "exactgeo/mesh/mesh.hpp"

namespace exactgeo::mesh::face_contact_detail {

struct Aabb {
  Point3 lower;
  Point3 upper;
};

/// Closed boxes: touching counts as overlapping.
inline bool overlap(const Aabb& a, const Aabb& b) noexcept {
  for (std::size_t k = 0; k < 3; ++k)
    if (a.upper[k] < b.lower[k] || b.upper[k] < a.lower[k]) return false;
  return true;
}

Aabb box_of(const Mesh& mesh, const Face& face) noexcept;

/// A binary tree of boxes, split at the median of the box centres along their widest
/// axis; leaves hold at most kLeafSize items.
class BoxTree {
 public:
  explicit BoxTree(std::vector<std::size_t> items, const std::vector<Aabb>& boxes)
      : items_(std::move(items)), boxes_(boxes) {
    if (!items_.empty()) build(0, items_.size());
  }

  /// Calls report(i, j) once for every unordered pair of items with overlapping boxes.
  template <class Report>
  void overlapping_pairs(Report&& report) const {
    if (!nodes_.empty()) self_pairs(0, report);
  }

 private:
  static constexpr std::size_t kLeafSize = 4;

  struct Node {
    Aabb box;
    std::size_t begin = 0, end = 0;   ///< items_[begin, end)
    std::size_t left = 0, right = 0;  ///< children; 0 (the root's index) for a leaf
    bool leaf() const noexcept { return left == 0; }
  };

  std::size_t build(std::size_t begin, std::size_t end);

  /// Twice the centre (no rounding of the halving, and only used to split).
  Point3 centre(std::size_t item) const noexcept {
    const Aabb& b = boxes_[item];
    return {b.lower[0] + b.upper[0], b.lower[1] + b.upper[1], b.lower[2] + b.upper[2]};
  }

  template <class Report>
  void self_pairs(std::size_t n, Report& report) const {
    const Node& node = nodes_[n];
    if (node.leaf()) {
      for (std::size_t i = node.begin; i < node.end; ++i)
        for (std::size_t j = i + 1; j < node.end; ++j)
          if (overlap(boxes_[items_[i]], boxes_[items_[j]])) report(items_[i], items_[j]);
      return;
    }
    self_pairs(node.left, report);
    self_pairs(node.right, report);
    cross_pairs(node.left, node.right, report);
  }

  template <class Report>
  void cross_pairs(std::size_t a, std::size_t b, Report& report) const {
    const Node& x = nodes_[a];
    const Node& y = nodes_[b];
    if (!overlap(x.box, y.box)) return;
    if (x.leaf() && y.leaf()) {
      for (std::size_t i = x.begin; i < x.end; ++i)
        for (std::size_t j = y.begin; j < y.end; ++j)
          if (overlap(boxes_[items_[i]], boxes_[items_[j]])) report(items_[i], items_[j]);
      return;
    }
    // Descend into the node with more items (a leaf never splits).
    if (y.leaf() || (!x.leaf() && x.end - x.begin >= y.end - y.begin)) {
      cross_pairs(x.left, b, report);
      cross_pairs(x.right, b, report);
    } else {
      cross_pairs(a, y.left, report);
      cross_pairs(a, y.right, report);
    }
  }

  std::vector<std::size_t> items_;
  const std::vector<Aabb>& boxes_;
  std::vector<Node> nodes_;
};

}  // namespace exactgeo::mesh::face_contact_detail
