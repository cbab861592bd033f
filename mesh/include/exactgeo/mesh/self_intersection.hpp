#pragma once

// Exact self-intersection of a surface mesh: which pairs of faces intersect (docs/
// self-intersection.md has the rule, the method per face type and what it cannot see).
//
// The rule: two faces intersect when some point lies in the relative interior of both,
// for a triangle the open triangle, for a quad the image of the open square (0, 1)^2,
// except that two coplanar faces whose interiors overlap while facing opposite ways
// (their normals by corner order pointing in opposite directions) only touch: that is
// the two sides of the surface meeting, as where two solids are set face to face or a
// sheet is folded flat onto itself. Coplanar faces that overlap facing the same way (a
// duplicated face, a surface overlapping itself) intersect. Faces sharing a vertex or an
// edge do not intersect by sharing it, and touching-only contacts (a vertex resting on a
// face, an edge lying on a face with the faces on one side of it, edges crossing edges)
// are not intersections. Degenerate faces (a repeated corner, or zero area) are skipped.
//
// Surfaces that must stay apart (cloth, sheets that collide) ask for the other rule
// (CoplanarOverlap::intersecting): a coplanar overlap with area is an intersection
// whichever way the faces face, since a sheet lying flat inside another is two sheets in
// contact, which the next collision step starts from.
//
// Why facing decides: a ray through a coplanar overlapping pair crosses both faces, so
// crossing parity (point-in-volume) never sees the overlap as surface. For two closed,
// consistently oriented solids set face to face (opposite facing) that gives their union,
// as meant; two same-facing faces have the material of both on one side, so the solids
// overlap there, or, for a duplicated face, the parity loses that face of the surface.

#include <cstddef>
#include <cstdint>
#include <string_view>
#include <vector>

#include "exactgeo/mesh/mesh.hpp"

namespace exactgeo::mesh {

/// Whether two faces intersect under the rule above.
enum class FaceContact : std::uint8_t {
  apart,         ///< not intersecting under the rule: no common interior point, or
                 ///< coplanar and facing opposite ways, or a method that found no
                 ///< intersection (see below)
  intersecting,  ///< a common interior point (and not coplanar facing opposite ways),
                 ///< proved
  undecided,     ///< the edge method met a touching contact it cannot see past: an edge
                 ///< of one face starts, ends or runs on the other face, or meets its
                 ///< boundary, and no separating plane was found (pairs with a quad only)
};
std::string_view to_string(FaceContact contact) noexcept;

/// What two coplanar faces whose interiors overlap while facing opposite ways are.
enum class CoplanarOverlap : std::uint8_t {
  touching,      ///< the two sides of one surface meeting (solids set face to face): apart
  intersecting,  ///< an intersection all the same (sheets that must stay apart: cloth)
};

/// Exact decision for faces a and b (a != b) of the mesh, coplanar overlaps facing
/// opposite ways read by `coplanar` (the rule above: touching).
///
/// Two triangles, or any two planar faces that are triangles or strictly convex quads:
/// exact and complete (apart or intersecting, never undecided); coplanar ones facing
/// opposite ways are apart whether or not they overlap (intersecting when they overlap,
/// under CoplanarOverlap::intersecting). Any other pair (a skew
/// quad, or a planar quad that is not convex): separating planes first, then every edge
/// of one face against the other face and vice versa; `intersecting` is always proved,
/// but `apart` is then only "no edge crosses the other face an odd number of times"
/// (docs/self-intersection.md lists what that cannot see). A coplanar pair with a
/// non-convex flat quad is undecided when the faces' corner hulls meet (apart otherwise),
/// never intersecting, whichever way the faces face. A degenerate face is apart from
/// everything.
///
/// Preconditions: a, b < mesh.faces.size(), corner indices in range, finite coordinates.
FaceContact face_contact(const Mesh& mesh, std::size_t a, std::size_t b,
                         CoplanarOverlap coplanar = CoplanarOverlap::touching);

/// Two faces by index, first < second.
struct FacePair {
  std::size_t first = 0;
  std::size_t second = 0;

  friend bool operator==(const FacePair&, const FacePair&) = default;
  friend auto operator<=>(const FacePair&, const FacePair&) = default;
};

struct SelfIntersections {
  std::vector<FacePair> intersecting;  ///< every intersecting pair, sorted
  std::vector<FacePair> undecided;     ///< every undecided pair, sorted
  /// The undecided pairs whose faces share a corner (neighbours, the usual case: the edges
  /// from the shared corner start on the other face).
  std::size_t undecided_neighbours = 0;
  std::size_t candidate_pairs = 0;  ///< pairs whose boxes overlap (given to face_contact)
};

/// face_contact for every pair of non-degenerate faces whose closed bounding boxes
/// overlap (a box tree finds them; any other pair is apart). The tree is traversed on one
/// thread; the pairs it finds are decided in blocks on `threads` workers (0: one per
/// hardware thread). The result is the same for every thread count.
///
/// `coplanar` as for face_contact.
///
/// Preconditions: corner indices in range, finite coordinates (check_mesh reports both).
SelfIntersections find_self_intersections(const Mesh& mesh, unsigned threads = 0,
                                          CoplanarOverlap coplanar = CoplanarOverlap::touching);

}  // namespace exactgeo::mesh
