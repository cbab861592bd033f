#pragma once

// Where a segment meets a triangle, decided in GMP rationals by solving for the meeting
// point (Cramer's rule on the segment's and the triangle's parametric forms, clipping in
// the plane when they share it): an oracle for exactgeo/predicates/segment_triangle.hpp,
// which decides by signs of orientations instead. Closed sets; finite coordinates (throws
// std::invalid_argument otherwise).

#include "exactgeo/predicates/point.hpp"

namespace exactgeo::testing {

bool collinear_oracle(const Point3& p, const Point3& q, const Point3& r);

/// The closed segment xy meets the closed triangle pqr (pqr not collinear).
bool segment_meets_triangle_oracle(const Point3& x, const Point3& y, const Point3& p,
                                   const Point3& q, const Point3& r);

/// The segment from s to x meets the closed triangle s p q at a point other than s.
bool segment_meets_triangle_beyond_oracle(const Point3& s, const Point3& x, const Point3& p,
                                          const Point3& q);

}  // namespace exactgeo::testing
