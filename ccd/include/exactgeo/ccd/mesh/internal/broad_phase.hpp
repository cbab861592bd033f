#pragma once

// The broad phase of mesh-level CCD (mesh_ccd.hpp): the vertex-face and edge-edge pairs
// whose swept boxes overlap, without pairs sharing a vertex and without rigid pairs.
//
// One box tree per kind of primitive (boxes/box_tree.hpp) over the vertices' swept boxes,
// built on the first step and refitted on the next ones; rebuilt when refitting has made
// it too loose. The pairs come from walking the vertex tree against the face tree and
// the edge tree against itself (boxes/tree_pairs.hpp), adjacent pairs skipped.

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "exactgeo/boxes/box_tree.hpp"
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

class MeshBroadPhase {
 public:
  /// `faces` and `edges` (sorted, unique) must outlive this object and stay unchanged.
  MeshBroadPhase(std::size_t vertex_count, std::span<const Triangle> faces,
                 std::span<const Edge> edges);

  /// Every candidate pair of the step, in an order that depends only on the input and on
  /// the steps before (through the trees), never on the thread count.
  /// Preconditions: positions hold 3 * vertex_count finite values each; `largest` is their
  /// largest magnitude (MeshCcd::step has it already; it sets the boxes' Scale).
  /// With min_separation > 0 (in the positions' units), also every pair whose swept boxes
  /// are within it.
  MeshCandidates candidates(const StepPositions& positions, double largest, unsigned threads,
                            double min_separation = 0.0);

 private:
  /// Refits the trees to this step's boxes, or builds them; returns whether it built.
  bool fit_trees(const boxes::VertexBoxes& sweep, unsigned threads);

  std::span<const Triangle> faces_;
  std::span<const Edge> edges_;
  std::vector<std::array<VertexIndex, 1>> vertices_;  // {0}, {1}, ...: vertices as primitives
  bool built_ = false;
  boxes::BoxTree<1> vertex_tree_;
  boxes::BoxTree<2> edge_tree_;
  boxes::BoxTree<3> face_tree_;
};

}  // namespace exactgeo::ccd::internal
