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
using boxes::NodePair;
using boxes::Packet;
using boxes::VertexBoxes;
using boxes::Walk;

namespace {

constexpr std::size_t kVertexBlock = 1 << 14;  // vertices per job when making their boxes

/// Node pairs each tree walk is split into (tree_pairs.hpp): enough for threads to share
/// the work evenly, few enough that opening them costs nothing next to the walk.
constexpr std::size_t kWalkPairs = 256;

/// A refitted tree is rebuilt once looseness() exceeds this factor times its value when
/// the tree was built. A refitted tree is never wrong, only slower; this factor only
/// trades the cost of a build (a few refits' worth) against a slower walk.
constexpr double kRebuildLooseness = 1.5;

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

/// Each vertex's swept box and exact displacement p_t1 - p_t0 (TwoDiff: its rounded value
/// and the rest, unique for each exact difference, so that rigid motion by a vector that is
/// not a double is recognised too), and whether the vertex moves at all (the rounded
/// difference of two finite doubles is zero only when they are equal).
VertexBoxes sweep_of(const StepPositions& positions, double largest, double min_separation,
                     unsigned threads) {
  const std::size_t n = positions.t0.size() / 3;
  VertexBoxes s;
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
  return s;
}

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

bool MeshBroadPhase::fit_trees(const VertexBoxes& sweep, unsigned threads) {
  // One job per tree, the largest (edges) first: on two threads the edge tree takes as
  // long as the other two together.
  std::array<bool, 3> built{};
  const auto fit = [&]<std::size_t N>(BoxTree<N>& tree,
                                      std::span<const std::array<VertexIndex, N>> primitives) {
    if (built_) {
      tree.refit(sweep);
      if (tree.looseness() <= kRebuildLooseness * tree.built_looseness()) return false;
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

MeshCandidates MeshBroadPhase::candidates(const StepPositions& positions, double largest,
                                          unsigned threads, double min_separation) {
  MeshCandidates result;
  const VertexBoxes sweep = sweep_of(positions, largest, min_separation, threads);
  result.trees_rebuilt = fit_trees(sweep, threads);

  // Both walks split into node pairs, vertex-face first; each pair's candidates in its
  // own list, joined in order, so the order does not depend on the thread count.
  const Walk<1, 3> vertex_face{vertex_tree_, face_tree_, sweep, boxes::SharedCorners::skip};
  const Walk<2, 2> edge_edge{edge_tree_, edge_tree_, sweep, boxes::SharedCorners::skip};
  const std::vector<NodePair> vertex_face_pairs = split_pairs(vertex_face, kWalkPairs);
  const std::vector<NodePair> edge_edge_pairs = split_pairs(edge_edge, kWalkPairs);
  struct Found {
    std::vector<VertexFacePair> vertex_face;
    std::vector<EdgeIndexPair> edge_edge;
  };
  std::vector<Found> found(vertex_face_pairs.size() + edge_edge_pairs.size());
  std::vector<NodePair> stack;  // each worker's copy of the lambda has its own
  parallel::for_each_block(found.size(), threads, [&, stack](std::size_t j) mutable {
    Found& out = found[j];
    if (j < vertex_face_pairs.size()) {
      overlapping_pairs(vertex_face, vertex_face_pairs[j], stack,
                        [&](const Packet<1>& v, std::size_t i, const Packet<3>& f, std::size_t k) {
                          if (!rigid(v, i, f, k, sweep))
                            out.vertex_face.push_back({v.id[i], f.id[k]});
                        });
      return;
    }
    overlapping_pairs(
        edge_edge, edge_edge_pairs[j - vertex_face_pairs.size()], stack,
        [&](const Packet<2>& a, std::size_t i, const Packet<2>& b, std::size_t k) {
          if (rigid(a, i, b, k, sweep)) return;
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
