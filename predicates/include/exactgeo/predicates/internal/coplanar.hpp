#pragma once

// Exact decisions for configurations that lie in one plane (or on one line) through the
// ray origin o: the rare paths of the ray-triangle and ray-patch tests (ray in a
// triangle's plane, degenerate triangles, flat patches with o in their plane, patches
// collapsed to a segment or a point).
//
// Points are given as offsets a_p = x_p - o. Everything reduces to 2D orientation and
// betweenness in a coordinate projection that is injective on the configuration's plane:
// dropping axis k is injective on a plane with normal n iff n_k != 0, and for two vectors
// v, w of the plane n is parallel to v x w, so any pair with (v x w)_k != 0 certifies k.
// When all vectors are parallel the configuration is a line through o, and one coordinate
// on which the line is not constant orders it.

#include <array>
#include <cstddef>
#include <optional>

#include "exactgeo/predicates/kernel/signs.hpp"

namespace exactgeo::internal {

using kernel::coordinate_sign;
using kernel::Offset;

struct Projection {
  enum class Kind { plane, line };
  Kind kind;
  /// plane: the dropped coordinate; line: a coordinate that is nonzero along the line.
  int axis;
};

/// A projection injective on the span of `vectors`, which must have dimension <= 2 (not
/// checked); nullopt when every vector is zero.
template <class Signs, std::size_t N>
std::optional<Projection> find_projection(const Signs& signs,
                                          const std::array<const Offset*, N>& vectors) noexcept {
  for (std::size_t i = 0; i < N; ++i) {
    for (std::size_t j = i + 1; j < N; ++j) {
      for (int axis = 0; axis < 3; ++axis) {
        if (signs.cross2(axis, *vectors[i], *vectors[j]) != Sign::zero) {
          return Projection{Projection::Kind::plane, axis};
        }
      }
    }
  }
  for (const Offset* v : vectors) {
    for (int axis = 0; axis < 3; ++axis) {
      if (coordinate_sign(*v, axis) != Sign::zero) return Projection{Projection::Kind::line, axis};
    }
  }
  return std::nullopt;
}

inline bool is_zero(const Offset& v) noexcept {
  return coordinate_sign(v, 0) == Sign::zero && coordinate_sign(v, 1) == Sign::zero &&
         coordinate_sign(v, 2) == Sign::zero;
}

/// o on the closed segment [x_p, x_q], for o, x_p, x_q in a plane on which dropping `axis`
/// is injective.
template <class Signs>
bool origin_on_segment(const Signs& signs, int axis, const Offset& p, const Offset& q) noexcept {
  if (is_zero(p) || is_zero(q)) return true;
  // Collinear with o, and p, q on opposite sides of it.
  return signs.cross2(axis, p, q) == Sign::zero && signs.dot3(p, q) == Sign::negative;
}

/// o strictly inside a triangle, from the three orientations (o, x_p, x_q) of its edges.
constexpr bool strictly_inside(Sign e0, Sign e1, Sign e2) noexcept {
  return e0 != Sign::zero && e0 == e1 && e1 == e2;
}

/// o in the convex hull of the points. Precondition: o and the points are coplanar.
template <class Signs, std::size_t N>
bool origin_in_hull(const Signs& signs, const std::array<const Offset*, N>& points) noexcept {
  const std::optional<Projection> projection = find_projection(signs, points);
  if (!projection) return true;  // every point coincides with o
  const int axis = projection->axis;
  if (projection->kind == Projection::Kind::line) {
    // Every point is o + lambda w with w_axis != 0: o is in the hull iff some lambda is zero
    // or two have opposite signs.
    bool positive = false;
    bool negative = false;
    for (const Offset* p : points) {
      const Sign s = coordinate_sign(*p, axis);
      if (s == Sign::zero) return true;
      (s == Sign::positive ? positive : negative) = true;
    }
    return positive && negative;
  }
  // Carathéodory: o is in the hull iff it is on a point, on a segment, or strictly inside a
  // triangle of the points.
  for (std::size_t i = 0; i < N; ++i) {
    for (std::size_t j = i + 1; j < N; ++j) {
      if (origin_on_segment(signs, axis, *points[i], *points[j])) return true;
    }
  }
  for (std::size_t i = 0; i < N; ++i) {
    for (std::size_t j = i + 1; j < N; ++j) {
      for (std::size_t k = j + 1; k < N; ++k) {
        if (strictly_inside(signs.cross2(axis, *points[i], *points[j]),
                            signs.cross2(axis, *points[j], *points[k]),
                            signs.cross2(axis, *points[k], *points[i]))) {
          return true;
        }
      }
    }
  }
  return false;
}

/// Does the ray {o + s d : s > 0} cross the closed segment [x_p, x_q] at a single point?
/// 2D, `axis` dropped. A segment lying on the ray's line is left to the callers' endpoint
/// tests (it meets the ray iff an endpoint is ahead of o, or o is inside it).
template <class Signs>
bool ray_crosses_segment_2d(const Signs& signs, int axis, const Offset& p, const Offset& q,
                            const Offset& d) noexcept {
  const Sign cp = signs.cross2(axis, d, p);
  const Sign cq = signs.cross2(axis, d, q);
  if (cp == cq) return false;  // both on one side of the ray's line, or both on it
  // The line o + s d meets the segment's line at s = (p x q) / (d x q - d x p); the
  // denominator's sign is that of cq, or of -cp when cq is zero. s = 0 (o on the segment)
  // is not on the ray.
  const Sign denominator = cq != Sign::zero ? cq : -cp;
  return signs.cross2(axis, p, q) * denominator == Sign::positive;
}

/// Does the ray {o + s d : s > 0} meet the convex hull of the points? Precondition: o,
/// o + d and the points are coplanar. (o may be in the hull: from its interior every ray
/// meets it, from its boundary only those pointing inward or along it.)
template <class Signs, std::size_t N>
bool ray_meets_hull(const Signs& signs, const std::array<const Offset*, N>& points,
                    const Offset& d) noexcept {
  std::array<const Offset*, N + 1> all;
  for (std::size_t i = 0; i < N; ++i)
    all[i] = points[i];
  all[N] = &d;
  const std::optional<Projection> projection = find_projection(signs, all);
  if (!projection) return false;  // d == 0 violates the precondition of every caller
  const int axis = projection->axis;
  if (projection->kind == Projection::Kind::line) {
    const Sign ahead = coordinate_sign(d, axis);
    for (const Offset* p : points) {
      if (coordinate_sign(*p, axis) == ahead) return true;
    }
    return false;
  }
  for (const Offset* p : points) {  // the ray passes through a point
    if (signs.cross2(axis, d, *p) == Sign::zero && signs.dot3(d, *p) == Sign::positive) return true;
  }
  for (std::size_t i = 0; i < N; ++i) {
    for (std::size_t j = i + 1; j < N; ++j) {
      if (ray_crosses_segment_2d(signs, axis, *points[i], *points[j], d)) return true;
    }
  }
  return false;
}

/// Like ray_meets_hull, but first checks that the ray lies in the plane of o and the
/// points (false if it leaves it). Precondition: o and the points are coplanar.
template <class Signs, std::size_t N>
bool coplanar_ray_meets_hull(const Signs& signs, const std::array<const Offset*, N>& points,
                             const Offset& d) noexcept {
  for (std::size_t i = 0; i < N; ++i) {
    for (std::size_t j = i + 1; j < N; ++j) {
      for (int axis = 0; axis < 3; ++axis) {
        if (signs.cross2(axis, *points[i], *points[j]) != Sign::zero) {
          // points i, j span the plane through o: d must lie in it.
          if (signs.det3_by_vector(*points[i], *points[j], d) != Sign::zero) return false;
          return ray_meets_hull(signs, points, d);
        }
      }
    }
  }
  return ray_meets_hull(signs, points, d);  // o and the points are collinear: always coplanar
}

}  // namespace exactgeo::internal
