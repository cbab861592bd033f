#pragma once

#include <cstdint>

#include "exactgeo/predicates/arithmetic.hpp"
#include "exactgeo/predicates/point.hpp"
#include "exactgeo/predicates/sign.hpp"

namespace exactgeo {

/// How the ray {origin + s * direction : s >= 0} meets the closed triangle (a, b, c).
enum class RayTriangle : std::uint8_t {
  miss,       ///< no common point
  interior,   ///< crosses the open triangle transversally, at s > 0
  edge,       ///< crosses the relative interior of an edge, transversally, at s > 0
  vertex,     ///< passes through a vertex, at s > 0
  origin_on,  ///< the origin lies on the closed triangle
  coplanar,   ///< the ray lies in the triangle's plane and meets the triangle, origin not
              ///< on it; also any ray meeting a degenerate (zero-area) triangle
};

/// Detailed result: which edge or vertex, and on which side the ray passes.
struct RayTriangleHit {
  RayTriangle kind = RayTriangle::miss;
  /// edge: 0 = ab, 1 = bc, 2 = ca; vertex: 0 = a, 1 = b, 2 = c; otherwise 0.
  std::uint8_t feature = 0;
  /// interior/edge/vertex: the common sign of det[a - o, b - o, d], det[b - o, c - o, d],
  /// det[c - o, a - o, d] that are not zero, i.e. the sign of (b - a) x (c - a) . d.
  Sign turn = Sign::zero;
};

/// Exact classification. Preconditions: finite coordinates, direction != 0.
RayTriangleHit classify_ray_triangle(const Point3& origin, const Vector3& direction,
                                     const Point3& a, const Point3& b, const Point3& c,
                                     Arithmetic arithmetic = Arithmetic::exact) noexcept;

}  // namespace exactgeo
