#pragma once

// The cloth remesher's memory of the collapse candidates whose shape suited neither way,
// from one collapse pass to the next of the same remesh. A collapse's shape check
// (collapse_suits, remesher.cpp) reads, for gone's removal into kept: the corners of the
// triangles around gone, the material coordinates, sizes and world positions of those
// corners (kept is one), and whether the edge has one triangle or two (also read from the
// triangles around gone). A pass of collapses keeps every vertex's material and index; it
// changes triangles, which it reports, and positions (TriangleChanges::moved), and the
// sizes patched after it may change. So a vertex v is settled when no changed triangle has
// it as a corner (before the pass or after) and no vertex of its closed ring moved or has
// another size: the triangles around it are the same corners, and everything the check of
// a collapse of v into a neighbour reads is as it was. An edge whose ends are both settled
// and whose collapse suited neither way in the last pass suits neither way now.

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "exactgeo/remesh/operations.hpp"

namespace exactgeo::cloth {

/// Marks into `unsettled` (1: may answer otherwise; one byte per vertex of `after`) the
/// vertices that are not settled after a pass of collapses that left `after` and reported
/// `changes`, the sizes having been `sizes_before` before it and `sizes_after` now (a
/// vertex beyond `sizes_before` counts as changed). `around(v)`: the triangles (indices
/// into `after`) around v in `after`. A vertex of the closed ring of a moved or resized
/// vertex y is a corner of a triangle around y in `after` unless a triangle it shares
/// with y changed, which marks it anyway.
template <class Around>
void mark_unsettled(const remesh::Surface& after, const remesh::TriangleChanges& changes,
                    std::span<const double> sizes_before, std::span<const double> sizes_after,
                    const Around& around, std::vector<char>& unsettled) {
  unsettled.assign(after.vertices.size(), 0);
  const auto mark_corners = [&](const remesh::Triangle& t) {
    for (const remesh::VertexIndex c : t)
      unsettled[c] = 1;
  };
  for (const remesh::TriangleChanges::Was& r : changes.removed)
    mark_corners(r.corners);
  for (const remesh::TriangleChanges::Was& r : changes.rewritten) {
    mark_corners(r.corners);
    mark_corners(after.triangles[changes.index_after(r.triangle)]);
  }
  for (std::size_t t = changes.first_added(); t < after.triangles.size(); ++t)
    mark_corners(after.triangles[t]);
  const auto mark_ring = [&](remesh::VertexIndex y) {
    unsettled[y] = 1;
    for (const std::size_t t : around(y))
      mark_corners(after.triangles[t]);
  };
  for (const remesh::VertexIndex y : changes.moved)
    mark_ring(y);
  for (std::size_t v = 0; v < sizes_after.size() && v < after.vertices.size(); ++v) {
    if (v >= sizes_before.size() || !(sizes_before[v] == sizes_after[v]))
      mark_ring(static_cast<remesh::VertexIndex>(v));
  }
}

/// The sheet edges (by key: smaller end times 2^32 plus larger end) that were collapse
/// candidates in the last pass and suited neither way, in ascending order, as the pass
/// met them in the sheet edge table; and the next pass's list as it is made.
class UnsuitedEdges {
 public:
  static std::uint64_t key(remesh::VertexIndex a, remesh::VertexIndex b) noexcept {
    const std::uint64_t lo = a < b ? a : b, hi = a < b ? b : a;
    return lo << 32 | hi;
  }
  /// Forgets the last pass's list (a remesh's first collapse pass has none).
  void clear() noexcept {
    last_.clear();
    next_.clear();
    at_ = 0;
  }
  /// Starts a pass: the list being made becomes the last pass's.
  void start_pass() {
    last_.swap(next_);
    next_.clear();
    at_ = 0;
  }
  /// Whether edge `k` is in the last pass's list. Asked in ascending order of k within a
  /// pass (the table's order), so the list is walked once.
  bool was_unsuited(std::uint64_t k) noexcept {
    while (at_ < last_.size() && last_[at_] < k)
      ++at_;
    return at_ < last_.size() && last_[at_] == k;
  }
  /// Edge `k` (ascending within a pass) suits neither way in this pass.
  void add(std::uint64_t k) { next_.push_back(k); }

 private:
  std::vector<std::uint64_t> last_, next_;
  std::size_t at_ = 0;
};

}  // namespace exactgeo::cloth
