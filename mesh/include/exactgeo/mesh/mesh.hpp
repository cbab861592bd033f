#pragma once

// A surface mesh of quads and triangles, with coordinates exactly as read. A quad is the
// bilinear patch through its four corners in boundary order: corners (c0, c1, c2, c3) are
// the patch's p00, p10, p11, p01, so no diagonal is ever chosen. A triangle is a face
// whose fourth corner is kNoVertex.

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "exactgeo/predicates/bilinear_patch.hpp"
#include "exactgeo/predicates/point.hpp"
#include "exactgeo/surface/triangle_surface.hpp"

namespace exactgeo::mesh {

using exactgeo::kNoVertex;    // predicates/point.hpp
using exactgeo::VertexIndex;  // predicates/point.hpp

struct Face {
  std::array<VertexIndex, 4> corners{kNoVertex, kNoVertex, kNoVertex, kNoVertex};

  bool is_triangle() const noexcept { return corners[3] == kNoVertex; }
  std::size_t size() const noexcept { return is_triangle() ? 3 : 4; }
  /// Corner i, cyclically: corner(size()) == corner(0).
  VertexIndex corner(std::size_t i) const noexcept { return corners[i % size()]; }
  friend bool operator==(const Face&, const Face&) = default;
};

inline Face make_triangle(VertexIndex a, VertexIndex b, VertexIndex c) noexcept {
  return Face{{a, b, c, kNoVertex}};
}
inline Face make_quad(VertexIndex a, VertexIndex b, VertexIndex c, VertexIndex d) noexcept {
  return Face{{a, b, c, d}};
}

struct Mesh {
  std::vector<Point3> vertices;
  std::vector<Face> faces;
};

/// A triangle surface as a mesh of triangles (the finder and the checks take a Mesh).
inline Mesh mesh_of(const TriangleSurface& surface) {
  Mesh m;
  m.vertices = surface.vertices;
  m.faces.reserve(surface.triangles.size());
  for (const Triangle& t : surface.triangles)
    m.faces.push_back(make_triangle(t[0], t[1], t[2]));
  return m;
}

/// A mesh as a triangle surface, for the triangle-only products (mesh CCD, the remesher):
/// each quad (c0, c1, c2, c3) split into (c0, c1, c2) and (c0, c2, c3), in face order.
/// The split chooses a diagonal, so the surface is the quad's only where the quad is flat.
inline TriangleSurface triangle_surface_of(const Mesh& mesh) {
  TriangleSurface s;
  s.vertices = mesh.vertices;
  s.triangles.reserve(mesh.faces.size());
  for (const Face& f : mesh.faces) {
    const auto& c = f.corners;
    s.triangles.push_back({c[0], c[1], c[2]});
    if (!f.is_triangle()) s.triangles.push_back({c[0], c[2], c[3]});
  }
  return s;
}

/// The patch of a quad, or the degenerate patch {a, b, c, c} of a triangle.
/// Precondition: every corner index is in range.
inline BilinearPatch patch_of(const Mesh& mesh, const Face& face) noexcept {
  const auto& v = mesh.vertices;
  const Point3& last = v[face.corners[face.is_triangle() ? 2 : 3]];
  return {v[face.corners[0]], v[face.corners[1]], v[face.corners[2]], last};
}

}  // namespace exactgeo::mesh
