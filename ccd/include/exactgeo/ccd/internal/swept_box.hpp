#pragma once

// Swept boxes in single precision, rounded outward.
//
// Every point of a primitive at time t in [0, 1] is a convex combination of its corners at
// t, and each corner at t is a convex combination of its positions at t0 and t1. So the
// primitive stays inside the box of its corners' t0 and t1 positions during the whole
// step, in exact arithmetic: min and max of doubles are exact. Converting to float rounds
// each lower bound down and each upper bound up (one nextafter when round-to-nearest went
// the wrong way; beyond the float range the bound becomes infinite), so the float box
// contains the double box and two boxes that could share a point overlap.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>

namespace exactgeo::ccd::internal {

/// The largest float <= x (x finite).
inline float float_below(double x) noexcept {
  constexpr double kMax = std::numeric_limits<float>::max();
  if (x > kMax) return std::numeric_limits<float>::max();
  if (x < -kMax) return -std::numeric_limits<float>::infinity();
  const float f = static_cast<float>(x);
  return static_cast<double>(f) > x ? std::nextafter(f, -std::numeric_limits<float>::infinity())
                                    : f;
}

/// The smallest float >= x (x finite).
inline float float_above(double x) noexcept {
  return -float_below(-x);
}

struct SweptBox {
  std::array<float, 3> lo;
  std::array<float, 3> hi;
  std::uint32_t id;  ///< the vertex, edge or face the box belongs to
};

/// Closed boxes: touching counts as overlapping.
inline bool overlap(const SweptBox& a, const SweptBox& b) noexcept {
  for (int k = 0; k < 3; ++k) {
    if (a.hi[k] < b.lo[k] || b.hi[k] < a.lo[k]) return false;
  }
  return true;
}

/// The swept box of the corners `ids` (vertex indices) of one primitive; positions are
/// 3 doubles per vertex at t0 and at t1.
template <std::size_t N>
SweptBox swept_box(const std::array<std::uint32_t, N>& ids, std::uint32_t id, const double* t0,
                   const double* t1) noexcept {
  SweptBox box{};
  box.id = id;
  for (int k = 0; k < 3; ++k) {
    double lo = t0[3 * ids[0] + k];
    double hi = lo;
    for (const double* frame : {t0, t1}) {
      for (const std::uint32_t v : ids) {
        lo = std::min(lo, frame[3 * v + k]);
        hi = std::max(hi, frame[3 * v + k]);
      }
    }
    box.lo[k] = float_below(lo);
    box.hi[k] = float_above(hi);
  }
  return box;
}

}  // namespace exactgeo::ccd::internal
