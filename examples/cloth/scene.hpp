#pragma once

// The cloth example's scenes: one triangle mesh holding the cloth (its vertices and faces
// first) and the obstacles, in metres, with y up and the ground at y = 0.
//
//   block  (the default) a square sheet (1.2 m), an n x n grid of vertices, each quad
//          split into two triangles along alternating diagonals, held horizontally and
//          centred 2 cm above a block (a square post 0.2 m wide, 0.55 m high) standing on
//          a floor. It lands on the block, its sides drape around it, the hanging skirt
//          folds onto itself, and its corners reach the floor.
//   stack  a long ribbon, n x 10n vertices (0.4 m by 10 times that), standing on its end
//          2 cm above a floor, slanted and curved along its length (its centre line turns
//          by a sine of its arc length), so that it buckles as it lands and piles up in
//          folds on itself.
//   ball   several square sheets (1 m, n x n vertices each), stacked 3 cm apart above a
//          ball (a UV sphere, 0.25 m) that spins about the vertical axis through its
//          centre, 5 cm above a floor; the sheets drape over the ball and onto each other.
//
// Every sheet vertex has flat rest ("material") coordinates: the sheet unrolled, which
// the mesh model's rest lengths and the remesher's sizes are measured in.

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "exactgeo/ccd/mesh/mesh_ccd.hpp"

namespace exactgeo::cloth {

enum class SceneKind : std::uint8_t { block, stack, ball };

/// "block", "stack", "ball"; parse_scene is its inverse (nullopt for any other name).
std::string_view to_string(SceneKind kind) noexcept;
std::optional<SceneKind> parse_scene(std::string_view name) noexcept;

struct SceneOptions {
  SceneKind kind = SceneKind::block;
  /// Vertices along each side of a sheet (>= 2); the ribbon has this many across its
  /// width and 10 times as many along it.
  std::uint32_t resolution = 40;
  /// Amplitude (metres) of a seeded vertical perturbation of the sheet's vertices; 0: none.
  double jitter = 0.0;
  std::uint64_t seed = 1;
  /// ball: the number of sheets.
  std::uint32_t layers = 3;
};

/// The ball of the ball scene: its vertices are obstacle vertices [first, first + count)
/// (counted from the first obstacle vertex), on a sphere about `centre`, turned by
/// `angular_speed` radians per second about the vertical axis through it.
struct SpinningBall {
  std::array<double, 3> centre{};
  double radius = 0.0;
  double angular_speed = 0.0;
  std::size_t first = 0;
  std::size_t count = 0;
};

struct Scene {
  /// x, y, z of every vertex: the sheets' vertices first, row by row, then the
  /// obstacles'.
  std::vector<double> positions;
  std::vector<ccd::Triangle> faces;
  std::size_t cloth_vertices = 0;
  std::size_t cloth_faces = 0;  ///< the sheets' faces come first too
  std::uint32_t resolution = 0;
  double spacing = 0.0;  ///< rest distance between neighbouring sheet vertices
  /// Gap between the sheets and what is below them at the start (the block's top, the
  /// floor, the ball or the sheet below): a jitter must stay below it.
  double start_gap = 0.0;
  SceneKind kind = SceneKind::block;
  /// Rest coordinates of every sheet vertex (the sheet flat, metres).
  std::vector<std::array<double, 2>> material;
  std::optional<SpinningBall> ball;
};

Scene make_scene(const SceneOptions& options);

/// The obstacle's vertices (3 values each, from the first obstacle vertex on) with the ball,
/// if there is one, turned by `angle` radians from the scene's start; `rest` is the
/// obstacle's part of Scene::positions.
void place_obstacle(const Scene& scene, std::span<const double> rest, double angle,
                    std::span<double> out);

}  // namespace exactgeo::cloth
