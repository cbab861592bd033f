#pragma once

// Candidate faces for a ray from exactgeo's own box tree (boxes/box_tree.hpp), for meshes
// too small to be worth opening Embree: loading Embree and starting its device cost a
// few milliseconds, more than all the rays of a small mesh (docs/inside.md, "End to end").
//
// Each face's box is its corners' box in the float frame (float_frame.hpp), rounded
// outward to float and padded by FloatFrame::kPad = 2^-20, as Embree's are. The ray/box
// test is done in double, in the same frame. Why it loses no face (u = 2^-53, the double
// unit roundoff; every mapped point of the frame's box has |x| < 2):
//
// - The query origin is mapped to q = fl((x - c) 2^-e), within 2^-52 of the exact image q*
//   (one rounding of a value below 2; the power of two is exact unless it underflows,
//   where it errs by less than 2^-1074). The face's corners are mapped the same way, and
//   then lowered (raised) by kPad in double (one more rounding, 2^-52) and rounded down
//   (up) to float: each float bound lies outside the exact image of the corners' box by
//   at least kPad - 2^-51.
// - The directions are (1, t, t^2) with t > 0 (ray_directions.hpp): every component is
//   positive and exact in double. With r = fl(1/d) per axis, the test computes, for each
//   bound b of a box, t_b = fl(fl(b - q) r) = ((b - q)/d)(1 + θ) with |θ| <= 3u + 3u^2 + u^3:
//   the exact parameter at which the ray crosses the plane of a bound b' = b + (b - q) θ.
//   With |b| < 2 + 2^-19 and |q| < 2, |b' - b| < 4.01 (3.01 u) < 2^-49. (A product that
//   underflows errs by at most 2^-1074 in t_b, a bound moved by d 2^-1074: nothing.) The
//   subtraction b - q never underflows inexactly, and nothing overflows (|b - q| < 5,
//   0 < r <= 1).
// - The box is met when max(0, t_lo per axis) <= min(t_hi per axis); max and min are exact.
//   So the computed test is the exact test of the ray q + s d, s >= 0, against a box
//   whose bounds each moved by less than 2^-49 from the float box's.
// So if the exact ray q* + s d (s >= 0) touches the corners' box at p, the computed ray
// passes q + s d, within 2^-52 of p on each axis, hence inside the float box shrunk by
// kPad - 2^-51 - 2^-52 > 2^-21, hence inside the box the computed test sees, at a parameter
// s >= 0: the box, and every node box above it (unions of boxes: exact min and max), is
// met. The margin is some 2^28 times what the rounding needs; it only makes a ray that
// passes within 2^-20 (of a unit-sized frame) of a face's box propose that face.
// tests/inside/tree_candidates_test.cpp checks it against every face the exact predicates
// say a ray touches, with rays through vertices and edges, along axis-parallel faces, and
// at magnitudes 2^-1000 to 2^1000.

#include <cstddef>
#include <memory>
#include <vector>

#include "exactgeo/mesh/check.hpp"
#include "exactgeo/mesh/mesh.hpp"

namespace exactgeo::inside::internal {

class TreeCandidates {
 public:
  /// Builds the tree over `mesh`'s faces (the mesh need not outlive it) in the float frame
  /// of `box`, which must hold every face's corners (corner_box(mesh) or larger).
  TreeCandidates(const mesh::Mesh& mesh, const mesh::Box& box);
  ~TreeCandidates();
  TreeCandidates(TreeCandidates&&) noexcept;
  TreeCandidates& operator=(TreeCandidates&&) noexcept;

  /// Replaces `out` with the candidates for the ray from `origin` along direction
  /// `direction_index` (any index whose direction is exact in double: below 2^25), sorted,
  /// without repeats. `origin` must lie in the closed box given to the constructor.
  /// Thread-safe.
  void find(const Point3& origin, std::size_t direction_index, std::vector<FaceIndex>& out) const;

 private:
  struct Tree;
  std::unique_ptr<Tree> tree_;
};

}  // namespace exactgeo::inside::internal
