#pragma once

// The cloth remesher's table of the sheets' edges: every edge of the triangles that have no
// fixed corner (the obstacles' have), with its one or two triangles, ordered by its ends.
// Built from a surface, or patched after a pass of operations from what the pass reports
// it changed (remesh::TriangleChanges) into the table a build of the surface after the
// pass gives, entry for entry: only the edges of the changed triangles are worked out
// again, and the others' triangle indices renumbered past the removed ones.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "exactgeo/remesh/operations.hpp"

namespace exactgeo::cloth {

/// A sheet edge with its triangles: `left` walks a -> b, `right` (if any) is the other.
/// `left` is the one of smaller index.
struct SheetEdge {
  remesh::VertexIndex a = 0;
  remesh::VertexIndex b = 0;
  std::size_t left = 0;
  std::optional<std::size_t> right;
  bool operator==(const SheetEdge&) const = default;
};

class SheetEdgeTable {
 public:
  /// Every edge of the sheets' triangles with its triangles (edges of more than two, which
  /// the sheets never have, are left out), ordered by their ends (the smaller first).
  explicit SheetEdgeTable(const remesh::Surface& s);

  const std::vector<SheetEdge>& edges() const noexcept { return edges_; }

  /// The table of `after`, the surface this table's was when a pass changed it as
  /// `changes` tells: patched where the pass changed a triangle, or built again when a
  /// patch cannot tell (an edge of more than two sheet triangles, which the table leaves
  /// out, was or would be among those changed). Equal to SheetEdgeTable(after).edges()
  /// either way. `touched` gets the ends of every edge whose triangles changed, before
  /// the pass or after it (the vertices whose edges may ask for other sizes), or, when the
  /// table was built again, nothing: the return value is false then.
  bool update(const remesh::Surface& after, const remesh::TriangleChanges& changes,
              std::vector<remesh::VertexIndex>& touched);

  /// The table of the same surface with its vertices and triangles numbered anew: vertex v
  /// as vertex[v], triangle t as triangle[t]. Precondition: both maps increase over the
  /// table's vertices and triangles (those of the sheets: a mesh written back with the
  /// sheets' vertices and faces first, each in their order), so that the entries keep
  /// their order and each its direction and its triangles' order.
  void renumber(std::span<const remesh::VertexIndex> vertex, std::span<const std::size_t> triangle);

 private:
  void build(const remesh::Surface& s);

  std::vector<SheetEdge> edges_;
  /// An edge of more than two sheet triangles was left out: its triangles are not known
  /// to a patch.
  bool crowded_ = false;

  // update()'s storage, kept from one patch to the next. An edge is named by one number,
  // its smaller end times 2^32 plus its larger end (ordered as the table is).
  struct Side {
    std::uint64_t edge;
    std::size_t triangle;  ///< after the pass
  };
  std::vector<std::uint64_t> old_keys_;  ///< the changed triangles' edges before the pass
  std::vector<std::uint64_t> keys_;      ///< their edges before and after, sorted, once each
  std::vector<Side> sides_;              ///< the changed triangles' sides after the pass
  std::vector<std::size_t> after_;       ///< per triangle before the pass: its index after
  std::vector<char> changed_;            ///< per triangle before the pass: removed or rewritten
  std::vector<SheetEdge> next_;          ///< the patched table, swapped in
};

}  // namespace exactgeo::cloth
