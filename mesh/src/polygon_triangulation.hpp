#pragma once

// A file's polygon of more than four corners, made into triangles in O(n log n) for n
// corners. The triangles come from the polygon's projection along a coordinate axis (the
// axis its Newell normal is nearest first, then the others), every decision an exact
// orientation sign: one plane sweep (polygon_sweep.hpp) finds whether the projection's
// edges meet only at shared corners and the region they bound (a bridge to a hole walked
// both ways bounds nothing), and refuses the projection otherwise; the classic sweep
// triangulation (monotone pieces, polygon_monotone.hpp) splits that region, and a
// certificate independent of how the triangles were made (polygon_certificate.hpp)
// proves that their projections tile it without overlap or gap. Ear clipping (quadratic,
// polygon_ears.hpp) is kept for the odd projection that touches itself at a corner,
// certified the same way, and splits the polygons of at most 16 corners (most faces of
// most files), which the certificate checks pair by pair: there the sweeps' setup would
// cost more than the quadratic work. So the triangles form a surface bounded by the
// polygon's edges that never folds over itself (a graph over the projection plane), none
// of them degenerate. For a planar polygon that surface is the polygon itself; a polygon
// whose corners are off one plane (decimal coordinates rarely are exactly planar) gets
// the graph. A polygon no projection makes simple has no such surface: the caller
// refuses it, or makes it the fan from its first corner on request.

#include <span>
#include <vector>

#include "exactgeo/mesh/mesh.hpp"

namespace exactgeo::mesh::internal {

enum class PolygonForm {
  planar,         ///< split into triangles covering exactly the polygon
  non_planar,     ///< split into triangles over a simple projection
  zero_area,      ///< every corner on one line: a fan of zero-area triangles
  self_crossing,  ///< no projection is simple (edges cross, touch or overlap): not split
};

/// The form of the polygon with these corners (indices into `vertices`, in range, finite
/// coordinates), and unless it is self_crossing its triangles, oriented as the polygon is
/// walked, appended to `out`. Precondition: at least three corners.
PolygonForm triangulate_polygon(std::span<const VertexIndex> corners,
                                std::span<const Point3> vertices, std::vector<Face>& out);

/// The fan of triangles from the first corner: (c0, c[i], c[i+1]).
void append_fan(std::span<const VertexIndex> corners, std::vector<Face>& out);

}  // namespace exactgeo::mesh::internal
