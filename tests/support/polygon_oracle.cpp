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

}  // namespace exactgeo::testing
