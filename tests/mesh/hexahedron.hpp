#pragma once

// The quads of a hexahedron whose corner (i, j, k) is vertex i + 2j + 4k, counter-clockwise
// seen from outside (every edge used once in each direction), shared by the mesh and inside tests.

#include <array>

#include "exactgeo/mesh/mesh.hpp"

namespace exactgeo::mesh::test_meshes {

inline constexpr std::array<std::array<VertexIndex, 4>, 6> kHexahedronFaces{{
    {0, 2, 3, 1},  // z = lower
    {4, 5, 7, 6},  // z = upper
    {0, 1, 5, 4},  // y = lower
    {2, 6, 7, 3},  // y = upper
    {0, 4, 6, 2},  // x = lower
    {1, 3, 7, 5},  // x = upper
}};

/// The closed mesh of six (possibly skew) quads on the given corners.
inline Mesh hexahedron(const std::array<Point3, 8>& corners) {
  Mesh mesh;
  mesh.vertices.assign(corners.begin(), corners.end());
  for (const auto& f : kHexahedronFaces)
    mesh.faces.push_back(make_quad(f[0], f[1], f[2], f[3]));
  return mesh;
}

}  // namespace exactgeo::mesh::test_meshes
