#pragma once

// Turning a file's polygons into exactgeo faces: triangles and quads are kept as they are,
// larger polygons are refused or (on request) split into a triangle fan.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>

#include "exactgeo/mesh/loaded_mesh.hpp"
#include "exactgeo/mesh/mesh.hpp"

namespace exactgeo::mesh::internal {

/// The most vertices a mesh can index: every index is below kNoVertex.
inline constexpr std::size_t kMaxVertices = kNoVertex;

/// Appends the polygon with these corners (indices already checked to be in range) to
/// out.mesh: one face for 3 or 4 corners; for more, a fan of triangles from the first
/// corner when `split_polygons` (counted in out.split_polygons). Returns nullopt, or the
/// reason the polygon was refused (fewer than 3 corners, or more than 4 without
/// `split_polygons`) for the caller to report with its place.
std::optional<std::string> add_polygon(std::span<const VertexIndex> corners, bool split_polygons,
                                       LoadedMesh& out);

/// nullopt when a 0-based vertex index (OFF, PLY) names one of `vertex_count` vertices,
/// else the reason it does not, for the caller to report with its place.
std::optional<std::string> zero_based_index_problem(std::int64_t index, std::uint64_t vertex_count);

/// Throws InputError("<source>: ... no faces") when the mesh has no face.
void require_faces(const LoadedMesh& loaded, const std::string& source);

}  // namespace exactgeo::mesh::internal
