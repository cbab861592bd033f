#pragma once

// What a flip or a split sweeps, and what touches it, decided exactly.
//
// A flip of edge ab between triangles abc and bad replaces them by cad and dbc: the
// surface moves across the closed convex hull of a, b, c, d (a tetrahedron, or, when the
// four are coplanar, the quadrilateral itself), whose boundary the old and the new
// triangles make. A split of ab at a point m that is not exactly on the segment moves
// the surface across the hull of a, b, c, m for each opposite corner c. If no other part
// of the surface meets that closed hull (beyond the corners, edges and triangles it
// shares with the operation), the surface before and after is the same set of
// non-touching pieces everywhere else, so an intersection-free surface stays so.
//
// Two convex sets meet outside the hull S of the corners they share exactly when a
// corner of one that is not shared lies in the other, or an edge of one meets a triangle
// of the other at a point other than a shared corner (a vertex of their intersection,
// which is a convex polytope not inside S, is one of these). That is what is tested,
// with orient3d and its coordinate-plane shadow orient2d_along only: every decision is
// an exact sign.

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "exactgeo/predicates/point.hpp"
#include "exactgeo/remesh/surface.hpp"

namespace exactgeo::remesh {

/// A surface element an operation would meet: a vertex, an edge or a triangle.
struct Blocker {
  enum class Kind : std::uint8_t { vertex, edge, triangle };
  Kind kind = Kind::vertex;
  /// Its corners (kNoVertex beyond the first one or two).
  std::array<VertexIndex, 3> corners{kNoVertex, kNoVertex, kNoVertex};
  friend bool operator==(const Blocker&, const Blocker&) = default;
};

/// "vertex 25", "edge 3 7", "triangle 25 27 26".
std::string to_string(const Blocker& blocker);

/// A corner of a region: a vertex of the surface, or a new point (vertex kNoVertex).
struct RegionCorner {
  VertexIndex vertex = kNoVertex;
  Point3 point{};
};

/// The first element of the surface (its vertices that some triangle uses, then its
/// edges, then its triangles) that meets the closed convex hull of the four corners
/// anywhere but in the hull of the corners it shares with them (by vertex index); the
/// operation's own elements are skipped: those whose corners are all region corners, and
/// the partner's.
/// nullopt when nothing meets it. Exact.
///
/// `partner`: a split of an inner edge ab at a point m off the edge sweeps two regions,
/// hull(a, b, c, m) and hull(a, b, d, m) (a and b: the first two corners); the edge's
/// other triangle abd is replaced too, so it is no obstacle to the first region: d is its
/// partner. Its corner d and its edges ad and bd stay (in the new triangles amd and mbd)
/// and are tested, as is every other element with corners among a, b, c, d, such as a
/// neighbouring triangle acd. Whether the new triangles of the two sides meet each other
/// is then the split's own exact check.
///
/// Preconditions: finite coordinates; no three of the region's corners collinear.
std::optional<Blocker> first_in_region(const Surface& surface,
                                       const std::array<RegionCorner, 4>& region,
                                       VertexIndex partner = kNoVertex);

/// Whether two regions (closed convex hulls of their corners, whatever the corners'
/// vertices) have a point in common. Exact. Two operations of a pass whose regions are
/// apart, and that share no vertex, can be checked against the surface as it is before
/// either: what one makes lies in its own region, which the other's does not reach.
/// Precondition: as first_in_region's, for each.
bool regions_meet(const std::array<RegionCorner, 4>& x, const std::array<RegionCorner, 4>& y);

/// Whether triangle `made`, which replaces `old` in a flip or a split, turns over in old's
/// plane: every corner of `made` lies in that plane and it faces the other way (its
/// corners turn the other way, seen from either side). The region test above keeps the
/// rest of the surface out of the swept hull, but not the new triangles off each other:
/// when the hull is flat (the four corners in one plane), a flip of a quadrilateral that
/// is not convex, or a split at a point beyond the opposite corner, leaves one new
/// triangle lying flat over another, facing the other way. Refusing every new triangle
/// that turns over rules that out: two new triangles that share an edge and face as the
/// old one have their third corners on opposite sides of it. Off the plane, the new and
/// old triangles are faces of one tetrahedron, which meet only at their shared edges.
/// Exact. Precondition: `old` has non-zero area.
bool turns_over_in_plane(const std::array<Point3, 3>& old, const std::array<Point3, 3>& made);

/// first_in_region for several regions at once: one scan of the surface's triangles
/// through a grid of the regions' boxes finds the triangles each region's box reaches,
/// and each region tests those and their corners and edges only, so that a pass of many
/// operations costs about one pass over the surface. `partners` is empty (none) or holds
/// one per region.
std::vector<std::optional<Blocker>> first_in_regions(
    const Surface& surface, std::span<const std::array<RegionCorner, 4>> regions,
    std::span<const VertexIndex> partners = {});

}  // namespace exactgeo::remesh
