#pragma once

// A hexahedron as a mesh (support/hexahedron.hpp numbers its corners and faces), shared by
// the mesh and inside tests.

#include <array>

#include "exactgeo/mesh/mesh.hpp"
#include "support/hexahedron.hpp"

namespace exactgeo::mesh::test_meshes {

/// The closed mesh of six (possibly skew) quads on the given corners.
inline Mesh hexahedron(const std::array<Point3, 8>& corners) {
  Mesh mesh;
  mesh.vertices.assign(corners.begin(), corners.end());
  for (const auto& f : testing::kHexahedronFaces)
    mesh.faces.push_back(make_quad(f[0], f[1], f[2], f[3]));
  return mesh;
}

}  // namespace exactgeo::mesh::test_meshes
