#pragma once

// What reading a mesh gives: the mesh, its format, and what was done to it on the way
// (the options that asked for it).

#include <cstddef>
#include <string>
#include <vector>

#include "exactgeo/mesh/file_numbering.hpp"
#include "exactgeo/mesh/mesh.hpp"

namespace exactgeo::mesh {

struct LoadOptions {
  /// Merge vertices with exactly equal coordinates (+0 and -0 count as equal) and
  /// re-index faces. Meshes stored as face soups (per-corner data) need it; STL files and
  /// the formats assimp reads are welded always.
  bool weld = false;
  /// Make a face of more than four corners that has no flat face to keep (its corners
  /// not in one plane, or its edges crossing or touching) the fan of triangles from its
  /// first corner, instead of refusing the file. (Flat polygons are always split, exactly.)
  bool split_polygons = false;
  /// The format, named like an extension in lower case ("obj", "off", "ply", "stl", or one
  /// that assimp reads: "glb", "3ds", ...). Empty: the file's extension decides.
  std::string format{};
};

struct LoadedMesh {
  Mesh mesh;
  /// "obj", "off", "ply ascii", "ply binary little endian", "ply binary big endian",
  /// "stl ascii", "stl binary", or "assimp " and the extension ("assimp glb").
  std::string format;
  bool coordinates_via_float = false;  ///< coordinates were rounded to 32-bit floats (assimp)
  std::size_t welded_vertices = 0;     ///< vertices removed by welding (weld, STL, assimp)
  /// Faces with more than four corners, split into triangles (flat ones exactly; others
  /// into fans, when LoadOptions::split_polygons asked for it, with a note).
  std::size_t split_polygons = 0;
  /// What the reader skipped, one message each, naming the file and line
  /// ("wuson.ply:3: skipped header line 'Created by ...': not a PLY keyword, and nothing
  /// the data's layout depends on"). Callers show them as warnings.
  std::vector<std::string> notes{};
  /// How the file numbers the mesh's vertices and faces, for messages: from 1 in OBJ,
  /// from 0 in OFF, PLY and STL (facets in file order, welded vertices in order of first
  /// appearance), and in exactgeo's Mesh.
  FileNumbering numbering{};
};

}  // namespace exactgeo::mesh
