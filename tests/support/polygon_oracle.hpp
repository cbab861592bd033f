#pragma once

// Exact oracles (GMP integers) for polygons in the plane, independent of exactgeo's
// predicates: their winding numbers, and triangles in the plane; with the polygon
// generators of exactgeo/testbed/polygons.hpp (shared with the benchmarks).

#include <array>
#include <cstdint>
#include <optional>
#include <random>
#include <vector>

#include "exactgeo/predicates/sign.hpp"
#include "exactgeo/testbed/polygons.hpp"

namespace exactgeo::testing {

using testbed::Point2;
using testbed::Polygon2;

/// Sign of (b - a) x (c - a), exactly.
Sign orientation_oracle(const Point2& a, const Point2& b, const Point2& c);

/// The winding number of the polygon's cycle around q, exactly; nullopt when q lies on one
/// of its edges. Exact comparisons of coordinates decide the edges whose boxes q is outside
/// of; GMP the others.
std::optional<int> winding_number_oracle(const Polygon2& polygon, const Point2& q);

/// Twice the signed area of the polygon's cycle (the shoelace sum) minus twice the signed
/// areas of the triangles, exactly: zero when the triangles' signed areas add up to the
/// polygon's. `triangles` index polygon.points.
bool areas_add_up(const Polygon2& polygon,
                  const std::vector<std::array<std::uint32_t, 3>>& triangles);

// The generators, shared with the benchmarks.
using testbed::comb_polygon;
using testbed::convex_polygon;
using testbed::holed_star_polygon;
using testbed::keyhole_polygon;
using testbed::random_star_polygon;
using testbed::star_polygon;

}  // namespace exactgeo::testing
