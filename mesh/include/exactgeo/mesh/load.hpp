#pragma once

// Loading a mesh file into an exactgeo::Mesh, keeping coordinates exact.
//
// OBJ, OFF, PLY (ASCII, binary little- and big-endian, float and double) and STL (ASCII
// and binary) are read by exactgeo's own readers: decimal numbers are converted with
// correct rounding (std::from_chars), binary values bit for bit, so a double-precision
// file keeps every bit. STL, a triangle soup, is always welded (LoadedMesh::welded_vertices).
// Every other format goes through assimp, whose coordinates are 32-bit floats:
// LoadedMesh::coordinates_via_float says so.
//
// Faces keep their corners: triangles stay triangles, quads stay quads (the bilinear
// patch through the four corners). A face with more than four corners is split into
// triangles, exactly: a planar one into triangles that cover exactly it, a non-planar one
// over its projection onto a coordinate plane (with a note); one whose edges cross is an
// error unless LoadOptions::split_polygons makes it a fan from its first corner.
// LoadedMesh::numbering keeps the file's face numbers for messages.

#include <string>

#include "exactgeo/io/input_error.hpp"
#include "exactgeo/mesh/loaded_mesh.hpp"

namespace exactgeo::mesh {

/// Reads `path`, or standard input when `path` is "-". The format is options.format when
/// given, else the file's extension (case-insensitive); standard input and a file without
/// an extension need options.format. Throws
/// io::InputError naming the file, and the line (text formats) or the face/vertex index
/// (binary formats), for anything malformed: unreadable file, bad or non-finite number,
/// index out of range, face with fewer than three corners or (without split_polygons)
/// more than four whose edges cross, truncated data, an empty mesh, an unknown format.
LoadedMesh load_mesh(const std::string& path, const LoadOptions& options = {});

/// The name a path stands for in messages: "standard input" for "-", else the path.
std::string mesh_source_name(const std::string& path);

}  // namespace exactgeo::mesh
