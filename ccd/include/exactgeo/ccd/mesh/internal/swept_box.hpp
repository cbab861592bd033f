#pragma once

// The swept box of a moving vertex: every point of a primitive at time t in [0, 1] is a
// convex combination of its corners at t, and each corner at t is a convex combination
// of its positions at t0 and t1. So the primitive stays inside the box of its corners' t0
// and t1 positions during the whole step, in exact arithmetic (min and max of doubles
// are exact), and inside that box rounded outward to float (boxes/float_box.hpp), in the
// step's Scale.

#include <algorithm>
#include <cstddef>

#include "exactgeo/boxes/float_box.hpp"

namespace exactgeo::ccd::internal {

using boxes::float_above;
using boxes::float_below;
using boxes::float_below_one_more;
using boxes::FloatBox;

/// The swept box of vertex v in the step's scale, grown by `margin` (in that scale, >= 0)
/// on every side; positions are 3 doubles per vertex at t0 and t1. A primitive's swept box
/// is the union of its corners' boxes: rounding outward after the scaling is monotone, so
/// the union of the rounded corner boxes is exactly the rounded box of all corners. With a
/// margin, the bound +- margin is a rounded double first, off by at most half a double's
/// ulp of it (or 2^-1075 below the normal range); the float next to it outward is farther
/// than that from the float it rounds to (a float's ulp is 2^29 times a double's, and at
/// least 2^-149), so one more float step outward keeps the box conservative.
inline FloatBox vertex_swept_box(const double* t0, const double* t1, std::size_t v,
                                 const boxes::Scale& scale, double margin = 0.0) noexcept {
  FloatBox box{};
  for (std::size_t k = 0; k < 3; ++k) {
    const double a = t0[3 * v + k], b = t1[3 * v + k];
    if (margin == 0.0) {
      box.lo[k] = float_below(scale(std::min(a, b)));
      box.hi[k] = float_above(scale(std::max(a, b)));
    } else {
      box.lo[k] = float_below_one_more(scale(std::min(a, b)) - margin);
      box.hi[k] = -float_below_one_more(-(scale(std::max(a, b)) + margin));
    }
  }
  return box;
}

}  // namespace exactgeo::ccd::internal
