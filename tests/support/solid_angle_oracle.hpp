#pragma once

// The generalized winding number from its definition, for the certified boundary term's
// tests: (1/4 pi) times the sum of the triangles' signed solid angles (Van Oosterom and
// Strackee's formula, each half angle atan2 in (-pi, pi)), evaluated in 512-bit MPFR.
// Independent of the library: no ray, no decomposition, no interval; its error (a few
// units of 2^-500 relative to the terms) is far below anything a double can show.

#include <array>
#include <cstdint>
#include <span>

#include "exactgeo/predicates/point.hpp"

namespace exactgeo::testing {

using Triangle = std::array<Point3, 3>;

/// w(p) - level, rounded to the nearest double (the level subtracted before rounding, so
/// that a small difference survives). Precondition: p on no triangle (there w is not
/// defined), finite coordinates.
double generalized_winding_oracle(const Point3& p, std::span<const Triangle> triangles,
                                  double level = 0.0);

/// The antipodal decomposition written out independently, for surfaces the definition
/// above cannot integrate (bilinear patches): crossings + (1/2 pi) sum of the half angles
/// atan2(det[A, B, C], ...) with A = a - p, B = b - p, C = -ray, over the boundary
/// segments a -> b, minus `level`, rounded to the nearest double. `crossings` is the
/// signed crossing count along the ray, from the rational ray oracles.
using Segment = std::array<Point3, 2>;
double decomposed_winding_oracle(const Point3& p, const Vector3& ray, std::int64_t crossings,
                                 std::span<const Segment> boundary, double level = 0.0);

}  // namespace exactgeo::testing
