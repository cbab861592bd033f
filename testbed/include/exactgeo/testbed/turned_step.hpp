#pragma once

// A dense CCD step without a collision: a mesh turned as a rigid body by an angle about
// the vertical axis through its centre, each vertex moving on the straight segment
// between its two positions (the motion mesh CCD assumes).
//
// Dense: a vertex at distance r from the axis sweeps a chord of length 2 r sin(angle / 2),
// so the swept boxes grow with the angle and so does the count of candidate pairs
// (docs/ccd.md counts them on Spot). Without a collision: at time t the
// mesh is c + M(t) (x - c) with M(t) = (1 - t) I + t R. In the plane across the axis M(t)
// multiplies by the complex number (1 - t) + t e^(i angle), of modulus at least
// cos(angle / 2) (at t = 1/2); along the axis it is the identity. So M(t) is invertible
// for angles below pi and shrinks no distance by more than the factor cos(angle / 2):
// primitives that are apart at t = 0 stay apart during the whole step. The end positions
// are rounded (below), which moves each vertex by far less than the gaps of any mesh this
// is used on.
//
// Both frames are rounded to multiples of 2^-40 of a power of two at least the mesh's
// largest coordinate magnitude, so that scaling them by 2^k for |k| <= 1000 is exact
// when that magnitude is in [2^-34, 2^23) (no bit falls below the smallest subnormal,
// 2^-1074, nor past the largest double): the step at 2^k is the same step.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <span>
#include <vector>

namespace exactgeo::testbed {

struct TurnedStep {
  std::vector<double> t0;
  std::vector<double> t1;
};

/// `positions` (x, y, z per vertex) at t0, turned by `degrees` (below 180) about the
/// vertical (z) axis through the centre of their bounding box at t1; both frames rounded
/// as above, then scaled by 2^scale_exponent.
inline TurnedStep turned_step(std::span<const double> positions, double degrees,
                              int scale_exponent = 0) {
  const std::size_t n = positions.size() / 3;
  double largest = 0.0;
  std::array<double, 3> lo{INFINITY, INFINITY, INFINITY}, hi{-INFINITY, -INFINITY, -INFINITY};
  for (std::size_t v = 0; v < n; ++v) {
    for (std::size_t k = 0; k < 3; ++k) {
      const double x = positions[3 * v + k];
      largest = std::max(largest, std::abs(x));
      lo[k] = std::min(lo[k], x);
      hi[k] = std::max(hi[k], x);
    }
  }
  int exponent = 0;
  std::frexp(largest, &exponent);  // largest < 2^exponent
  const double grid = std::ldexp(1.0, exponent - 40);
  const auto snapped = [&](double x) {
    return std::ldexp(std::nearbyint(x / grid) * grid, scale_exponent);
  };
  const double cx = (lo[0] + hi[0]) / 2, cy = (lo[1] + hi[1]) / 2;
  const double radians = degrees * std::numbers::pi / 180.0;
  const double c = std::cos(radians), s = std::sin(radians);
  TurnedStep step;
  step.t0.resize(3 * n);
  step.t1.resize(3 * n);
  for (std::size_t v = 0; v < n; ++v) {
    const double x = positions[3 * v] - cx, y = positions[3 * v + 1] - cy;
    const double z = positions[3 * v + 2];
    step.t0[3 * v] = snapped(positions[3 * v]);
    step.t0[3 * v + 1] = snapped(positions[3 * v + 1]);
    step.t0[3 * v + 2] = snapped(z);
    step.t1[3 * v] = snapped(cx + c * x - s * y);
    step.t1[3 * v + 1] = snapped(cy + s * x + c * y);
    step.t1[3 * v + 2] = snapped(z);
  }
  return step;
}

}  // namespace exactgeo::testbed
