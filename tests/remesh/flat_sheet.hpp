#pragma once

// Flat sheets for the fold-over tests of flips and splits: points of a plane (z = 0, or a
// tilted plane z = x - 2y) on an integer grid times 2^e, so that every point, every
// rounding-free midpoint and the plane itself are exact at 2^0 and 2^+-1000; and the
// oracle's verdict on a surface: no two triangles overlap with area (whichever way they
// face), none has zero area.

#include <cstddef>
#include <functional>
#include <optional>
#include <string>

#include "exactgeo/remesh/surface.hpp"
#include "support/coplanar_overlap_oracle.hpp"

namespace exactgeo::testing {

/// A point of the plane at grid coordinates (x, y), exact for |x|, |y| < 2^20.
using FlatPlane = std::function<Point3(double x, double y)>;

inline FlatPlane flat_plane(bool tilted, int exponent) {
  const double s = std::ldexp(1.0, exponent);
  if (!tilted) return [s](double x, double y) { return Point3{s * x, s * y, 0.0}; };
  return [s](double x, double y) { return Point3{s * x, s * y, s * (x - 2 * y)}; };
}

inline TrianglePoints points_of(const remesh::Surface& s, const remesh::Triangle& t) {
  return {s.vertices[t[0]], s.vertices[t[1]], s.vertices[t[2]]};
}

/// The first pair of triangles of a flat surface that overlap with area, or a triangle of
/// zero area, by the rational oracle; nullopt for a surface whose triangles tile without
/// overlap (touching at edges and corners only).
inline std::optional<std::string> flat_overlap(const remesh::Surface& s) {
  for (std::size_t i = 0; i < s.triangles.size(); ++i) {
    const TrianglePoints a = points_of(s, s.triangles[i]);
    if (facing_oracle(a, a) == Sign::zero)
      return "triangle " + std::to_string(i) + " has zero area";
  }
  for (std::size_t i = 0; i < s.triangles.size(); ++i) {
    const TrianglePoints a = points_of(s, s.triangles[i]);
    for (std::size_t j = i + 1; j < s.triangles.size(); ++j) {
      if (coplanar_overlap_oracle(a, points_of(s, s.triangles[j]))) {
        return "triangles " + std::to_string(i) + " and " + std::to_string(j) + " overlap";
      }
    }
  }
  return std::nullopt;
}

}  // namespace exactgeo::testing
