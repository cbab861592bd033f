#pragma once

// The scene of the Scales/Operations tests (relocation_test.cpp, collapse_test.cpp,
// flip_test.cpp, split_test.cpp; instantiated at 2^0 and 2^+-1000 in operations_test.cpp):
// a flat sheet (a grid of triangles in z = 0) under a second sheet (one large triangle at
// height h), every coordinate times the test's scale, and the exact self-intersection
// finder's verdict after an operation.
//
// The fixture is one class for every file of the test binary (GoogleTest keys a TEST_P's
// suite by its fixture type), so it lives in a named namespace, not an anonymous one.

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "exactgeo/mesh/self_intersection.hpp"
#include "exactgeo/remesh/surface.hpp"
#include "remesh/surface_mesh.hpp"

namespace exactgeo::testing {

using remesh::Surface;

/// n x n squares of side 1 in z = 0 (vertex (i, j) is i + (n + 1) j), each split along
/// its diagonal (i, j)-(i+1, j+1), turning counter-clockwise seen from +z; then a large
/// triangle over it at height h, facing down. Every coordinate times `scale`.
inline Surface sheets(int n, double h, double scale) {
  Surface s;
  const auto index = [n](int i, int j) { return static_cast<VertexIndex>(i + (n + 1) * j); };
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i)
      s.vertices.push_back({scale * i, scale * j, 0.0});
  }
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      s.triangles.push_back({index(i, j), index(i + 1, j), index(i + 1, j + 1)});
      s.triangles.push_back({index(i, j), index(i + 1, j + 1), index(i, j + 1)});
    }
  }
  const auto top = static_cast<VertexIndex>(s.vertices.size());
  s.vertices.push_back({-scale * n, -scale * n, scale * h});
  s.vertices.push_back({scale * 2 * n, scale * n / 2, scale * h});
  s.vertices.push_back({-scale * n, scale * 2 * n, scale * h});
  s.triangles.push_back({top, top + 2, top + 1});
  return s;
}

inline void expect_intersection_free(const Surface& s, const std::string& after) {
  const mesh::SelfIntersections found = sheets_meeting(s);
  EXPECT_TRUE(found.intersecting.empty()) << "after " << after;
}

inline constexpr VertexIndex kInner = 1 + 5 * 1;      // vertex (1, 1) of the 4 x 4 grid
inline constexpr VertexIndex kTopTriangleFirst = 25;  // the upper sheet's corners: 25, 26, 27

/// The scale 2^k of the test's parameter k.
class Operations : public ::testing::TestWithParam<int> {
 protected:
  double scale() const { return std::ldexp(1.0, GetParam()); }
  /// One step below height h (scaled): the largest double under it.
  double just_below(double h) const { return std::nextafter(scale() * h, 0.0); }
};

}  // namespace exactgeo::testing
