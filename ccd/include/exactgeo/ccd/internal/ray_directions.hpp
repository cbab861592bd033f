#pragma once

// The fixed sequence of ray directions for root parity, and why it always ends.
//
// Direction k is (1, t_k, t_k^2) with t_k = (2k + 3) / 16: points of the moment curve.
// Any three of them are linearly independent, because det[(1, s, s^2), (1, t, t^2),
// (1, r, r^2)] is the Vandermonde determinant (t - s)(r - s)(r - t), nonzero for distinct
// parameters; and no two are parallel. (Every coordinate is exact: t_k^2 has at most 14
// significant bits.)
//
// A ray from the origin is "degenerate" for a query only if it passes through a vertex or
// an edge of the image of the domain's boundary, or lies in the plane of a flat face.
// Those directions lie on at most V lines through the origin (one per vertex) and at most
// E + F planes through it (one per edge, one per flat face). A line holds at most one
// direction of the sequence and a plane at most two, so at most V + 2 (E + F) directions
// are degenerate: 6 + 2 (9 + 5) = 34 for the vertex-face prism, 8 + 2 (12 + 6) = 44 for the
// edge-edge hexahedron. The sequence has 64: some direction always gives a clean count.

#include <array>
#include <cstddef>

#include "exactgeo/predicates/point.hpp"

namespace exactgeo::ccd::internal {

inline constexpr std::size_t kRayDirectionCount = 64;

constexpr std::array<Vector3, kRayDirectionCount> make_ray_directions() {
  std::array<Vector3, kRayDirectionCount> d{};
  for (std::size_t k = 0; k < kRayDirectionCount; ++k) {
    const double t = static_cast<double>(2 * k + 3) / 16.0;
    d[k] = {1.0, t, t * t};
  }
  return d;
}

inline constexpr std::array<Vector3, kRayDirectionCount> kRayDirections = make_ray_directions();

}  // namespace exactgeo::ccd::internal
