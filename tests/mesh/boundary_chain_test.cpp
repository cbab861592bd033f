// The boundary of a surface as a chain (boundary_chain.hpp) and the misoriented edges of
// the checks: a closed cube has none of either; an open one has its hole's loop, oriented
// as the faces around it run it; faces repeated k times give multiplicity k; a turned
// face of a closed cube makes its four edges misoriented (net 2), which the winding rules
// refuse.

#include "exactgeo/mesh/boundary_chain.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <utility>
#include <vector>

#include "exactgeo/mesh/check.hpp"
#include "mesh/hexahedron.hpp"
#include "support/hexahedron.hpp"

namespace exactgeo::mesh {
namespace {

Mesh unit_cube() {
  return test_meshes::hexahedron(testing::unit_cube_corners());
}

std::vector<std::pair<VertexIndex, VertexIndex>> edges_of(const std::vector<BoundaryEdge>& chain,
                                                          std::int32_t multiplicity) {
  std::vector<std::pair<VertexIndex, VertexIndex>> out;
  for (const BoundaryEdge& e : chain) {
    EXPECT_EQ(e.multiplicity, multiplicity);
    out.emplace_back(e.from, e.to);
  }
  std::sort(out.begin(), out.end());
  return out;
}

TEST(BoundaryChain, ClosedCubeHasNone) {
  EXPECT_TRUE(boundary_chain(unit_cube()).empty());
  EXPECT_EQ(check_mesh(unit_cube()).misoriented_edges.count, 0u);
}

TEST(BoundaryChain, OpenCubeHasItsHolesLoopAsTheFacesRunIt) {
  Mesh mesh = unit_cube();
  mesh.faces.erase(mesh.faces.begin() + 1);  // z = upper: 4 5 7 6
  // The faces around the hole run its edges opposite to the missing face: 5-4, 7-5, 6-7, 4-6.
  const std::vector<std::pair<VertexIndex, VertexIndex>> loop{{4, 6}, {5, 4}, {6, 7}, {7, 5}};
  EXPECT_EQ(edges_of(boundary_chain(mesh), 1), loop);
  const MeshCheck check = check_mesh(mesh);
  EXPECT_EQ(check.misoriented_edges.count, 0u);
  EXPECT_EQ(check.unbalanced_edges.count, 4u);
  EXPECT_EQ(orientable_surface_problem(check), std::nullopt);
  EXPECT_NE(closed_surface_problem(check), std::nullopt);

  // Three copies: the same loop, three times.
  Mesh tripled = mesh;
  for (int copy = 0; copy < 2; ++copy)
    tripled.faces.insert(tripled.faces.end(), mesh.faces.begin(), mesh.faces.end());
  EXPECT_EQ(edges_of(boundary_chain(tripled), 3), loop);
  // Net three on the rim: as for a turned face, two more one way, but the surface is open,
  // so it is taken as given.
  EXPECT_EQ(check_mesh(tripled).misoriented_edges.count, 4u);
  EXPECT_EQ(orientable_surface_problem(check_mesh(tripled)), std::nullopt);
}

TEST(BoundaryChain, ATurnedFaceMakesMisorientedEdges) {
  Mesh mesh = unit_cube();
  std::reverse(mesh.faces[1].corners.begin(), mesh.faces[1].corners.begin() + 4);
  // Its edges are now run twice the same way: net 2, not a boundary.
  EXPECT_EQ(edges_of(boundary_chain(mesh), 2).size(), 4u);
  const MeshCheck check = check_mesh(mesh);
  EXPECT_EQ(check.misoriented_edges.count, 4u);
  EXPECT_EQ(orientable_surface_problem(check),
            "faces not oriented alike: 4 edges are run the same way by two more faces than the "
            "other way (first: 4-5, 4-6, 5-7, 6-7)");
  EXPECT_EQ(closed_surface_problem(check), std::nullopt);  // parity takes it
}

TEST(BoundaryChain, RepeatedCornersJoinNothing) {
  Mesh mesh;
  mesh.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  mesh.faces = {make_quad(0, 1, 2, 2)};
  EXPECT_EQ(edges_of(boundary_chain(mesh), 1),
            (std::vector<std::pair<VertexIndex, VertexIndex>>{{0, 1}, {1, 2}, {2, 0}}));
}

}  // namespace
}  // namespace exactgeo::mesh
