#include "narrow_phase_timing.hpp"

#include <chrono>
#include <stdexcept>
#include <utility>
#include <vector>

namespace exactgeo::cloth {

namespace {

using Clock = std::chrono::steady_clock;

inline ccd::Result call(const ccd::VertexFaceQuery& q, const ccd::Options& o) {
  return ccd::vertex_face_ccd(q, o);
}
inline ccd::Result call(const ccd::EdgeEdgeQuery& q, const ccd::Options& o) {
  return ccd::edge_edge_ccd(q, o);
}

/// Times `method` on the queries, then again on those it found colliding.
template <class Query>
void time_calls(const std::vector<Query>& queries, ccd::Method method, CallTimes& times) {
  ccd::Options options;
  options.method = method;
  std::vector<Query> colliding;
  const Clock::time_point start = Clock::now();
  for (const Query& q : queries) {
    if (call(q, options).collision) colliding.push_back(q);
  }
  times.seconds += std::chrono::duration<double>(Clock::now() - start).count();
  times.calls += queries.size();

  std::size_t confirmed = 0;
  const Clock::time_point again = Clock::now();
  for (const Query& q : colliding)
    confirmed += call(q, options).collision ? 1 : 0;
  times.colliding_seconds += std::chrono::duration<double>(Clock::now() - again).count();
  times.colliding_calls += colliding.size();
  if (confirmed != colliding.size()) {
    throw std::logic_error("a CCD method answered the same query in two ways");
  }
}

double per_call(double seconds, std::size_t calls) {
  return calls > 0 ? 1e9 * seconds / static_cast<double>(calls) : 0.0;
}

}  // namespace

double CallTimes::nanoseconds_per_call() const noexcept {
  return per_call(seconds, calls);
}
double CallTimes::nanoseconds_per_colliding_call() const noexcept {
  return per_call(colliding_seconds, colliding_calls);
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
  for (const auto& [method, times] :
       {std::pair{ccd::Method::exact, &exact_}, std::pair{ccd::Method::cubic, &cubic_}}) {
    time_calls(vertex_face, method, times->vertex_face);
    time_calls(edge_edge, method, times->edge_edge);
  }
}

}  // namespace exactgeo::cloth
