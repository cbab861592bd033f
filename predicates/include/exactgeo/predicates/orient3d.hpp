#pragma once

#include "exactgeo/predicates/arithmetic.hpp"
#include "exactgeo/predicates/point.hpp"
#include "exactgeo/predicates/sign.hpp"

namespace exactgeo {

/// The exact sign of det[b - a, c - a, d - a]. Positive when d lies on the side of the
/// plane (a, b, c) from which a, b, c appear counter-clockwise (the side (b - a) x (c - a)
/// points to): orient3d((0,0,0), (1,0,0), (0,1,0), (0,0,1)) is positive. Exact for every
/// finite input, including subnormals and values near the overflow threshold.
///
/// Precondition: every coordinate is finite (not NaN or infinite).
Sign orient3d(const Point3& a, const Point3& b, const Point3& c, const Point3& d) noexcept;

/// The same determinant in a chosen arithmetic (see Arithmetic).
Sign orient3d(const Point3& a, const Point3& b, const Point3& c, const Point3& d,
              Arithmetic arithmetic) noexcept;

/// The exact sign of ((b - a) x (c - a))_axis, for axis 0, 1 or 2: how a, b, c turn seen
/// along that coordinate axis (projected with coordinate `axis` dropped, the other two in
/// cyclic order, so that axis 2 gives the usual orientation in the (x, y) plane). Exact
/// for every finite input. Precondition: finite coordinates, axis in {0, 1, 2}.
Sign orient2d_along(int axis, const Point3& a, const Point3& b, const Point3& c) noexcept;

/// p, q and r on one line (or at one point), exactly: (q - p) x (r - p) = 0, orient2d_along
/// zero for all three axes; a triangle of zero area. A triangle of nonzero area has a
/// nonzero component, which the filter certifies at once, where asking orient3d about the
/// degenerate tetrahedron (p, q, r, r) gets an exact zero, the slowest answer. Exact for
/// every finite input. Precondition: finite coordinates.
bool collinear(const Point3& p, const Point3& q, const Point3& r) noexcept;

}  // namespace exactgeo
