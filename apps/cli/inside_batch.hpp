#pragma once

// `exactgeo inside MESHES POINTS --output-dir DIR`: a data set's meshes, one labels file
// each. MESHES is a folder (its mesh files, in every subfolder), a .txt list of mesh paths,
// or one mesh; POINTS is one points file for every mesh, or a pattern naming each mesh's
// own ("{mesh}.points.npy", {mesh} standing for the mesh's path without its extension).
// Each mesh is classified as `exactgeo inside MESH POINTS` would, its labels written to
// DIR/<name>.labels.txt (or .labels.npy) whole or not at all; a mesh that fails is reported on
// `err` and the others go on.

#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "cli/exit_code.hpp"
#include "cli/inside_command.hpp"

namespace exactgeo::cli {

/// The file extensions a folder's files are taken as meshes by (lower case, with the dot).
extern const std::vector<std::string> kBatchMeshExtensions;

/// One mesh of a batch and the labels file it gets.
struct BatchMesh {
  std::string mesh;
  std::string labels;
};

/// The meshes `given` names and their labels files under `output_dir`: a folder's mesh
/// files (walked recursively, sorted; labels under their path relative to the folder), a
/// ".txt" file's lines (paths relative to the list's folder; blank lines and '#' comments
/// skipped), or `given` itself. nullopt, with `error` set, for an unreadable list or
/// folder, no mesh at all, or two meshes whose labels files would be one.
std::optional<std::vector<BatchMesh>> batch_meshes(const std::string& given,
                                                   const std::string& output_dir,
                                                   BatchLabelsFormat format, std::string& error);

/// The points file of `mesh` for the pattern `points`: "{mesh}" replaced by the mesh's
/// path without its extension (a pattern without it names one file for every mesh).
std::string batch_points(const std::string& points, const std::string& mesh);

/// Runs the batch: once every mesh has succeeded, one line per mesh on `out` ("MESH: N
/// points, ... -> LABELS", or with options.json one JSON object per line); messages on
/// `err`. Exit code 2, and nothing on `out`, when the meshes could not be listed (nothing
/// is run) or any mesh failed (after all have run; the others' files are written).
ExitCode run_inside_batch(const InsideCommandOptions& options, std::ostream& out,
                          std::ostream& err);

}  // namespace exactgeo::cli
