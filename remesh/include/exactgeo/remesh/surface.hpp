#pragma once

// The surface that collision-safe operations change: a triangle surface (the libraries'
// shared picture of one, exactgeo/surface/triangle_surface.hpp), possibly of several
// components, some of whose vertices may be fixed (static obstacles, never moved, removed
// or re-connected by an operation). Operations keep it intersection free: each is applied
// only when the motion it stands for meets nothing (operations.hpp).

#include <cstddef>
#include <vector>

#include "exactgeo/predicates/point.hpp"
#include "exactgeo/surface/triangle_surface.hpp"

namespace exactgeo::remesh {

using exactgeo::Edge;         // surface/triangle_surface.hpp
using exactgeo::edge_of;      // ...
using exactgeo::kNoVertex;    // predicates/point.hpp
using exactgeo::third_corner;  // surface/triangle_surface.hpp
using exactgeo::Triangle;     // ...
using exactgeo::VertexIndex;  // predicates/point.hpp
using exactgeo::walks;        // surface/triangle_surface.hpp

/// A triangle surface and which of its vertices are fixed. Written like the surface it is:
/// Surface{vertices, triangles} or Surface{vertices, triangles, fixed}.
struct Surface : TriangleSurface {
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

}  // namespace exactgeo::remesh
