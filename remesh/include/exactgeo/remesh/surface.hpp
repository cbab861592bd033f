#pragma once

// The surface that collision-safe operations change: a triangle mesh, possibly of several
// components, some of whose vertices may be fixed (static obstacles, never moved, removed
// or re-connected by an operation). Operations keep it intersection free: each is applied
// only when the motion it stands for meets nothing (operations.hpp).

#include <array>
#include <cstddef>
#include <optional>
#include <span>
#include <vector>

#include "exactgeo/predicates/point.hpp"

namespace exactgeo::remesh {

using exactgeo::kNoVertex;    // predicates/point.hpp
using exactgeo::VertexIndex;  // predicates/point.hpp
using Triangle = std::array<VertexIndex, 3>;
/// An edge with its smaller vertex first.
using Edge = std::array<VertexIndex, 2>;

inline Edge edge_of(VertexIndex a, VertexIndex b) noexcept {
  return a < b ? Edge{a, b} : Edge{b, a};
}

struct Surface {
  std::vector<Point3> vertices;
  std::vector<Triangle> triangles;
  /// One flag per vertex (or empty: none fixed). A triangle with a fixed corner belongs
  /// to an obstacle: it is never flipped, split or collapsed.
  std::vector<bool> fixed{};

  bool is_fixed(VertexIndex v) const noexcept { return !fixed.empty() && fixed[v]; }

  /// The triangles that have both a and b as corners, in triangle order.
  std::vector<std::size_t> triangles_on_edge(VertexIndex a, VertexIndex b) const;
  /// The triangles that have v as a corner, in triangle order.
  std::vector<std::size_t> triangles_around(VertexIndex v) const;
  /// The unique edges of the triangles, sorted.
  std::vector<Edge> edges() const;
};

/// A triangle's corner other than a and b. Precondition: a and b are corners of t.
VertexIndex third_corner(const Triangle& t, VertexIndex a, VertexIndex b) noexcept;

/// Whether the triangle is a, b, c in this cyclic order (a walks to b).
bool walks(const Triangle& t, VertexIndex a, VertexIndex b) noexcept;

/// All three points on one line (or at one point), exactly: a triangle of zero area.
bool zero_area(const Point3& p, const Point3& q, const Point3& r) noexcept;

}  // namespace exactgeo::remesh
