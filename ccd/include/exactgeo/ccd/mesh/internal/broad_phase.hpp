#pragma once

// The broad phase of mesh-level CCD (mesh_ccd.hpp): the vertex-face and edge-edge pairs
// whose swept boxes overlap, without pairs sharing a vertex and without rigid pairs.
//
// One box tree per kind of primitive (boxes/box_tree.hpp) over the vertices' swept boxes,
// built on the first step and refitted on the next ones; rebuilt when refitting has made
// it too loose. The pairs come from walking the vertex tree against the face tree and
// the edge tree against itself (boxes/tree_pairs.hpp), adjacent pairs skipped.
//
// A step is prepared once (boxes swept, trees fitted, both walks split into tasks), then
// each task is walked on its own, on any thread, and hands its pairs over in batches of
// a fixed size: a caller that decides each batch where it is found (MeshCcd::step) never
// holds the step's candidate list, whose size has no bound but the square of the mesh's.

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "exactgeo/boxes/box_tree.hpp"
#include "exactgeo/boxes/tree_pairs.hpp"
#include "exactgeo/ccd/mesh/mesh_ccd.hpp"

namespace exactgeo::ccd::internal {

/// Two edges by their index in the mesh's sorted edge list, a < b.
struct EdgeIndexPair {
  std::uint32_t a;
  std::uint32_t b;
};

struct MeshCandidates {
  std::vector<VertexFacePair> vertex_face;
  std::vector<EdgeIndexPair> edge_edge;
  bool trees_rebuilt = false;  ///< the trees were built in this call, not refitted
};

/// Some of a task's candidate pairs, each kind in the order the walk met them.
struct CandidateBatch {
  std::span<const VertexFacePair> vertex_face;
  std::span<const EdgeIndexPair> edge_edge;
};

/// A worker's memory for walking tasks, reused from task to task: the walk's stack of node
/// pairs and the batch being filled.
struct WalkScratch {
  std::vector<boxes::NodePair> stack;
  std::vector<VertexFacePair> vertex_face;
  std::vector<EdgeIndexPair> edge_edge;
};

/// Fills `out` with each vertex's swept box in the Scale of `largest` (grown by half of
/// min_separation on every side), its exact displacement p_t1 - p_t0 and its motion digest,
/// as the broad phase sees them; `out` keeps its capacity from call to call.
void sweep_vertices(const StepPositions& positions, double largest, double min_separation,
                    unsigned threads, boxes::VertexBoxes& out);

class MeshBroadPhase {
 public:
  /// Pairs of one kind in a batch, at most: 16 KiB of vertex-face pairs, as much again of
  /// edge-edge pairs, per worker; enough that handing a batch over costs nothing next to
  /// deciding its pairs.
  static constexpr std::size_t kBatchPairs = 2048;

  /// `faces` and `edges` (sorted, unique) must outlive this object and stay unchanged.
  MeshBroadPhase(std::size_t vertex_count, std::span<const Triangle> faces,
                 std::span<const Edge> edges);

  struct PreparedStep {
    std::size_t tasks = 0;       ///< walk(task, ...) for every task in [0, tasks)
    bool trees_rebuilt = false;  ///< the trees were built for this step, not refitted
  };

  /// Sweeps the step's boxes, fits the trees to them and splits both walks into tasks, on
  /// `threads` threads. Preconditions: positions hold 3 * vertex_count finite values each
  /// and outlive the walks of this step; `largest` is their largest magnitude (MeshCcd::step
  /// has it already; it sets the boxes' Scale). With min_separation > 0 (in the positions'
  /// units), pairs whose swept boxes are within it count too.
  PreparedStep prepare(const StepPositions& positions, double largest, unsigned threads,
                       double min_separation = 0.0);

  /// Task `task` of the prepared step: its candidate pairs, given to `decide` in batches of
  /// at most kBatchPairs of each kind. The tasks together give every candidate pair of the
  /// step once; which task gives which pair, and in what order, depends only on the input
  /// and on the steps before (through the trees), never on the thread count. Const: tasks
  /// may run at once, each worker with its own scratch.
  void walk(std::size_t task, WalkScratch& scratch,
            const std::function<void(const CandidateBatch&)>& decide) const;

  /// Every candidate pair of the step, tasks in order: prepare(), then every walk().
  MeshCandidates candidates(const StepPositions& positions, double largest, unsigned threads,
                            double min_separation = 0.0);

 private:
  /// Refits the trees to this step's boxes, or builds them; returns whether it built.
  bool fit_trees(unsigned threads);
  boxes::Walk<1, 3> vertex_face_walk() const noexcept {
    return {vertex_tree_, face_tree_, sweep_, boxes::SharedCorners::skip};
  }
  boxes::Walk<2, 2> edge_edge_walk() const noexcept {
    return {edge_tree_, edge_tree_, sweep_, boxes::SharedCorners::skip};
  }

  std::span<const Triangle> faces_;
  std::span<const Edge> edges_;
  std::vector<std::array<VertexIndex, 1>> vertices_;  // {0}, {1}, ...: vertices as primitives
  bool built_ = false;
  boxes::BoxTree<1> vertex_tree_;
  boxes::BoxTree<2> edge_tree_;
  boxes::BoxTree<3> face_tree_;
  // The prepared step: its vertex boxes, and the node pairs each task starts from (the
  // vertex-face walk's first, then the edge-edge walk's).
  boxes::VertexBoxes sweep_;
  std::vector<boxes::NodePair> vertex_face_starts_;
  std::vector<boxes::NodePair> edge_edge_starts_;
};

}  // namespace exactgeo::ccd::internal
