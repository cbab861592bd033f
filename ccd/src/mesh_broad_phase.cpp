#include "exactgeo/ccd/internal/mesh_broad_phase.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>

#include "exactgeo/ccd/internal/tree_pairs.hpp"
#include "exactgeo/parallel/blocks.hpp"
#include "exactgeo/predicates/kernel/error_free.hpp"

namespace exactgeo::ccd::internal {

namespace {

constexpr std::size_t kVertexBlock = 1 << 14;  // vertices per job when making their boxes

/// Node pairs each tree walk is split into (tree_pairs.hpp): enough for threads to share
/// the work evenly, few enough that opening them costs nothing next to the walk.
constexpr std::size_t kWalkPairs = 256;

/// A refitted tree is rebuilt once looseness() exceeds this factor times its value when
/// the tree was built. A refitted tree is never wrong, only slower; this factor only
/// trades the cost of a build (a few refits' worth) against a slower walk.
constexpr double kRebuildLooseness = 1.5;

/// A digest of an exact displacement: equal vectors give equal digests (-0 and +0 are
/// made one first), never 0.
std::uint32_t motion_digest(const Vector3& d) noexcept {
  std::uint64_t h = 0;
  for (const double x : d)
    h = (h ^ std::bit_cast<std::uint64_t>(x + 0.0)) * 0x9E3779B97F4A7C15u;
  return static_cast<std::uint32_t>(h >> 32) | 1u;
}

/// Each vertex's swept box and displacement p_t1 - p_t0: whether every coordinate of the
/// displacement is exactly a double, and whether the vertex moves at all (the rounded
/// difference of two finite doubles is zero only when they are equal).
struct VertexMotion {
  VertexBoxes boxes;
  std::vector<Vector3> d;
  std::vector<std::uint8_t> exact;

  VertexMotion(const MeshFrames& frames, unsigned threads) {
    const std::size_t n = frames.positions_t0.size() / 3;
    boxes.box.resize(n);
    boxes.moving.resize(n);
    boxes.motion.resize(n);
    d.resize(n);
    exact.resize(n);
    const double* t0 = frames.positions_t0.data();
    const double* t1 = frames.positions_t1.data();
    const StepScale scale(
        std::max(largest_magnitude(frames.positions_t0), largest_magnitude(frames.positions_t1)));
    parallel::for_each_block((n + kVertexBlock - 1) / kVertexBlock, threads, [&](std::size_t b) {
      for (std::size_t v = b * kVertexBlock; v < std::min(n, (b + 1) * kVertexBlock); ++v) {
        boxes.box[v] = vertex_swept_box(t0, t1, v, scale);
        exact[v] = 1;
        for (std::size_t k = 0; k < 3; ++k) {
          const auto diff = exactgeo::kernel::two_diff(t1[3 * v + k], t0[3 * v + k]);
          d[v][k] = diff.head;
          if (diff.tail != 0.0 || !std::isfinite(diff.head)) exact[v] = 0;
        }
        boxes.moving[v] = d[v] != Vector3{0.0, 0.0, 0.0} ? 1 : 0;
        boxes.motion[v] = exact[v] != 0 ? motion_digest(d[v]) : 0;
      }
    });
  }

