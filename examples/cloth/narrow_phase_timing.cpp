#include "narrow_phase_timing.hpp"

#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <utility>
#include <vector>

namespace exactgeo::cloth {

namespace {

using Clock = std::chrono::steady_clock;

constexpr int kReplays = 3;

inline ccd::Result call(const ccd::VertexFaceQuery& q, const ccd::Options& o) {
  return ccd::vertex_face_ccd(q, o);
}
inline ccd::Result call(const ccd::EdgeEdgeQuery& q, const ccd::Options& o) {
  return ccd::edge_edge_ccd(q, o);
}

ccd::Options options_of(ccd::Method method) {
  ccd::Options options;
  options.method = method;
  return options;
}

/// Times `method` on the queries, and keeps those it finds colliding.
template <class Query>
void time_calls(const std::vector<Query>& queries, ccd::Method method, CallTimes& times,
                std::vector<Query>& colliding) {
  const ccd::Options options = options_of(method);
  const Clock::time_point start = Clock::now();
  for (const Query& q : queries) {
    if (call(q, options).collision) colliding.push_back(q);
  }
  times.seconds += std::chrono::duration<double>(Clock::now() - start).count();
  times.calls += queries.size();
}

/// Replays the kept colliding calls kReplays times, each a sample, and empties them.
template <class Query>
void replay(std::vector<Query>& colliding, ccd::Method method, CallTimes& times) {
  if (colliding.empty()) return;
  const ccd::Options options = options_of(method);
  for (int r = 0; r < kReplays; ++r) {
    std::size_t confirmed = 0;
    const Clock::time_point start = Clock::now();
    for (const Query& q : colliding)
      confirmed += call(q, options).collision ? 1 : 0;
    const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
    if (confirmed != colliding.size()) {
      throw std::logic_error("a CCD method answered the same query in two ways");
    }
    times.colliding_seconds += seconds;
    times.colliding_replayed += colliding.size();
    times.colliding_samples.push_back(1e9 * seconds / static_cast<double>(colliding.size()));
  }
  times.colliding_calls += colliding.size();
  colliding.clear();
}

double per_call(double seconds, std::size_t calls) {
  return calls > 0 ? 1e9 * seconds / static_cast<double>(calls) : 0.0;
}

}  // namespace

double CallTimes::nanoseconds_per_call() const noexcept {
  return per_call(seconds, calls);
}
double CallTimes::nanoseconds_per_colliding_call() const noexcept {
  return per_call(colliding_seconds, colliding_replayed);
}
double CallTimes::colliding_min() const noexcept {
  return colliding_samples.empty()
             ? 0.0
             : *std::min_element(colliding_samples.begin(), colliding_samples.end());
}
double CallTimes::colliding_max() const noexcept {
  return colliding_samples.empty()
             ? 0.0
             : *std::max_element(colliding_samples.begin(), colliding_samples.end());
}

void NarrowPhaseTiming::add(const ccd::StepPositions& positions,
                            std::span<const ccd::Triangle> faces,
                            const ccd::MeshCcdCandidates& candidates) {
  std::vector<ccd::VertexFaceQuery> vertex_face;
  vertex_face.reserve(candidates.vertex_face.size());
  for (const ccd::VertexFacePair& pair : candidates.vertex_face)
    vertex_face.push_back(ccd::vertex_face_query(positions, faces, pair));
  std::vector<ccd::EdgeEdgeQuery> edge_edge;
  edge_edge.reserve(candidates.edge_edge.size());
  for (const ccd::EdgeEdgePair& pair : candidates.edge_edge)
    edge_edge.push_back(ccd::edge_edge_query(positions, pair));
  for (const auto& [method, times, kept] :
       {std::tuple{ccd::Method::exact, &exact_, &kept_exact_},
        std::tuple{ccd::Method::cubic, &cubic_, &kept_cubic_}}) {
    time_calls(vertex_face, method, times->vertex_face, kept->vertex_face);
    time_calls(edge_edge, method, times->edge_edge, kept->edge_edge);
    if (kept->vertex_face.size() >= kCollidingBatch)
      replay(kept->vertex_face, method, times->vertex_face);
    if (kept->edge_edge.size() >= kCollidingBatch)
      replay(kept->edge_edge, method, times->edge_edge);
  }
}

void NarrowPhaseTiming::finish() {
  for (const auto& [method, times, kept] :
       {std::tuple{ccd::Method::exact, &exact_, &kept_exact_},
        std::tuple{ccd::Method::cubic, &cubic_, &kept_cubic_}}) {
    replay(kept->vertex_face, method, times->vertex_face);
    replay(kept->edge_edge, method, times->edge_edge);
  }
}

}  // namespace exactgeo::cloth
