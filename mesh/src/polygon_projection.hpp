#pragma once

// A polygon seen along one coordinate axis: its points with that coordinate dropped, the
// other two in cyclic order (u, v), so that orientations are those of orient2d_along.
// Every decision is exact: orientations are exact signs, positions are compared as the
// doubles they are. The sweeps order points lexicographically, by u then v: the standard
// symbolic tilt of the sweep line that makes points of equal u (vertical edges) harmless.

#include <algorithm>

#include "exactgeo/predicates/kernel/signs.hpp"
#include "exactgeo/predicates/point.hpp"
#include "exactgeo/predicates/sign.hpp"

namespace exactgeo::mesh::internal {

class Projection {
 public:
  explicit constexpr Projection(int axis) noexcept
      : axis_(axis), u_((axis + 1) % 3), v_((axis + 2) % 3) {}

  int axis() const noexcept { return axis_; }

  /// The sign of ((b - a) x (c - a)) along the dropped axis, exactly: positive when a, b, c
  /// turn counter-clockwise in the (u, v) plane.
  /// It is orient2d_along's sign, the kernel's filter then exact stages, written inline:
  /// the sweeps ask it a few dozen times per corner, most often in the flat projection
  /// (axis 2, a constant once inlined), where the filter is a handful of instructions.
  Sign orientation(const Point3& a, const Point3& b, const Point3& c) const noexcept {
    using kernel::Offset;
    return kernel::ExactSigns{}.cross2(axis_, Offset::between(a, b), Offset::between(a, c));
  }

  double u(const Point3& p) const noexcept { return p[u_]; }
  double v(const Point3& p) const noexcept { return p[v_]; }

  /// p's projection as a point of the plane z = 0 (its two coordinates copied exactly):
  /// Projection(2) sees the same orientations and the same sweep order in such points, and
  /// the sweeps keep them side by side in memory.
  Point3 flat(const Point3& p) const noexcept { return {p[u_], p[v_], 0.0}; }

  /// p before q in the sweep: (p_u, p_v) lexicographically smaller than (q_u, q_v).
  bool before(const Point3& p, const Point3& q) const noexcept {
    return p[u_] < q[u_] || (p[u_] == q[u_] && p[v_] < q[v_]);
  }

  /// p and q project to the same point.
  bool same(const Point3& p, const Point3& q) const noexcept {
    return p[u_] == q[u_] && p[v_] == q[v_];
  }

  /// p in the closed triangle abc, whose orientation is `turn` (not zero). The box test
  /// first spares the orientations for most points.
  bool in_triangle(const Point3& a, const Point3& b, const Point3& c, Sign turn,
                   const Point3& p) const noexcept {
    for (const int k : {u_, v_}) {
      if (p[k] < std::min({a[k], b[k], c[k]}) || p[k] > std::max({a[k], b[k], c[k]})) return false;
    }
    return orientation(a, b, p) != -turn && orientation(b, c, p) != -turn &&
           orientation(c, a, p) != -turn;
  }

 private:
  int axis_;
  int u_;
  int v_;
};

}  // namespace exactgeo::mesh::internal
