#pragma once

// The cloth remesher's memory of its flip candidates from one flip pass to the next of the
// same remesh. Whether a sheet edge ab is a flip candidate (flip_pass, remesher.cpp) reads
// its two triangles' corners (a, b, the third corners c and d), the material coordinates
// of a, b, c and d and their world positions (the quality guard). A remesh's flip passes
// run one after another at its end: none moves a vertex or changes its material, none
// removes or appends a triangle; each gives new corners to the two triangles of every
// flip it makes, and reports them (remesh::TriangleChanges::rewritten). So an edge whose
// two triangles the last flip pass did not rewrite has the same triangles, with the same
// corners, as in that pass (a triangle gains or loses an edge only when it is rewritten),
// and is a candidate now exactly when it was one then.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "exactgeo/remesh/operations.hpp"
#include "sheet_edges.hpp"
#include "unsuited_edges.hpp"

namespace exactgeo::cloth {

/// The last flip pass's candidates (by key, UnsuitedEdges::key, ascending as the pass met
/// them in the sheet edge table), the next pass's list as it is made, and which triangles
/// the last pass rewrote.
class FlipCandidates {
 public:
  /// Starts a pass on a surface of `triangles` triangles. `last`: what the last flip pass
  /// of this remesh changed (it changed the surface: a remesh runs another flip pass only
  /// then), or none for a remesh's first flip pass, whose candidates are all asked. A
  /// report that removed or appended triangles (a pass of another kind) is not read.
  void start_pass(const remesh::TriangleChanges* last, std::size_t triangles) {
    last_.swap(next_);
    next_.clear();
    at_ = 0;
    known_ = last != nullptr && last->removed.empty() && last->triangles_before == triangles;
    if (!known_) return;
    rewritten_.assign(triangles, 0);
    for (const remesh::TriangleChanges::Was& r : last->rewritten)
      rewritten_[r.triangle] = 1;
  }
  /// Whether edge e (an inner edge: two triangles) with key `key` is a candidate, when the
  /// last pass's answer stands (neither of its triangles rewritten), or nullopt: ask it.
  /// Asked in ascending order of key within a pass (the table's order), so the last list
  /// is walked once.
  std::optional<bool> known(const SheetEdge& e, std::uint64_t key) noexcept {
    if (!known_ || !e.right || rewritten_[e.left] != 0 || rewritten_[*e.right] != 0)
      return std::nullopt;
    while (at_ < last_.size() && last_[at_] < key)
      ++at_;
    return at_ < last_.size() && last_[at_] == key;
  }
  /// Edge `key` (ascending within a pass) is a candidate in this pass.
  void add(std::uint64_t key) { next_.push_back(key); }

 private:
  std::vector<std::uint64_t> last_, next_;
  std::size_t at_ = 0;
  bool known_ = false;
  std::vector<char> rewritten_;  ///< per triangle: the last pass gave it new corners
};

}  // namespace exactgeo::cloth
