#include "exactgeo/ccd/mesh_ccd.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

#include "exactgeo/ccd/internal/box_tree.hpp"
#include "exactgeo/ccd/internal/swept_box.hpp"
#include "exactgeo/predicates/internal/parallel_blocks.hpp"

namespace exactgeo::ccd {

namespace {

using internal::BoxTree;
using internal::SweptBox;

using Boxes = std::vector<SweptBox>;

enum class PairKind { vertex_face, edge_edge };

/// One pass of the broad phase: every query box against a tree.
struct TreePass {
  const Boxes* queries;
  const BoxTree* tree;
  PairKind kind;
  bool same_set;  ///< queries and tree hold the same primitives: keep each pair once
};

struct EdgeIndexPair {
  std::uint32_t a;
  std::uint32_t b;  ///< a < b
};

struct Candidates {
  std::vector<VertexFacePair> vertex_face;
  std::vector<EdgeIndexPair> edge_edge;
};

/// Narrow-phase answers of one block of candidates.
struct BlockCollisions {
  std::vector<VertexFacePair> vertex_face;
  std::vector<EdgeIndexPair> edge_edge;
  /// With a time of impact asked for: each colliding pair's bracket, vertex-face first.
  std::vector<TimeInterval> brackets;
};

/// The first round of the mesh's time of impact brackets every colliding pair to this
/// width; only the pairs that can still hold the earliest root are refined further.
constexpr double kCoarseWidth = 1.0 / 64;

constexpr std::size_t kQueryBlock = 1024;  // query boxes per broad-phase job
constexpr std::size_t kNarrowBlock = 256;  // candidates per narrow-phase job

std::string vertex_name(std::size_t v) {
  return "vertex " + std::to_string(v);
}

void check_frame(std::span<const double> positions, std::size_t vertex_count, const char* name) {
  if (positions.size() != 3 * vertex_count) {
    std::string message(name);
    message.append(" holds ").append(std::to_string(positions.size())).append(" values; ");
    message.append(std::to_string(3 * vertex_count)).append(" (3 per vertex) are needed");
    throw std::invalid_argument(message);
  }
  for (std::size_t i = 0; i < positions.size(); ++i) {
    if (!std::isfinite(positions[i])) {
      std::string message(name);
      message.append(": ").append(vertex_name(i / 3)).append(" has a non-finite coordinate");
      throw std::invalid_argument(message);
    }
  }
}

std::vector<Edge> unique_edges(std::span<const Triangle> faces) {
  std::vector<Edge> edges;
  edges.reserve(3 * faces.size());
  for (const Triangle& f : faces) {
    for (int i = 0; i < 3; ++i) {
      const VertexIndex a = f[i];
      const VertexIndex b = f[(i + 1) % 3];
      edges.push_back({std::min(a, b), std::max(a, b)});
    }
  }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  return edges;
}

bool shares_vertex(const Edge& a, const Edge& b) noexcept {
  return a[0] == b[0] || a[0] == b[1] || a[1] == b[0] || a[1] == b[1];
}

bool is_corner(VertexIndex v, const Triangle& f) noexcept {
  return v == f[0] || v == f[1] || v == f[2];
}

Point3 position(std::span<const double> positions, VertexIndex v) noexcept {
  return {positions[3 * v], positions[3 * v + 1], positions[3 * v + 2]};
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void keep_earliest(std::optional<TimeInterval>& earliest, const TimeInterval& t) noexcept {
  if (!earliest) {
    earliest = t;
    return;
  }
  // No root of any pair before the smallest start; some pair has a root by the smallest end.
  earliest->start = std::min(earliest->start, t.start);
  earliest->end = std::min(earliest->end, t.end);
}

}  // namespace

struct MeshCcd::State {
  std::size_t vertex_count = 0;
  std::vector<Triangle> faces;
  std::vector<Edge> edges;

  // The boxes of standing primitives, kept while the same vertices stand at the same place.
  bool standing_valid = false;
  std::vector<std::uint8_t> moving;        // per vertex, when the standing boxes were built
  std::vector<double> standing_positions;  // t0 positions then (only standing ones compared)
  Boxes standing_vertices;
  BoxTree standing_edges, standing_faces;

