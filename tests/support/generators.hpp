#pragma once

// Input generators for exactness tests: random, near-degenerate (degenerate up to
// rounding), exactly degenerate (small dyadic integers), one-ulp perturbations, exact
// power-of-two scaling across the whole double range, and mixed magnitudes.

#include <array>
#include <cmath>
#include <random>

#include "exactgeo/predicates/point.hpp"

namespace exactgeo::testing {

using Rng = std::mt19937_64;

inline double uniform(Rng& rng, double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}
inline int uniform_int(Rng& rng, int lo, int hi) {
  return std::uniform_int_distribution<int>(lo, hi)(rng);
}

inline Point3 random_point(Rng& rng, double scale = 1.0) {
  return {uniform(rng, -scale, scale), uniform(rng, -scale, scale), uniform(rng, -scale, scale)};
}

/// Small integer coordinates in [-range, range]: dyadic, exact under scaling by 2^k.
inline Point3 integer_point(Rng& rng, int range) {
  return {double(uniform_int(rng, -range, range)), double(uniform_int(rng, -range, range)),
          double(uniform_int(rng, -range, range))};
}

/// a + s (b - a) + t (c - a) evaluated in double: coplanar with a, b, c up to rounding.
inline Point3 rounded_affine(const Point3& a, const Point3& b, const Point3& c, double s,
                             double t) {
  Point3 p;
  for (int i = 0; i < 3; ++i)
    p[i] = a[i] + s * (b[i] - a[i]) + t * (c[i] - a[i]);
  return p;
}

/// Four points, the last one computed as a + s (b - a) + t (c - a) in double with s, t
/// uniform in [-spread, spread]: coplanar up to rounding, the hard case for orient3d.
inline std::array<Point3, 4> near_coplanar_points(Rng& rng, double scale, double spread) {
  const Point3 a = random_point(rng, scale), b = random_point(rng, scale),
               c = random_point(rng, scale);
  return {a, b, c,
          rounded_affine(a, b, c, uniform(rng, -spread, spread), uniform(rng, -spread, spread))};
}

/// A nonzero vector with integer coordinates in [-range, range].
inline Vector3 nonzero_integer_direction(Rng& rng, int range) {
  Vector3 d;
  do {
    d = integer_point(rng, range);
  } while (d[0] == 0 && d[1] == 0 && d[2] == 0);
  return d;
}

/// x with its coordinate `axis` moved by `steps` ulps (nextafter, repeated).
inline Point3 ulp_step(Point3 x, int axis, int steps) {
  for (int i = 0; i < std::abs(steps); ++i) {
    x[axis] = std::nextafter(x[axis], steps > 0 ? INFINITY : -INFINITY);
  }
  return x;
}

/// 2^k x, exact as long as nothing overflows or loses bits to underflow.
inline Point3 scaled(const Point3& x, int k) {
  return {std::ldexp(x[0], k), std::ldexp(x[1], k), std::ldexp(x[2], k)};
}

/// A double with random sign, 53 random significand bits and an exponent uniform in
/// [min_exponent, max_exponent] (subnormal or zero when the exponent is low enough).
inline double random_magnitude(Rng& rng, int min_exponent, int max_exponent) {
  const double significand = uniform(rng, 1.0, 2.0);
  const double sign = uniform_int(rng, 0, 1) == 0 ? -1.0 : 1.0;
  return sign * std::ldexp(significand, uniform_int(rng, min_exponent, max_exponent));
}

inline Point3 random_magnitude_point(Rng& rng, int min_exponent, int max_exponent) {
  return {random_magnitude(rng, min_exponent, max_exponent),
          random_magnitude(rng, min_exponent, max_exponent),
          random_magnitude(rng, min_exponent, max_exponent)};
}

}  // namespace exactgeo::testing
