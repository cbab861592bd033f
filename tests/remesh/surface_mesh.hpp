#pragma once

// A remesh::Surface as the mesh::Mesh the exact self-intersection finder reads.

#include "exactgeo/mesh/mesh.hpp"
#include "exactgeo/remesh/surface.hpp"

namespace exactgeo::testing {

inline mesh::Mesh as_mesh(const remesh::Surface& s) {
  mesh::Mesh m;
  m.vertices = s.vertices;
  for (const remesh::Triangle& t : s.triangles)
    m.faces.push_back(mesh::make_triangle(t[0], t[1], t[2]));
  return m;
}

}  // namespace exactgeo::testing
