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
  mesh::Box box{mesh.vertices[face.corners[0]], mesh.vertices[face.corners[0]]};
  for (std::size_t k = 1; k < face.size(); ++k) {
    const Point3& p = mesh.vertices[face.corners[k]];
    for (int i = 0; i < 3; ++i) {
      box.lower[i] = std::min(box.lower[i], p[i]);
      box.upper[i] = std::max(box.upper[i], p[i]);
    }
  }
  return box;
}

/// The box of every face's corners (vertices no face uses do not count); none without
/// faces.
inline std::optional<mesh::Box> corner_box(const mesh::Mesh& mesh) noexcept {
  std::optional<mesh::Box> all;
  for (const mesh::Face& face : mesh.faces) {
    const mesh::Box b = corner_box(mesh, face);
    if (!all) {
      all = b;
      continue;
    }
    for (int i = 0; i < 3; ++i) {
      all->lower[i] = std::min(all->lower[i], b.lower[i]);
      all->upper[i] = std::max(all->upper[i], b.upper[i]);
    }
  }
  return all;
}

/// p outside the closed box: no face, hence no point of the solid, is there.
inline bool strictly_outside(const mesh::Box& box, const Point3& p) noexcept {
  for (int i = 0; i < 3; ++i) {
    if (p[i] < box.lower[i] || p[i] > box.upper[i]) return true;
  }
  return false;
}

}  // namespace exactgeo::inside::internal