  /// True when all `vertices` move by one and the same vector (standing still included):
  /// their relative positions, hence all their distances, stay the same during the step.
  bool rigid(const std::array<VertexIndex, 4>& vertices) const noexcept {
    const VertexIndex first = vertices[0];
    if (exact[first] == 0) return false;
    for (const VertexIndex v : vertices) {
      if (exact[v] == 0 || d[v] != d[first]) return false;
    }
    return true;
  }
};

}  // namespace

MeshBroadPhase::MeshBroadPhase(std::size_t vertex_count, std::span<const Triangle> faces,
                               std::span<const Edge> edges)
    : faces_(faces), edges_(edges), vertices_(vertex_count) {
  for (std::size_t v = 0; v < vertex_count; ++v)
    vertices_[v] = {static_cast<VertexIndex>(v)};
}

bool MeshBroadPhase::fit_trees(const VertexBoxes& boxes, unsigned threads) {
  // One job per tree, the largest (edges) first: on two threads the edge tree takes as
  // long as the other two together.
  std::array<bool, 3> built{};
  const auto fit = [&]<std::size_t N>(BoxTree<N>& tree,
                                      std::span<const std::array<VertexIndex, N>> primitives) {
    if (built_) {
      tree.refit(boxes);
      if (tree.looseness() <= kRebuildLooseness * tree.built_looseness()) return false;
    }
    tree = BoxTree<N>(primitives, boxes);
    return true;
  };
  parallel::for_each_block(3, threads, [&](std::size_t k) {
    if (k == 0) built[0] = fit(edge_tree_, edges_);
    if (k == 1) built[1] = fit(face_tree_, faces_);
    if (k == 2)
      built[2] = fit(vertex_tree_, std::span<const std::array<VertexIndex, 1>>(vertices_));
  });
  built_ = true;
  return built[0] || built[1] || built[2];
}

MeshCandidates MeshBroadPhase::candidates(const MeshFrames& frames, unsigned threads) {
  MeshCandidates result;
  const VertexMotion motion(frames, threads);
  result.trees_rebuilt = fit_trees(motion.boxes, threads);

  // Both walks split into node pairs, vertex-face first; each pair's candidates in its
  // own list, joined in order, so the order does not depend on the thread count.
  const std::vector<NodePair> vertex_face =
      split_pairs(vertex_tree_, face_tree_, false, kWalkPairs);
  const std::vector<NodePair> edge_edge = split_pairs(edge_tree_, edge_tree_, true, kWalkPairs);
  struct Found {
    std::vector<VertexFacePair> vertex_face;
    std::vector<EdgeIndexPair> edge_edge;
  };
  std::vector<Found> found(vertex_face.size() + edge_edge.size());
  std::vector<NodePair> stack;  // each worker's copy of the lambda has its own
  parallel::for_each_block(found.size(), threads, [&, stack](std::size_t j) mutable {
    Found& out = found[j];
    if (j < vertex_face.size()) {
      overlapping_pairs(vertex_tree_, face_tree_, false, vertex_face[j], stack,
                        [&](const Packet<1>& v, std::size_t i, const Packet<3>& f, std::size_t k) {
                          const VertexIndex p = v.id[i];
                          const Triangle c = f.corners(k);
                          if (v.motion[i] != 0 && v.motion[i] == f.motion[k] &&
                              motion.rigid({p, c[0], c[1], c[2]}))
                            return;
                          out.vertex_face.push_back({p, f.id[k]});
                        });
      return;
    }
    overlapping_pairs(
        edge_tree_, edge_tree_, true, edge_edge[j - vertex_face.size()], stack,
        [&](const Packet<2>& a, std::size_t i, const Packet<2>& b, std::size_t k) {
          const Edge ea = a.corners(i), eb = b.corners(k);
          if (motion.rigid({ea[0], ea[1], eb[0], eb[1]})) return;
          out.edge_edge.push_back({std::min(a.id[i], b.id[k]), std::max(a.id[i], b.id[k])});
        });
  });
  // Joined in parallel: each list copied to its offset.
  std::vector<std::array<std::size_t, 2>> offset(found.size() + 1);
  for (std::size_t j = 0; j < found.size(); ++j)
    offset[j + 1] = {offset[j][0] + found[j].vertex_face.size(),
                     offset[j][1] + found[j].edge_edge.size()};
  result.vertex_face.resize(offset.back()[0]);
  result.edge_edge.resize(offset.back()[1]);
  parallel::for_each_block(found.size(), threads, [&](std::size_t j) {
    std::copy(found[j].vertex_face.begin(), found[j].vertex_face.end(),
              result.vertex_face.begin() + static_cast<std::ptrdiff_t>(offset[j][0]));
    std::copy(found[j].edge_edge.begin(), found[j].edge_edge.end(),
              result.edge_edge.begin() + static_cast<std::ptrdiff_t>(offset[j][1]));
  });
  return result;
}

}  // namespace exactgeo::ccd::internal
