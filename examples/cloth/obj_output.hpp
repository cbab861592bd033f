#pragma once

// Wavefront OBJ output of one frame of the whole mesh: `v x y z` lines with every double
// written exactly (%.17g round-trips), then `f a b c` lines with 1-based indices, the
// cloth's first under `g cloth`, then the obstacles' under `g obstacle`. Every file is
// complete on its own, so a pair of them is an input of `exactgeo ccd-mesh`.

#include <filesystem>
#include <span>

#include "exactgeo/ccd/mesh/mesh_ccd.hpp"

namespace exactgeo::cloth {

/// Throws std::runtime_error naming the file when it cannot be written.
/// faces [0, cloth_faces) are the cloth's.
void write_obj(const std::filesystem::path& path, std::span<const double> positions,
               std::span<const ccd::Triangle> faces, std::size_t cloth_faces);

}  // namespace exactgeo::cloth
