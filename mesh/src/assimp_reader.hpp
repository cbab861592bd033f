#pragma once

// Every mesh format exactgeo does not read itself (glTF/GLB, FBX, Collada, 3DS, RAW, ...),
// through assimp. assimp stores coordinates as 32-bit floats, so the result is marked
// coordinates_via_float. No assimp post-process runs (no triangulation): quads stay quads.

#include <string>

#include "exactgeo/mesh/load.hpp"

namespace exactgeo::mesh::internal {

/// Reads `path` with assimp, which picks the importer from the extension `extension`
/// (lower case, without the dot). The meshes of every scene node are merged into one
/// vertex array, each placed by its node's transformation (identity transformations copy
/// the float coordinates exactly; others are applied in double precision). Point and line
/// primitives are skipped. Vertices are always welded (assimp splits them per face for
/// triangle soups such as RAW, and at texture seams); welded_vertices reports it. Throws InputError
/// for an unsupported extension, a file assimp cannot read, a non-finite coordinate, or a scene
/// without faces.
LoadedMesh read_with_assimp(const std::string& path, const std::string& extension,
                            const LoadOptions& options);

/// The same for a file already in memory (standard input); `source` names it in errors.
/// Formats that refer to other files (glTF with a .bin, OBJ with materials) cannot find
/// them from here.
LoadedMesh read_with_assimp_from_memory(const std::string& bytes, const std::string& source,
                                        const std::string& extension, const LoadOptions& options);

}  // namespace exactgeo::mesh::internal
