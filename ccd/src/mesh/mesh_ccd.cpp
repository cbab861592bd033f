#include "exactgeo/ccd/mesh/mesh_ccd.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

#include "exactgeo/predicates/kernel/unit_magnitude.hpp"
#include "exactgeo/ccd/mesh/internal/broad_phase.hpp"
#include "exactgeo/parallel/blocks.hpp"

namespace exactgeo::ccd {

namespace {

/// The narrow phase's answers for one task of the broad phase's walk, and its times.
struct TaskCollisions {
  std::vector<VertexFacePair> vertex_face;
  std::vector<internal::EdgeIndexPair> edge_edge;
  /// With a time of impact asked for: each colliding pair's bracket, in the pairs' order.
  std::vector<TimeInterval> vertex_face_brackets;
  std::vector<TimeInterval> edge_edge_brackets;
  std::size_t vertex_face_candidates = 0;
  std::size_t edge_edge_candidates = 0;
  double narrow_seconds = 0.0;  ///< deciding the task's batches
  double seconds = 0.0;         ///< the whole task: walking and deciding
};

/// The first round of the mesh's time of impact brackets every colliding pair to this
/// width; only the pairs that can still hold the earliest root are refined further.
constexpr double kCoarseWidth = 1.0 / 64;

void check_positions(std::span<const double> positions, std::size_t vertex_count,
                     const char* name) {
  if (positions.size() != 3 * vertex_count) {
    std::string message(name);
    message.append(" holds ").append(std::to_string(positions.size())).append(" values; ");
    message.append(std::to_string(3 * vertex_count)).append(" (3 per vertex) are needed");
    throw std::invalid_argument(message);
  }
  for (std::size_t i = 0; i < positions.size(); ++i) {
    if (!std::isfinite(positions[i])) {
      std::string message(name);
      message.append(": vertex ")
          .append(std::to_string(i / 3))
          .append(" has a non-finite coordinate");
      throw std::invalid_argument(message);
    }
  }
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
  State(std::size_t count, std::span<const Triangle> triangles)
      : vertex_count(count),
        faces(triangles.begin(), triangles.end()),
        edges(edges_of(faces, count)),
        broad_phase(vertex_count, faces, edges) {}

  std::size_t vertex_count;
  std::vector<Triangle> faces;
  std::vector<Edge> edges;
  internal::MeshBroadPhase broad_phase;  // views faces and edges: State never moves
  State(const State&) = delete;
  State& operator=(const State&) = delete;
};

MeshCcd::MeshCcd(std::size_t vertex_count, std::span<const Triangle> faces) {
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
  state_ = std::make_unique<State>(vertex_count, faces);
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

/// A step's positions as the pairs see them, their largest coordinate magnitude, and the
/// separation in their units.
struct ScaledStep {
  StepPositions positions;
  double largest;
  double min_separation;
};

/// `positions`, or both ends scaled to magnitude 1 by one power of two, stored in `unit`,
/// when they are far from it and the scaling is exact for them and for the separation
/// (predicates/kernel/unit_magnitude.hpp).
ScaledStep at_unit_magnitude(const StepPositions& positions, double min_separation,
                             std::vector<double>& unit) {
  const double largest = std::max(kernel::largest_magnitude(positions.t0),
                                  kernel::largest_magnitude(positions.t1));
  const ScaledStep as_given{positions, largest, min_separation};
  if (kernel::near_unit_magnitude(largest)) return as_given;
  unit.assign(positions.t0.begin(), positions.t0.end());
  unit.insert(unit.end(), positions.t1.begin(), positions.t1.end());
  if (!kernel::scale_to_unit_magnitude(unit, largest)) return as_given;
  int exponent = 0;  // the scaling took largest to its significand in [1/2, 1), exactly
  const double significand = std::frexp(largest, &exponent);
  const double separation = kernel::PowerOfTwo(-exponent)(min_separation);
  if (kernel::PowerOfTwo(exponent)(separation) != min_separation) return as_given;
  const std::span<const double> both(unit);
  return {{both.first(positions.t0.size()), both.subspan(positions.t0.size())},
          significand,
          separation};
}

/// The mesh's earliest root, bracketed to `width`, from every colliding pair's coarse
/// bracket (result's pairs, in order: vertex-face, then edge-edge). Some pair has a root
/// by E, the smallest bracket end, so a pair whose bracket starts after E has no root
/// before E and cannot hold the earliest one: only the others are refined.
TimeInterval refine_earliest(const MeshCcdResult& result, std::span<const TimeInterval> brackets,
                             double min_separation, const StepPositions& positions,
                             std::span<const Triangle> faces, double width,
                             const MeshCcdOptions& options) {
  std::optional<TimeInterval> coarse;
  for (const TimeInterval& t : brackets)
    keep_earliest(coarse, t);
  if (width >= kCoarseWidth) return *coarse;
  std::vector<std::size_t> open;
  for (std::size_t i = 0; i < brackets.size(); ++i) {
    if (brackets[i].start <= coarse->end) open.push_back(i);
  }
  Options fine{options.method, width};
  fine.min_separation = min_separation;
  std::vector<TimeInterval> refined(open.size());
  parallel::for_each_block(open.size(), options.threads, [&](std::size_t k) {
    const std::size_t i = open[k];
    const Result r =
        i < result.vertex_face.size()
            ? vertex_face_ccd(vertex_face_query(positions, faces, result.vertex_face[i]), fine)
            : edge_edge_ccd(
                  edge_edge_query(positions, result.edge_edge[i - result.vertex_face.size()]),
                  fine);
    refined[k] = r.time_of_impact.value_or(brackets[i]);
  });
  std::optional<TimeInterval> earliest;
  for (const TimeInterval& t : refined)
    keep_earliest(earliest, t);
  return *earliest;
}

/// Throws std::invalid_argument for frames or options MeshCcd::step does not take.
void check_step(const StepPositions& positions, const MeshCcdOptions& options,
                std::size_t vertex_count) {
  check_positions(positions.t0, vertex_count, "positions.t0");
  check_positions(positions.t1, vertex_count, "positions.t1");
  if (!is_valid_min_separation(options.min_separation)) {
    throw std::invalid_argument("MeshCcd::step: min_separation must be finite and >= 0");
  }
  if (options.min_separation > 0.0 && options.method != Method::exact) {
    throw std::invalid_argument("MeshCcd::step: min_separation > 0 needs the exact method");
  }
}

/// The narrow phase on one batch of candidates: each colliding pair into `out`, with its
/// bracket when a time of impact is asked for (a method without one brackets the step).
void decide(const internal::CandidateBatch& batch, const StepPositions& positions,
            std::span<const Triangle> faces, std::span<const Edge> edges, const Options& options,
            bool brackets, TaskCollisions& out) {
  out.vertex_face_candidates += batch.vertex_face.size();
  out.edge_edge_candidates += batch.edge_edge.size();
  for (const VertexFacePair pair : batch.vertex_face) {
    const Result r = vertex_face_ccd(vertex_face_query(positions, faces, pair), options);
    if (!r.collision) continue;
    out.vertex_face.push_back(pair);
    if (brackets) out.vertex_face_brackets.push_back(r.time_of_impact.value_or(TimeInterval{}));
  }
  for (const internal::EdgeIndexPair pair : batch.edge_edge) {
    const Result r =
        edge_edge_ccd(edge_edge_query(positions, {edges[pair.a], edges[pair.b]}), options);
    if (!r.collision) continue;
    out.edge_edge.push_back(pair);
    if (brackets) out.edge_edge_brackets.push_back(r.time_of_impact.value_or(TimeInterval{}));
  }
}

}  // namespace

MeshCcdCandidates MeshCcd::candidates(const StepPositions& positions,
                                      const MeshCcdOptions& options) {
  State& s = *state_;
  MeshCcdOptions as_exact = options;  // the method does not matter to the broad phase
  as_exact.method = Method::exact;
  check_step(positions, as_exact, s.vertex_count);
  std::vector<double> unit;
  const ScaledStep scaled = at_unit_magnitude(positions, options.min_separation, unit);
  const internal::MeshCandidates found = s.broad_phase.candidates(
      scaled.positions, scaled.largest, options.threads, scaled.min_separation);
  MeshCcdCandidates out;
  out.vertex_face = found.vertex_face;
  out.edge_edge.reserve(found.edge_edge.size());
  for (const internal::EdgeIndexPair& pair : found.edge_edge)
    out.edge_edge.push_back({s.edges[pair.a], s.edges[pair.b]});
  return out;
}

MeshCcdResult MeshCcd::step(const StepPositions& positions, const MeshCcdOptions& options) {
  State& s = *state_;
  check_step(positions, options, s.vertex_count);
  MeshCcdResult result;
  const auto broad_start = std::chrono::steady_clock::now();
  // A step far from magnitude 1 is brought there once for all its pairs, both ends by
  // one power of two (predicates/kernel/unit_magnitude.hpp); no answer or time changes.
  std::vector<double> unit;
  const ScaledStep scaled_step = at_unit_magnitude(positions, options.min_separation, unit);
  const StepPositions& scaled = scaled_step.positions;

  const internal::MeshBroadPhase::PreparedStep prepared = s.broad_phase.prepare(
      scaled, scaled_step.largest, options.threads, scaled_step.min_separation);
  result.trees_rebuilt = prepared.trees_rebuilt;
  const double prepare_seconds = seconds_since(broad_start);

  // Each task of the walk decides its candidates a batch at a time, where they are found:
  // the step never holds its candidate list (internal/broad_phase.hpp).
  const std::optional<double> width = options.time_of_impact_width;
  Options pair_options{options.method,
                       width ? std::optional(std::max(*width, kCoarseWidth)) : std::nullopt};
  pair_options.min_separation = scaled_step.min_separation;
  std::vector<TaskCollisions> collisions(prepared.tasks);
  const auto walk_start = std::chrono::steady_clock::now();
  parallel::for_each_block(
      prepared.tasks, options.threads,
      [&, scratch = internal::WalkScratch{}](std::size_t task) mutable {
        const auto task_start = std::chrono::steady_clock::now();
        TaskCollisions& out = collisions[task];
        s.broad_phase.walk(task, scratch, [&](const internal::CandidateBatch& batch) {
          const auto batch_start = std::chrono::steady_clock::now();
          decide(batch, scaled, s.faces, s.edges, pair_options, width.has_value(), out);
          out.narrow_seconds += seconds_since(batch_start);
        });
        out.seconds = seconds_since(task_start);
      });
  // Walking and deciding ran interleaved: their wall time is split in the ratio of their
  // times summed over the tasks.
  const double walk_seconds = seconds_since(walk_start);
  double narrow_sum = 0.0, task_sum = 0.0;
  for (const TaskCollisions& c : collisions) {
    result.vertex_face_candidates += c.vertex_face_candidates;
    result.edge_edge_candidates += c.edge_edge_candidates;
    narrow_sum += c.narrow_seconds;
    task_sum += c.seconds;
  }
  const double narrow_share = task_sum > 0.0 ? std::min(1.0, narrow_sum / task_sum) : 0.0;
  result.broad_phase_seconds = prepare_seconds + (1.0 - narrow_share) * walk_seconds;

  const auto gather_start = std::chrono::steady_clock::now();
  // Tasks in order, vertex-face pairs before edge-edge ones, as result holds them; the
  // brackets in the same order.
  std::vector<TimeInterval> brackets;
  for (const TaskCollisions& c : collisions) {
    result.vertex_face.insert(result.vertex_face.end(), c.vertex_face.begin(), c.vertex_face.end());
    brackets.insert(brackets.end(), c.vertex_face_brackets.begin(), c.vertex_face_brackets.end());
  }
  for (const TaskCollisions& c : collisions) {
    for (const internal::EdgeIndexPair& pair : c.edge_edge)
      result.edge_edge.push_back({s.edges[pair.a], s.edges[pair.b]});
    brackets.insert(brackets.end(), c.edge_edge_brackets.begin(), c.edge_edge_brackets.end());
  }
  if (!brackets.empty()) {
    result.time_of_impact = refine_earliest(result, brackets, scaled_step.min_separation, scaled,
                                            s.faces, *width, options);
  }
  std::sort(result.vertex_face.begin(), result.vertex_face.end());
  std::sort(result.edge_edge.begin(), result.edge_edge.end());
  result.narrow_phase_seconds = narrow_share * walk_seconds + seconds_since(gather_start);
  return result;
}

std::vector<double> flat_positions(std::span<const Point3> points) {
  std::vector<double> flat;
  flat.reserve(3 * points.size());
  for (const Point3& p : points)
    flat.insert(flat.end(), p.begin(), p.end());
  return flat;
}

MeshCcdResult find_collisions(std::span<const Triangle> faces, const StepPositions& positions,
                              const MeshCcdOptions& options) {
  if (positions.t0.size() % 3 != 0) {
    throw std::invalid_argument("positions.t0 holds " + std::to_string(positions.t0.size()) +
                                " values, not a multiple of 3");
  }
  return MeshCcd(positions.t0.size() / 3, faces).step(positions, options);
}

VertexFaceQuery vertex_face_query(const StepPositions& positions, std::span<const Triangle> faces,
                                  VertexFacePair pair) noexcept {
  const Triangle& f = faces[pair.face];
  const auto& t0 = positions.t0;
  const auto& t1 = positions.t1;
  return {position(t0, pair.vertex), position(t0, f[0]), position(t0, f[1]), position(t0, f[2]),
          position(t1, pair.vertex), position(t1, f[0]), position(t1, f[1]), position(t1, f[2])};
}

EdgeEdgeQuery edge_edge_query(const StepPositions& positions, const EdgeEdgePair& pair) noexcept {
  const auto& t0 = positions.t0;
  const auto& t1 = positions.t1;
  return {position(t0, pair.a[0]), position(t0, pair.a[1]), position(t0, pair.b[0]),
          position(t0, pair.b[1]), position(t1, pair.a[0]), position(t1, pair.a[1]),
          position(t1, pair.b[0]), position(t1, pair.b[1])};
}

}  // namespace exactgeo::ccd
