#pragma once

// The value of an open surface's generalized winding number w = S + (boundary term)
// (exactgeo/predicates/boundary_term.hpp), as certified bounds: what a user asks for
// when they want the number itself rather than the label open_label.hpp draws from it.

#include <cstdint>
#include <span>

#include "exactgeo/predicates/arithmetic.hpp"
#include "exactgeo/predicates/boundary_term.hpp"

namespace exactgeo::inside::internal {

/// Bounds on w narrower than this (in turns) are taken; wider ones are narrowed at the
/// next precision (the last precision's are taken whatever their width).
inline constexpr double kWindingWidth = 0x1p-40;

enum class OpenWindingKind : std::uint8_t {
  enclosed,     ///< `w` holds the generalized winding number
  on_edge,      ///< the point lies on a boundary edge: on the surface, no w
  ray_on_edge,  ///< the ray meets a boundary edge: cast the next one
};

struct OpenWinding {
  OpenWindingKind kind = OpenWindingKind::enclosed;
  Enclosure w;
};

/// The generalized winding number of `point`, whose ray along `ray` meets the faces in
/// `crossings` signed crossings and lies on no face: S plus the boundary term at the first
/// precision whose bounds are at most kWindingWidth wide, the sum rounded outward. Where
/// no precision encloses the term, the bounds every term obeys (each boundary edge adds
/// less than half a turn per use). Arithmetic::plain_double evaluates the term in plain
/// doubles instead (lower == upper, not certified).
OpenWinding open_winding(std::int64_t crossings, const Point3& point, const Vector3& ray,
                         std::span<const Point3> vertices, std::span<const BoundaryEdge> boundary,
                         Arithmetic arithmetic);

/// a + b rounded down and up: bounds on the exact sum (no overflow for finite bounds of
/// a winding number).
double add_down(double a, double b) noexcept;
double add_up(double a, double b) noexcept;

}  // namespace exactgeo::inside::internal
