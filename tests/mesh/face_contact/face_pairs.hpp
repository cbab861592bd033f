#pragma once

// Pairs of faces with a known answer, for the tests of the pair test's stages: faces as
// the stages read them (FaceGeometry), closed triangles that are disjoint by an exact
// oracle (support/segment_triangle_oracle.hpp: two closed triangles meet exactly when an
// edge of one meets the other), and triangles built through a common interior point, whose
// interiors therefore meet.

#include <array>
#include <cstddef>
#include <random>
#include <vector>

#include "../../../mesh/src/face_contact/face_geometry.hpp"
#include "support/generators.hpp"
#include "support/rational_oracle.hpp"
#include "support/segment_triangle_oracle.hpp"

namespace exactgeo::mesh::test_faces {

using Triangle = std::array<Point3, 3>;

/// The face on these corners (3 or 4) as the stages read it, its shape classified.
inline internal::FaceGeometry face(const std::vector<Point3>& corners) {
  Mesh mesh;
  mesh.vertices = corners;
  const Face f = corners.size() == 3 ? make_triangle(0, 1, 2) : make_quad(0, 1, 2, 3);
  return internal::geometry_of(mesh, f, internal::shape_of(mesh, f));
}

inline internal::FaceGeometry face(const Triangle& t) {
  return face(std::vector<Point3>(t.begin(), t.end()));
}

inline bool collinear(const Triangle& t) {
  return testing::collinear_oracle(t[0], t[1], t[2]);
}

/// Every corner of b in a's plane (a not collinear).
inline bool coplanar(const Triangle& a, const Triangle& b) {
  for (const Point3& p : b) {
    if (testing::orient3d_oracle(a[0], a[1], a[2], p) != Sign::zero) return false;
  }
  return true;
}

/// The closed triangles share no point (neither collinear).
inline bool closed_disjoint(const Triangle& a, const Triangle& b) {
  for (int k = 0; k < 3; ++k) {
    if (testing::segment_meets_triangle_oracle(a[k], a[(k + 1) % 3], b[0], b[1], b[2])) {
      return false;
    }
    if (testing::segment_meets_triangle_oracle(b[k], b[(k + 1) % 3], a[0], a[1], a[2])) {
      return false;
    }
  }
  return true;
}

/// A random triangle on the integer grid [-range, range]^3 (possibly collinear).
inline Triangle random_triangle(std::mt19937_64& rng, int range) {
  return {testing::integer_point(rng, range), testing::integer_point(rng, range),
          testing::integer_point(rng, range)};
}

/// Two triangles whose interiors share the point m = (b0 + b1 + 2 b2) / 4 (inside b) and
/// the centroid of a: a = (m + d + e, m - d + e, m - 2 e) for random integer d, e. Exact:
/// quarters of small integers. Either may be collinear, or the two coplanar: the caller
/// checks.
inline std::array<Triangle, 2> through_a_common_point(std::mt19937_64& rng) {
  const Triangle b = random_triangle(rng, 3);
  Point3 m, d = testing::integer_point(rng, 2), e = testing::integer_point(rng, 2);
  for (int i = 0; i < 3; ++i)
    m[i] = (b[0][i] + b[1][i] + 2 * b[2][i]) / 4;
  Triangle a;
  for (int i = 0; i < 3; ++i) {
    a[0][i] = m[i] + d[i] + e[i];
    a[1][i] = m[i] - d[i] + e[i];
    a[2][i] = m[i] - 2 * e[i];
  }
  return {a, b};
}

}  // namespace exactgeo::mesh::test_faces
