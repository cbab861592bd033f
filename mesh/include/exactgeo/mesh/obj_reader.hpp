#pragma once

// Wavefront OBJ, read exactly: `v x y z [w]` (w must be 1; `v x y z r g b` vertex colours
// are accepted and ignored) and `f`/`fo` faces whose corners are `i`, `i/t`, `i//n` or
// `i/t/n`, with 1-based or negative (relative) indices. Only the position index is used,
// so texture and normal seams never split vertices. Every other statement (vt, vn, vp, o,
// g, s, usemtl, mtllib, l, p, free-form geometry, ...) is ignored, as are comments and
// blank lines; CRLF line ends are fine.

#include <string>
#include <string_view>

#include "exactgeo/mesh/loaded_mesh.hpp"

namespace exactgeo::mesh {

/// Parses OBJ text; `source` names it in errors ("<source>:<line>: ..."). Applies
/// options.split_polygons and options.weld (vertices welded before polygons are split). Throws
/// io::InputError.
LoadedMesh read_obj(std::string_view text, const std::string& source, const LoadOptions& options);

}  // namespace exactgeo::mesh
