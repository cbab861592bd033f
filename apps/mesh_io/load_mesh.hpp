#pragma once

// Loading a mesh file into an exactgeo::inside::Mesh, keeping coordinates exact.
//
// OBJ, OFF and PLY (ASCII, binary little- and big-endian, float and double) are read by
// exactgeo's own readers: decimal numbers are converted with correct rounding
// (std::from_chars), binary values bit for bit, so a double-precision file keeps every
// bit. Every other format goes through assimp, whose coordinates are 32-bit floats:
// LoadedMesh::coordinates_via_float says so.
//
// Faces keep their corners: triangles stay triangles, quads stay quads (the bilinear
// patch through the four corners). A face with more than four corners is an error unless
// LoadOptions::split_polygons asks for a fan split from its first corner.

#include <cstddef>
#include <string>

#include "exactgeo/inside/mesh.hpp"

namespace exactgeo::cli {

struct LoadOptions {
  /// Merge vertices with exactly equal coordinates (+0 and -0 count as equal) and
  /// re-index faces. Meshes stored as face soups (STL, per-corner data) need it.
  bool weld = false;
  /// Split faces with more than four corners into a triangle fan from their first
  /// corner, instead of refusing them.
  bool split_polygons = false;
};

struct LoadedMesh {
  inside::Mesh mesh;
  /// "obj", "off", "ply ascii", "ply binary little endian", "ply binary big endian",
  /// or "assimp " and the extension ("assimp stl").
  std::string format;
  bool coordinates_via_float = false;  ///< coordinates were rounded to 32-bit floats (assimp)
  std::size_t welded_vertices = 0;     ///< vertices removed by welding (LoadOptions::weld, assimp)
  std::size_t split_polygons = 0;      ///< faces with more than four corners that were split
};

/// Reads `path`; the format comes from the extension (case-insensitive). Throws
/// InputError naming the file, and the line (text formats) or the face/vertex index
/// (binary formats), for anything malformed: unreadable file, bad or non-finite number,
/// index out of range, face with fewer than three or (without split_polygons) more
/// than four corners, truncated data, an empty mesh.
LoadedMesh load_mesh(const std::string& path, const LoadOptions& options = {});

}  // namespace exactgeo::cli
