#include "baseline/mesh_broad_phase.hpp"

#include <algorithm>
#include <cmath>

#include "exactgeo/predicates/kernel/unit_magnitude.hpp"
#include "exactgeo/parallel/blocks.hpp"
#include "exactgeo/predicates/kernel/error_free.hpp"

namespace exactgeo::ccd::bench::baseline {

using kernel::largest_magnitude;

namespace {

using Boxes = std::vector<SweptBox>;

enum class PairKind { vertex_face, edge_edge };

/// One pass of the broad phase: every query box against a tree.
struct TreePass {
  std::span<const SweptBox> queries;
  const QueryTree* tree;
  PairKind kind;
  bool same_set;  ///< queries and tree hold the same primitives: keep each pair once
};

constexpr std::size_t kQueryBlock = 1024;  // query boxes per job

bool shares_vertex(const Edge& a, const Edge& b) noexcept {
  return a[0] == b[0] || a[0] == b[1] || a[1] == b[0] || a[1] == b[1];
}

bool is_corner(VertexIndex v, const Triangle& f) noexcept {
  return v == f[0] || v == f[1] || v == f[2];
}

template <std::size_t N>
bool any_moves(const std::array<VertexIndex, N>& corners, const std::vector<std::uint8_t>& moving) {
  return std::any_of(corners.begin(), corners.end(), [&](VertexIndex v) { return moving[v] != 0; });
}

/// Each vertex's displacement p_t1 - p_t0, whether every coordinate of it is exactly a
/// double, and whether the vertex moves at all (the rounded difference of two finite
/// doubles is zero only when they are equal).
struct Displacements {
  std::vector<Vector3> d;
  std::vector<std::uint8_t> exact;

  explicit Displacements(const StepPositions& frames) {
    const std::size_t n = frames.t0.size() / 3;
    d.resize(n);
    exact.assign(n, 1);
    for (std::size_t i = 0; i < 3 * n; ++i) {
      const auto diff = exactgeo::kernel::two_diff(frames.t1[i], frames.t0[i]);
      d[i / 3][i % 3] = diff.head;
      if (diff.tail != 0.0 || !std::isfinite(diff.head)) exact[i / 3] = 0;
    }
  }

  std::vector<std::uint8_t> moving() const {
    std::vector<std::uint8_t> m(d.size());
    for (std::size_t v = 0; v < d.size(); ++v)
      m[v] = d[v] != Vector3{0.0, 0.0, 0.0} ? 1 : 0;
    return m;
  }

