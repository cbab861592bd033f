#pragma once

// Exact static distances between the primitives of a CCD query at a rational time, by
// clamped projections and 2x2 Gram systems: a route of their own, apart from the feature
// conditions of the library and of the minimum-separation oracle.

#include <gmpxx.h>

#include <algorithm>
#include <array>
#include <cstddef>

#include "exactgeo/ccd/queries.hpp"

namespace exactgeo::testing {

namespace static_distance {

using Rational = mpq_class;
using Vec = std::array<Rational, 3>;

inline Vec at(const exactgeo::Point3& p0, const exactgeo::Point3& p1, const Rational& t) {
  Vec x;
  for (std::size_t i = 0; i < 3; ++i)
    x[i] = Rational(p0[i]) + t * (Rational(p1[i]) - Rational(p0[i]));
  return x;
}

inline Vec operator-(const Vec& a, const Vec& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
inline Vec operator+(const Vec& a, const Vec& b) {
  return {a[0] + b[0], a[1] + b[1], a[2] + b[2]};
}
inline Vec operator*(const Rational& k, const Vec& a) {
  return {k * a[0], k * a[1], k * a[2]};
}
inline Rational dot(const Vec& a, const Vec& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

inline Rational point_segment_d2(const Vec& p, const Vec& a, const Vec& b) {
  const Vec e = b - a, w = p - a;
  const Rational ee = dot(e, e);
  if (ee == 0) return dot(w, w);
  const Rational s = std::clamp(Rational(dot(w, e) / ee), Rational(0), Rational(1));
  const Vec d = w - s * e;
  return dot(d, d);
}

inline Rational point_triangle_d2(const Vec& p, const Vec& a, const Vec& b, const Vec& c) {
  Rational best =
      std::min({point_segment_d2(p, a, b), point_segment_d2(p, b, c), point_segment_d2(p, c, a)});
  // Stationary point of |w - x e1 - y e2|^2: [e1.e1 e1.e2; e1.e2 e2.e2] (x, y) = (e1.w, e2.w).
  const Vec e1 = b - a, e2 = c - a, w = p - a;
  const Rational g11 = dot(e1, e1), g12 = dot(e1, e2), g22 = dot(e2, e2);
  const Rational det = g11 * g22 - g12 * g12;
  if (det != 0) {
    const Rational x = (dot(e1, w) * g22 - g12 * dot(e2, w)) / det;
    const Rational y = (g11 * dot(e2, w) - g12 * dot(e1, w)) / det;
    if (x >= 0 && y >= 0 && x + y <= 1) {
      const Vec d = w - x * e1 - y * e2;
      best = std::min(best, dot(d, d));
    }
  }
  return best;
}

inline Rational segment_segment_d2(const Vec& a0, const Vec& a1, const Vec& b0, const Vec& b1) {
  Rational best = std::min({point_segment_d2(a0, b0, b1), point_segment_d2(a1, b0, b1),
                            point_segment_d2(b0, a0, a1), point_segment_d2(b1, a0, a1)});
  // Stationary point of |r0 + s da - u db|^2 with r0 = a0 - b0:
  // s da.da - u da.db = -r0.da,  s da.db - u db.db = -r0.db.
  const Vec da = a1 - a0, db = b1 - b0, r0 = a0 - b0;
  const Rational m11 = dot(da, da), m12 = -dot(da, db), m21 = dot(da, db), m22 = -dot(db, db);
  const Rational det = m11 * m22 - m12 * m21;
  if (det != 0) {
    const Rational rhs1 = -dot(r0, da), rhs2 = -dot(r0, db);
    const Rational s = (rhs1 * m22 - m12 * rhs2) / det;
    const Rational u = (m11 * rhs2 - rhs1 * m21) / det;
    if (s >= 0 && s <= 1 && u >= 0 && u <= 1) {
      const Vec d = r0 + s * da - u * db;
      best = std::min(best, dot(d, d));
    }
  }
  return best;
}

inline Rational distance2_at(const ccd::VertexFaceQuery& q, const Rational& t) {
  return point_triangle_d2(at(q.v_t0, q.v_t1, t), at(q.f0_t0, q.f0_t1, t), at(q.f1_t0, q.f1_t1, t),
                           at(q.f2_t0, q.f2_t1, t));
}

inline Rational distance2_at(const ccd::EdgeEdgeQuery& q, const Rational& t) {
  return segment_segment_d2(at(q.ea0_t0, q.ea0_t1, t), at(q.ea1_t0, q.ea1_t1, t),
                            at(q.eb0_t0, q.eb0_t1, t), at(q.eb1_t0, q.eb1_t1, t));
}

}  // namespace static_distance

/// The squared distance between the primitives of q at time t.
using static_distance::distance2_at;

}  // namespace exactgeo::testing
