#pragma once

// The plane sweep that finds whether a polygon's walk, seen along one coordinate axis,
// bounds a region: its edges meet only at common endpoints, and every winding number is
// 0 or 1 (or every one 0 or -1). O(n log n) for n corners. Both the certificate
// (polygon_certificate.hpp) and the triangulation (polygon_triangulation.hpp) start here:
// a projection this sweep refuses is never triangulated.

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "exactgeo/predicates/sign.hpp"
#include "polygon_projection.hpp"
#include "polygon_walk.hpp"
#include "scratch_vector.hpp"

namespace exactgeo::mesh::internal {

/// The closed segments [a0, a1] and [b0, b1] of the projection (each from its earlier
/// end in sweep order to its later one, neither of zero length) share a point other than
/// a common endpoint position, exactly: they cross, an endpoint of one lies inside the
/// other, or they overlap on one line.
bool segments_meet_improperly(const Point3& a0, const Point3& a1, const Point3& b0,
                              const Point3& b1, const Projection& plane);

/// How the region the walk winds around turns in this projection: positive when the
/// walk's winding number is 0 or 1 at every point off its edges, negative when it is 0 or
/// -1 (the walk runs clockwise); nullopt when two of the walk's edges (each pair of
/// vertices it joins, a bridge walked both ways included) meet anywhere but at a common
/// endpoint position (cross, or one's end lies inside the other, or they overlap on one
/// line), when an edge has zero length in the projection, when winding numbers beyond
/// +-1 or of both signs occur, or when every one is 0. `order` is
/// sweep_order(walk, vertices, plane).
///
/// A Shamos–Hoey sweep in the lexicographic order of the projected points: the status
/// (edges across the sweep line, bottom to top) is ordered by exact orientations at
/// insertion, and each edge is tested exactly against its neighbours when it is inserted
/// and when it leaves (removals at a point before insertions there), which finds the
/// first place two edges meet improperly if there is one. Each status edge carries the
/// winding number of the region just above it: the region's below it plus the edge's net
/// direction (+1 for each walk left to right, -1 for each walk right to left; 0 for a
/// bridge); below the lowest edge it is 0. Every region of the plane is just above some
/// edge at the lexicographically first point of its boundary, where that edge is inserted
/// (edges from one point are inserted lowest first): so every region is checked.
///
/// When `below` is given, the sweep also records what the triangulation's own sweep would
/// search for (polygon_monotone.hpp), so that it need not: for each vertex (by local
/// number), the edge just below its point when the sweep reaches it (after the edges that
/// end there have left), passing over bridges (edges of coefficient 0): an index into
/// walk.edges, kNoEdge when none lies below, kUnknownEdge when more than a few bridges
/// lie in between. Nothing the certificate decides depends on it.
inline constexpr std::uint32_t kNoEdge = 0xffffffff;
inline constexpr std::uint32_t kUnknownEdge = 0xfffffffe;
std::optional<Sign> region_turn(const PolygonWalk& walk, std::span<const std::uint32_t> order,
                                std::span<const Point3> vertices, const Projection& plane,
                                ScratchVector<std::uint32_t>* below = nullptr);

}  // namespace exactgeo::mesh::internal
