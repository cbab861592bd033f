#include "support/coplanar_overlap_oracle.hpp"

#include <gmpxx.h>

#include <cmath>
#include <stdexcept>
#include <vector>

namespace exactgeo::testing {
namespace {

using Rational = mpq_class;
using Vec3 = std::array<Rational, 3>;
using Vec2 = std::array<Rational, 2>;

Vec3 exact(const Point3& p) {
  for (const double x : p) {
    if (!std::isfinite(x)) throw std::invalid_argument("overlap oracle: non-finite coordinate");
  }
  return {Rational(p[0]), Rational(p[1]), Rational(p[2])};
}

Vec3 normal(const TrianglePoints& t) {
  const Vec3 p = exact(t[0]), q = exact(t[1]), r = exact(t[2]);
  Vec3 u, v;
  for (int k = 0; k < 3; ++k) {
    u[k] = q[k] - p[k];
    v[k] = r[k] - p[k];
  }
  return {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
}

Rational dot(const Vec3& a, const Vec3& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

Rational cross(const Vec2& o, const Vec2& p, const Vec2& q) {
  return (p[0] - o[0]) * (q[1] - o[1]) - (p[1] - o[1]) * (q[0] - o[0]);
}

/// Twice the signed area of a polygon (shoelace).
Rational twice_area(const std::vector<Vec2>& polygon) {
  Rational sum = 0;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Vec2& p = polygon[i];
    const Vec2& q = polygon[(i + 1) % polygon.size()];
    sum += p[0] * q[1] - p[1] * q[0];
  }
  return sum;
}

/// The part of `polygon` on the closed left side of the directed line pq.
std::vector<Vec2> clip(const std::vector<Vec2>& polygon, const Vec2& p, const Vec2& q) {
  std::vector<Vec2> kept;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Vec2& s = polygon[i];
    const Vec2& e = polygon[(i + 1) % polygon.size()];
    const Rational side_s = cross(p, q, s), side_e = cross(p, q, e);
    if (side_s >= 0) kept.push_back(s);
    if ((side_s > 0 && side_e < 0) || (side_s < 0 && side_e > 0)) {
      const Rational t = side_s / (side_s - side_e);
      kept.push_back({s[0] + t * (e[0] - s[0]), s[1] + t * (e[1] - s[1])});
    }
  }
  return kept;
}

}  // namespace

bool coplanar_oracle(const TrianglePoints& a, const TrianglePoints& b) {
  const Vec3 n = normal(a);
  if (n[0] == 0 && n[1] == 0 && n[2] == 0) throw std::invalid_argument("overlap oracle: zero area");
  const Vec3 origin = exact(a[0]);
  for (const Point3& x : b) {
    const Vec3 p = exact(x);
    const Vec3 d{p[0] - origin[0], p[1] - origin[1], p[2] - origin[2]};
    if (dot(n, d) != 0) return false;
  }
  return true;
}

Sign facing_oracle(const TrianglePoints& a, const TrianglePoints& b) {
  const int s = sgn(dot(normal(a), normal(b)));
  return s > 0 ? Sign::positive : s < 0 ? Sign::negative : Sign::zero;
}

bool coplanar_overlap_oracle(const TrianglePoints& a, const TrianglePoints& b) {
  if (!coplanar_oracle(a, b)) throw std::invalid_argument("overlap oracle: not in one plane");
  // Drop the coordinate along which the normal is largest: the projection keeps areas up
  // to that component's factor, and the region's positivity exactly.
  const Vec3 n = normal(a);
  int axis = 0;
  for (int k = 1; k < 3; ++k) {
    if (abs(n[k]) > abs(n[axis])) axis = k;
  }
  const int i = (axis + 1) % 3, j = (axis + 2) % 3;
  const auto project = [&](const TrianglePoints& t) {
    std::vector<Vec2> polygon;
    for (const Point3& x : t) {
      const Vec3 p = exact(x);
      polygon.push_back({p[i], p[j]});
    }
    if (twice_area(polygon) < 0) std::swap(polygon[1], polygon[2]);  // counter-clockwise
    return polygon;
  };
  std::vector<Vec2> left = project(a);
  const std::vector<Vec2> clipper = project(b);
  if (twice_area(clipper) == 0) throw std::invalid_argument("overlap oracle: zero area");
  for (std::size_t k = 0; k < 3 && !left.empty(); ++k)
    left = clip(left, clipper[k], clipper[(k + 1) % 3]);
  return left.size() >= 3 && twice_area(left) > 0;
}

}  // namespace exactgeo::testing
