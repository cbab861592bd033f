#include "scene.hpp"

#include <array>
#include <random>

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
    }
  }
  for (std::uint32_t i = 0; i + 1 < n; ++i) {
    for (std::uint32_t j = 0; j + 1 < n; ++j) {
      const VertexIndex a = i * n + j;
      add_quad(scene, a, a + n, a + n + 1, a + 1, (i + j) % 2 == 0);
    }
  }
  scene.cloth_vertices = std::size_t{n} * n;
  scene.cloth_faces = scene.faces.size();
  scene.resolution = n;
  scene.spacing = h;
  scene.start_gap = kStartGap;
}

void add_floor(Scene& scene) {
  const std::uint32_t m = kFloorCells;
  const auto first = static_cast<VertexIndex>(scene.positions.size() / 3);
  const double h = 2.0 * kFloorHalfSize / m;
  for (std::uint32_t i = 0; i <= m; ++i) {
    for (std::uint32_t j = 0; j <= m; ++j) {
      add_vertex(scene, -kFloorHalfSize + j * h, 0.0, -kFloorHalfSize + i * h);
    }
  }
  for (std::uint32_t i = 0; i < m; ++i) {
    for (std::uint32_t j = 0; j < m; ++j) {
      const VertexIndex a = first + i * (m + 1) + j;
      add_quad(scene, a, a + m + 1, a + m + 2, a + 1, (i + j) % 2 == 0);
    }
  }
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

Scene make_scene(const SceneOptions& options) {
  Scene scene;
  add_sheet(scene, options);
  add_floor(scene);
  add_block(scene);
  return scene;
}

}  // namespace exactgeo::cloth
