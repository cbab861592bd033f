#pragma once

// Where to look for a separating plane: the direction from the origin to the point of a
// flat polygon (a triangle, or a parallelogram as two triangles) closest to it, in plain
// doubles. Only a proposal: any normal will do, because whoever uses it certifies every
// corner's side of the plane it spans (the culling planes of the pair room,
// internal/culling.hpp; the planes of minimum separation, separation/min_separation.cpp).
// An estimate off by rounding gives a slightly tilted plane, never a wrong answer.
//
// Shared by both rooms, so it lives below them (docs/architecture.md, "ccd/").

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

#include "exactgeo/predicates/kernel/formulas.hpp"
#include "exactgeo/predicates/point.hpp"

namespace exactgeo::ccd::internal {

/// A normal that spans a plane: finite and not zero.
inline bool usable(const Vector3& n) noexcept {
  return std::isfinite(n[0]) && std::isfinite(n[1]) && std::isfinite(n[2]) &&
         (n[0] != 0.0 || n[1] != 0.0 || n[2] != 0.0);
}

/// The point of segment [p, q] closest to the origin, in plain doubles.
inline Vector3 closest_on_segment(const Vector3& p, const Vector3& q) noexcept {
  const Vector3 d = kernel::difference(q, p);
  const double dd = kernel::dot3(d, d);
  const double s = dd > 0.0 ? std::clamp(-kernel::dot3(p, d) / dd, 0.0, 1.0) : 0.0;
  return {p[0] + s * d[0], p[1] + s * d[1], p[2] + s * d[2]};
}

/// The point of triangle (a, b, c) closest to the origin, in plain doubles (an estimate:
/// it only proposes a normal, which its user then certifies).
inline Vector3 closest_on_triangle(const Vector3& a, const Vector3& b, const Vector3& c) noexcept {
  const Vector3 e1 = kernel::difference(b, a);
  const Vector3 e2 = kernel::difference(c, a);
  // Minimise |a + s e1 + t e2|^2: the normal equations.
  const double d11 = kernel::dot3(e1, e1), d12 = kernel::dot3(e1, e2), d22 = kernel::dot3(e2, e2);
  const double r1 = -kernel::dot3(a, e1), r2 = -kernel::dot3(a, e2);
  const double det = d11 * d22 - d12 * d12;
  if (det > 0.0) {
    const double s = (r1 * d22 - r2 * d12) / det;
    const double t = (r2 * d11 - r1 * d12) / det;
    if (s >= 0.0 && t >= 0.0 && s + t <= 1.0) {
      return {a[0] + s * e1[0] + t * e2[0], a[1] + s * e1[1] + t * e2[1],
              a[2] + s * e1[2] + t * e2[2]};
    }
  }
  Vector3 best = closest_on_segment(a, b);
  for (const Vector3& candidate : {closest_on_segment(b, c), closest_on_segment(c, a)}) {
    if (kernel::dot3(candidate, candidate) < kernel::dot3(best, best)) best = candidate;
  }
  return best;
}

/// The direction to the slice's point closest to the origin: stable when the primitives
/// stay close and nearly parallel, where the slice's own plane turns quickly with time.
template <std::size_t H>
Vector3 closest_direction(const std::array<Vector3, H>& x) noexcept {
  Vector3 closest = closest_on_triangle(x[0], x[1], x[2]);
  if constexpr (H == 4) {
    const Vector3 other = closest_on_triangle(x[0], x[2], x[3]);
    if (kernel::dot3(other, other) < kernel::dot3(closest, closest)) closest = other;
  }
  return closest;
}

}  // namespace exactgeo::ccd::internal
