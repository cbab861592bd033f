#include "exactgeo/ccd/mesh/internal/broad_phase.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>

#include "exactgeo/boxes/tree_pairs.hpp"
#include "exactgeo/ccd/mesh/internal/swept_box.hpp"
#include "exactgeo/parallel/blocks.hpp"
#include "exactgeo/predicates/kernel/error_free.hpp"

namespace exactgeo::ccd::internal {

using boxes::BoxTree;
using boxes::Packet;
using boxes::VertexBoxes;

namespace {

constexpr std::size_t kVertexBlock = 1 << 14;  // vertices per job when making their boxes

/// Node pairs each tree walk is split into (tree_pairs.hpp): enough for threads to share
/// the work evenly, few enough that opening them costs nothing next to the walk.
constexpr std::size_t kWalkPairs = 256;

/// A refitted tree is rebuilt once its centre_spread() (box_tree.hpp) exceeds this factor
/// times its value when the tree was built. A refitted tree is never wrong, only slower;
/// this factor only trades the cost of a build (a few refits) against a slower walk.
constexpr double kRebuildSpread = 1.5;

/// A digest of an exact displacement, head + tail: equal vectors give equal digests (-0
/// and +0 are made one first), never 0.
std::uint32_t motion_digest(const Vector3& head, const Vector3& tail) noexcept {
  std::uint64_t h = 0;
  for (const Vector3* part : {&head, &tail}) {
    for (const double x : *part)
      h = (h ^ std::bit_cast<std::uint64_t>(x + 0.0)) * 0x9E3779B97F4A7C15u;
  }
  return static_cast<std::uint32_t>(h >> 32) | 1u;
}

}  // namespace

// The displacement is TwoDiff's rounded value and the rest, unique for each exact
// difference, so that rigid motion by a vector that is not a double is recognised too; a
// vertex moves at all when the rounded difference is not zero (the rounded difference of
// two finite doubles is zero only when they are equal).
void sweep_vertices(const StepPositions& positions, double largest, double min_separation,
                    unsigned threads, VertexBoxes& s) {
  const std::size_t n = positions.t0.size() / 3;
  s.box.resize(n);
  s.displacement.resize(n);
  s.displacement_tail.resize(n);
  s.moving.resize(n);
  s.motion.resize(n);
  const double* t0 = positions.t0.data();
  const double* t1 = positions.t1.data();
  const boxes::Scale scale(largest);
  // Each box grows by half the separation δ: two primitives within δ of each other have
  // boxes within δ on every axis (a distance bounds each coordinate difference), so grown
  // boxes overlap. In the step's scale S (two products by powers of two) that needs
  // 2 margin >= S(b) - S(a) for the bounds a <= b of two boxes with b - a <= δ. S is exact
  // unless a product underflows, where each rounds by at most half a subnormal's ulp,
  // 2^-1075: S(b) - S(a) <= (b - a) 2^-e + 4 2^-1075, and fl(S(δ) / 2) >= δ 2^-e / 2 -
  // 2 2^-1075 (two products, then the halving). Two steps up add at least 2^-1074 each
  // (a step is one ulp), so margin >= δ 2^-e / 2 + 2 2^-1075 and 2 margin >= δ 2^-e +
  // 4 2^-1075: enough.
  // vertex_swept_box then rounds the grown bounds outward to float.
  double margin = 0.0;
  if (min_separation > 0.0) {
    margin = std::nextafter(std::nextafter(scale(min_separation) * 0.5, INFINITY), INFINITY);
  }
  parallel::for_each_block((n + kVertexBlock - 1) / kVertexBlock, threads, [&](std::size_t b) {
    for (std::size_t v = b * kVertexBlock; v < std::min(n, (b + 1) * kVertexBlock); ++v) {
      s.box[v] = vertex_swept_box(t0, t1, v, scale, margin);
      Vector3& d = s.displacement[v];
      Vector3& rest = s.displacement_tail[v];
      bool exact = true;
      for (std::size_t k = 0; k < 3; ++k) {
        const auto diff = exactgeo::kernel::two_diff(t1[3 * v + k], t0[3 * v + k]);
        d[k] = diff.head;
        rest[k] = diff.tail;
        exact = exact && std::isfinite(diff.head);  // TwoDiff is exact unless it overflows
      }
      s.moving[v] = d != Vector3{0.0, 0.0, 0.0} ? 1 : 0;
      s.motion[v] = exact ? motion_digest(d, rest) : 0;
    }
  });
}

namespace {

/// True when two primitives (lane i of leaf a, lane k of leaf b) move by one and the same
/// vector, standing still included: their relative positions, hence all their distances,
/// stay the same during the step. Unequal digests rule it out without reading vertices.
template <std::size_t NA, std::size_t NB>
bool rigid(const Packet<NA>& a, std::size_t i, const Packet<NB>& b, std::size_t k,
           const VertexBoxes& sweep) noexcept {
  if (a.motion[i] == 0 || a.motion[i] != b.motion[k]) return false;
  const VertexIndex first = a.corner[0][i];
  for (std::size_t c = 0; c < NA; ++c) {
    if (!sweep.move_together(first, a.corner[c][i])) return false;
  }
  for (std::size_t c = 0; c < NB; ++c) {
    if (!sweep.move_together(first, b.corner[c][k])) return false;
  }
  return true;
}

}  // namespace

MeshBroadPhase::MeshBroadPhase(std::size_t vertex_count, std::span<const Triangle> faces,
                               std::span<const Edge> edges)
    : faces_(faces), edges_(edges), vertices_(vertex_count) {
  for (std::size_t v = 0; v < vertex_count; ++v)
    vertices_[v] = {static_cast<VertexIndex>(v)};
}

bool MeshBroadPhase::fit_trees(unsigned threads) {
  const VertexBoxes& sweep = sweep_;
  // One job per tree, the largest (edges) first: on two threads the edge tree takes as
  // long as the other two together.
  std::array<bool, 3> built{};
  const auto fit = [&]<std::size_t N>(BoxTree<N>& tree,
                                      std::span<const std::array<VertexIndex, N>> primitives) {
    if (built_) {
      tree.refit(sweep);
      if (tree.centre_spread() <= kRebuildSpread * tree.built_centre_spread()) return false;
    }
    tree = BoxTree<N>(primitives, sweep);
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

MeshBroadPhase::PreparedStep MeshBroadPhase::prepare(const StepPositions& positions, double largest,
                                                     unsigned threads, double min_separation) {
  sweep_vertices(positions, largest, min_separation, threads, sweep_);
  PreparedStep step;
  step.trees_rebuilt = fit_trees(threads);
  vertex_face_starts_ = split_pairs(vertex_face_walk(), kWalkPairs);
  edge_edge_starts_ = split_pairs(edge_edge_walk(), kWalkPairs);
  step.tasks = vertex_face_starts_.size() + edge_edge_starts_.size();
  return step;
}

void MeshBroadPhase::walk(std::size_t task, WalkScratch& scratch,
                          const std::function<void(const CandidateBatch&)>& decide) const {
  auto& vertex_face = scratch.vertex_face;
  auto& edge_edge = scratch.edge_edge;
  vertex_face.clear();
  edge_edge.clear();
  const auto hand_over = [&] {
    decide({vertex_face, edge_edge});
    vertex_face.clear();
    edge_edge.clear();
  };
  if (task < vertex_face_starts_.size()) {
    overlapping_pairs(vertex_face_walk(), vertex_face_starts_[task], scratch.stack,
                      [&](const Packet<1>& v, std::size_t i, const Packet<3>& f, std::size_t k) {
                        if (rigid(v, i, f, k, sweep_)) return;
                        vertex_face.push_back({v.id[i], f.id[k]});
                        if (vertex_face.size() == kBatchPairs) hand_over();
                      });
  } else {
    overlapping_pairs(
        edge_edge_walk(), edge_edge_starts_[task - vertex_face_starts_.size()], scratch.stack,
        [&](const Packet<2>& a, std::size_t i, const Packet<2>& b, std::size_t k) {
          if (rigid(a, i, b, k, sweep_)) return;
          edge_edge.push_back({std::min(a.id[i], b.id[k]), std::max(a.id[i], b.id[k])});
          if (edge_edge.size() == kBatchPairs) hand_over();
        });
  }
  if (!vertex_face.empty() || !edge_edge.empty()) hand_over();
}

MeshCandidates MeshBroadPhase::candidates(const StepPositions& positions, double largest,
                                          unsigned threads, double min_separation) {
  const PreparedStep step = prepare(positions, largest, threads, min_separation);
  // Each task's pairs in its own list, joined in task order, so the order does not
  // depend on the thread count.
  std::vector<MeshCandidates> found(step.tasks);
  parallel::for_each_block(
      step.tasks, threads, [&, scratch = WalkScratch{}](std::size_t task) mutable {
        MeshCandidates& out = found[task];
        walk(task, scratch, [&](const CandidateBatch& batch) {
          out.vertex_face.insert(out.vertex_face.end(), batch.vertex_face.begin(),
                                 batch.vertex_face.end());
          out.edge_edge.insert(out.edge_edge.end(), batch.edge_edge.begin(), batch.edge_edge.end());
        });
      });
  MeshCandidates result;
  result.trees_rebuilt = step.trees_rebuilt;
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
