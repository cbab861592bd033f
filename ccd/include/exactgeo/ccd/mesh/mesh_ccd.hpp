#pragma once

// Mesh-level continuous collision detection: every colliding vertex-face and edge-edge
// pair of a triangle mesh over one time step, and optionally the earliest time of impact.
//
// A simulator hands over the positions at the start (t0) and the end (t1) of a step; each
// vertex moves on the straight line between them. The connectivity is fixed when the
// MeshCcd is made, so the edge list and the adjacency are built once.
//
//   broad phase   swept boxes (the box of a primitive's corners at t0 and t1 contains the
//                 primitive at every time in between, because each corner moves on a
//                 segment and a box is convex), rounded outward to float, in one box tree
//                 per kind of primitive (boxes/box_tree.hpp), built on the first step
//                 and refitted on later ones; the vertex tree is walked against the face
//                 tree and the edge tree against itself (docs/ccd.md says why). Pairs
//                 sharing a vertex are skipped, and so are rigid pairs: all four corners
//                 move by exactly the same vector p_t1 - p_t0 (standing still, the zero
//                 vector, included), so their distance is constant over the step and a
//                 contact between them is not a collision of this step.
//   narrow phase  vertex_face_ccd / edge_edge_ccd (ccd.hpp) on every candidate, in
//                 batches of a fixed size decided where the tree walk finds them, on all
//                 threads: a step's memory is the mesh, its trees, a fixed budget per
//                 thread and the pairs that collide, however many candidates it has.
//                 The output is sorted, so it is the same for every thread count.
//
// The broad phase never drops a pair that the narrow phase would report (tests compare
// with exhaustive pairwise CCD on every non-adjacent pair).

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "exactgeo/ccd/ccd.hpp"
#include "exactgeo/predicates/point.hpp"
#include "exactgeo/surface/triangle_surface.hpp"

namespace exactgeo::ccd {

using exactgeo::Edge;         // surface/triangle_surface.hpp: smaller vertex first
using exactgeo::FaceIndex;    // predicates/point.hpp
using exactgeo::Triangle;     // surface/triangle_surface.hpp
using exactgeo::VertexIndex;  // predicates/point.hpp

struct VertexFacePair {
  VertexIndex vertex = 0;
  FaceIndex face = 0;
  friend auto operator<=>(const VertexFacePair&, const VertexFacePair&) = default;
};

/// Two edges, each with its smaller vertex first, the smaller edge first.
struct EdgeEdgePair {
  Edge a{};
  Edge b{};
  friend auto operator<=>(const EdgeEdgePair&, const EdgeEdgePair&) = default;
};

/// Positions at both ends of the step: x, y, z of vertex 0, then of vertex 1, ...
/// (3 * vertex_count doubles each, finite). Flat doubles rather than points, so that a
/// simulator's arrays (numpy, Eigen, a solver's state) are read where they lie, uncopied.
struct StepPositions {
  std::span<const double> t0;
  std::span<const double> t1;
};

/// The points in StepPositions' layout: x, y, z of the first point, then of the second, ...
std::vector<double> flat_positions(std::span<const Point3> points);

struct MeshCcdOptions {
  /// exact (every root) or parity (odd root counts and boundary roots); the other methods
  /// are accepted for measuring the trade.
  Method method = Method::exact;
  /// Also bracket the mesh's earliest root to at most this width (exact; the other
  /// methods have no time of impact and bracket the whole step, [0, 1]).
  std::optional<double> time_of_impact_width;
  /// Worker threads for the sweep and the narrow phase; 0: one per hardware thread.
  unsigned threads = 0;
  /// exact only: report pairs whose Euclidean distance drops to at most this during the
  /// step (ccd.hpp, Options::min_separation); the broad phase grows its boxes by it.
  /// Finite and >= 0. The time of impact is then the earliest time within it.
  double min_separation = 0.0;
};

struct MeshCcdResult {
  std::vector<VertexFacePair> vertex_face;  ///< sorted, each pair once
  std::vector<EdgeEdgePair> edge_edge;      ///< sorted, each pair once
  std::size_t vertex_face_candidates = 0;   ///< broad-phase pairs given to the narrow phase
  std::size_t edge_edge_candidates = 0;
  /// With time_of_impact_width and a collision: no root before start, a root by end.
  std::optional<TimeInterval> time_of_impact;
  /// True when the broad phase built a tree in this step (the first step, or one after
  /// the mesh moved so far that refitting the trees would have made them slow).
  bool trees_rebuilt = false;
  /// Wall times. The tree walk and the narrow phase run interleaved (each batch of
  /// candidates is decided where it is found); their shared wall time is split between
  /// the two in the ratio of their times summed over the threads.
  double broad_phase_seconds = 0.0;
  double narrow_phase_seconds = 0.0;

  std::size_t candidates() const noexcept { return vertex_face_candidates + edge_edge_candidates; }
  bool collision() const noexcept { return !vertex_face.empty() || !edge_edge.empty(); }
};

/// The broad phase's pairs of a step, before the narrow phase (MeshCcd::candidates).
struct MeshCcdCandidates {
  std::vector<VertexFacePair> vertex_face;
  std::vector<EdgeEdgePair> edge_edge;
};

class MeshCcd {
 public:
  /// Throws std::invalid_argument when a face has a corner index >= vertex_count or a
  /// repeated corner.
  MeshCcd(std::size_t vertex_count, std::span<const Triangle> faces);
  MeshCcd(MeshCcd&&) noexcept;
  MeshCcd& operator=(MeshCcd&&) noexcept;
  ~MeshCcd();

  /// Every colliding pair over the step. Throws std::invalid_argument when a frame does not
  /// hold 3 * vertex_count() values or holds a non-finite one (naming the vertex), and
  /// when options.min_separation is negative or not finite, or positive with another
  /// method than exact.
  /// Not const: it keeps the broad phase's trees for the next step. One
  /// MeshCcd per thread; different MeshCcd objects are independent.
  MeshCcdResult step(const StepPositions& positions, const MeshCcdOptions& options = {});

  /// The pairs step() would give to the narrow phase for these positions (its broad phase
  /// alone, trees kept as step() keeps them; options.method is not used), for simulators
  /// that run their own narrow phase and for measuring it: vertex_face_query and
  /// edge_edge_query make each pair's query. Throws as step() does.
  MeshCcdCandidates candidates(const StepPositions& positions, const MeshCcdOptions& options = {});

  std::size_t vertex_count() const noexcept;
  std::span<const Triangle> faces() const noexcept;
  /// The unique edges of the faces, sorted, each with its smaller vertex first.
  std::span<const Edge> edges() const noexcept;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

/// One step without keeping anything: MeshCcd(vertex_count, faces).step(positions, options).
MeshCcdResult find_collisions(std::span<const Triangle> faces, const StepPositions& positions,
                              const MeshCcdOptions& options = {});

/// The per-pair queries of a mesh, for simulators that run their own broad phase.
/// Preconditions: indices in range, positions as for MeshCcd::step.
VertexFaceQuery vertex_face_query(const StepPositions& positions, std::span<const Triangle> faces,
                                  VertexFacePair pair) noexcept;
EdgeEdgeQuery edge_edge_query(const StepPositions& positions, const EdgeEdgePair& pair) noexcept;

}  // namespace exactgeo::ccd
