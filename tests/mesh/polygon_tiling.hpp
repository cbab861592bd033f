#pragma once

// Whether triangles tile a polygon of the plane, decided by exact oracles that know
// nothing of how the triangles were made (support/polygon_oracle.hpp): shared by the tests
// of the readers' polygons and of the triangulation's parts.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "exactgeo/predicates/sign.hpp"
#include "support/polygon_oracle.hpp"

namespace exactgeo::mesh::test_polygons {

using testing::Point2;
using testing::Polygon2;

/// The certificate that `triangles` tile the polygon (in its own (x, y) coordinates):
/// each turns as the polygon does, strictly; their areas add up; at random points
/// (dyadic, off every edge) the triangles covering the point number the polygon's
/// winding number there.
inline void expect_tiles(const Polygon2& polygon,
                         const std::vector<std::array<std::uint32_t, 3>>& triangles,
                         std::mt19937_64& rng, const std::string& what, int samples = 400) {
  SCOPED_TRACE(what);
  ASSERT_EQ(triangles.size(), polygon.cycle.size() - 2);
  for (const auto& t : triangles) {
    ASSERT_EQ(testing::orientation_oracle(polygon.points[t[0]], polygon.points[t[1]],
                                          polygon.points[t[2]]),
              Sign::positive);  // the generators' polygons turn counter-clockwise
  }
  ASSERT_TRUE(testing::areas_add_up(polygon, triangles));
  Point2 lower = polygon.points[0];
  Point2 upper = lower;
  for (const Point2& q : polygon.points) {
    for (int k = 0; k < 2; ++k) {
      lower[k] = std::min(lower[k], q[k]);
      upper[k] = std::max(upper[k], q[k]);
    }
  }
  // Each triangle's box: a point outside it is neither inside the triangle nor on a side
  // (exact comparisons), which spares the rational orientations for most triangles.
  std::vector<std::array<Point2, 2>> boxes;
  for (const auto& t : triangles) {
    std::array<Point2, 2> box{polygon.points[t[0]], polygon.points[t[0]]};
    for (const std::uint32_t c : t) {
      for (int k = 0; k < 2; ++k) {
        box[0][k] = std::min(box[0][k], polygon.points[c][k]);
        box[1][k] = std::max(box[1][k], polygon.points[c][k]);
      }
    }
    boxes.push_back(box);
  }
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int checked = 0;
  int inside = 0;
  for (int sample = 0; sample < samples; ++sample) {
    Point2 q;
    for (int k = 0; k < 2; ++k)  // 2^-12 steps: exact sums with the integers (below 2^40)
      q[k] =
          lower[k] + std::ldexp(std::floor(std::ldexp(unit(rng), 12) * (upper[k] - lower[k])), -12);
    const std::optional<int> winding = testing::winding_number_oracle(polygon, q);
    if (!winding) continue;
    int covering = 0;
    bool on_a_side = false;
    for (std::size_t i = 0; i < triangles.size(); ++i) {
      const auto& box = boxes[i];
      if (q[0] < box[0][0] || q[0] > box[1][0] || q[1] < box[0][1] || q[1] > box[1][1]) continue;
      const auto& t = triangles[i];
      const Point2 &a = polygon.points[t[0]], &b = polygon.points[t[1]], &c = polygon.points[t[2]];
      const Sign s0 = testing::orientation_oracle(a, b, q);
      const Sign s1 = testing::orientation_oracle(b, c, q);
      const Sign s2 = testing::orientation_oracle(c, a, q);
      on_a_side = on_a_side || s0 == Sign::zero || s1 == Sign::zero || s2 == Sign::zero;
      covering += s0 == Sign::positive && s1 == Sign::positive && s2 == Sign::positive;
    }
    if (on_a_side) continue;
    ASSERT_EQ(covering, *winding) << "at (" << q[0] << ", " << q[1] << ")";
    ++checked;
    inside += covering;
  }
  EXPECT_GT(checked, samples * 3 / 4);
  EXPECT_GT(inside, 0);
}

}  // namespace exactgeo::mesh::test_polygons
