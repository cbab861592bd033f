#pragma once

// `exactgeo inside MESH --slice AXIS=VALUE --image FILE.png`: the cross-section picture
// (cli/slice_image.hpp) of the mesh `inside` would classify against, and a report of it.

#include <iosfwd>

#include "cli/exit_code.hpp"
#include "cli/inside_mesh.hpp"
#include "cli/slice_options.hpp"

namespace exactgeo::cli {

/// Draws `slice` (precondition: slice.plane is set) of the mesh `mesh_options` names,
/// classified by its method on its threads, and reports it on `out` (one JSON object with
/// `json`). Reads no points. The image is reserved before any work (an unwritable path fails
/// at once) and appears whole or not at all.
ExitCode run_slice(const InsideMeshOptions& mesh_options, const SliceOptions& slice, bool json,
                   std::ostream& out, std::ostream& err);

}  // namespace exactgeo::cli
