#pragma once

// The plans of a pass's operations (split.cpp, flip.cpp, collapse.cpp), in a header of
// their own so that a PassWorkspace (pass_workspace.hpp) can keep their arrays.

#include <array>
#include <cstddef>

#include "exactgeo/predicates/sign.hpp"
#include "exactgeo/remesh/operations.hpp"
#include "operation_checks.hpp"

namespace exactgeo::remesh::internal {

/// A split: the edge's triangles, and once its geometry is checked whether it sweeps
/// regions (not when the new vertex lies exactly on the edge): one per triangle x y c of
/// the edge, the hull of a, b, c and the new vertex, with the other side's opposite corner
/// as its partner (none for an edge of one triangle). The regions are made when asked
/// for, not held: a pass plans thousands of splits.
struct SplitPlan {
  VertexIndex a = 0;
  VertexIndex b = 0;
  Point3 at{};
  EdgeTrianglesOfOne on_edge;
  bool sweeps = false;
  /// Per triangle x y c of the edge, orient3d(a, b, c, at), which split_geometry asks:
  /// region i's volume's sign, its corners in region()'s order.
  std::array<Sign, 2> volume{};

  std::size_t region_count() const noexcept { return sweeps ? on_edge.size() : 0; }
  /// Region i (below region_count()) on the surface the split was planned on.
  std::array<RegionCorner, 4> region(const Surface& s, std::size_t i) const {
    const VertexIndex c = third_corner(s.triangles[on_edge[i]], a, b);
    return {RegionCorner{a, s.vertices[a]}, RegionCorner{b, s.vertices[b]},
            RegionCorner{c, s.vertices[c]}, RegionCorner{kNoVertex, at}};
  }
  VertexIndex partner(const Surface& s, std::size_t i) const {
    return on_edge.size() == 2 ? third_corner(s.triangles[on_edge[1 - i]], a, b) : kNoVertex;
  }
};

/// A flip that passed its topology checks: its triangles and their replacements; the
/// region it sweeps (a, b, c, d) is made when asked for.
struct FlipPlan {
  VertexIndex a = 0;
  VertexIndex b = 0;
  std::size_t t1 = 0;  ///< walks a -> b
  std::size_t t2 = 0;  ///< walks b -> a
  Triangle new1{};     ///< c a d
  Triangle new2{};     ///< d b c

  std::array<VertexIndex, 4> corners() const noexcept { return {a, b, new1[0], new1[2]}; }
  std::array<RegionCorner, 4> region(const Surface& s) const {
    const std::array<VertexIndex, 4> v = corners();
    return {RegionCorner{v[0], s.vertices[v[0]]}, RegionCorner{v[1], s.vertices[v[1]]},
            RegionCorner{v[2], s.vertices[v[2]]}, RegionCorner{v[3], s.vertices[v[3]]}};
  }
};

/// A collapse that passed its topology checks.
struct CollapsePlan {
  VertexIndex a = 0;
  VertexIndex b = 0;
  Point3 to{};
  EdgeTrianglesOfOne on_edge;  ///< the edge's triangles, removed
};

}  // namespace exactgeo::remesh::internal
