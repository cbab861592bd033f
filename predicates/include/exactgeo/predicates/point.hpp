#pragma once

#include <array>
#include <limits>

namespace exactgeo {

static_assert(std::numeric_limits<double>::is_iec559,
              "exactgeo needs IEEE 754 binary64 doubles with round-to-nearest arithmetic");

/// A point or a vector in 3D, with coordinates exactly as given by the caller.
using Point3 = std::array<double, 3>;
using Vector3 = std::array<double, 3>;

}  // namespace exactgeo
