#pragma once

// `exactgeo ccd-mesh`'s two frames: the same triangle mesh at the start and at the end of
// the step, each read exactly (OBJ, OFF or PLY; no welding, which could merge vertices in
// one frame and not in the other), checked to hold the same faces over the same vertex
// count, and put in the form ccd::MeshCcd takes.

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "exactgeo/ccd/mesh/mesh_ccd.hpp"
#include "exactgeo/mesh/loaded_mesh.hpp"
#include "exactgeo/mesh/mesh.hpp"

namespace exactgeo::cli {

/// Where the frames come from and what may be done to them on the way.
struct FrameFiles {
  std::array<std::string, 2> paths;  ///< frame 0 and frame 1; "-" for standard input
  std::string format;                ///< --format of both: empty for each file's extension
  bool split_polygons = false;       ///< faces of more than four corners into triangle fans
  bool split_quads = false;          ///< quads accepted, to be split along c0-c2
};

/// Both frames, loaded and checked: read with `files`' options, by exact readers, with
/// triangles only (or quads too with split_quads), the same vertex count and the same
/// faces. On failure, nullopt and the reason in `problem`, naming the file.
std::optional<std::array<mesh::LoadedMesh, 2>> load_frames(const FrameFiles& files,
                                                           std::string& problem);

}  // namespace exactgeo::cli
