#pragma once

// `exactgeo info MESH`: what a mesh file holds and whether `exactgeo inside` can use it
// (counts, bounding box, closed/manifold/oriented, exact degenerate faces and non-planar
// quads, components, pairs of faces that intersect; the command-line contract,
// README.md), and with --mark the same findings as a coloured mesh.

#include <iosfwd>
#include <string>

#include "cli/exit_code.hpp"
#include "exactgeo/mesh/load.hpp"

namespace CLI {
class App;
}

namespace exactgeo::cli {

struct InfoOptions {
  std::string mesh;  ///< the mesh file
  mesh::LoadOptions load;
  bool json = false;
  std::string mark;  ///< --mark: a PLY file with the findings as face colours; empty for none
};

/// Loads and checks the mesh, then reports on `out`. An open, non-manifold or otherwise
/// unusable mesh is a fact to report (ExitCode::success); only a file that cannot be loaded
/// is an error (nothing on `out`, the reason on `err`, ExitCode::input_error).
ExitCode run_info(const InfoOptions& options, std::ostream& out, std::ostream& err);

/// Registers the subcommand on `app`; `options` must outlive the parse.
CLI::App& add_info_command(CLI::App& app, InfoOptions& options);

}  // namespace exactgeo::cli
