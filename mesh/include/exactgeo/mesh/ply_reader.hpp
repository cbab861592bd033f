#pragma once

// PLY 1.0, read exactly: ASCII (decimal numbers correctly rounded), binary little- and
// big-endian (values bit for bit: float64 stays exact, float32 and integers are widened
// exactly). The mesh comes from element `vertex` (properties x, y, z of any scalar type;
// other properties are skipped) and element `face` (a list property `vertex_indices` or
// `vertex_index` with integer count and index types; other properties are skipped). Any
// other element is skipped, list properties included.

#include <string>
#include <string_view>

#include "exactgeo/mesh/loaded_mesh.hpp"

namespace exactgeo::mesh {

/// Parses PLY data; `source` names it in errors: "<source>:<line>: ..." for the header
/// and ASCII data, "<source>: <element> <index>: ..." for binary data. Every count in the
/// header is checked against the bytes present before anything is allocated for it.
/// Applies options.split_polygons and options.weld (vertices welded before polygons are
/// split). Throws io::InputError.
LoadedMesh read_ply(std::string_view data, const std::string& source, const LoadOptions& options);

}  // namespace exactgeo::mesh
