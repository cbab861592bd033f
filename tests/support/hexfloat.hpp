#pragma once

// A point in hexfloat, so that a failing case can be replayed bit for bit.

#include <cstdio>
#include <string>

#include "exactgeo/predicates/point.hpp"

namespace exactgeo::testing {

inline std::string hex(const Point3& p) {
  char buf[160];
  std::snprintf(buf, sizeof buf, "(%a, %a, %a)", p[0], p[1], p[2]);
  return buf;
}

}  // namespace exactgeo::testing