  bool standing_unchanged(const std::vector<std::uint8_t>& now, const MeshFrames& frames) const;
  void rebuild_standing(std::vector<std::uint8_t> now, const MeshFrames& frames);
  template <std::size_t N>
  Boxes moving_boxes(std::span<const std::array<VertexIndex, N>> primitives,
                     const std::vector<std::uint8_t>& now, const MeshFrames& frames) const;
  template <std::size_t N>
  Boxes standing_boxes(std::span<const std::array<VertexIndex, N>> primitives,
                       const MeshFrames& frames) const;
};

namespace {

template <std::size_t N>
bool any_moves(const std::array<VertexIndex, N>& corners, const std::vector<std::uint8_t>& moving) {
  return std::any_of(corners.begin(), corners.end(), [&](VertexIndex v) { return moving[v] != 0; });
}

std::vector<std::uint8_t> moving_vertices(const MeshFrames& frames, std::size_t vertex_count) {
  std::vector<std::uint8_t> moving(vertex_count, 0);
  for (std::size_t i = 0; i < 3 * vertex_count; ++i) {
    if (frames.positions_t0[i] != frames.positions_t1[i]) moving[i / 3] = 1;
  }
  return moving;
}

std::vector<std::array<VertexIndex, 1>> vertex_list(std::size_t vertex_count) {
  std::vector<std::array<VertexIndex, 1>> vertices(vertex_count);
  for (std::size_t v = 0; v < vertex_count; ++v)
    vertices[v] = {static_cast<VertexIndex>(v)};
  return vertices;
}

}  // namespace

template <std::size_t N>
Boxes MeshCcd::State::moving_boxes(std::span<const std::array<VertexIndex, N>> primitives,
                                   const std::vector<std::uint8_t>& now,
                                   const MeshFrames& frames) const {
  Boxes boxes;
  for (std::size_t i = 0; i < primitives.size(); ++i) {
    if (!any_moves(primitives[i], now)) continue;
    boxes.push_back(internal::swept_box(primitives[i], static_cast<std::uint32_t>(i),
                                        frames.positions_t0.data(), frames.positions_t1.data()));
  }
  return boxes;
}

template <std::size_t N>
Boxes MeshCcd::State::standing_boxes(std::span<const std::array<VertexIndex, N>> primitives,
                                     const MeshFrames& frames) const {
  Boxes boxes;
  for (std::size_t i = 0; i < primitives.size(); ++i) {
    if (any_moves(primitives[i], moving)) continue;
    boxes.push_back(internal::swept_box(primitives[i], static_cast<std::uint32_t>(i),
                                        frames.positions_t0.data(), frames.positions_t0.data()));
  }
  return boxes;
}

bool MeshCcd::State::standing_unchanged(const std::vector<std::uint8_t>& now,
                                        const MeshFrames& frames) const {
  if (!standing_valid || now != moving) return false;
  for (std::size_t i = 0; i < 3 * vertex_count; ++i) {
    if (moving[i / 3] == 0 && frames.positions_t0[i] != standing_positions[i]) return false;
  }
  return true;
}

void MeshCcd::State::rebuild_standing(std::vector<std::uint8_t> now, const MeshFrames& frames) {
  moving = std::move(now);
  standing_positions.assign(frames.positions_t0.begin(), frames.positions_t0.end());
  const auto vertices = vertex_list(vertex_count);
  standing_vertices = standing_boxes(std::span<const std::array<VertexIndex, 1>>(vertices), frames);
  standing_edges = BoxTree(standing_boxes(std::span<const Edge>(edges), frames));
  standing_faces = BoxTree(standing_boxes(std::span<const Triangle>(faces), frames));
  standing_valid = true;
}

MeshCcd::MeshCcd(std::size_t vertex_count, std::span<const Triangle> faces)
    : state_(std::make_unique<State>()) {
  if (vertex_count > std::numeric_limits<VertexIndex>::max()) {
    throw std::invalid_argument("MeshCcd: more than 2^32 - 1 vertices");
  }
  for (std::size_t f = 0; f < faces.size(); ++f) {
    const Triangle& t = faces[f];
    const auto problem = [f](const std::string& what) {
      return std::invalid_argument("MeshCcd: face " + std::to_string(f) + ": " + what);
    };
    for (int i = 0; i < 3; ++i) {
      if (t[i] >= vertex_count) {
        throw problem("corner " + std::to_string(t[i]) + " is not a vertex (there are " +
                      std::to_string(vertex_count) + ")");
      }
      if (t[i] == t[(i + 1) % 3]) throw problem("repeated corner " + std::to_string(t[i]));
    }
  }
  state_->vertex_count = vertex_count;
  state_->faces.assign(faces.begin(), faces.end());
  state_->edges = unique_edges(faces);
}

MeshCcd::MeshCcd(MeshCcd&&) noexcept = default;
MeshCcd& MeshCcd::operator=(MeshCcd&&) noexcept = default;
MeshCcd::~MeshCcd() = default;

std::size_t MeshCcd::vertex_count() const noexcept {
  return state_->vertex_count;
}
std::span<const Triangle> MeshCcd::faces() const noexcept {
  return state_->faces;
}
std::span<const Edge> MeshCcd::edges() const noexcept {
  return state_->edges;
}

namespace {

/// The mesh's earliest root, bracketed to `width`, from every colliding pair's coarse
/// bracket (result's pairs, in order: vertex-face, then edge-edge). Some pair has a root
/// by E, the smallest bracket end, so a pair whose bracket starts after E has no root
/// before E and cannot hold the earliest one: only the others are refined.
TimeInterval refine_earliest(const MeshCcdResult& result, std::span<const TimeInterval> brackets,
                             const MeshFrames& frames, std::span<const Triangle> faces,
                             double width, const MeshCcdOptions& options) {
  std::optional<TimeInterval> coarse;
  for (const TimeInterval& t : brackets)
    keep_earliest(coarse, t);
  if (width >= kCoarseWidth) return *coarse;
  std::vector<std::size_t> open;
  for (std::size_t i = 0; i < brackets.size(); ++i) {
    if (brackets[i].start <= coarse->end) open.push_back(i);
  }
  const Options fine{options.method, width};
  std::vector<TimeInterval> refined(open.size());
  exactgeo::internal::for_each_block(open.size(), options.threads, [&](std::size_t k) {
    const std::size_t i = open[k];
    const Result r =
        i < result.vertex_face.size()
            ? vertex_face_ccd(vertex_face_query(frames, faces, result.vertex_face[i]), fine)
            : edge_edge_ccd(
                  edge_edge_query(frames, result.edge_edge[i - result.vertex_face.size()]), fine);
    refined[k] = r.time_of_impact.value_or(brackets[i]);
  });
  std::optional<TimeInterval> earliest;
  for (const TimeInterval& t : refined)
    keep_earliest(earliest, t);
  return *earliest;
}

}  // namespace

MeshCcdResult MeshCcd::step(const MeshFrames& frames, const MeshCcdOptions& options) {
  State& s = *state_;
  check_frame(frames.positions_t0, s.vertex_count, "positions_t0");
  check_frame(frames.positions_t1, s.vertex_count, "positions_t1");
  MeshCcdResult result;
  const auto broad_start = std::chrono::steady_clock::now();

  auto now = moving_vertices(frames, s.vertex_count);
  if (!s.standing_unchanged(now, frames)) {
    s.rebuild_standing(now, frames);
    result.static_boxes_rebuilt = true;
  }
  const auto vertices = vertex_list(s.vertex_count);
  const Boxes moving_vertices_boxes =
      s.moving_boxes(std::span<const std::array<VertexIndex, 1>>(vertices), now, frames);
  const Boxes moving_edges = s.moving_boxes(std::span<const Edge>(s.edges), now, frames);
  const BoxTree moving_edge_tree(moving_edges);
  const BoxTree moving_face_tree(s.moving_boxes(std::span<const Triangle>(s.faces), now, frames));

  // Every pair with at least one moving primitive, each once.
  const TreePass passes[] = {
      {&moving_vertices_boxes, &moving_face_tree, PairKind::vertex_face, false},
      {&moving_vertices_boxes, &s.standing_faces, PairKind::vertex_face, false},
      {&s.standing_vertices, &moving_face_tree, PairKind::vertex_face, false},
      {&moving_edges, &moving_edge_tree, PairKind::edge_edge, true},
      {&moving_edges, &s.standing_edges, PairKind::edge_edge, false},
  };
  struct QueryJob {
    const TreePass* pass;
    std::size_t begin, end;
  };
  std::vector<QueryJob> jobs;
  for (const TreePass& pass : passes) {
    if (pass.tree->empty()) continue;
    for (std::size_t b = 0; b < pass.queries->size(); b += kQueryBlock)
      jobs.push_back({&pass, b, std::min(pass.queries->size(), b + kQueryBlock)});
  }
  std::vector<Candidates> found(jobs.size());
  exactgeo::internal::for_each_block(jobs.size(), options.threads, [&](std::size_t j) {
    const QueryJob& job = jobs[j];
    Candidates& out = found[j];
    for (std::size_t q = job.begin; q < job.end; ++q) {
      const SweptBox& box = (*job.pass->queries)[q];
      const std::uint32_t mine = box.id;
      if (job.pass->kind == PairKind::vertex_face) {
        job.pass->tree->query(box, [&](std::uint32_t face) {
          if (!is_corner(mine, s.faces[face])) out.vertex_face.push_back({mine, face});
        });
      } else {
        job.pass->tree->query(box, [&](std::uint32_t other) {
          if (job.pass->same_set && other <= mine) return;
          if (!shares_vertex(s.edges[mine], s.edges[other]))
            out.edge_edge.push_back({std::min(mine, other), std::max(mine, other)});
        });
      }
    }
  });
  Candidates candidates;
  for (Candidates& c : found) {
    candidates.vertex_face.insert(candidates.vertex_face.end(), c.vertex_face.begin(),
                                  c.vertex_face.end());
    candidates.edge_edge.insert(candidates.edge_edge.end(), c.edge_edge.begin(), c.edge_edge.end());
    c = {};
  }
  result.vertex_face_candidates = candidates.vertex_face.size();
  result.edge_edge_candidates = candidates.edge_edge.size();
  result.broad_phase_seconds = seconds_since(broad_start);

  // Narrow phase: blocks of candidates, vertex-face first, then edge-edge.
  const auto narrow_start = std::chrono::steady_clock::now();
  const std::optional<double> width = options.time_of_impact_width;
  const Options pair_options{options.method,
                             width ? std::optional(std::max(*width, kCoarseWidth)) : std::nullopt};
  const std::size_t vf_blocks = (candidates.vertex_face.size() + kNarrowBlock - 1) / kNarrowBlock;
  const std::size_t ee_blocks = (candidates.edge_edge.size() + kNarrowBlock - 1) / kNarrowBlock;
  std::vector<BlockCollisions> collisions(vf_blocks + ee_blocks);
  exactgeo::internal::for_each_block(collisions.size(), options.threads, [&](std::size_t b) {
    BlockCollisions& out = collisions[b];
    const auto note = [&](const Result& r) {
      if (r.collision && r.time_of_impact) out.brackets.push_back(*r.time_of_impact);
      return r.collision;
    };
    if (b < vf_blocks) {
      const std::size_t end = std::min(candidates.vertex_face.size(), (b + 1) * kNarrowBlock);
      for (std::size_t i = b * kNarrowBlock; i < end; ++i) {
        const VertexFacePair pair = candidates.vertex_face[i];
        if (note(vertex_face_ccd(vertex_face_query(frames, s.faces, pair), pair_options)))
          out.vertex_face.push_back(pair);
      }
      return;
    }
    const std::size_t first = (b - vf_blocks) * kNarrowBlock;
    const std::size_t end = std::min(candidates.edge_edge.size(), first + kNarrowBlock);
    for (std::size_t i = first; i < end; ++i) {
      const EdgeIndexPair pair = candidates.edge_edge[i];
      const EdgeEdgePair edges{s.edges[pair.a], s.edges[pair.b]};
      if (note(edge_edge_ccd(edge_edge_query(frames, edges), pair_options)))
        out.edge_edge.push_back(pair);
    }
  });
  // Blocks of vertex-face candidates come first, so this is the order of the pairs in
  // result (vertex-face, then edge-edge), which is also the order of the brackets.
  std::vector<TimeInterval> brackets;
  for (const BlockCollisions& c : collisions) {
    result.vertex_face.insert(result.vertex_face.end(), c.vertex_face.begin(), c.vertex_face.end());
    for (const EdgeIndexPair& pair : c.edge_edge)
      result.edge_edge.push_back({s.edges[pair.a], s.edges[pair.b]});
    brackets.insert(brackets.end(), c.brackets.begin(), c.brackets.end());
  }
  if (width && !brackets.empty()) {
    result.time_of_impact = refine_earliest(result, brackets, frames, s.faces, *width, options);
  }
  std::sort(result.vertex_face.begin(), result.vertex_face.end());
  std::sort(result.edge_edge.begin(), result.edge_edge.end());
  result.narrow_phase_seconds = seconds_since(narrow_start);
  return result;
}

MeshCcdResult find_collisions(std::span<const Triangle> faces, const MeshFrames& frames,
                              const MeshCcdOptions& options) {
  if (frames.positions_t0.size() % 3 != 0) {
    throw std::invalid_argument("positions_t0 holds " + std::to_string(frames.positions_t0.size()) +
                                " values, not a multiple of 3");
  }
  return MeshCcd(frames.positions_t0.size() / 3, faces).step(frames, options);
}

VertexFaceQuery vertex_face_query(const MeshFrames& frames, std::span<const Triangle> faces,
                                  VertexFacePair pair) noexcept {
  const Triangle& f = faces[pair.face];
  const auto& t0 = frames.positions_t0;
  const auto& t1 = frames.positions_t1;
  return {position(t0, pair.vertex), position(t0, f[0]), position(t0, f[1]), position(t0, f[2]),
          position(t1, pair.vertex), position(t1, f[0]), position(t1, f[1]), position(t1, f[2])};
}

EdgeEdgeQuery edge_edge_query(const MeshFrames& frames, const EdgeEdgePair& pair) noexcept {
  const auto& t0 = frames.positions_t0;
  const auto& t1 = frames.positions_t1;
  return {position(t0, pair.a[0]), position(t0, pair.a[1]), position(t0, pair.b[0]),
          position(t0, pair.b[1]), position(t1, pair.a[0]), position(t1, pair.a[1]),
          position(t1, pair.b[0]), position(t1, pair.b[1])};
}

}  // namespace exactgeo::ccd
