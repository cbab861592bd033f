#pragma once

// `exactgeo ccd-mesh FRAME0 FRAME1`: every colliding vertex-face and edge-edge pair of a
// triangle mesh over one time step, from two files holding the same mesh at the start and
// at the end of the step (the command-line contract, README.md). exactgeo/ccd/mesh/mesh_ccd.hpp
// does the work; the frames are read and checked in cli/ccd_mesh_frames.hpp, the reports
// written in cli/ccd_mesh_report.hpp.

#include <iosfwd>
#include <optional>
#include <string>

#include "cli/exit_code.hpp"
#include "exactgeo/ccd/ccd.hpp"

namespace CLI {
class App;
}

namespace exactgeo::cli {

struct CcdMeshOptions {
  std::string frame0;  ///< positions at the start of the step
  std::string frame1;  ///< positions at the end; the same vertices and faces
  ccd::Method method = ccd::Method::exact;
  bool time_of_impact = false;                ///< also bracket the earliest time of impact
  double time_of_impact_width = 1e-6;         ///< the widest bracket accepted
  std::optional<std::string> min_separation;  ///< --min-separation as given (the run checks it)
  unsigned threads = 0;                       ///< 0: one per hardware thread
  bool split_polygons = false;
  std::string format;  ///< --format of both frames: empty for each file's extension
  /// Split each quad (c0, c1, c2, c3) along its diagonal c0-c2 into (c0, c1, c2) and
  /// (c0, c2, c3), in place in the face order, instead of refusing quads.
  bool split_quads = false;
  bool json = false;
  std::string mark;  ///< --mark: frame 0 as a PLY file with the collisions coloured; empty for none
};

/// Loads both frames exactly (OBJ, OFF or PLY, no welding) and checks that they hold the
/// same triangles (or quads, with split_quads) over the same vertex count, then runs one step and
/// reports on `out`. Collisions or not, ExitCode::success; any usage or input error prints nothing
/// on `out`, the reason (naming the file) on `err`, and returns ExitCode::input_error.
ExitCode run_ccd_mesh(const CcdMeshOptions& options, std::ostream& out, std::ostream& err);

/// Registers the subcommand on `app`; `options` must outlive the parse.
CLI::App& add_ccd_mesh_command(CLI::App& app, CcdMeshOptions& options);

}  // namespace exactgeo::cli
