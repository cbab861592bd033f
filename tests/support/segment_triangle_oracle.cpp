#include "support/segment_triangle_oracle.hpp"

#include <gmpxx.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <stdexcept>

namespace exactgeo::testing {
namespace {

using Q = mpq_class;
using V3 = std::array<Q, 3>;
using V2 = std::array<Q, 2>;

V3 exact(const Point3& p) {
  for (const double x : p) {
    if (!std::isfinite(x)) throw std::invalid_argument("segment oracle: non-finite coordinate");
  }
  return {Q(p[0]), Q(p[1]), Q(p[2])};
}

V3 sub(const V3& a, const V3& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}

V3 cross(const V3& a, const V3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

Q dot(const V3& a, const V3& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

bool zero(const V3& a) {
  return a[0] == 0 && a[1] == 0 && a[2] == 0;
}

/// The parameter interval [lo, hi] of the points a + t (b - a), t in [0, 1], inside the
/// closed 2D triangle pqr (counter-clockwise after orienting), or nullopt when empty:
/// Cyrus-Beck clipping against the three edge half-planes.
std::optional<std::array<Q, 2>> clip(const V2& a, const V2& b, std::array<V2, 3> t) {
  const auto cross2 = [](const V2& o, const V2& u, const V2& v) -> Q {
    return (u[0] - o[0]) * (v[1] - o[1]) - (u[1] - o[1]) * (v[0] - o[0]);
  };
  if (cross2(t[0], t[1], t[2]) < 0) std::swap(t[1], t[2]);
  Q lo = 0, hi = 1;
  for (int k = 0; k < 3; ++k) {
    const V2& e0 = t[k];
    const V2& e1 = t[(k + 1) % 3];
    // side(t) = cross2(e0, e1, a + t (b - a)) = side_a + t (side_b - side_a) >= 0.
    const Q side_a = cross2(e0, e1, a);
    const Q slope = cross2(e0, e1, b) - side_a;
    if (slope == 0) {
      if (side_a < 0) return std::nullopt;
      continue;
    }
    const Q t0 = -side_a / slope;
    if (slope > 0) {
      lo = std::max(lo, t0);
    } else {
      hi = std::min(hi, t0);
    }
  }
  if (lo > hi) return std::nullopt;
  return std::array<Q, 2>{lo, hi};
}

/// The points projected along the axis of the largest normal component.
struct Plane2 {
  int i, j;
  V2 operator()(const V3& p) const { return {p[i], p[j]}; }
};

Plane2 plane_of(const V3& normal) {
  int axis = 0;
  for (int k = 1; k < 3; ++k) {
    if (abs(normal[k]) > abs(normal[axis])) axis = k;
  }
  return {(axis + 1) % 3, (axis + 2) % 3};
}

}  // namespace

bool collinear_oracle(const Point3& p, const Point3& q, const Point3& r) {
  const V3 a = exact(p);
  return zero(cross(sub(exact(q), a), sub(exact(r), a)));
}

bool segment_meets_triangle_oracle(const Point3& x, const Point3& y, const Point3& p,
                                   const Point3& q, const Point3& r) {
  const V3 X = exact(x), Y = exact(y), P = exact(p), Q1 = exact(q), R = exact(r);
  const V3 e1 = sub(Q1, P), e2 = sub(R, P), d = sub(Y, X);
  const V3 normal = cross(e1, e2);
  if (zero(normal)) throw std::invalid_argument("segment oracle: a collinear triangle");
  const Q denominator = dot(normal, d);
  if (denominator != 0) {
    // x + t d = p + u e1 + v e2: t from the plane, then u, v in the plane.
    const Q t = dot(normal, sub(P, X)) / denominator;
    if (t < 0 || t > 1) return false;
    const V3 point{X[0] + t * d[0], X[1] + t * d[1], X[2] + t * d[2]};
    const V3 w = sub(point, P);
    const Q nn = dot(normal, normal);
    const Q u = dot(cross(w, e2), normal) / nn;
    const Q v = dot(cross(e1, w), normal) / nn;
    return u >= 0 && v >= 0 && u + v <= 1;
  }
  if (dot(normal, sub(X, P)) != 0) return false;  // parallel, off the plane
  const Plane2 flat = plane_of(normal);
  return clip(flat(X), flat(Y), {flat(P), flat(Q1), flat(R)}).has_value();
}

bool segment_meets_triangle_beyond_oracle(const Point3& s, const Point3& x, const Point3& p,
                                          const Point3& q) {
  const V3 S = exact(s), X = exact(x), P = exact(p), Q1 = exact(q);
  const V3 normal = cross(sub(P, S), sub(Q1, S));
  if (zero(normal)) throw std::invalid_argument("segment oracle: a collinear triangle");
  if (dot(normal, sub(X, S)) != 0) return false;  // leaves the plane at s: meets it there only
  if (X == S) return false;
  const Plane2 flat = plane_of(normal);
  const auto part = clip(flat(S), flat(X), {flat(S), flat(P), flat(Q1)});
  return part.has_value() && (*part)[1] > 0;
}

}  // namespace exactgeo::testing