  /// True when all `vertices` move by one and the same vector (standing still included):
  /// their relative positions, hence all their distances, stay the same during the step.
  template <std::size_t N>
  bool rigid(const std::array<VertexIndex, N>& vertices) const noexcept {
    const VertexIndex first = vertices[0];
    if (exact[first] == 0) return false;
    for (const VertexIndex v : vertices) {
      if (exact[v] == 0 || d[v] != d[first]) return false;
    }
    return true;
  }
};

/// The swept boxes of the primitives whose corners move (`moving` true) or all stand
/// still (`moving` false).
template <std::size_t N>
Boxes boxes_of(std::span<const std::array<VertexIndex, N>> primitives,
               const std::vector<std::uint8_t>& moving_vertex, bool moving,
               const StepPositions& frames, const boxes::Scale& scale) {
  Boxes boxes;
  for (std::size_t i = 0; i < primitives.size(); ++i) {
    if (any_moves(primitives[i], moving_vertex) != moving) continue;
    boxes.push_back(swept_box(primitives[i], static_cast<std::uint32_t>(i), frames.t0.data(),
                              frames.t1.data(), scale));
  }
  return boxes;
}

}  // namespace

MeshBroadPhase::MeshBroadPhase(std::size_t vertex_count, std::span<const Triangle> faces,
                               std::span<const Edge> edges)
    : vertex_count_(vertex_count), faces_(faces), edges_(edges), vertices_(vertex_count) {
  for (std::size_t v = 0; v < vertex_count; ++v)
    vertices_[v] = {static_cast<VertexIndex>(v)};
}

bool MeshBroadPhase::standing_unchanged(const std::vector<std::uint8_t>& moving,
                                        const StepPositions& frames,
                                        const boxes::Scale& scale) const {
  if (!standing_valid_ || moving != moving_ || scale.exponent() != standing_scale_.exponent())
    return false;
  for (std::size_t i = 0; i < 3 * vertex_count_; ++i) {
    if (moving_[i / 3] == 0 && frames.t0[i] != standing_positions_[i]) return false;
  }
  return true;
}

void MeshBroadPhase::rebuild_standing(std::vector<std::uint8_t> moving, const StepPositions& frames,
                                      const boxes::Scale& scale) {
  moving_ = std::move(moving);
  standing_scale_ = scale;
  standing_positions_.assign(frames.t0.begin(), frames.t0.end());
  standing_vertices_ = QueryTree(boxes_of(std::span<const std::array<VertexIndex, 1>>(vertices_),
                                          moving_, false, frames, scale));
  standing_edges_ = QueryTree(boxes_of(edges_, moving_, false, frames, scale));
  standing_faces_ = QueryTree(boxes_of(faces_, moving_, false, frames, scale));
  standing_valid_ = true;
}

MeshCandidates MeshBroadPhase::candidates(const StepPositions& frames, unsigned threads) {
  MeshCandidates result;
  const Displacements motion(frames);
  const std::vector<std::uint8_t> moving = motion.moving();
  const boxes::Scale scale(std::max(largest_magnitude(frames.t0), largest_magnitude(frames.t1)));
  if (!standing_unchanged(moving, frames, scale)) {
    rebuild_standing(moving, frames, scale);
    result.standing_rebuilt = true;
  }
  // The three trees of moving primitives are built side by side. Queries run in tree
  // order (QueryTree::boxes), which keeps them spatially coherent.
  std::array<QueryTree, 3> trees;
  parallel::for_each_block(3, threads, [&](std::size_t k) {
    if (k == 0)
      trees[0] = QueryTree(boxes_of(std::span<const std::array<VertexIndex, 1>>(vertices_), moving,
                                    true, frames, scale));
    if (k == 1) trees[1] = QueryTree(boxes_of(edges_, moving, true, frames, scale));
    if (k == 2) trees[2] = QueryTree(boxes_of(faces_, moving, true, frames, scale));
  });
  const QueryTree &moving_vertex_tree = trees[0], &moving_edge_tree = trees[1],
                  &moving_face_tree = trees[2];
  const auto moving_vertices = moving_vertex_tree.boxes();
  const auto moving_edges = moving_edge_tree.boxes();

  // Every pair with at least one moving primitive, each once, except pairs moving rigidly.
  const TreePass passes[] = {
      {moving_vertices, &moving_face_tree, PairKind::vertex_face, false},
      {moving_vertices, &standing_faces_, PairKind::vertex_face, false},
      {standing_vertices_.boxes(), &moving_face_tree, PairKind::vertex_face, false},
      {moving_edges, &moving_edge_tree, PairKind::edge_edge, true},
      {moving_edges, &standing_edges_, PairKind::edge_edge, false},
  };
  struct Candidates {
    std::vector<VertexFacePair> vertex_face;
    std::vector<EdgeIndexPair> edge_edge;
  };
  struct QueryJob {
    const TreePass* pass;
    std::size_t begin, end;
  };
  std::vector<QueryJob> jobs;
  for (const TreePass& pass : passes) {
    if (pass.tree->empty()) continue;
    for (std::size_t b = 0; b < pass.queries.size(); b += kQueryBlock)
      jobs.push_back({&pass, b, std::min(pass.queries.size(), b + kQueryBlock)});
  }
  std::vector<Candidates> found(jobs.size());
  parallel::for_each_block(jobs.size(), threads, [&](std::size_t j) {
    const QueryJob& job = jobs[j];
    Candidates& out = found[j];
    for (std::size_t q = job.begin; q < job.end; ++q) {
      const SweptBox& box = job.pass->queries[q];
      const std::uint32_t mine = box.id;
      if (job.pass->kind == PairKind::vertex_face) {
        job.pass->tree->query(box, [&](std::uint32_t face) {
          const Triangle& f = faces_[face];
          if (is_corner(mine, f) || motion.rigid(std::array{mine, f[0], f[1], f[2]})) return;
          out.vertex_face.push_back({mine, face});
        });
      } else {
        job.pass->tree->query(box, [&](std::uint32_t other) {
          if (job.pass->same_set && other <= mine) return;
          const Edge &a = edges_[mine], &b = edges_[other];
          if (shares_vertex(a, b) || motion.rigid(std::array{a[0], a[1], b[0], b[1]})) return;
          out.edge_edge.push_back({std::min(mine, other), std::max(mine, other)});
        });
      }
    }
  });
  for (Candidates& c : found) {
    result.vertex_face.insert(result.vertex_face.end(), c.vertex_face.begin(), c.vertex_face.end());
    result.edge_edge.insert(result.edge_edge.end(), c.edge_edge.begin(), c.edge_edge.end());
    c = {};
  }
  return result;
}

}  // namespace exactgeo::ccd::bench::baseline
