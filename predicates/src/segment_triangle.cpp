#include "exactgeo/predicates/segment_triangle.hpp"

#include <algorithm>
#include <array>

#include "exactgeo/predicates/orient3d.hpp"

namespace exactgeo {

namespace {

/// x, in the plane of the non-degenerate triangle pqr (seen along `axis`, along which the
/// plane has a shadow), in the closed triangle: on no edge's far side.
bool in_shadow(int axis, const Point3& p, const Point3& q, const Point3& r,
               const Point3& x) noexcept {
  const Sign turn = orient2d_along(axis, p, q, r);
  return orient2d_along(axis, p, q, x) != -turn && orient2d_along(axis, q, r, x) != -turn &&
         orient2d_along(axis, r, p, x) != -turn;
}

}  // namespace

std::optional<int> shadow_axis(const Point3& p, const Point3& q, const Point3& r) noexcept {
  for (const int axis : {0, 1, 2}) {
    if (orient2d_along(axis, p, q, r) != Sign::zero) return axis;
  }
  return std::nullopt;
}

bool in_triangle_of_its_plane(const Point3& p, const Point3& q, const Point3& r,
                              const Point3& x) noexcept {
  return in_shadow(*shadow_axis(p, q, r), p, q, r, x);
}

bool segments_meet_in_plane(int axis, const Point3& a, const Point3& b, const Point3& c,
                            const Point3& d) noexcept {
  const Sign c_side = orient2d_along(axis, a, b, c);
  const Sign d_side = orient2d_along(axis, a, b, d);
  const Sign a_side = orient2d_along(axis, c, d, a);
  const Sign b_side = orient2d_along(axis, c, d, b);
  if (c_side * d_side == Sign::negative && a_side * b_side == Sign::negative) return true;
  // Collinear cases: a point on the other segment's line lies on the segment exactly when
  // it lies in its box (coordinates compare exactly).
  const auto in_box = [](const Point3& s, const Point3& t, const Point3& x) {
    for (int k = 0; k < 3; ++k) {
      if (x[k] < std::min(s[k], t[k]) || x[k] > std::max(s[k], t[k])) return false;
    }
    return true;
  };
  return (c_side == Sign::zero && in_box(a, b, c)) || (d_side == Sign::zero && in_box(a, b, d)) ||
         (a_side == Sign::zero && in_box(c, d, a)) || (b_side == Sign::zero && in_box(c, d, b));
}

bool segment_meets_triangle(const Point3& x, const Point3& y, const Point3& p, const Point3& q,
                            const Point3& r) noexcept {
  const Sign sx = orient3d(p, q, r, x);
  const Sign sy = orient3d(p, q, r, y);
  if (sx == sy && sx != Sign::zero) return false;  // one side of the plane
  if (sx == Sign::zero && sy == Sign::zero) {      // in the plane
    const int axis = *shadow_axis(p, q, r);
    return in_shadow(axis, p, q, r, x) || in_shadow(axis, p, q, r, y) ||
           segments_meet_in_plane(axis, x, y, p, q) || segments_meet_in_plane(axis, x, y, q, r) ||
           segments_meet_in_plane(axis, x, y, r, p);
  }
  // The line xy meets the plane once, at a point of the segment: in the closed triangle
  // when it passes no edge on the wrong side (the three signs do not disagree: they are
  // the sides of the line against the triangle's edges).
  const Sign u = orient3d(x, y, p, q);
  const Sign v = orient3d(x, y, q, r);
  const Sign w = orient3d(x, y, r, p);
  const bool positive = u == Sign::positive || v == Sign::positive || w == Sign::positive;
  const bool negative = u == Sign::negative || v == Sign::negative || w == Sign::negative;
  return !(positive && negative);
}

bool segment_meets_triangle_beyond(const Point3& s, const Point3& x, const Point3& p,
                                   const Point3& q) noexcept {
  if (x == s || orient3d(s, p, q, x) != Sign::zero) return false;  // the point s, or leaves s
  const int axis = *shadow_axis(s, p, q);
  const Sign turn = orient2d_along(axis, s, p, q);
  return orient2d_along(axis, s, p, x) != -turn && orient2d_along(axis, s, x, q) != -turn;
}

}  // namespace exactgeo
