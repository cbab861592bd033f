#pragma once

// The ray directions root parity tries, and why 64 of them always suffice.
//
// They are the first directions of the shared sequence (exactgeo/predicates/
// ray_directions.hpp: points of the moment curve, so a line through the origin holds at
// most one of them and a plane at most two). A ray from the origin is degenerate for a
// query only if it passes through a vertex or an edge of the image of the domain's
// boundary, or lies in the plane of a flat face: at most V + 2 (E + F) directions, that is
// 6 + 2 (9 + 5) = 34 for the vertex-face prism and 8 + 2 (12 + 6) = 44 for the edge-edge
// hexahedron. Some direction among the first 64 always gives a clean count.

#include <array>
#include <cstddef>

#include "exactgeo/predicates/point.hpp"
#include "exactgeo/predicates/ray_directions.hpp"

namespace exactgeo::ccd::internal {

inline constexpr std::size_t kRayDirectionCount = 64;

constexpr std::array<Vector3, kRayDirectionCount> make_ray_directions() {
  std::array<Vector3, kRayDirectionCount> d{};
  for (std::size_t k = 0; k < kRayDirectionCount; ++k)
    d[k] = ray_direction(k);
  return d;
}

inline constexpr std::array<Vector3, kRayDirectionCount> kRayDirections = make_ray_directions();

}  // namespace exactgeo::ccd::internal
