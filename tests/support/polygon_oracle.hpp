#pragma once

// Polygons in the plane for the tests of faces with more than four corners: generators
// of simple ones (concave, with corners inside straight edges, with a hole written
// through a bridge) on integer coordinates, and exact oracles (GMP rationals) for their
// winding numbers and for triangles in the plane, independent of exactgeo's predicates.

#include <array>
#include <cstdint>
#include <optional>
#include <random>
#include <vector>

#include "exactgeo/predicates/sign.hpp"

namespace exactgeo::testing {

using Point2 = std::array<double, 2>;

/// A polygon: its distinct points, and the cycle of indices walked (a polygon with a hole
/// walks its bridge's two ends twice).
struct Polygon2 {
  std::vector<Point2> points;
  std::vector<std::uint32_t> cycle;
};

/// Sign of (b - a) x (c - a), exactly.
Sign orientation_oracle(const Point2& a, const Point2& b, const Point2& c);

/// The winding number of the polygon's cycle around q, exactly; nullopt when q lies on one
/// of its edges.
std::optional<int> winding_number_oracle(const Polygon2& polygon, const Point2& q);

/// Twice the signed area of the polygon's cycle (the shoelace sum) minus twice the signed
/// areas of the triangles, exactly: zero when the triangles' signed areas add up to the
/// polygon's. `triangles` index polygon.points.
bool areas_add_up(const Polygon2& polygon,
                  const std::vector<std::array<std::uint32_t, 3>>& triangles);

/// A simple polygon of `corners` corners, star-shaped about the origin, counter-clockwise:
/// corner k is t_k (dx_k, dy_k) on integer rays of strictly increasing angle with gaps
/// below pi (so consecutive edges stay in disjoint wedges), with integer t_k. With
/// `collinear`, about a third of the edges get their midpoint as an extra corner (the
/// coordinates are even, so midpoints are integers).
Polygon2 random_star_polygon(std::mt19937_64& rng, int corners, bool collinear);

/// The square [0, 8]^2 with the hole [3, 5]^2 (or, when `concave_hole`, an L-shaped hole
/// in [2, 6]^2), counter-clockwise around the outside, written as one cycle through a
/// bridge from (0, 0) to the hole's corner nearest it, walked there and back.
Polygon2 keyhole_polygon(bool concave_hole);

}  // namespace exactgeo::testing
