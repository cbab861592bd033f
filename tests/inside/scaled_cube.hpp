#pragma once

// The cube [0, 2^k]^3 as a mesh (six quads or twelve triangles, outward), its exact
// point-in-volume truth, and points printed exactly, for the inside tests that plant
// something into a cube whose labels are known.

#include <cmath>
#include <cstdio>
#include <string>

#include "exactgeo/inside/location.hpp"
#include "exactgeo/mesh/mesh.hpp"
#include "support/hexahedron.hpp"
#include "support/hexfloat.hpp"

namespace exactgeo::testing {

/// The cube [0, 2^k]^3, as six quads or as twelve triangles.
inline mesh::Mesh scaled_cube(int k, bool triangles) {
  mesh::Mesh mesh;
  for (const Point3& c : unit_cube_corners())
    mesh.vertices.push_back({std::ldexp(c[0], k), std::ldexp(c[1], k), std::ldexp(c[2], k)});
  for (const auto& f : kHexahedronFaces) {
    if (triangles) {
      mesh.faces.push_back(mesh::make_triangle(f[0], f[1], f[2]));
      mesh.faces.push_back(mesh::make_triangle(f[0], f[2], f[3]));
    } else {
      mesh.faces.push_back(mesh::make_quad(f[0], f[1], f[2], f[3]));
    }
  }
  return mesh;
}

/// The exact label of p against the cube [0, 2^k]^3.
inline inside::Location cube_truth(const Point3& p, int k) {
  const double side = std::ldexp(1.0, k);
  bool on_surface = false;
  for (const double x : p) {
    if (x < 0 || x > side) return inside::Location::outside;
    on_surface = on_surface || x == 0 || x == side;
  }
  return on_surface ? inside::Location::boundary : inside::Location::inside;
}

}  // namespace exactgeo::testing
