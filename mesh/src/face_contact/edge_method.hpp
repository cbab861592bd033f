#pragma once

// The edge method: every edge of one face against the other face, for any pair that is
// not two convex polygons (a skew quad, or a flat quad that is not strictly convex).
//
// Each open edge's crossings with the other face are counted by exact ray-face tests
// (crossing_parity.hpp): the crossings of the ray from one end through the other, minus
// those of the ray from the far end onward. An odd count proves an intersection; an edge
// that starts, ends or runs on the other face, or meets its boundary, leaves the pair
// undecided, since touching is not intersecting and the rays cannot tell the two apart.

#include "exactgeo/mesh/self_intersection.hpp"
#include "face_geometry.hpp"

namespace exactgeo::mesh::internal {

/// An edge of one face crossing the other's interior an odd number of times crosses it
/// transversally at some interior point z (multiplicities are 1 or 2, a tangency counts
/// 2), so nearby points of the first face's interior lie on both sides of the second
/// face near z, and the interiors meet.
FaceContact edge_method(const FaceGeometry& a, const FaceGeometry& b) noexcept;

}  // namespace exactgeo::mesh::internal
