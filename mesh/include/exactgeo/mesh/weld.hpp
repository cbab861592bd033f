#pragma once

// Welding: vertices at exactly the same position become one vertex.

#include <cstddef>
#include <optional>
#include <vector>

#include "exactgeo/mesh/mesh.hpp"

namespace exactgeo::mesh {

/// Merges vertices whose coordinates are exactly equal (+0 and -0 count as equal), keeping
/// each position's first occurrence (its coordinates and its place in the order of first
/// occurrences, so the result is deterministic), and re-indexes the faces. Vertices no face
/// uses are kept. Returns the number of vertices removed. Faces may become degenerate
/// (two corners at one position); they are kept for the mesh checks to report.
/// Precondition: every corner index is in range or kNoVertex.
std::size_t weld_vertices(Mesh& mesh);

/// The merge of weld_vertices on positions alone: `vertices` keeps each position's first
/// occurrence, and the result maps each old vertex to its new index; empty (and
/// `vertices` unchanged) when no two positions are equal.
std::vector<VertexIndex> merge_equal_positions(std::vector<Point3>& vertices);

/// A face soup's test: when the mesh has boundary edges only because its faces do not
/// share vertices, the number of vertices welding would merge to close it (every edge then
/// used by an even number of faces); nullopt when it is closed already, or stays open.
/// Classifying a soup as an open surface gives the same labels, far more slowly (every
/// face's edges are boundary), so callers name --weld instead.
std::optional<std::size_t> vertices_welding_closes(const Mesh& mesh);

}  // namespace exactgeo::mesh
