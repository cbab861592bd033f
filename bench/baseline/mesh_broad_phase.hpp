#pragma once

// Kept unchanged as the baseline that ccd_mesh_bench measures the library's broad phase
// against in the same run (docs/ccd.md): the broad phase before refitted trees and
// dual-tree traversal, which builds a tree over the moving primitives every step and
// queries it once per primitive box.
//
// The broad phase of mesh-level CCD (ccd/mesh/mesh_ccd.hpp): the vertex-face and edge-edge pairs
// whose swept boxes overlap, without pairs sharing a vertex and without pairs whose
// corners all stand still. Standing primitives live in their own trees, kept from step to
// step while the same vertices stand at the same place (and the step's scale, swept_box.hpp,
// stays the same).

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "baseline/box_tree.hpp"
#include "baseline/swept_box.hpp"
#include "exactgeo/ccd/mesh/internal/broad_phase.hpp"
#include "exactgeo/ccd/mesh/mesh_ccd.hpp"

namespace exactgeo::ccd::bench::baseline {

using internal::EdgeIndexPair;  // the library's: the candidates of both are compared

struct MeshCandidates {
  std::vector<VertexFacePair> vertex_face;
  std::vector<EdgeIndexPair> edge_edge;
  bool standing_rebuilt = false;  ///< the standing trees were (re)built in this call
};

class MeshBroadPhase {
 public:
  /// `faces` and `edges` (sorted, unique) must outlive this object and stay unchanged.
  MeshBroadPhase(std::size_t vertex_count, std::span<const Triangle> faces,
                 std::span<const Edge> edges);

  /// Every candidate pair of the step, in an order that depends only on the input.
  /// Precondition: frames hold 3 * vertex_count finite values each.
  MeshCandidates candidates(const StepPositions& frames, unsigned threads);

 private:
  using Boxes = std::vector<SweptBox>;

  bool standing_unchanged(const std::vector<std::uint8_t>& moving, const StepPositions& frames,
                          const boxes::Scale& scale) const;
  void rebuild_standing(std::vector<std::uint8_t> moving, const StepPositions& frames,
                        const boxes::Scale& scale);

  std::size_t vertex_count_;
  std::span<const Triangle> faces_;
  std::span<const Edge> edges_;
  std::vector<std::array<VertexIndex, 1>> vertices_;  // {0}, {1}, ...: vertices as primitives

  bool standing_valid_ = false;
  std::vector<std::uint8_t> moving_;        // per vertex, when the standing trees were built
  std::vector<double> standing_positions_;  // t0 positions then (standing ones compared)
  boxes::Scale standing_scale_;             // the scale their boxes were made in
  QueryTree standing_vertices_;             // a tree only for its spatial order of queries
  QueryTree standing_edges_, standing_faces_;
};

}  // namespace exactgeo::ccd::bench::baseline
