#pragma once

// `exactgeo inside MESH [POINTS|-]`: classifies points against a closed mesh, one word
// per point in input order (the command-line contract, README.md). Points stream through in blocks,
// so memory stays flat however many there are.

#include <iosfwd>
#include <string>

#include "cli/exit_code.hpp"
#include "exactgeo/predicates/arithmetic.hpp"

namespace CLI {
class App;
}

namespace exactgeo::cli {

struct InsideCommandOptions {
  std::string mesh;
  std::string points = "-";  ///< a file, or "-" for standard input
  Arithmetic arithmetic = Arithmetic::exact;
  unsigned threads = 0;  ///< 0: one per hardware thread
  bool json = false;
  bool weld = false;
  bool split_polygons = false;
  bool allow_non_manifold = false;
  bool progress = false;  ///< a progress line on `err` (the binary sets it for a terminal)
};

/// Loads and checks the mesh, builds the search structure, then classifies `in`'s points
/// block by block. An input error stops the run with exit code 2: the mesh's errors
/// before anything is printed, a bad point line after the labels of the blocks before it
/// (each printed label is right; the message names the line).
ExitCode run_inside(const InsideCommandOptions& options, std::istream& in,
                    const std::string& points_source, std::ostream& out, std::ostream& err);

/// Registers the subcommand on `app`; `options` must outlive the parse.
CLI::App& add_inside_command(CLI::App& app, InsideCommandOptions& options);

}  // namespace exactgeo::cli
