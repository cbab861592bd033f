#include "support/polygon_oracle.hpp"

#include <gmpxx.h>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace exactgeo::testing {
namespace {

using Rational = mpq_class;

Rational cross(const Point2& a, const Point2& b, const Point2& c) {
  return (Rational(b[0]) - a[0]) * (Rational(c[1]) - a[1]) -
         (Rational(b[1]) - a[1]) * (Rational(c[0]) - a[0]);
}

Sign sign_of(const Rational& x) {
  const int s = sgn(x);
  return s > 0 ? Sign::positive : s < 0 ? Sign::negative : Sign::zero;
}

}  // namespace

Sign orientation_oracle(const Point2& a, const Point2& b, const Point2& c) {
  return sign_of(cross(a, b, c));
}

std::optional<int> winding_number_oracle(const Polygon2& polygon, const Point2& q) {
  // Signed crossings of the ray from q towards +x, each edge counted when it straddles
  // the horizontal line through q with its lower end included (the half-open rule).
  int winding = 0;
  const std::size_t n = polygon.cycle.size();
  for (std::size_t k = 0; k < n; ++k) {
    const Point2& a = polygon.points[polygon.cycle[k]];
    const Point2& b = polygon.points[polygon.cycle[(k + 1) % n]];
    const Sign side = orientation_oracle(a, b, q);
    if (side == Sign::zero && std::min(a[0], b[0]) <= q[0] && q[0] <= std::max(a[0], b[0]) &&
        std::min(a[1], b[1]) <= q[1] && q[1] <= std::max(a[1], b[1])) {
      return std::nullopt;  // on the edge
    }
    if (a[1] <= q[1] && b[1] > q[1] && side == Sign::positive) ++winding;  // upward, q left
    if (a[1] > q[1] && b[1] <= q[1] && side == Sign::negative) --winding;  // downward, q right
  }
  return winding;
}

bool areas_add_up(const Polygon2& polygon,
                  const std::vector<std::array<std::uint32_t, 3>>& triangles) {
  const Point2 origin{0.0, 0.0};
  Rational difference = 0;
  const std::size_t n = polygon.cycle.size();
  for (std::size_t k = 0; k < n; ++k) {
    difference +=
        cross(origin, polygon.points[polygon.cycle[k]], polygon.points[polygon.cycle[(k + 1) % n]]);
  }
  for (const auto& t : triangles) {
    difference -= cross(polygon.points[t[0]], polygon.points[t[1]], polygon.points[t[2]]);
  }
  return sgn(difference) == 0;
}

Polygon2 random_star_polygon(std::mt19937_64& rng, int corners, bool collinear) {
  std::uniform_int_distribution<int> component(-8, 8);
  std::uniform_int_distribution<int> length(1, 1 << 16);
  std::vector<std::array<int, 2>> rays;
  for (;;) {
    rays.clear();
    while (static_cast<int>(rays.size()) < corners) {
      const int dx = component(rng);
      const int dy = component(rng);
      if ((dx == 0 && dy == 0) || std::gcd(dx, dy) != 1) continue;  // one ray, one direction
      if (std::find(rays.begin(), rays.end(), std::array<int, 2>{dx, dy}) != rays.end()) continue;
      rays.push_back({dx, dy});
    }
    std::sort(rays.begin(), rays.end(), [](const auto& a, const auto& b) {
      return std::atan2(a[1], a[0]) < std::atan2(b[1], b[0]);  // distinct rays: far apart
    });
    bool gaps_below_pi = true;
    for (std::size_t k = 0; k < rays.size(); ++k) {
      const auto& a = rays[k];
      const auto& b = rays[(k + 1) % rays.size()];
      gaps_below_pi = gaps_below_pi && a[0] * b[1] - a[1] * b[0] > 0;
    }
    if (gaps_below_pi) break;
  }
  Polygon2 polygon;
  std::bernoulli_distribution split(1.0 / 3.0);
  for (const auto& ray : rays) {
    const double t = 2.0 * length(rng);
    polygon.points.push_back({t * ray[0], t * ray[1]});
  }
  const std::size_t n = polygon.points.size();
  for (std::uint32_t k = 0; k < n; ++k) {
    polygon.cycle.push_back(k);
    if (collinear && split(rng)) {
      const Point2& a = polygon.points[k];
      const Point2& b = polygon.points[(k + 1) % n];
      polygon.points.push_back({(a[0] + b[0]) / 2, (a[1] + b[1]) / 2});
      polygon.cycle.push_back(static_cast<std::uint32_t>(polygon.points.size() - 1));
    }
  }
  return polygon;
}

Polygon2 keyhole_polygon(bool concave_hole) {
  Polygon2 polygon;
  polygon.points = {{0, 0}, {8, 0}, {8, 8}, {0, 8}};
  if (concave_hole) {
    polygon.points.insert(polygon.points.end(), {{2, 2}, {2, 6}, {4, 6}, {4, 4}, {6, 4}, {6, 2}});
  } else {
    polygon.points.insert(polygon.points.end(), {{3, 3}, {3, 5}, {5, 5}, {5, 3}});
  }
  // Around the outside, to the hole's first corner, around the hole (clockwise), back.
  polygon.cycle = {0, 1, 2, 3, 0};
  for (std::uint32_t k = 4; k < polygon.points.size(); ++k)
    polygon.cycle.push_back(k);
  polygon.cycle.push_back(4);
  return polygon;
}

}  // namespace exactgeo::testing
