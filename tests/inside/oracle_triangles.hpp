#pragma once

// A mesh's faces as the solid-angle oracle (support/solid_angle_oracle.hpp) takes them:
// triangles of points. The oracle integrates triangles, so a mesh of quads is split first
// (triangulated), and the classifier is then asked about the same split mesh.

#include <vector>

#include "exactgeo/mesh/mesh.hpp"
#include "support/solid_angle_oracle.hpp"

namespace exactgeo::testing {

/// The mesh's quads split along c0-c2; its triangles as they are.
inline mesh::Mesh triangulated(const mesh::Mesh& m) {
  mesh::Mesh out;
  out.vertices = m.vertices;
  for (const mesh::Face& f : m.faces) {
    const auto& c = f.corners;
    out.faces.push_back(mesh::make_triangle(c[0], c[1], c[2]));
    if (!f.is_triangle()) out.faces.push_back(mesh::make_triangle(c[0], c[2], c[3]));
  }
  return out;
}

/// The triangles of a mesh of triangles, as points.
inline std::vector<Triangle> triangles_of(const mesh::Mesh& m) {
  std::vector<Triangle> out;
  for (const mesh::Face& f : m.faces)
    out.push_back({m.vertices[f.corners[0]], m.vertices[f.corners[1]], m.vertices[f.corners[2]]});
  return out;
}

}  // namespace exactgeo::testing
