#pragma once

// Ray-triangle classification from orientation signs (Plücker-style). With the triangle's
// corners as offsets a, b, c from the ray origin o and direction d:
//
//   edge signs  e_ab = det[a, b, d], e_bc = det[b, c, d], e_ca = det[c, a, d] tell on which
//               side of each edge the ray's line passes. The line meets the closed triangle
//               iff they are not of mixed sign. Their sum is n . d with
//               n = (b - a) x (c - a), so when one is nonzero and none has the opposite
//               sign, the triangle is nondegenerate and the line is not parallel to it.
//   plane side  det[a, b, c] = orient3d(o, a, b, c) = n . (a - o): the line meets the plane
//               at parameter s = det[a, b, c] / (n . d), so the crossing is ahead of the
//               origin iff det[a, b, c] has the sign of the edge signs, at the origin iff it
//               is zero.
//
// All three edge signs zero means o, o + d and the triangle are coplanar (for a
// nondegenerate triangle the three planes through the line and the edges meet only in
// the line; for a degenerate one its corners and the line span at most a plane): that
// rare case is decided in 2D (coplanar.hpp).

#include <array>
#include <optional>

#include "exactgeo/predicates/internal/coplanar.hpp"
#include "exactgeo/predicates/ray_triangle.hpp"

namespace exactgeo::internal {

using kernel::Offset;

/// Classification from precomputed edge signs; `plane_side` is det[a, b, c] when the
/// caller already has it (computed here otherwise, and only when needed).
template <class Signs>
RayTriangleHit classify_from_edge_signs(const Signs& signs, const Offset& a, const Offset& b,
                                        const Offset& c, const Offset& d,
                                        const std::array<Sign, 3>& edge,
                                        std::optional<Sign> plane_side = std::nullopt) noexcept {
  bool any_positive = false;
  bool any_negative = false;
  int zero_edges = 0;
  int nonzero_edge = 0;
  for (int i = 0; i < 3; ++i) {
    any_positive |= edge[i] == Sign::positive;
    any_negative |= edge[i] == Sign::negative;
    if (edge[i] == Sign::zero) {
      ++zero_edges;
    } else {
      nonzero_edge = i;
    }
  }
  if (any_positive && any_negative) return {RayTriangle::miss, 0, Sign::zero};

  if (!any_positive && !any_negative) {
    const std::array<const Offset*, 3> corners{&a, &b, &c};
    if (origin_in_hull(signs, corners)) return {RayTriangle::origin_on, 0, Sign::zero};
    if (ray_meets_hull(signs, corners, d)) return {RayTriangle::coplanar, 0, Sign::zero};
    return {RayTriangle::miss, 0, Sign::zero};
  }

  const Sign turn = any_positive ? Sign::positive : Sign::negative;
  const Sign side = plane_side ? *plane_side : signs.det3_by_axis(a, b, c);
  if (side == Sign::zero) return {RayTriangle::origin_on, 0, Sign::zero};
  if (side != turn) return {RayTriangle::miss, 0, Sign::zero};  // the crossing is behind o
  switch (zero_edges) {
    case 0:
      return {RayTriangle::interior, 0, turn};
    case 1:
      for (std::uint8_t i = 0; i < 3; ++i) {
        if (edge[i] == Sign::zero) return {RayTriangle::edge, i, turn};
      }
      break;
    default:
      // Two edge lines through the crossing point: the vertex opposite the nonzero edge
      // (edge 0 = ab faces c, edge 1 = bc faces a, edge 2 = ca faces b).
      return {RayTriangle::vertex, static_cast<std::uint8_t>((nonzero_edge + 2) % 3), turn};
  }
  return {RayTriangle::miss, 0, Sign::zero};  // unreachable
}

template <class Signs>
RayTriangleHit classify_ray_triangle_offsets(const Signs& signs, const Offset& a, const Offset& b,
                                             const Offset& c, const Offset& d) noexcept {
  const std::array<Sign, 3> edge{signs.det3_by_vector(a, b, d), signs.det3_by_vector(b, c, d),
                                 signs.det3_by_vector(c, a, d)};
  return classify_from_edge_signs(signs, a, b, c, d, edge);
}

}  // namespace exactgeo::internal
