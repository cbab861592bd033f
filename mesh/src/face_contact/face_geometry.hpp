#pragma once

// One face as the pair test of self_intersection.cpp sees it: its corners and its shape
// class, which decides the method a pair gets (exact and complete for two convex
// polygons, separating planes and the edge method otherwise). The class comes from the
// exact classification of the face's bilinear patch (classify_patch), so every later
// stage can rely on it: a convex polygon is one, a skew quad lies in no plane.

#include <array>
#include <cstddef>
#include <cstdint>

#include "exactgeo/mesh/mesh.hpp"

namespace exactgeo::mesh::internal {

/// The shape classes that decide which method a pair gets.
enum class Shape : std::uint8_t {
  degenerate,  ///< a repeated corner index, or zero area: skipped
  triangle,    ///< three corners, not collinear
  convex,      ///< planar quad whose boundary is strictly convex: the patch is that polygon
  skew,        ///< corners not coplanar (the patch is injective on [0, 1]^2)
  other_flat,  ///< planar quad that is not strictly convex: concave, butterfly, or with a
               ///< straight corner (its patch may fold over itself)
};

Shape shape_of(const Mesh& mesh, const Face& face) noexcept;

struct FaceGeometry {
  std::array<Point3, 4> p{};  ///< corners in boundary order (p00, p10, p11, p01)
  std::size_t n = 0;          ///< 3 or 4
  Shape shape = Shape::degenerate;

  /// A triangle or a convex quad: the face is a convex polygon, open face = its interior.
  bool convex_polygon() const noexcept {
    return shape == Shape::triangle || shape == Shape::convex;
  }
  /// Distinct points of the face map to distinct parameters: a triangle, a convex quad,
  /// a skew quad. Then the open face and its boundary edges are disjoint.
  bool injective() const noexcept { return shape != Shape::other_flat; }
  const Point3& corner(std::size_t i) const noexcept { return p[i % n]; }
};

FaceGeometry geometry_of(const Mesh& mesh, const Face& face, Shape shape) noexcept;

}  // namespace exactgeo::mesh::internal
