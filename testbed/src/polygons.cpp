#include "exactgeo/testbed/polygons.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <numeric>

namespace exactgeo::testbed {

namespace {

/// The cycle through the polygon's points in order; with `collinear`, about a third of the
/// edges get their midpoint as an extra corner (exact: the coordinates are even integers).
void walk_corners(Polygon2& polygon, std::mt19937_64& rng, bool collinear) {
  std::bernoulli_distribution split(1.0 / 3.0);
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
}

}  // namespace

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
  for (const auto& ray : rays) {
    const double t = 2.0 * length(rng);
    polygon.points.push_back({t * ray[0], t * ray[1]});
  }
  walk_corners(polygon, rng, collinear);
  return polygon;
}

Polygon2 convex_polygon(std::mt19937_64& rng, int corners) {
  const double radius = std::max(65536.0, static_cast<double>(corners) * corners);
  const double start = std::uniform_real_distribution<double>(0.0, 2.0 * std::numbers::pi)(rng);
  Polygon2 polygon;
  for (int k = 0; k < corners; ++k) {
    const double angle = start + 2.0 * std::numbers::pi * k / corners;
    polygon.points.push_back(
        {std::round(radius * std::cos(angle)), std::round(radius * std::sin(angle))});
    polygon.cycle.push_back(static_cast<std::uint32_t>(k));
  }
  return polygon;
}

Polygon2 star_polygon(std::mt19937_64& rng, int corners, bool collinear) {
  const double radius = std::max(65536.0, 16.0 * corners);
  std::uniform_real_distribution<double> jitter(-0.25, 0.25);
  std::uniform_real_distribution<double> length(radius / 2, radius);
  Polygon2 polygon;
  for (int k = 0; k < corners; ++k) {
    const double angle = 2.0 * std::numbers::pi * (k == 0 ? 0.0 : k + jitter(rng)) / corners;
    const double r = length(rng);
    polygon.points.push_back(
        {2.0 * std::round(r * std::cos(angle) / 2), 2.0 * std::round(r * std::sin(angle) / 2)});
  }
  walk_corners(polygon, rng, collinear);
  return polygon;
}

Polygon2 comb_polygon(std::mt19937_64& rng, int teeth) {
  std::uniform_int_distribution<int> step(1, 3);
  std::uniform_int_distribution<int> height(1, 4);
  std::vector<std::array<double, 3>> tooth;  // left x, right x, top y
  double x = 0;
  for (int k = 0; k < teeth; ++k) {
    const double left = k == 0 ? 0.0 : x + step(rng);
    x = left + step(rng);
    tooth.push_back({left, x, 2.0 + 8.0 * height(rng)});
  }
  // Along the spine's bottom, then over the teeth from the last back to the first.
  Polygon2 polygon;
  polygon.points = {{0, 0}, {x, 0}};
  for (std::size_t k = tooth.size(); k-- > 0;) {
    const auto [left, right, top] = tooth[k];
    if (k + 1 < tooth.size()) polygon.points.push_back({right, 2});
    polygon.points.push_back({right, top});
    polygon.points.push_back({left, top});
    if (k > 0) polygon.points.push_back({left, 2});
  }
  for (std::uint32_t k = 0; k < polygon.points.size(); ++k)
    polygon.cycle.push_back(k);
  return polygon;
}

Polygon2 holed_star_polygon(std::mt19937_64& rng, int corners) {
  Polygon2 polygon = star_polygon(rng, corners, false);
  const double radius = std::max(65536.0, 16.0 * corners);
  // Centres from r/4 inward, every `gap`, half-diagonal gap/4: well inside, where the star
  // (radii at least r/2, gaps of angle below 3 pi / corners) contains the disk of r/4.
  const int holes = std::max(1, corners / 16);
  const double gap = std::floor(radius / 8 / holes);
  const double half = std::floor(gap / 4);
  std::uint32_t first = static_cast<std::uint32_t>(polygon.points.size());
  for (int h = 0; h < holes; ++h) {
    const double c = std::floor(radius / 4) - gap * h;
    // Right, bottom, left, top: clockwise.
    polygon.points.insert(polygon.points.end(),
                          {{c + half, 0}, {c, -half}, {c - half, 0}, {c, half}});
  }
  const auto corner = [&](int h, int k) { return first + static_cast<std::uint32_t>(4 * h + k); };
  polygon.cycle.push_back(0);  // back at corner 0, then out along the first bridge
  for (int h = 0; h < holes; ++h) {
    polygon.cycle.insert(polygon.cycle.end(), {corner(h, 0), corner(h, 1), corner(h, 2)});
  }
  polygon.cycle.push_back(corner(holes - 1, 3));
  polygon.cycle.push_back(corner(holes - 1, 0));
  for (int h = holes - 1; h-- > 0;) {
    polygon.cycle.insert(polygon.cycle.end(), {corner(h, 2), corner(h, 3), corner(h, 0)});
  }
  return polygon;  // the cycle closes from the first hole's right corner to corner 0
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

}  // namespace exactgeo::testbed
