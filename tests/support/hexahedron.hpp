#pragma once

// The quads of a hexahedron whose corner (i, j, k) is vertex i + 2j + 4k, counter-clockwise
// seen from outside (every edge used once in each direction), in boundary order; shared by
// the tests of every library that works on closed surfaces.

#include <array>

#include "exactgeo/predicates/point.hpp"

namespace exactgeo::testing {

inline constexpr std::array<std::array<VertexIndex, 4>, 6> kHexahedronFaces{{
    {0, 2, 3, 1},  // z = lower
    {4, 5, 7, 6},  // z = upper
    {0, 1, 5, 4},  // y = lower
    {2, 6, 7, 3},  // y = upper
    {0, 4, 6, 2},  // x = lower
    {1, 3, 7, 5},  // x = upper
}};

/// The corners of the unit cube [0, 1]^3 in that numbering.
inline std::array<Point3, 8> unit_cube_corners() {
  std::array<Point3, 8> corners;
  for (int c = 0; c < 8; ++c)
    corners[static_cast<std::size_t>(c)] = {double(c & 1), double((c >> 1) & 1),
                                            double((c >> 2) & 1)};
  return corners;
}

}  // namespace exactgeo::testing
