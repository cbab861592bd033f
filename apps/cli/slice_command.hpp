#pragma once

// `exactgeo inside MESH --slice AXIS=VALUE --image FILE.png`: the cross-section picture
// (cli/slice_image.hpp) of the mesh `inside` would classify against, and a report of it.

#include <iosfwd>

#include "cli/exit_code.hpp"
#include "cli/inside_command.hpp"

namespace exactgeo::cli {

/// Precondition: options.slice.plane is set. Reads no points. The image is reserved
/// before any work (an unwritable path fails at once) and appears whole or not at all.
ExitCode run_slice(const InsideCommandOptions& options, std::ostream& out, std::ostream& err);

}  // namespace exactgeo::cli
