// One face as the pair test sees it (face_contact/face_geometry.hpp, internal): its shape
// class by hand (a triangle, a collinear one, repeated corners, a square, a dart, a bow
// tie, a quad with a straight corner, a skew quad, four equal points) and, on random faces
// of a small integer grid (most of them degenerate or flat), against the rational patch
// shape oracle (support/rational_oracle.hpp) read by the rule of face_geometry.hpp; and
// the geometry: corners in boundary order, read cyclically, and what each class allows.

#include "../../../mesh/src/face_contact/face_geometry.hpp"

#include <gtest/gtest.h>

#include <array>
#include <random>
#include <string>

#include "support/rational_oracle.hpp"
#include "support/seed.hpp"

namespace exactgeo::mesh::internal {
namespace {

/// The shape of a face on these corners (a triangle when the fourth is absent).
Shape shape(const std::vector<Point3>& corners, std::array<VertexIndex, 4> face) {
  Mesh mesh;
  mesh.vertices = corners;
  return shape_of(mesh, Face{face});
}

constexpr VertexIndex kNone = kNoVertex;

TEST(FaceGeometry, ShapesByHand) {
  const std::vector<Point3> square{{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}};
  EXPECT_EQ(shape(square, {0, 1, 2, kNone}), Shape::triangle);
  EXPECT_EQ(shape(square, {0, 1, 2, 3}), Shape::convex);
  EXPECT_EQ(shape(square, {0, 1, 1, kNone}), Shape::degenerate);  // a repeated index
  EXPECT_EQ(shape(square, {0, 1, 2, 2}), Shape::degenerate);      // though it has an area
  EXPECT_EQ(shape(square, {0, 2, 1, 3}), Shape::other_flat);      // a bow tie
  const std::vector<Point3> dart{{0, 0, 0}, {4, 0, 0}, {1, 1, 0}, {0, 4, 0}};
  EXPECT_EQ(shape(dart, {0, 1, 2, 3}), Shape::other_flat);
  const std::vector<Point3> straight{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {1, 1, 0}};
  EXPECT_EQ(shape(straight, {0, 1, 2, 3}), Shape::other_flat);      // a corner of zero turn
  EXPECT_EQ(shape(straight, {0, 1, 2, kNone}), Shape::degenerate);  // collinear: a segment
  const std::vector<Point3> saddle{{0, 0, 0}, {1, 0, 0}, {1, 1, 1}, {0, 1, 0}};
  EXPECT_EQ(shape(saddle, {0, 1, 2, 3}), Shape::skew);
  const std::vector<Point3> one_point(4, Point3{3, 3, 3});
  EXPECT_EQ(shape(one_point, {0, 1, 2, 3}), Shape::degenerate);  // distinct indices, one point
}

/// The rule of face_geometry.hpp on the oracle's shape of the face's patch.
Shape expected_shape(const std::vector<Point3>& v, const std::array<VertexIndex, 4>& c) {
  const bool triangle = c[3] == kNoVertex;
  const std::size_t n = triangle ? 3 : 4;
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = i + 1; j < n; ++j) {
      if (c[i] == c[j]) return Shape::degenerate;
    }
  }
  const BilinearPatch patch{v[c[0]], v[c[1]], v[c[2]], v[c[triangle ? 2 : 3]]};
  switch (testing::patch_shape_oracle(patch)) {
    case PatchShape::point:
    case PatchShape::segment:
      return Shape::degenerate;
    case PatchShape::skew:
      return Shape::skew;
    case PatchShape::convex:
      return triangle ? Shape::triangle : Shape::convex;
    default:
      return triangle ? Shape::triangle : Shape::other_flat;
  }
}

TEST(FaceGeometry, RandomFacesAgreeWithThePatchShapeOracle) {
  auto rng = testing::seeded_engine("mesh.face_geometry.shapes");
  std::uniform_int_distribution<int> small(-1, 1), index(0, 5);
  std::array<int, 5> seen{};
  for (int trial = 0; trial < 4000; ++trial) {
    std::vector<Point3> v(6);
    for (Point3& p : v)  // z often 0: many flat faces
      p = {double(small(rng)), double(small(rng)), trial % 2 == 0 ? 0.0 : double(small(rng))};
    std::array<VertexIndex, 4> c;
    for (VertexIndex& k : c)
      k = static_cast<VertexIndex>(index(rng));
    if (trial % 3 == 0) c[3] = kNoVertex;
    const Shape want = expected_shape(v, c);
    ASSERT_EQ(shape(v, c), want) << "trial " << trial;
    ++seen[static_cast<std::size_t>(want)];
  }
  for (std::size_t s = 0; s < seen.size(); ++s)
    EXPECT_GT(seen[s], 20) << "shape " << s;
}

TEST(FaceGeometry, CornersInBoundaryOrderAndWhatEachClassAllows) {
  Mesh mesh;
  mesh.vertices = {{9, 9, 9}, {0, 0, 0}, {1, 0, 0}, {1, 1, 1}, {0, 1, 0}};
  const Face quad = make_quad(1, 2, 3, 4);
  const FaceGeometry g = geometry_of(mesh, quad, shape_of(mesh, quad));
  EXPECT_EQ(g.n, 4u);
  EXPECT_EQ(g.shape, Shape::skew);
  for (std::size_t i = 0; i < 4; ++i)
    EXPECT_EQ(g.p[i], mesh.vertices[i + 1]);
  EXPECT_EQ(g.corner(5), g.p[1]);
  EXPECT_FALSE(g.convex_polygon());
  EXPECT_TRUE(g.injective());
  const Face triangle = make_triangle(4, 2, 1);
  const FaceGeometry t = geometry_of(mesh, triangle, shape_of(mesh, triangle));
  EXPECT_EQ(t.n, 3u);
  EXPECT_EQ(t.corner(3), mesh.vertices[4]);
  EXPECT_TRUE(t.convex_polygon());
  EXPECT_TRUE(t.injective());
  FaceGeometry flat = g;
  flat.shape = Shape::other_flat;  // a flat quad that is not strictly convex may fold
  EXPECT_FALSE(flat.convex_polygon());
  EXPECT_FALSE(flat.injective());
  flat.shape = Shape::convex;
  EXPECT_TRUE(flat.convex_polygon());
}

}  // namespace
}  // namespace exactgeo::mesh::internal
