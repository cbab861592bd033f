// The edge method (face_contact/edge_method.hpp, internal), called directly, past the
// filters: triangles against the saddle z = x y over the unit square (a skew patch, a graph
// over the square, so a vertical segment crosses it once), at points p(u, v) of a dyadic
// grid, exact: an edge through the saddle's interior proves an intersection; the same
// triangle lifted above it is apart; a triangle with a corner on the saddle and the rest
// below it is undecided (touching is not intersecting, and the rays cannot tell), and so is
// a triangle hanging from the saddle's edge; faces far apart are apart. The answer is the
// same with the faces swapped.

#include "../../../mesh/src/face_contact/edge_method.hpp"

#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

#include "mesh/face_contact/face_pairs.hpp"
#include "support/seed.hpp"

namespace exactgeo::mesh::internal {
namespace {

using test_faces::face;

const std::vector<Point3> kSaddle{{0, 0, 0}, {1, 0, 0}, {1, 1, 1}, {0, 1, 0}};

FaceContact both_ways(const std::vector<Point3>& other) {
  const FaceGeometry saddle = face(kSaddle), f = face(other);
  const FaceContact answer = edge_method(saddle, f);
  EXPECT_EQ(edge_method(f, saddle), answer);
  return answer;
}

TEST(EdgeMethod, TrianglesAtDyadicPointsOfTheSaddle) {
  ASSERT_EQ(face(kSaddle).shape, Shape::skew);
  auto rng = testing::seeded_engine("mesh.edge_method.saddle");
  std::uniform_int_distribution<int> sixteenth(1, 15);
  for (int trial = 0; trial < 500; ++trial) {
    const double u = sixteenth(rng) / 16.0, v = sixteenth(rng) / 16.0;
    const Point3 x{u, v, u * v};  // on the saddle, exactly
    const double h = sixteenth(rng) / 64.0, w = sixteenth(rng) / 256.0;
    const std::string what = "at (" + std::to_string(u) + ", " + std::to_string(v) + ")";
    // A vertical edge through x: crosses the graph once, at x, inside both faces.
    const std::vector<Point3> pierce{{u, v, x[2] - h}, {u, v, x[2] + h}, {u + w, v, x[2]}};
    EXPECT_EQ(both_ways(pierce), FaceContact::intersecting) << what;
    // The same lifted above the saddle (z <= 1 there): nothing crosses.
    std::vector<Point3> lifted = pierce;
    for (Point3& p : lifted)
      p[2] += 3;
    EXPECT_EQ(both_ways(lifted), FaceContact::apart) << what;
    // A corner on the saddle at x, the rest below it: (u + t w, v, u v - t h) lies below
    // the saddle's (u + t w) v for t > 0.
    const std::vector<Point3> resting{x, {u, v, x[2] - h}, {u + w, v, x[2] - h}};
    EXPECT_EQ(both_ways(resting), FaceContact::undecided) << what;
  }
}

TEST(EdgeMethod, FacesMeetingOnTheSaddlesBoundaryAreUndecided) {
  // A triangle hanging below the saddle's edge (0, 0, 0)-(1, 0, 0): the shared edge is no
  // crossing, but the triangle's other edges start at the saddle's corners, on its
  // boundary, where the rays cannot tell touching from crossing (in face_contact the
  // corner planes, which run first, settle such pairs).
  EXPECT_EQ(both_ways({{0, 0, 0}, {1, 0, 0}, {0.5, -1, -1}}), FaceContact::undecided);
  // Far away, and under the saddle's middle: apart.
  EXPECT_EQ(both_ways({{5, 5, 5}, {6, 5, 5}, {5, 6, 5}}), FaceContact::apart);
  EXPECT_EQ(both_ways({{0.25, 0.25, -1}, {0.75, 0.25, -1}, {0.5, 0.75, -1}}), FaceContact::apart);
}

}  // namespace
}  // namespace exactgeo::mesh::internal
