#pragma once

// Where segments and triangles meet, exactly: the tests a swept region needs of the
// surface's edges and triangles (remesh/), built from orient3d and its coordinate-plane
// shadow orient2d_along only, so every answer is exact for every finite input.
//
// Closed sets throughout: a segment includes its ends, a triangle its edges and corners.
// "In the plane" cases are decided in the shadow along an axis the plane's normal has a
// component on, where every point of the plane has its own shadow and orientations keep
// their meaning.

#include <optional>

#include "exactgeo/predicates/point.hpp"

namespace exactgeo {

/// An axis along which triangle pqr's normal has a non-zero component (its shadow on the
/// other two coordinates is a triangle); nullopt when p, q, r are collinear.
std::optional<int> shadow_axis(const Point3& p, const Point3& q, const Point3& r) noexcept;

/// x, lying in the plane of the non-degenerate triangle pqr, in the closed triangle.
/// Precondition: orient3d(p, q, r, x) is zero.
bool in_triangle_of_its_plane(const Point3& p, const Point3& q, const Point3& r,
                              const Point3& x) noexcept;

/// The closed segments ab and cd, lying in one plane whose normal has a component along
/// `axis` (shadow_axis of a triangle of that plane), share a point.
bool segments_meet_in_plane(int axis, const Point3& a, const Point3& b, const Point3& c,
                            const Point3& d) noexcept;

/// The closed segment xy meets the closed non-degenerate triangle pqr.
bool segment_meets_triangle(const Point3& x, const Point3& y, const Point3& p, const Point3& q,
                            const Point3& r) noexcept;

/// The segment from s to x meets the closed non-degenerate triangle s p q somewhere other
/// than at their shared end s: only in the triangle's plane, and then exactly where x lies
/// in the triangle's closed angle at s.
bool segment_meets_triangle_beyond(const Point3& s, const Point3& x, const Point3& p,
                                   const Point3& q) noexcept;

}  // namespace exactgeo
