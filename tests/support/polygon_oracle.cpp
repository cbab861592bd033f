#include "support/polygon_oracle.hpp"

#include <gmpxx.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <numbers>
#include <numeric>

namespace exactgeo::testing {
namespace {

// Every double is m 2^k with m an integer: the coordinates of a few points, all
// multiples of 2^e for the least such k, are exact integers once divided by 2^e, and
// GMP integers (no fractions to reduce) decide their signs.

/// The exponent of x's lowest set bit (x not zero): x is an integer times 2^that.
int lowest_exponent(double x) {
  int k = 0;
  const double f = std::frexp(std::abs(x), &k);  // |x| = f 2^k, f in [1/2, 1)
  const auto m = static_cast<std::uint64_t>(std::ldexp(f, 53));
  return k - 53 + std::countr_zero(m);
}

/// x / 2^e, exactly (x a multiple of 2^e).
mpz_class scaled(double x, int e) {
  if (x == 0) return 0;
  int k = 0;
  const double f = std::frexp(std::abs(x), &k);
  auto bits = static_cast<std::uint64_t>(std::ldexp(f, 53));
  const int zeros = std::countr_zero(bits);
  bits >>= zeros;
  k += zeros - 53;
  const mpz_class m(static_cast<unsigned long>(bits));
  mpz_class result;
  mpz_mul_2exp(result.get_mpz_t(), m.get_mpz_t(), static_cast<mp_bitcnt_t>(k - e));
  return x < 0 ? mpz_class(-result) : result;
}

/// The least exponent of the points' nonzero coordinates (0 when all are zero).
int common_exponent(std::initializer_list<const Point2*> points) {
  int e = 0;
  bool any = false;
  for (const Point2* p : points) {
    for (const double x : *p) {
      if (x == 0) continue;
      e = any ? std::min(e, lowest_exponent(x)) : lowest_exponent(x);
      any = true;
    }
  }
  return e;
}

/// (b - a) x (c - a) / 2^(2e), exactly, for coordinates that are multiples of 2^e.
mpz_class cross(const Point2& a, const Point2& b, const Point2& c, int e) {
  const mpz_class a0 = scaled(a[0], e), a1 = scaled(a[1], e);
  return (scaled(b[0], e) - a0) * (scaled(c[1], e) - a1) -
         (scaled(b[1], e) - a1) * (scaled(c[0], e) - a0);
}

Sign sign_of(const mpz_class& x) {
  const int s = sgn(x);
  return s > 0 ? Sign::positive : s < 0 ? Sign::negative : Sign::zero;
}

}  // namespace

Sign orientation_oracle(const Point2& a, const Point2& b, const Point2& c) {
  const int e = common_exponent({&a, &b, &c});
  // Integers below 2^60 once divided by 2^e (most points of the tests): 128-bit integer
  // arithmetic is exact for them (differences below 2^61, products below 2^122).
  std::array<std::int64_t, 6> v{};
  bool small = true;
  const std::array<double, 6> x{a[0], a[1], b[0], b[1], c[0], c[1]};
  for (std::size_t k = 0; k < 6; ++k) {
    const double y = std::ldexp(x[k], -e);  // exact: an integer, or too large
    small = small && std::abs(y) < 0x1p60;
    if (small) v[k] = static_cast<std::int64_t>(y);
  }
  if (small) {
    __extension__ typedef __int128 Int128;
    const Int128 d = static_cast<Int128>(v[2] - v[0]) * (v[5] - v[1]) -
                     static_cast<Int128>(v[3] - v[1]) * (v[4] - v[0]);
    return d > 0 ? Sign::positive : d < 0 ? Sign::negative : Sign::zero;
  }
  return sign_of(cross(a, b, c, e));
}

std::optional<int> winding_number_oracle(const Polygon2& polygon, const Point2& q) {
  // Signed crossings of the ray from q towards +x, each edge counted when it straddles
  // the horizontal line through q with its lower end included (the half-open rule).
  int winding = 0;
  const std::size_t n = polygon.cycle.size();
  for (std::size_t k = 0; k < n; ++k) {
    const Point2& a = polygon.points[polygon.cycle[k]];
    const Point2& b = polygon.points[polygon.cycle[(k + 1) % n]];
    // Outside the edge's band of y, q is not on it and the line through q misses it.
    if (q[1] < std::min(a[1], b[1]) || q[1] > std::max(a[1], b[1])) continue;
    // Beside the edge's box, q is not on it, and it lies on the side of the line through
    // a and b that the edge's vertical direction says (west of an upward edge: left).
    const Sign up = a[1] < b[1] ? Sign::positive : Sign::negative;
    Sign side;
    if (q[0] < std::min(a[0], b[0])) {
      side = up;
    } else if (q[0] > std::max(a[0], b[0])) {
      side = -up;
    } else {
      side = orientation_oracle(a, b, q);
      if (side == Sign::zero) return std::nullopt;  // on the edge (q is in its box)
    }
    if (a[1] <= q[1] && b[1] > q[1] && side == Sign::positive) ++winding;  // upward, q left
    if (a[1] > q[1] && b[1] <= q[1] && side == Sign::negative) --winding;  // downward, q right
  }
  return winding;
}

bool areas_add_up(const Polygon2& polygon,
                  const std::vector<std::array<std::uint32_t, 3>>& triangles) {
  // One scale for every cross product, so that they add up exactly.
  int e = 0;
  bool any = false;
  for (const Point2& p : polygon.points) {
    for (const double x : p) {
      if (x == 0) continue;
      e = any ? std::min(e, lowest_exponent(x)) : lowest_exponent(x);
      any = true;
    }
  }
  const Point2 origin{0.0, 0.0};
  mpz_class difference = 0;
  const std::size_t n = polygon.cycle.size();
  for (std::size_t k = 0; k < n; ++k) {
    difference += cross(origin, polygon.points[polygon.cycle[k]],
                        polygon.points[polygon.cycle[(k + 1) % n]], e);
  }
  for (const auto& t : triangles) {
    difference -= cross(polygon.points[t[0]], polygon.points[t[1]], polygon.points[t[2]], e);
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

}  // namespace exactgeo::testing
