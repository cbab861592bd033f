#include "face_geometry.hpp"

#include "exactgeo/predicates/bilinear_patch.hpp"

namespace exactgeo::mesh::internal {

namespace {

bool repeated_corner(const Face& face) noexcept {
  const std::size_t n = face.size();
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j)
      if (face.corners[i] == face.corners[j]) return true;
  return false;
}

}  // namespace

Shape shape_of(const Mesh& mesh, const Face& face) noexcept {
  if (repeated_corner(face)) return Shape::degenerate;
  switch (classify_patch(patch_of(mesh, face))) {
    case PatchShape::segment:
    case PatchShape::point:
      return Shape::degenerate;
    case PatchShape::skew:
      return Shape::skew;
    case PatchShape::convex:
      return face.is_triangle() ? Shape::triangle : Shape::convex;
    case PatchShape::concave:
    case PatchShape::butterfly:
    case PatchShape::degenerate_planar:
      break;
  }
  // The patch {a, b, c, c} of a non-collinear triangle has a repeated corner, so it is
  // degenerate_planar (or convex); any other flat quad is not strictly convex.
  return face.is_triangle() ? Shape::triangle : Shape::other_flat;
}

FaceGeometry geometry_of(const Mesh& mesh, const Face& face, Shape shape) noexcept {
  FaceGeometry g;
  g.n = face.size();
  for (std::size_t i = 0; i < g.n; ++i)
    g.p[i] = mesh.vertices[face.corners[i]];
  g.shape = shape;
  return g;
}

}  // namespace exactgeo::mesh::internal
