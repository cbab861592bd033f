#pragma once

// Simple polygons in the plane on integer coordinates, for the tests and benchmarks of faces
// with more than four corners: convex, star-shaped (with corners inside straight edges, or
// with holes written through bridges) and comb-shaped. Integer coordinates keep every
// corner exact, so that an exact oracle can judge what is made of them.

#include <array>
#include <cstdint>
#include <random>
#include <vector>

namespace exactgeo::testbed {

using Point2 = std::array<double, 2>;

/// A polygon: its distinct points, and the cycle of indices walked (a polygon with a hole
/// walks its bridge's two ends twice).
struct Polygon2 {
  std::vector<Point2> points;
  std::vector<std::uint32_t> cycle;
};

/// A simple polygon of `corners` corners, star-shaped about the origin, counter-clockwise:
/// corner k is t_k (dx_k, dy_k) on integer rays of strictly increasing angle with gaps
/// below pi (so consecutive edges stay in disjoint wedges), with integer t_k. With
/// `collinear`, about a third of the edges get their midpoint as an extra corner (the
/// coordinates are even, so midpoints are integers).
Polygon2 random_star_polygon(std::mt19937_64& rng, int corners, bool collinear);

/// A strictly convex polygon of `corners` corners, counter-clockwise: points on a circle
/// of radius max(2^16, corners^2) about the origin, from a random angle on, rounded to
/// integers (the radius makes each corner's distance from its neighbours' chord, about
/// 2 pi^2 r / corners^2 >= 19, far larger than the rounding can move it).
Polygon2 convex_polygon(std::mt19937_64& rng, int corners);

/// A simple polygon of `corners` corners (more with `collinear`), star-shaped about the
/// origin, counter-clockwise: corner k at angle 2 pi (k + jitter_k) / corners, jitter in
/// [-1/4, 1/4], at a random radius in [r/2, r], r = max(2^16, 16 corners), rounded to
/// even integers (so that the angles stay strictly increasing and the gaps below pi).
/// Corner 0 lies on the positive x axis. With `collinear`, about a third of the edges get
/// their midpoint as an extra corner.
Polygon2 star_polygon(std::mt19937_64& rng, int corners, bool collinear);

/// A comb of `teeth` teeth, counter-clockwise: a spine along the x axis and teeth up from
/// it, of random widths, gaps and heights drawn from few values (so that many edges share
/// a line and many corners a coordinate), on integer coordinates: 4 corners a tooth.
Polygon2 comb_polygon(std::mt19937_64& rng, int teeth);

/// star_polygon(rng, corners, false) with max(1, corners / 16) holes, squares turned by 45
/// degrees (clockwise) centred on the positive x axis inside it, written as one cycle: out
/// to the first hole along a bridge from corner 0, half around it, on to the next hole
/// along another bridge, and so on; around the last hole, then back along each bridge,
/// finishing each hole on the way (each bridge walked there and back).
Polygon2 holed_star_polygon(std::mt19937_64& rng, int corners);

/// The square [0, 8]^2 with the hole [3, 5]^2 (or, when `concave_hole`, an L-shaped hole
/// in [2, 6]^2), counter-clockwise around the outside, written as one cycle through a
/// bridge from (0, 0) to the hole's corner nearest it, walked there and back.
Polygon2 keyhole_polygon(bool concave_hole);

}  // namespace exactgeo::testbed
