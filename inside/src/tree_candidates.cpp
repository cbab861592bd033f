// The box tree as a candidate finder: one primitive per face (a triangle repeats its last
// corner), each vertex's float box in the frame, and a depth-first walk that tests node
// and face boxes in double (the argument is in internal/tree_candidates.hpp).

#include "exactgeo/inside/internal/tree_candidates.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <span>
#include <stdexcept>

#include "exactgeo/boxes/box_tree.hpp"
#include "exactgeo/inside/internal/float_frame.hpp"
#include "exactgeo/predicates/ray_directions.hpp"

namespace exactgeo::inside::internal {
namespace {

using Tree4 = boxes::BoxTree<4>;

/// The ray in the frame: its origin q, and the reciprocals r of its direction's
/// components, all positive.
struct FrameRay {
  std::array<double, 3> q;
  std::array<double, 3> r;
};

/// Whether the ray may meet the box [lo, hi] at some s >= 0: max(0, t_lo) <= min(t_hi)
/// with t_b = fl(fl(b - q) r) per axis (outward enough: tree_candidates.hpp).
inline bool may_meet(const FrameRay& ray, float lo0, float lo1, float lo2, float hi0, float hi1,
                     float hi2) noexcept {
  const double enter = std::max({0.0, (static_cast<double>(lo0) - ray.q[0]) * ray.r[0],
                                 (static_cast<double>(lo1) - ray.q[1]) * ray.r[1],
                                 (static_cast<double>(lo2) - ray.q[2]) * ray.r[2]});
  const double leave = std::min({(static_cast<double>(hi0) - ray.q[0]) * ray.r[0],
                                 (static_cast<double>(hi1) - ray.q[1]) * ray.r[1],
                                 (static_cast<double>(hi2) - ray.q[2]) * ray.r[2]});
  return enter <= leave;
}

inline bool may_meet(const FrameRay& ray, const boxes::FloatBox& b) noexcept {
  return may_meet(ray, b.lo[0], b.lo[1], b.lo[2], b.hi[0], b.hi[1], b.hi[2]);
}

/// Deeper than any box tree gets: its splits halve a run at most 30 times by Morton
/// bits and then by count (at most 32 times), and a depth-first walk keeps at most one
/// pending right child per level.
constexpr std::size_t kStackDepth = 128;

}  // namespace

struct TreeCandidates::Tree {
  FloatFrame frame;
  Tree4 tree;
};

TreeCandidates::TreeCandidates(const mesh::Mesh& mesh, const mesh::Box& box)
    : tree_(std::make_unique<Tree>()) {
  if (mesh.faces.size() > std::numeric_limits<FaceIndex>::max()) {
    throw std::runtime_error("box tree: too many faces");
  }
  Tree& t = *tree_;
  t.frame = FloatFrame(box.lower, box.upper);
  // Every vertex a face uses gets its box in the frame; the others are never read (and
  // may lie outside the frame's box, where the map is not meant to be used).
  std::vector<boxes::FloatBox> vertex_boxes(mesh.vertices.size(),
                                            boxes::FloatBox{{0, 0, 0}, {0, 0, 0}});
  std::vector<Tree4::Corners> primitives(mesh.faces.size());
  std::vector<std::uint8_t> used(mesh.vertices.size(), 0);
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    const mesh::Face& face = mesh.faces[f];
    for (std::size_t k = 0; k < 4; ++k) {
      const VertexIndex v = face.corners[std::min(k, face.size() - 1)];
      primitives[f][k] = v;
      used[v] = 1;
    }
  }
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    if (used[v] == 0) continue;
    for (int i = 0; i < 3; ++i) {
      vertex_boxes[v].lo[static_cast<std::size_t>(i)] = t.frame.lower_bound(i, mesh.vertices[v][i]);
      vertex_boxes[v].hi[static_cast<std::size_t>(i)] = t.frame.upper_bound(i, mesh.vertices[v][i]);
    }
  }
  t.tree = Tree4(std::span<const Tree4::Corners>(primitives),
                 boxes::VertexBoxes::at_rest(std::move(vertex_boxes)));
}

TreeCandidates::~TreeCandidates() = default;
TreeCandidates::TreeCandidates(TreeCandidates&&) noexcept = default;
TreeCandidates& TreeCandidates::operator=(TreeCandidates&&) noexcept = default;

void TreeCandidates::find(const Point3& origin, std::size_t direction_index,
                          std::vector<FaceIndex>& out) const {
  out.clear();
  const Tree& t = *tree_;
  if (t.tree.empty()) return;
  const Vector3 d = ray_direction(direction_index);
  FrameRay ray{};
  for (int i = 0; i < 3; ++i) {
    const auto k = static_cast<std::size_t>(i);
    ray.q[k] = t.frame.map(i, origin[i]);
    ray.r[k] = 1.0 / d[k];
  }
  std::array<std::uint32_t, kStackDepth> pending;
  std::size_t top = 0;
  std::uint32_t index = 0;
  for (;;) {
    const Tree4::Node& node = t.tree.node(index);
    if (may_meet(ray, node.box)) {
      if (!node.is_leaf()) {
        pending[top++] = node.first;  // the right child; the left one follows its parent
        ++index;
        continue;
      }
      const Tree4::Leaf& leaf = t.tree.leaf(node);
      for (std::size_t j = 0; j < node.count; ++j) {
        if (may_meet(ray, leaf.lo[0][j], leaf.lo[1][j], leaf.lo[2][j], leaf.hi[0][j], leaf.hi[1][j],
                     leaf.hi[2][j])) {
          out.push_back(leaf.id[j]);
        }
      }
    }
    if (top == 0) break;
    index = pending[--top];
  }
  // Each face is one primitive in one leaf: no repeats. Sorted, as every finder's list is.
  std::sort(out.begin(), out.end());
}

}  // namespace exactgeo::inside::internal
