#pragma once

// The fixed sequence of ray directions that crossing-parity algorithms (root parity for
// CCD, point-in-volume for meshes) try in turn, and why trying them in turn always ends.
//
// Direction k is (1, t_k, t_k^2) with t_k = (2k + 3) / 16: points of the moment curve.
// Any three of them are linearly independent, because det[(1, s, s^2), (1, t, t^2),
// (1, r, r^2)] is the Vandermonde determinant (t - s)(r - s)(r - t), nonzero for distinct
// parameters; and no two are parallel. So a line through the ray origin holds at most one
// direction of the sequence, and a plane through it at most two.
//
// A ray is "degenerate" for a set of faces only if it passes through a vertex or an edge
// of a face (the faces' own edges and the diagonals the patch predicate uses), or lies in
// the plane of a flat face. Those directions lie on at most V lines and E + F planes
// through the origin (V vertices, E edges, F faces), so at most V + 2 (E + F) directions
// of the sequence are degenerate, and the first clean one comes no later than that.
//
// Every coordinate is exact in double while (2k + 3)^2 < 2^53, and in float (for
// single-precision ray tracers) while (2k + 3)^2 < 2^24, that is for k < kFloatExactRayDirections.
// No component is zero, so no ray lies in an axis-aligned plane (where box traversal is
// least robust).

#include <cstddef>

#include "exactgeo/predicates/point.hpp"

namespace exactgeo {

/// Directions 0 .. kFloatExactRayDirections - 1 have coordinates exact in float.
inline constexpr std::size_t kFloatExactRayDirections = 2047;

/// Direction k of the sequence; exact in double for k < 2^25.
constexpr Vector3 ray_direction(std::size_t k) noexcept {
  const double t = static_cast<double>(2 * k + 3) / 16.0;
  return {1.0, t, t * t};
}

}  // namespace exactgeo
