#pragma once

// Object File Format (OFF), ASCII, read exactly. The header keyword is `OFF` with the
// usual ST/C/N prefixes (`COFF`, `NOFF`, `CNOFF`, `STOFF`, ...; optional, as in the
// format's definition), then the counts `nv nf [ne]` (on the header line or the next),
// then nv vertex lines (the first three numbers are x y z; further columns such as
// normals, colours or texture coordinates are ignored), then nf face lines
// `n i0 ... i(n-1)` with 0-based indices, optionally followed by a colour. `#` starts a
// comment anywhere; blank lines are skipped. `4OFF`, `nOFF` and binary OFF are refused.

#include <string>
#include <string_view>

#include "exactgeo/mesh/loaded_mesh.hpp"

namespace exactgeo::mesh {

/// Parses OFF text; `source` names it in errors ("<source>:<line>: ..."). Applies
/// options.split_polygons and options.weld (vertices welded before polygons are split). Throws
/// io::InputError.
LoadedMesh read_off(std::string_view text, const std::string& source, const LoadOptions& options);

}  // namespace exactgeo::mesh
