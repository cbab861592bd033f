#pragma once

// Candidate faces for a ray: a superset of the faces the ray {origin + s d : s >= 0}
// touches. The exact predicates decide every candidate, so a finder may propose too much
// but never too little. Directions are given by their index in the fixed sequence
// (exactgeo/predicates/ray_directions.hpp).

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "exactgeo/mesh/check.hpp"
#include "exactgeo/mesh/mesh.hpp"

namespace exactgeo::inside::internal {

/// Every face: the oracle the accelerated finder is tested against, and the fallback for
/// directions a single-precision tracer cannot represent exactly.
inline void all_faces(const mesh::Mesh& mesh, std::vector<FaceIndex>& out) {
  out.resize(mesh.faces.size());
  for (std::size_t f = 0; f < out.size(); ++f)
    out[f] = static_cast<FaceIndex>(f);
}

/// Embree over user geometry: one primitive per face, bounded by the corners' box rounded
/// outward to float and padded. The intersection callback only records the face and lets
/// traversal go on. Embree stays out of every public header.
class EmbreeCandidates {
 public:
  /// Builds the BVH over `mesh` (which must outlive this object) in the float frame of
  /// `box`, which must hold every face's corners (corner_box(mesh) or larger; not much
  /// larger, or the frame's floats get coarse). Throws std::runtime_error if Embree fails
  /// (out of memory, unsupported CPU).
  EmbreeCandidates(const mesh::Mesh& mesh, const mesh::Box& box);
  ~EmbreeCandidates();
  EmbreeCandidates(EmbreeCandidates&&) noexcept;
  EmbreeCandidates& operator=(EmbreeCandidates&&) noexcept;

  /// Replaces `out` with the candidates for the ray from `origin` along direction
  /// `direction_index` (< kFloatExactRayDirections), sorted, without repeats. `origin`
  /// must lie in the closed box given to the constructor: the frame's rounding argument
  /// (float_frame.hpp) holds there and nowhere else. Thread-safe.
  void find(const Point3& origin, std::size_t direction_index, std::vector<FaceIndex>& out) const;

 private:
  struct Scene;
  std::unique_ptr<Scene> scene_;
};

}  // namespace exactgeo::inside::internal
