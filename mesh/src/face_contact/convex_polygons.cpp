#include "convex_polygons.hpp"

#include <array>
#include <cstddef>

#include "exactgeo/predicates/orient3d.hpp"
#include "separating_planes.hpp"

namespace exactgeo::mesh::internal {

namespace {

/// orient2d of the projections that drop coordinate `axis`, as orient3d of the points
/// flattened onto that coordinate plane and the unit point on the axis (the determinant
/// reduces to the 2D one, up to a sign fixed by `axis`).
Sign orient2d(const Point3& a, const Point3& b, const Point3& c, std::size_t axis) noexcept {
  const auto flat = [axis](Point3 p) {
    p[axis] = 0.0;
    return p;
  };
  Point3 up{0.0, 0.0, 0.0};
  up[axis] = 1.0;
  return orient3d(flat(a), flat(b), flat(c), up);
}

/// An edge line of convex polygon f (in the common plane, projected along `axis`) with
/// every corner of g on its closed outer side. `inward`: f's orientation in the projection.
bool edge_line_separates(const FaceGeometry& f, const FaceGeometry& g, std::size_t axis,
                         Sign inward) noexcept {
  for (std::size_t i = 0; i < f.n; ++i) {
    bool all_outside = true;
    for (std::size_t c = 0; c < g.n && all_outside; ++c)
      all_outside = orient2d(f.corner(i), f.corner(i + 1), g.p[c], axis) != inward;
    if (all_outside) return true;
  }
  return false;
}

/// Coplanar convex polygons. Facing opposite ways they only touch, by the rule, whether
/// or not they overlap (unless `coplanar` says such an overlap intersects). Otherwise
/// their interiors are disjoint exactly when a
/// line weakly separates them, and then one through an edge of either does (the Minkowski
/// difference of two convex polygons has edges parallel to theirs; the origin lies
/// outside its interior exactly when it is on the closed outer side of one of its edge
/// lines).
///
/// Facing: the normals by corner order, n = (p1 - p0) x (p2 - p0) for each, are parallel
/// and nonzero (one plane, first three corners not collinear), so they point the same way
/// exactly when their components on `axis` (nonzero for a, hence for b) have one sign.
/// orient2d(p0, p1, p2, axis) is that sign times a constant: the flattened points lie in
/// the plane x_axis = 0, `up` one unit above it, and the cross product of the flattened
/// differences is (0, .., n[axis], .., 0), the other coordinates dropping out. For a
/// strictly convex quad every three corners in boundary order have the polygon's
/// orientation, so its first three corners give its facing. The edge lines are tested
/// against each polygon's own facing (its inside is on that side of each of its edges),
/// so the separation test holds for either facing of the other.
FaceContact coplanar_contact(const FaceGeometry& a, const FaceGeometry& b,
                             CoplanarOverlap coplanar) noexcept {
  // Dropping a coordinate on which the plane's normal is nonzero keeps the configuration.
  std::size_t axis = 0;
  Sign a_facing = orient2d(a.p[0], a.p[1], a.p[2], axis);
  while (axis < 2 && a_facing == Sign::zero)
    a_facing = orient2d(a.p[0], a.p[1], a.p[2], ++axis);
  // Nonzero too: b lies in a's plane and its first three corners are not collinear.
  const Sign b_facing = orient2d(b.p[0], b.p[1], b.p[2], axis);
  if (a_facing != b_facing && coplanar == CoplanarOverlap::touching) {
    return FaceContact::apart;  // the two sides of the surface
  }
  if (edge_line_separates(a, b, axis, a_facing) || edge_line_separates(b, a, axis, b_facing))
    return FaceContact::apart;
  return FaceContact::intersecting;
}

/// One end of the chord in which a plane cuts a convex polygon that has corners strictly
/// on both sides: the crossing point of edge (p, q), p strictly on side `side`, q on the
/// other closed side (q itself when it lies on the plane).
struct ChordEnd {
  const Point3* p;
  const Point3* q;
  Sign side;
};

/// The two chord ends. Precondition: `sides` (of f's corners against the plane) has a
/// positive and a negative entry, and f is a convex polygon, so its boundary crosses the
/// plane exactly twice and the chord's open segment lies in the open polygon.
std::array<ChordEnd, 2> chord_ends(const FaceGeometry& f,
                                   const std::array<Sign, 4>& sides) noexcept {
  std::array<ChordEnd, 2> ends{};
  std::size_t found = 0;
  for (std::size_t i = 0; i < f.n && found < 2; ++i) {
    const Sign s = sides[i], t = sides[(i + 1) % f.n];
    if (s != Sign::zero && t != s) ends[found++] = {&f.p[i], &f.corner(i + 1), s};
  }
  return ends;
}

/// Convex polygons in planes that cross: each cuts the other's plane in a chord, and the
/// open polygons meet exactly when the open chords overlap on the planes' common line L.
///
/// The order of two chord ends along L is one orient3d: for ends k on edge (p, q) of a
/// and m on edge (p', q') of b, with s = side of p against b's plane and s' = side of p'
/// against a's plane, sign(orient3d(p, q, p', q')) = s s' sign(t(m) - t(k)), where t is
/// the coordinate along d = n_a x n_b (write q - p and q' - p' as multiples of k - p and
/// m - p' and expand the determinant in a frame of d and the two normals). Zero means
/// k = m. The chords are disjoint exactly when every end of one is at or before every
/// end of the other.
FaceContact crossing_planes_contact(const FaceGeometry& a, const std::array<Sign, 4>& a_sides,
                                    const FaceGeometry& b,
                                    const std::array<Sign, 4>& b_sides) noexcept {
  Sides order;
  for (const ChordEnd& k : chord_ends(a, a_sides))
    for (const ChordEnd& m : chord_ends(b, b_sides))
      order.add(orient3d(*k.p, *k.q, *m.p, *m.q) * k.side * m.side);
  return order.both() ? FaceContact::intersecting : FaceContact::apart;
}

/// The sides of f's corners against the plane of convex polygon g (its first three
/// corners are not collinear).
std::array<Sign, 4> sides_against(const FaceGeometry& f, const FaceGeometry& g) noexcept {
  std::array<Sign, 4> sides{};
  for (std::size_t c = 0; c < f.n; ++c)
    sides[c] = orient3d(g.p[0], g.p[1], g.p[2], f.p[c]);
  return sides;
}

Sides sides_reached(const std::array<Sign, 4>& sides, std::size_t n) noexcept {
  Sides s;
  for (std::size_t c = 0; c < n; ++c)
    s.add(sides[c]);
  return s;
}

}  // namespace

FaceContact convex_polygons_contact(const FaceGeometry& a, const FaceGeometry& b,
                                    CoplanarOverlap coplanar) noexcept {
  const std::array<Sign, 4> a_sides = sides_against(a, b);
  const std::array<Sign, 4> b_sides = sides_against(b, a);
  const Sides a_reach = sides_reached(a_sides, a.n), b_reach = sides_reached(b_sides, b.n);
  if (!b_reach.any()) return coplanar_contact(a, b, coplanar);
  // Not both sides: the polygon's interior is off the other plane (or the two are
  // coplanar, handled above).
  if (!a_reach.both() || !b_reach.both()) return FaceContact::apart;
  return crossing_planes_contact(a, a_sides, b, b_sides);
}

}  // namespace exactgeo::mesh::internal
