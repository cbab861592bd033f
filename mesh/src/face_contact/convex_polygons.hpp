#pragma once

// Two convex polygons (triangles, convex quads): exact and complete, apart or intersecting,
// never undecided.
//
// The open faces are the polygons' interiors. Coplanar polygons facing opposite ways only
// touch by the rule of self_intersection.hpp (CoplanarOverlap::touching); facing the same
// way, or under CoplanarOverlap::intersecting either way, they meet exactly when no line
// through an edge of either weakly separates them. Polygons in planes that cross
// meet exactly when the open chords in which each cuts the other's plane overlap on the
// planes' common line. Every test is an exact orient3d sign (convex_polygons.cpp has the
// derivations).

#include "exactgeo/mesh/self_intersection.hpp"
#include "face_geometry.hpp"

namespace exactgeo::mesh::internal {

/// Precondition: a.convex_polygon() and b.convex_polygon().
FaceContact convex_polygons_contact(const FaceGeometry& a, const FaceGeometry& b,
                                    CoplanarOverlap coplanar) noexcept;

}  // namespace exactgeo::mesh::internal
