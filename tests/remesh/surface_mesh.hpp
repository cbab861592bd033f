#pragma once

// The exact self-intersection finder's verdict on a remesh::Surface under the rule for
// sheets that must stay apart (a coplanar overlap with area counts whichever way the
// triangles face).

#include "exactgeo/mesh/mesh.hpp"
#include "exactgeo/mesh/self_intersection.hpp"
#include "exactgeo/remesh/surface.hpp"

namespace exactgeo::testing {

/// The pairs of triangles that meet outside their shared corners, a flat overlap included.
inline mesh::SelfIntersections sheets_meeting(const remesh::Surface& s) {
  return mesh::find_self_intersections(mesh::mesh_of(s), 1, mesh::CoplanarOverlap::intersecting);
}

}  // namespace exactgeo::testing
