#pragma once

// The certificate that triangles tile a polygon's projection, independent of how they
// were made, in O(n log n) for n corners: the sweep and the ear clipping of
// polygon_triangulation.cpp are both checked by it (a polygon of few corners by its
// pairwise form, few_triangles_tile), and nothing else makes a polygon's triangles
// trusted.
//
// The argument. Let every triangle turn strictly as `turn` in the projection, and let
// the boundary of the triangles' 2-chain equal the polygon's 1-chain: every directed
// triangle edge a -> b cancelled against a b -> a, what remains is exactly the polygon's
// directed edges with the same cancellation applied (a bridge to a hole walked both ways
// cancels itself). Then at every point y on no edge, the number of triangles covering y
// equals turn times the polygon's winding number around y: the winding number is
// additive over chains, a triangle turning as `turn` winds `turn` times around its
// interior and 0 times around its exterior, and the triangles' chain and the polygon's
// have one boundary. So the triangles' interiors are pairwise disjoint if and only if
// turn * winding(polygon, y) <= 1 at every y off the edges (two open triangles that
// overlap do so on an open set, which holds points on no edge), and they cover exactly
// the region where it is 1. One plane sweep over the polygon's edges decides that
// (region_turn, polygon_sweep.hpp), with the triangles unread: the sweep finds the
// winding number of every region of the plane the edges cut out, and the region's turn.
// It also refuses edges that meet other than at a common endpoint (a proper crossing, an
// endpoint inside another edge, an overlap on one line), so a projection that crosses
// itself is refused before any triangle is made. For the edges that bound triangles a
// tiling rules that out anyway (a corner inside an edge would have its triangles overlap
// the edge's); a bridge bounds none, and is checked so because ear clipping, which makes
// a bridge the edge of two triangles, always refused a walk whose bridge crosses an edge:
// the behaviour is kept, not needed for the tiling.
//
// One more condition keeps what the readers have always made: n - 2 triangles for n
// corners, as ear clipping makes. Loops that touch at a corner (a figure eight) are
// tiled by fewer, and have always been refused.

#include <span>
#include <vector>

#include "exactgeo/mesh/mesh.hpp"
#include "exactgeo/predicates/sign.hpp"
#include "polygon_projection.hpp"
#include "polygon_walk.hpp"

namespace exactgeo::mesh::internal {

/// The part of the certificate that reads the triangles, for a walk whose sweep
/// (region_turn) found `turn` in this projection: walk.corners - 2 triangles, each
/// turning strictly as `turn`, over the walk's vertices, whose boundary chain is the
/// walk's (pairs of coefficient 0 aside).
bool triangles_fit(const PolygonWalk& walk, std::span<const Face> triangles,
                   std::span<const Point3> vertices, const Projection& plane, Sign turn);

/// The same certificate for a polygon of few corners, pair by pair instead of by sweeps
/// (below a few dozen corners the sweeps' setup costs more than the quadratic work):
/// corners.size() - 2 triangles, each turning strictly as `turn`, whose boundary chain
/// is the walk's; no two triangles' interiors meeting, found by a separating line
/// through an edge of one of them (convex sets), which with the chain is the winding
/// number condition: a point inside two triangles is wound around twice; and no bridge
/// (an edge walked both ways) of zero length or meeting another edge of the walk other
/// than at a common endpoint (for the edges that bound triangles the tiling implies it).
/// `corners` has no corner next to an occurrence of itself.
bool few_triangles_tile(std::span<const VertexIndex> corners, std::span<const Face> triangles,
                        std::span<const Point3> vertices, const Projection& plane, Sign turn);

/// The whole certificate: the triangles' projections along `axis` tile the region the
/// polygon with these corners (indices into `vertices`, finite coordinates; corners
/// repeated next to each other count once) bounds in that projection, with pairwise
/// disjoint interiors, n - 2 of them, each turning as the polygon.
bool triangles_tile_polygon(std::span<const VertexIndex> corners, std::span<const Face> triangles,
                            std::span<const Point3> vertices, int axis);

}  // namespace exactgeo::mesh::internal
