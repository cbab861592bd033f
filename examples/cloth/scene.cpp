#include "scene.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <random>
#include <utility>

namespace exactgeo::cloth {

namespace {

// Sizes in metres. Tuned so that at resolution 12 the sheet hits the block within a few
// steps and itself (the hanging skirt folding) before step 50 at dt = 1/120 s.
constexpr double kSheetSize = 1.2;
constexpr double kStartGap = 0.02;  // sheet above the top of the block at the start
constexpr double kFloorHalfSize = 1.5;
constexpr std::uint32_t kFloorCells = 6;  // per side
constexpr double kBlockHalfWidth = 0.1;   // a square post, 0.2 wide
constexpr double kBlockHeight = 0.55;     // the sheet's corners reach the floor

using ccd::Triangle;
using ccd::VertexIndex;

VertexIndex add_vertex(Scene& scene, double x, double y, double z) {
  const auto index = static_cast<VertexIndex>(scene.positions.size() / 3);
  scene.positions.insert(scene.positions.end(), {x, y, z});
  return index;
}

/// Two triangles of the quad a b c d (counter-clockwise seen from its front), split along
/// a-c or b-d.
void add_quad(Scene& scene, VertexIndex a, VertexIndex b, VertexIndex c, VertexIndex d,
              bool split_ac) {
  if (split_ac) {
    scene.faces.push_back(Triangle{a, b, c});
    scene.faces.push_back(Triangle{a, c, d});
  } else {
    scene.faces.push_back(Triangle{a, b, d});
    scene.faces.push_back(Triangle{b, c, d});
  }
}

/// The material coordinates of the grid vertex in row i, column j at spacing h.
std::array<double, 2> grid_material(std::uint32_t i, std::uint32_t j, double h) {
  return {j * h, i * h};
}

/// The faces of a rows x columns grid of vertices numbered row by row from `first`.
void add_grid_faces(Scene& scene, VertexIndex first, std::uint32_t rows, std::uint32_t columns) {
  for (std::uint32_t i = 0; i + 1 < rows; ++i) {
    for (std::uint32_t j = 0; j + 1 < columns; ++j) {
      const VertexIndex a = first + i * columns + j;
      add_quad(scene, a, a + columns, a + columns + 1, a + 1, (i + j) % 2 == 0);
    }
  }
}

void add_sheet(Scene& scene, const SceneOptions& options) {
  const std::uint32_t n = options.resolution;
  const double h = kSheetSize / (n - 1);
  const double y = kBlockHeight + kStartGap;
  // Seeded perturbation: mt19937_64's sequence is fixed by the standard, and the mapping
  // to [0, 1) is ours (the standard distributions differ between libraries).
  std::mt19937_64 random(options.seed);
  for (std::uint32_t i = 0; i < n; ++i) {    // rows along z
    for (std::uint32_t j = 0; j < n; ++j) {  // columns along x
      double dy = 0.0;
      if (options.jitter > 0.0) {
        const double u = static_cast<double>(random() >> 11) * 0x1p-53;
        dy = options.jitter * (2.0 * u - 1.0);
      }
      add_vertex(scene, -0.5 * kSheetSize + j * h, y + dy, -0.5 * kSheetSize + i * h);
      scene.material.push_back(grid_material(i, j, h));
    }
  }
  add_grid_faces(scene, 0, n, n);
  scene.cloth_vertices = std::size_t{n} * n;
  scene.cloth_faces = scene.faces.size();
  scene.resolution = n;
  scene.spacing = h;
  scene.start_gap = kStartGap;
}

void add_floor(Scene& scene, double half_size) {
  const std::uint32_t m = kFloorCells;
  const auto first = static_cast<VertexIndex>(scene.positions.size() / 3);
  const double h = 2.0 * half_size / m;
  for (std::uint32_t i = 0; i <= m; ++i) {
    for (std::uint32_t j = 0; j <= m; ++j) {
      add_vertex(scene, -half_size + j * h, 0.0, -half_size + i * h);
    }
  }
  add_grid_faces(scene, first, m + 1, m + 1);
}

// The ribbon of the stack scene: 0.4 m wide, 10 times as long, its lower end 2 cm above
// the floor. Its centre line, in the x-y plane, leans from the vertical by
// kLean + kWave sin(2 pi s / kWavelength) at arc length s (integrated at the midpoint of
// each step of length h, so neighbouring rows are h apart, as in the material).
constexpr double kRibbonWidth = 0.4;
constexpr double kRibbonGap = 0.02;
constexpr double kLean = 0.25;       // radians
constexpr double kWave = 0.35;       // radians
constexpr double kWavelength = 0.8;  // metres of arc length
constexpr double kStackFloorHalfSize = 3.0;

void add_ribbon(Scene& scene, std::uint32_t n) {
  const std::uint32_t rows = 10 * n;
  const double h = kRibbonWidth / (n - 1);
  double x = 0.0;
  double y = kRibbonGap;
  for (std::uint32_t i = 0; i < rows; ++i) {
    for (std::uint32_t j = 0; j < n; ++j) {
      add_vertex(scene, x, y, -0.5 * kRibbonWidth + j * h);
      scene.material.push_back(grid_material(i, j, h));
    }
    const double s = (i + 0.5) * h;
    const double lean = kLean + kWave * std::sin(2.0 * std::numbers::pi * s / kWavelength);
    x += h * std::sin(lean);
    y += h * std::cos(lean);
  }
  add_grid_faces(scene, 0, rows, n);
  scene.cloth_vertices = scene.positions.size() / 3;
  scene.cloth_faces = scene.faces.size();
  scene.resolution = n;
  scene.spacing = h;
  scene.start_gap = kRibbonGap;
}

// The ball scene: a UV sphere (its poles on the vertical axis, so that spinning moves
// only the others) above the floor, and square sheets above it, each turned about the
// vertical axis a little more than the one below.
constexpr double kBallRadius = 0.25;
constexpr std::array<double, 3> kBallCentre{0.0, 0.30, 0.0};
constexpr double kBallSpin = 1.5;  // radians per second
constexpr std::uint32_t kBallSegments = 32;
constexpr std::uint32_t kBallRings = 16;
constexpr double kLayerSize = 1.0;
constexpr double kLayerGap = 0.03;
constexpr double kLayerTurn = 0.35;  // radians between consecutive sheets
constexpr double kBallFloorHalfSize = 2.0;

void add_layers(Scene& scene, std::uint32_t n, std::uint32_t layers) {
  const double h = kLayerSize / (n - 1);
  for (std::uint32_t k = 0; k < layers; ++k) {
    const auto first = static_cast<VertexIndex>(scene.positions.size() / 3);
    const double y = kBallCentre[1] + kBallRadius + kLayerGap * (k + 1);
    const double c = std::cos(kLayerTurn * k), s = std::sin(kLayerTurn * k);
    for (std::uint32_t i = 0; i < n; ++i) {
      for (std::uint32_t j = 0; j < n; ++j) {
        const double u = -0.5 * kLayerSize + j * h, w = -0.5 * kLayerSize + i * h;
        add_vertex(scene, c * u + s * w, y, -s * u + c * w);
        scene.material.push_back(grid_material(i, j, h));
      }
    }
    add_grid_faces(scene, first, n, n);
  }
  scene.cloth_vertices = scene.positions.size() / 3;
  scene.cloth_faces = scene.faces.size();
  scene.resolution = n;
  scene.spacing = h;
  scene.start_gap = kLayerGap;
}

void add_ball(Scene& scene) {
  const auto first = static_cast<VertexIndex>(scene.positions.size() / 3);
  const auto& c = kBallCentre;
  const double r = kBallRadius;
  const VertexIndex north = add_vertex(scene, c[0], c[1] + r, c[2]);
  for (std::uint32_t k = 1; k < kBallRings; ++k) {
    const double theta = std::numbers::pi * k / kBallRings;
    for (std::uint32_t j = 0; j < kBallSegments; ++j) {
      const double phi = 2.0 * std::numbers::pi * j / kBallSegments;
      add_vertex(scene, c[0] + r * std::sin(theta) * std::cos(phi), c[1] + r * std::cos(theta),
                 c[2] + r * std::sin(theta) * std::sin(phi));
    }
  }
  const VertexIndex south = add_vertex(scene, c[0], c[1] - r, c[2]);
  const auto ring = [&](std::uint32_t k, std::uint32_t j) {
    return north + 1 + (k - 1) * kBallSegments + j % kBallSegments;
  };
  const std::size_t first_face = scene.faces.size();
  for (std::uint32_t j = 0; j < kBallSegments; ++j) {
    scene.faces.push_back(Triangle{north, ring(1, j), ring(1, j + 1)});
    for (std::uint32_t k = 1; k + 1 < kBallRings; ++k) {
      add_quad(scene, ring(k, j), ring(k + 1, j), ring(k + 1, j + 1), ring(k, j + 1), true);
    }
    scene.faces.push_back(Triangle{south, ring(kBallRings - 1, j + 1), ring(kBallRings - 1, j)});
  }
  // Outward normals: turn any face whose normal points to the centre.
  const auto at = [&](VertexIndex v, int k) { return scene.positions[3 * v + k] - c[k]; };
  for (std::size_t f = first_face; f < scene.faces.size(); ++f) {
    Triangle& t = scene.faces[f];
    std::array<double, 3> e1{}, e2{}, centroid{};
    for (int k = 0; k < 3; ++k) {
      e1[k] = at(t[1], k) - at(t[0], k);
      e2[k] = at(t[2], k) - at(t[0], k);
      centroid[k] = at(t[0], k) + at(t[1], k) + at(t[2], k);
    }
    const double outward = (e1[1] * e2[2] - e1[2] * e2[1]) * centroid[0] +
                           (e1[2] * e2[0] - e1[0] * e2[2]) * centroid[1] +
                           (e1[0] * e2[1] - e1[1] * e2[0]) * centroid[2];
    if (outward < 0.0) std::swap(t[1], t[2]);
  }
  scene.ball = SpinningBall{kBallCentre, kBallRadius, kBallSpin, first - scene.cloth_vertices,
                            scene.positions.size() / 3 - first};
}

/// A closed box standing on the floor (its bottom face lies in the floor's plane; both are
/// static, so the mesh CCD never pairs them).
void add_block(Scene& scene) {
  std::array<VertexIndex, 8> v{};
  for (std::uint32_t k = 0; k < 8; ++k) {
    const double x = (k & 1U) != 0 ? kBlockHalfWidth : -kBlockHalfWidth;
    const double y = (k & 2U) != 0 ? kBlockHeight : 0.0;
    const double z = (k & 4U) != 0 ? kBlockHalfWidth : -kBlockHalfWidth;
    v[k] = add_vertex(scene, x, y, z);
  }
  add_quad(scene, v[2], v[6], v[7], v[3], true);  // top    (y = height)
  add_quad(scene, v[0], v[1], v[5], v[4], true);  // bottom (y = 0)
  add_quad(scene, v[0], v[4], v[6], v[2], true);  // -x
  add_quad(scene, v[1], v[3], v[7], v[5], true);  // +x
  add_quad(scene, v[0], v[2], v[3], v[1], true);  // -z
  add_quad(scene, v[4], v[5], v[7], v[6], true);  // +z
}

}  // namespace

std::string_view to_string(SceneKind kind) noexcept {
  switch (kind) {
    case SceneKind::block:
      return "block";
    case SceneKind::stack:
      return "stack";
    case SceneKind::ball:
      return "ball";
  }
  return "?";
}

std::optional<SceneKind> parse_scene(std::string_view name) noexcept {
  for (const SceneKind kind : {SceneKind::block, SceneKind::stack, SceneKind::ball}) {
    if (name == to_string(kind)) return kind;
  }
  return std::nullopt;
}

Scene make_scene(const SceneOptions& options) {
  Scene scene;
  scene.kind = options.kind;
  switch (options.kind) {
    case SceneKind::block:
      add_sheet(scene, options);
      add_floor(scene, kFloorHalfSize);
      add_block(scene);
      break;
    case SceneKind::stack:
      add_ribbon(scene, options.resolution);
      add_floor(scene, kStackFloorHalfSize);
      break;
    case SceneKind::ball:
      add_layers(scene, options.resolution, options.layers);
      add_floor(scene, kBallFloorHalfSize);
      add_ball(scene);
      break;
  }
  return scene;
}

void place_obstacle(const Scene& scene, std::span<const double> rest, double angle,
                    std::span<double> out) {
  std::copy(rest.begin(), rest.end(), out.begin());
  if (!scene.ball || angle == 0.0) return;
  const SpinningBall& b = *scene.ball;
  const double c = std::cos(angle), s = std::sin(angle);
  for (std::size_t v = b.first; v < b.first + b.count; ++v) {
    const double x = rest[3 * v] - b.centre[0], z = rest[3 * v + 2] - b.centre[2];
    out[3 * v] = b.centre[0] + (c * x + s * z);
    out[3 * v + 2] = b.centre[2] + (-s * x + c * z);
  }
}

}  // namespace exactgeo::cloth
