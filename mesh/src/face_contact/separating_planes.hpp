#pragma once

// Separating planes: filters that prove two faces apart (they never prove an intersection;
// a pair they do not separate goes on to an exact method).
//
// Every relative-interior point of a face is a combination of all its corners with
// positive weights: barycentric for a triangle, (1-u)(1-v), u(1-v), uv, (1-u)v with
// u, v in (0, 1) for a quad. So if a plane has the corners of one face on its closed
// positive side and those of the other on its closed negative side, and some corner
// strictly off it, the face owning that corner has its whole interior strictly on one
// side while the other face lies on the other closed side: the interiors cannot meet.
//
// Two families of planes are tried: planes through three corners of one face, and planes
// normal to the cross product of an edge of each face's corner hull (separating axes).
// Every side is an exact orient3d or 3x3 determinant sign.

#include "exactgeo/predicates/sign.hpp"
#include "face_geometry.hpp"

namespace exactgeo::mesh::internal {

/// Which open sides of a plane a set of points reaches.
struct Sides {
  bool positive = false;
  bool negative = false;

  void add(Sign s) noexcept {
    positive = positive || s == Sign::positive;
    negative = negative || s == Sign::negative;
  }
  bool both() const noexcept { return positive && negative; }
  bool any() const noexcept { return positive || negative; }
};

/// The planes through three corners of `f` (the faces of its corners' convex hull; for a
/// flat face, its plane once), tried against the corners of `f` and `g`.
bool separated_by_corner_plane(const FaceGeometry& f, const FaceGeometry& g) noexcept;

/// The separating axis test along n = (f_j - f_i) x (g_l - g_k) for every pair of corners
/// of each face (EdgePairAxis in separating_planes.cpp). Symmetric in f, g.
bool separated_by_edge_pair_axis(const FaceGeometry& f, const FaceGeometry& g) noexcept;

}  // namespace exactgeo::mesh::internal
