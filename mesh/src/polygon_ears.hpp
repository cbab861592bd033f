#pragma once

// Ear clipping in a projection, quadratic in the number of corners: the fallback for the
// few polygons the sweep (polygon_monotone.hpp) does not take.

#include <span>
#include <vector>

#include "exactgeo/mesh/mesh.hpp"
#include "exactgeo/predicates/sign.hpp"
#include "polygon_projection.hpp"

namespace exactgeo::mesh::internal {

/// Ear clipping in a projection: a corner is an ear when it turns as `turn` (strictly)
/// and no other remaining corner lies in the closed triangle it makes with its
/// neighbours, except another occurrence of one of the triangle's own vertices (a polygon
/// with a hole, written with a bridge walked both ways, repeats the bridge's ends).
/// Appends the n - 2 triangles, oriented as the polygon is walked, each turning as `turn`;
/// false when no ear is left before the end (a polygon whose edges cross). `p` holds the
/// corners' points. Precondition: no corner next to an occurrence of itself.
bool clip_ears(std::span<const VertexIndex> corners, std::span<const Point3> p,
               const Projection& plane, Sign turn, std::vector<Face>& out);

}  // namespace exactgeo::mesh::internal
