#pragma once

// Triangles for the region a polygon's walk bounds in one projection, by the classic
// sweep (de Berg, Cheong, van Kreveld, Overmars, Computational Geometry, chapter 3): one
// pass in sweep order splits the region into pieces monotone along the sweep direction
// with diagonals from each split and merge corner to a helper corner, then each piece is
// triangulated with a stack. O(n log n) for n corners; every turn an exact orientation,
// the sweep order lexicographic (polygon_projection.hpp).

#include <cstdint>
#include <span>
#include <vector>

#include "exactgeo/mesh/mesh.hpp"
#include "exactgeo/predicates/sign.hpp"
#include "polygon_projection.hpp"
#include "polygon_walk.hpp"

namespace exactgeo::mesh::internal {

/// Appends triangles for the region the walk winds around, turning as `turn` in the
/// projection (oriented as the polygon is walked), and returns true; or returns false,
/// appending nothing, when the walk is not of the form the sweep takes: after a bridge's
/// two walks cancel, every corner still joined must have one edge in and one out (loops
/// that touch at a corner, or an edge walked twice, do not), and those corners must
/// project to distinct points. Precondition: region_turn (polygon_sweep.hpp) found
/// `turn` for this projection, so the loops are disjoint and bound a region on one side
/// each. Its output is not trusted: the caller certifies it (polygon_certificate.hpp),
/// and so a region the sweep mishandles costs time, never a wrong surface. `below` is
/// what region_turn recorded for this projection (its `below`), which spares this sweep
/// its searches; empty, or with a gap, the sweep searches its own status.
bool triangulate_by_sweep(const PolygonWalk& walk, std::span<const std::uint32_t> order,
                          std::span<const Point3> vertices, const Projection& plane, Sign turn,
                          std::span<const std::uint32_t> below, std::vector<Face>& out);

}  // namespace exactgeo::mesh::internal
