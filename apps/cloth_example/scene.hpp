#pragma once

// The cloth example's scene: one triangle mesh holding a square cloth sheet (vertices and
// faces first) and a static obstacle (a floor with a raised block, a square post, standing
// on it), in metres, with y up.
//
// The sheet (1.2 m) is an n x n grid of vertices, each quad split into two triangles along
// alternating diagonals, held horizontally and centred 2 cm above the block (0.2 m wide,
// 0.55 m high). It lands on the block, its sides fall and drape around it, the hanging
// skirt folds onto itself, and its corners reach the floor.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "exactgeo/ccd/mesh/mesh_ccd.hpp"

namespace exactgeo::cloth {

struct SceneOptions {
  /// Vertices along each side of the sheet (>= 2).
  std::uint32_t resolution = 40;
  /// Amplitude (metres) of a seeded vertical perturbation of the sheet's vertices; 0: none.
  double jitter = 0.0;
  std::uint64_t seed = 1;
};

struct Scene {
  /// x, y, z of every vertex: the sheet's resolution^2 vertices first, row by row, then
  /// the obstacle's.
  std::vector<double> positions;
  std::vector<ccd::Triangle> faces;
  std::size_t cloth_vertices = 0;
  std::size_t cloth_faces = 0;  ///< the sheet's faces come first too
  std::uint32_t resolution = 0;
  double spacing = 0.0;  ///< rest distance between neighbouring sheet vertices
  /// Gap between the sheet's start height and the top of the block: a jitter must stay
  /// below it so that the start is collision free.
  double start_gap = 0.0;
};

Scene make_scene(const SceneOptions& options);

}  // namespace exactgeo::cloth
