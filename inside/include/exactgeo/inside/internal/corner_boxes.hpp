#pragma once

// Boxes of faces' corners. A bilinear patch (and a triangle) lies in the convex hull of its
// corners, hence in their box: every conservative structure of exactgeo::inside (Embree's
// float boxes, the space cells, the baseline's early "outside") starts from these boxes.
// Exact: minima and maxima of doubles.

#include <algorithm>
#include <cstddef>
#include <optional>

#include "exactgeo/mesh/check.hpp"
#include "exactgeo/mesh/mesh.hpp"

namespace exactgeo::inside::internal {

/// The box of one face's corners. Precondition: corner indices in range.
inline mesh::Box corner_box(const mesh::Mesh& mesh, const mesh::Face& face) noexcept {
  mesh::Box box = mesh::Box::of(mesh.vertices[face.corners[0]]);
  for (std::size_t k = 1; k < face.size(); ++k)
    box.add(mesh.vertices[face.corners[k]]);
  return box;
}

/// The box of every face's corners (vertices no face uses do not count); none without
/// faces.
inline std::optional<mesh::Box> corner_box(const mesh::Mesh& mesh) noexcept {
  std::optional<mesh::Box> all;
  for (const mesh::Face& face : mesh.faces) {
    const mesh::Box b = corner_box(mesh, face);
    if (all) {
      all->add(b);
    } else {
      all = b;
    }
  }
  return all;
}

/// p outside the closed box: no face, hence no point of the solid, is there.
inline bool strictly_outside(const mesh::Box& box, const Point3& p) noexcept {
  return !box.holds(p);
}

}  // namespace exactgeo::inside::internal
