#pragma once

// `exactgeo inside MESH [POINTS|-]`: classifies points against a closed mesh, one word
// per point in input order (the command-line contract, README.md). Points stream through in blocks,
// so memory stays flat however many there are. They are text, raw float64 or .npy
// (io/point_reader.hpp).

#include <cstdint>
#include <iosfwd>
#include <optional>
#include <string>

#include "cli/exit_code.hpp"
#include "cli/inside_mesh.hpp"
#include "cli/progress_line.hpp"
#include "cli/slice_options.hpp"
#include "exactgeo/io/point_reader.hpp"

namespace CLI {
class App;
}

namespace exactgeo::cli {

/// The labels files of a batch: one word a line (NAME.labels.txt), or a NumPy int8 array
/// of the Python module's codes (NAME.labels.npy, as exactgeo.dask.classify_meshes writes).
enum class BatchLabelsFormat : std::uint8_t { text, npy };

struct InsideCommandOptions {
  /// The mesh, its checks, the method and the threads (cli/inside_mesh.hpp).
  InsideMeshOptions mesh;
  std::string points = "-";  ///< a file, or "-" for standard input
  /// nullopt: npy for a path ending in ".npy", text otherwise (io::default_point_format)
  std::optional<io::PointFormat> points_format;
  bool json = false;
  bool labels = false;  ///< with json: the labels too, in input order
  /// Print each point's winding number instead of its label ("boundary" on the surface).
  bool winding = false;
  bool progress_asked = false;  ///< --progress
  /// How progress shows on `err` (the binary sets it: progress_mode(progress_asked, terminal))
  ProgressMode progress = ProgressMode::off;
  /// --output-dir: `mesh.path` names a batch of meshes (a folder, a .txt list, or one
  /// mesh), `points` a points file or pattern, and each mesh's labels go to a file there
  /// (cli/inside_batch.hpp).
  std::string output_dir;
  /// --labels-format: how the batch writes each mesh's labels.
  BatchLabelsFormat labels_format = BatchLabelsFormat::text;
  /// --slice, --image, --resolution: a cross-section picture instead of labels; no points
  /// are read (cli/slice_command.hpp).
  SliceOptions slice;
};

/// Loads and checks the mesh, builds the search structure, then classifies `in`'s points
/// block by block. An input error stops the run with exit code 2: the mesh's errors
/// before anything is printed, a bad point after the labels of the blocks before it
/// (each printed label is right; the message names the line, or the binary point). The
/// JSON object is printed whole at the end, or not at all. With a slice plane it draws the
/// cross-section instead, with the same classifier, and reads nothing from `in`: an
/// unwritable image is reported before the pixels are classified, and the file appears
/// whole or not at all.
ExitCode run_inside(const InsideCommandOptions& options, std::istream& in,
                    const std::string& points_source, std::ostream& out, std::ostream& err);

/// Registers the subcommand on `app`; `options` must outlive the parse.
CLI::App& add_inside_command(CLI::App& app, InsideCommandOptions& options);

}  // namespace exactgeo::cli
