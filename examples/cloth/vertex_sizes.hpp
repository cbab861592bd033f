#pragma once

// The sizes the cloth remesher's vertices ask for (remesher.hpp, "Sizing"): each inner
// sheet edge asks, from the angle between its two triangles' normals, for edges of
// L * turn_per_edge / theta around it; a vertex takes the smallest ask of its edges,
// clamped to [min_length, max_length]. Worked out for every vertex, or patched after a
// pass for the vertices whose edges it changed (SheetEdgeTable::update names them), to the
// same numbers: a vertex's size is the least of its edges' asks, and an edge whose
// triangles kept their corners, which kept their places, asks for what it asked before.

#include <array>
#include <span>
#include <vector>

#include "exactgeo/remesh/operations.hpp"
#include "remesher.hpp"
#include "sheet_edges.hpp"

namespace exactgeo::cloth {

using Material = std::array<double, 2>;

/// The size every vertex of `s` asks for, from the sheet edges of `s` (`edges`) and the
/// vertices' material coordinates.
std::vector<double> vertex_sizes(const remesh::Surface& s, std::span<const Material> material,
                                 const std::vector<SheetEdge>& edges, const RemeshParameters& p);

/// `size`, vertex_sizes of a surface before some passes, made vertex_sizes of `s`, the
/// surface after them (`edges` its sheet edges, `material` its vertices', unchanged for the
/// vertices it had before): the vertices appended since and those in `touched` (the ends
/// of every edge whose triangles the passes changed) worked out again. False, with `size` not to be
/// used, when a vertex in `moved` (one the passes gave a new position) is still an end of a sheet
/// edge: the triangles around it turned, and the caller works every size out again. `marks` is
/// storage kept between calls.
bool update_vertex_sizes(std::vector<double>& size, const remesh::Surface& s,
                         std::span<const Material> material, const std::vector<SheetEdge>& edges,
                         const RemeshParameters& p, std::span<const remesh::VertexIndex> touched,
                         std::span<const remesh::VertexIndex> moved, std::vector<char>& marks);

}  // namespace exactgeo::cloth
