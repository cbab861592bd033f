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

/// w(p) - offset, rounded to the nearest double (offset an integer, subtracted before
/// rounding, so that a small fractional part survives a large w). Precondition: p on no
/// triangle (there w is not defined), finite coordinates.
double generalized_winding_oracle(const Point3& p, std::span<const Triangle> triangles,
                                  std::int64_t offset = 0);

}  // namespace exactgeo::testing
