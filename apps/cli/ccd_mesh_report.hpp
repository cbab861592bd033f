#pragma once

// `exactgeo ccd-mesh`'s reports of a step: the text report (the mesh, the method, the pair
// and candidate counts, the time of impact when asked for, the broad and narrow phases' times, then
// every colliding pair, one per line) and, with --json, one JSON object. Both end with the legend
// of the --mark file when there is one.

#include <cstddef>
#include <optional>
#include <string>

#include "cli/marked_ply.hpp"
#include "exactgeo/ccd/ccd.hpp"
#include "exactgeo/ccd/mesh/mesh_ccd.hpp"

namespace exactgeo::cli {

/// Appends the JSON object (and a newline) to `text`. `time_of_impact`: it was asked for,
/// so the key is there (null without a collision). `marks`: the legend of the file
/// written to `mark_path`. `peak_memory_bytes`: the process's peak resident memory
/// (null when unknown).
void write_ccd_mesh_json(std::string& text, ccd::Method method, bool time_of_impact,
                         const ccd::MeshCcdResult& result, const std::optional<MarkedMesh>& marks,
                         const std::string& mark_path,
                         std::optional<std::size_t> peak_memory_bytes);

/// Appends the text report of `mesh`'s step to `text`; the other arguments as for
/// write_ccd_mesh_json.
void write_ccd_mesh_report(std::string& text, ccd::Method method, bool time_of_impact,
                           const ccd::MeshCcd& mesh, const ccd::MeshCcdResult& result,
                           const std::optional<MarkedMesh>& marks, const std::string& mark_path);

}  // namespace exactgeo::cli
