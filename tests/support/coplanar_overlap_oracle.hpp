#pragma once

// Whether two triangles of one plane overlap with area, decided in GMP rationals by
// clipping one against the other (Sutherland-Hodgman) and measuring what is left: an
// oracle for sheets that must stay apart, where a triangle lying flat on another counts
// as contact whichever way they face. It shares no code with the library's
// self-intersection test (which separates by edge lines) or with the remesher.
//
// Requires finite coordinates; throws std::invalid_argument for triangles not in one
// plane or of zero area.

#include <array>

#include "exactgeo/predicates/point.hpp"
#include "exactgeo/predicates/sign.hpp"

namespace exactgeo::testing {

using TrianglePoints = std::array<Point3, 3>;

/// The two triangles, in one plane, share a region of positive area.
bool coplanar_overlap_oracle(const TrianglePoints& a, const TrianglePoints& b);

/// Whether the triangles lie in one plane (every corner of b in a's plane; a of non-zero
/// area), exactly.
bool coplanar_oracle(const TrianglePoints& a, const TrianglePoints& b);

/// The sign of b's normal along a's, for triangles of non-zero area: +1 when they face the
/// same way (their corner orders turn alike), -1 when opposite, 0 when perpendicular.
Sign facing_oracle(const TrianglePoints& a, const TrianglePoints& b);

}  // namespace exactgeo::testing
