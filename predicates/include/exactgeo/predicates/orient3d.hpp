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

}  // namespace exactgeo
