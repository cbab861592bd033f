#pragma once

// A remesh::Surface as the mesh::Mesh the exact self-intersection finder reads, and the
// finder's verdict under the rule for sheets that must stay apart (a coplanar overlap with
// area counts whichever way the triangles face).

#include "exactgeo/mesh/mesh.hpp"
#include "exactgeo/mesh/self_intersection.hpp"
#include "exactgeo/remesh/surface.hpp"

namespace exactgeo::testing {

inline mesh::Mesh as_mesh(const remesh::Surface& s) {
  mesh::Mesh m;
  m.vertices = s.vertices;
  for (const remesh::Triangle& t : s.triangles)
    m.faces.push_back(mesh::make_triangle(t[0], t[1], t[2]));
  return m;
}

/// The pairs of triangles that meet outside their shared corners, a flat overlap included.
inline mesh::SelfIntersections sheets_meeting(const remesh::Surface& s) {
  return mesh::find_self_intersections(as_mesh(s), 1, mesh::CoplanarOverlap::intersecting);
}

}  // namespace exactgeo::testing
