// Boxes of faces' corners (internal/corner_boxes.hpp), against the box computed here by
// hand: a face's box holds its corners and each bound is one of them (a triangle's unused
// fourth corner is never read); the mesh's box is that of the faces' corners only (a far
// vertex no face uses does not count), none without faces; strictly_outside is false on
// the closed box's faces and true one ulp beyond them. Random meshes at 2^+-1000 too.

#include "exactgeo/inside/internal/corner_boxes.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "support/generators.hpp"
#include "support/seed.hpp"

namespace exactgeo::inside {
namespace {

using internal::corner_box;
using internal::strictly_outside;
using mesh::Mesh;

constexpr double kInf = std::numeric_limits<double>::infinity();

/// The box of the corners of `faces`, by hand: per coordinate, the least and the largest.
mesh::Box by_hand(const Mesh& mesh, std::size_t first, std::size_t end) {
  mesh::Box box{{kInf, kInf, kInf}, {-kInf, -kInf, -kInf}};
  for (std::size_t f = first; f < end; ++f) {
    const mesh::Face& face = mesh.faces[f];
    for (std::size_t k = 0; k < face.size(); ++k) {
      const Point3& p = mesh.vertices[face.corners[k]];
      for (int i = 0; i < 3; ++i) {
        box.lower[i] = std::min(box.lower[i], p[i]);
        box.upper[i] = std::max(box.upper[i], p[i]);
      }
    }
  }
  return box;
}

void expect_same_box(const mesh::Box& actual, const mesh::Box& expected) {
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(actual.lower[i], expected.lower[i]) << "axis " << i;
    EXPECT_EQ(actual.upper[i], expected.upper[i]) << "axis " << i;
  }
}

TEST(CornerBoxes, AFacesBoxIsThatOfItsCornersOnly) {
  Mesh mesh;
  mesh.vertices = {{0, 5, -1}, {2, -3, 4}, {1, 1, 1}, {-7, 0, 9}, {100, 100, 100}};
  const mesh::Face triangle = mesh::make_triangle(0, 1, 2);
  const mesh::Face quad = mesh::make_quad(0, 1, 2, 3);
  const mesh::Box t = corner_box(mesh, triangle);
  EXPECT_EQ(t.lower, (Point3{0, -3, -1}));
  EXPECT_EQ(t.upper, (Point3{2, 5, 4}));
  const mesh::Box q = corner_box(mesh, quad);
  EXPECT_EQ(q.lower, (Point3{-7, -3, -1}));
  EXPECT_EQ(q.upper, (Point3{2, 5, 9}));
}

TEST(CornerBoxes, AMeshsBoxIgnoresVerticesNoFaceUses) {
  Mesh mesh;
  EXPECT_FALSE(corner_box(mesh).has_value());
  mesh.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1e300, -1e300, 7}};
  EXPECT_FALSE(corner_box(mesh).has_value());  // vertices but no faces
  mesh.faces = {mesh::make_triangle(0, 2, 1), mesh::make_triangle(0, 1, 3)};
  const auto box = corner_box(mesh);
  ASSERT_TRUE(box.has_value());
  EXPECT_EQ(box->lower, (Point3{0, 0, 0}));
  EXPECT_EQ(box->upper, (Point3{1, 1, 1}));
  EXPECT_FALSE(box->holds(mesh.vertices[4]));
}

TEST(CornerBoxes, StrictlyOutsideMeansBeyondTheClosedBox) {
  const mesh::Box box{{-1, 0, 2}, {1, 0, 3}};  // flat along y
  EXPECT_FALSE(strictly_outside(box, {0, 0, 2.5}));
  EXPECT_FALSE(strictly_outside(box, {-1, 0, 2}));   // a corner
  EXPECT_FALSE(strictly_outside(box, {1, 0, 2.5}));  // on a face
  EXPECT_TRUE(strictly_outside(box, {std::nextafter(1.0, 2.0), 0, 2.5}));
  EXPECT_TRUE(strictly_outside(box, {0, std::nextafter(0.0, -1.0), 2.5}));
  EXPECT_TRUE(strictly_outside(box, {0, 0, std::nextafter(2.0, 0.0)}));
}

TEST(CornerBoxes, RandomMeshesAgreeWithTheBoxByHand) {
  auto rng = testing::seeded_engine("inside.corner_boxes");
  for (const int k : {0, 1000, -1000}) {
    for (int trial = 0; trial < 50; ++trial) {
      Mesh mesh;
      const int vertices = testing::uniform_int(rng, 4, 40);
      for (int v = 0; v < vertices; ++v)
        mesh.vertices.push_back(testing::scaled(testing::random_point(rng), k));
      const auto corner = [&] {
        return static_cast<VertexIndex>(testing::uniform_int(rng, 0, vertices - 1));
      };
      const int faces = testing::uniform_int(rng, 1, 10);
      for (int f = 0; f < faces; ++f) {
        mesh.faces.push_back(testing::uniform_int(rng, 0, 1) == 0
                                 ? mesh::make_triangle(corner(), corner(), corner())
                                 : mesh::make_quad(corner(), corner(), corner(), corner()));
      }
      for (std::size_t f = 0; f < mesh.faces.size(); ++f)
        expect_same_box(corner_box(mesh, mesh.faces[f]), by_hand(mesh, f, f + 1));
      const auto all = corner_box(mesh);
      ASSERT_TRUE(all.has_value());
      const mesh::Box expected = by_hand(mesh, 0, mesh.faces.size());
      expect_same_box(*all, expected);
      // Every corner is in the box.
      for (const mesh::Face& face : mesh.faces) {
        for (std::size_t c = 0; c < face.size(); ++c)
          EXPECT_FALSE(strictly_outside(*all, mesh.vertices[face.corners[c]]));
      }
    }
  }
}

}  // namespace
}  // namespace exactgeo::inside
