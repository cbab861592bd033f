// The mesh type (mesh.hpp): a triangle is a face whose fourth corner is kNoVertex, corners
// are read cyclically, a quad's patch has its corners in boundary order (c0, c1, c2, c3 are
// p00, p10, p11, p01: no diagonal chosen) and a triangle's is {a, b, c, c}; a triangle
// surface becomes a mesh of the same triangles on the same vertices.

#include "exactgeo/mesh/mesh.hpp"

#include <gtest/gtest.h>

#include <cstddef>
#include <vector>

namespace exactgeo::mesh {
namespace {

TEST(Mesh, TrianglesAndQuadsReadTheirCornersCyclically) {
  const Face t = make_triangle(4, 7, 2);
  EXPECT_TRUE(t.is_triangle());
  EXPECT_EQ(t.size(), 3u);
  EXPECT_EQ(t.corners[3], kNoVertex);
  EXPECT_EQ(t.corner(3), 4u);
  EXPECT_EQ(t.corner(5), 2u);
  const Face q = make_quad(4, 7, 2, 9);
  EXPECT_FALSE(q.is_triangle());
  EXPECT_EQ(q.size(), 4u);
  EXPECT_EQ(q.corner(3), 9u);
  EXPECT_EQ(q.corner(4), 4u);
  EXPECT_FALSE(t == q);
  EXPECT_TRUE(q == make_quad(4, 7, 2, 9));
  EXPECT_FALSE(q == make_quad(7, 2, 9, 4));  // the same cycle from another corner: not equal
}

TEST(Mesh, PatchesKeepTheBoundaryOrder) {
  Mesh mesh;
  mesh.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 1}, {0, 1, 0}};
  const BilinearPatch quad = patch_of(mesh, make_quad(0, 1, 2, 3));
  EXPECT_EQ(quad.p00, mesh.vertices[0]);
  EXPECT_EQ(quad.p10, mesh.vertices[1]);
  EXPECT_EQ(quad.p11, mesh.vertices[2]);
  EXPECT_EQ(quad.p01, mesh.vertices[3]);
  const BilinearPatch triangle = patch_of(mesh, make_triangle(3, 1, 0));
  EXPECT_EQ(triangle.p00, mesh.vertices[3]);
  EXPECT_EQ(triangle.p10, mesh.vertices[1]);
  EXPECT_EQ(triangle.p11, mesh.vertices[0]);
  EXPECT_EQ(triangle.p01, mesh.vertices[0]);
}

TEST(Mesh, ATriangleSurfaceIsAMeshOfItsTriangles) {
  TriangleSurface surface;
  surface.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {5, 5, 5}};
  surface.triangles = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}};
  const Mesh mesh = mesh_of(surface);
  EXPECT_EQ(mesh.vertices, surface.vertices);  // unused vertex 4 too
  EXPECT_EQ(mesh.faces, (std::vector<Face>{make_triangle(0, 2, 1), make_triangle(0, 1, 3),
                                           make_triangle(1, 2, 3)}));
}

}  // namespace
}  // namespace exactgeo::mesh
