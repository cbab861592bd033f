// Mesh checks: counts, edges (boundary, non-manifold, odd, orientation), exact degenerate
// faces and non-planar quads, components, and the classification message, on meshes built
// here: cubes (whole, flipped, open, glued, perturbed by one ulp), an octahedron, degenerate
// faces, bad indices and coordinates, and the same facts at scales 2^±1000 and subnormal;
// and the self-intersection message, in the file's numbering.

#include "exactgeo/mesh/check.hpp"
#include "mesh/hexahedron.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace exactgeo::mesh {
namespace {

using testing::kHexahedronFaces;

/// Appends the box [lower, upper] as six quads, reusing existing vertices with exactly the
/// same coordinates (so two boxes can share an edge).
void add_box(Mesh& mesh, const Point3& lower, const Point3& upper) {
  std::array<VertexIndex, 8> index{};
  for (std::size_t c = 0; c < 8; ++c) {
    const Point3 p{(c & 1) ? upper[0] : lower[0], (c & 2) ? upper[1] : lower[1],
                   (c & 4) ? upper[2] : lower[2]};
    const auto it = std::find(mesh.vertices.begin(), mesh.vertices.end(), p);
    index[c] = static_cast<VertexIndex>(it - mesh.vertices.begin());
    if (it == mesh.vertices.end()) mesh.vertices.push_back(p);
  }
  for (const auto& f : kHexahedronFaces)
    mesh.faces.push_back(make_quad(index[f[0]], index[f[1]], index[f[2]], index[f[3]]));
}

Mesh box(const Point3& lower, const Point3& upper) {
  Mesh mesh;
  add_box(mesh, lower, upper);
  return mesh;
}

Mesh unit_cube() {
  return box({0, 0, 0}, {1, 1, 1});
}

Mesh scaled(Mesh mesh, int exponent) {
  for (Point3& p : mesh.vertices)
    for (double& x : p)
      x = std::ldexp(x, exponent);
  return mesh;
}

std::string problem(const Mesh& mesh, bool allow_non_manifold = false) {
  return closed_surface_problem(check_mesh(mesh), allow_non_manifold).value_or("");
}

void expect_closed_manifold_oriented(const MeshCheck& c) {
  EXPECT_TRUE(c.closed());
  EXPECT_TRUE(c.manifold());
  EXPECT_EQ(c.boundary_edges.count, 0u);
  EXPECT_EQ(c.non_manifold_edges.count, 0u);
  EXPECT_EQ(c.odd_edges.count, 0u);
  EXPECT_EQ(c.consistently_oriented, std::optional<bool>(true));
}

TEST(MeshCheck, CubeIsClosedManifoldOrientedPlanar) {
  const MeshCheck c = check_mesh(unit_cube());
  EXPECT_EQ(c.vertices, 8u);
  EXPECT_EQ(c.faces, 6u);
  EXPECT_EQ(c.quads, 6u);
  EXPECT_EQ(c.triangles, 0u);
  ASSERT_TRUE(c.bounding_box);
  EXPECT_EQ(c.bounding_box->lower, (Point3{0, 0, 0}));
  EXPECT_EQ(c.bounding_box->upper, (Point3{1, 1, 1}));
  expect_closed_manifold_oriented(c);
  EXPECT_EQ(c.out_of_range_faces.count, 0u);
  EXPECT_EQ(c.non_finite_vertices.count, 0u);
  EXPECT_EQ(c.degenerate_faces.count, 0u);
  EXPECT_EQ(c.non_planar_quads.count, 0u);
  EXPECT_EQ(c.unreferenced_vertices, 0u);
  EXPECT_EQ(c.components, 1u);
  EXPECT_EQ(closed_surface_problem(c), std::nullopt);
}

TEST(MeshCheck, FlippedFaceIsClosedButNotConsistentlyOriented) {
  Mesh mesh = unit_cube();
  auto& corners = mesh.faces[3].corners;
  std::reverse(corners.begin(), corners.end());
  const MeshCheck c = check_mesh(mesh);
  EXPECT_TRUE(c.closed());
  EXPECT_TRUE(c.manifold());
  EXPECT_EQ(c.consistently_oriented, std::optional<bool>(false));
  EXPECT_EQ(closed_surface_problem(c), std::nullopt);  // orientation does not matter
}

TEST(MeshCheck, CubeWithoutTopHasFourBoundaryEdges) {
  Mesh mesh = unit_cube();
  mesh.faces.erase(mesh.faces.begin() + 1);  // {4, 5, 7, 6}
  const MeshCheck c = check_mesh(mesh);
  EXPECT_FALSE(c.closed());
  EXPECT_TRUE(c.manifold());
  EXPECT_EQ(c.boundary_edges.count, 4u);
  EXPECT_EQ(c.odd_edges.count, 4u);
  EXPECT_EQ(c.boundary_edges.first, (std::vector<Edge>{{4, 5}, {4, 6}, {5, 7}, {6, 7}}));
  EXPECT_EQ(c.consistently_oriented, std::nullopt);
  EXPECT_EQ(c.components, 1u);
  EXPECT_EQ(problem(mesh), "mesh is not closed: 4 boundary edges (first: 4-5, 4-6, 5-7, 6-7)");
  EXPECT_EQ(problem(mesh, true), problem(mesh));
}

TEST(MeshCheck, ManyBoundaryEdgesListTheFirstFew) {
  Mesh mesh = unit_cube();
  mesh.faces.resize(2);  // bottom {0,2,3,1} and top {4,5,7,6}: 8 boundary edges
  const MeshCheck c = check_mesh(mesh);
  EXPECT_EQ(c.boundary_edges.count, 8u);
  EXPECT_EQ(c.boundary_edges.first.size(), Examples<Edge>::kKept);
  EXPECT_EQ(c.components, 2u);
  EXPECT_EQ(problem(mesh),
            "mesh is not closed: 8 boundary edges (first: 0-1, 0-2, 1-3, 2-3, 4-5, ...)");
}

TEST(MeshCheck, CubesSharingAnEdgeAreNonManifold) {
  Mesh mesh = unit_cube();
  add_box(mesh, {1, 1, 0}, {2, 2, 1});  // shares vertices 3 = (1,1,0) and 7 = (1,1,1)
  const MeshCheck c = check_mesh(mesh);
  EXPECT_EQ(c.vertices, 14u);
  EXPECT_EQ(c.faces, 12u);
  EXPECT_TRUE(c.closed());
  EXPECT_FALSE(c.manifold());
  EXPECT_EQ(c.boundary_edges.count, 0u);
  EXPECT_EQ(c.odd_edges.count, 0u);
  EXPECT_EQ(c.non_manifold_edges.count, 1u);
  EXPECT_EQ(c.non_manifold_edges.first, (std::vector<Edge>{{3, 7}}));
  EXPECT_EQ(c.consistently_oriented, std::nullopt);
  EXPECT_EQ(c.components, 1u);
  EXPECT_EQ(problem(mesh), "1 non-manifold edge (used by more than two faces; first: 3-7)");
  EXPECT_EQ(closed_surface_problem(c, true), std::nullopt);
}

TEST(MeshCheck, EdgeUsedThreeTimesIsRejectedEvenWhenNonManifoldIsAllowed) {
  Mesh mesh = unit_cube();
  mesh.faces.push_back(make_triangle(3, 7, 0));  // a fin on edge 3-7
  const MeshCheck c = check_mesh(mesh);
  EXPECT_FALSE(c.closed());
  EXPECT_EQ(c.non_manifold_edges.first, (std::vector<Edge>{{3, 7}}));
  EXPECT_EQ(c.boundary_edges.first, (std::vector<Edge>{{0, 3}, {0, 7}}));
  EXPECT_EQ(c.odd_edges.first, (std::vector<Edge>{{0, 3}, {0, 7}, {3, 7}}));
  // Everything at once: the odd edges that --allow-non-manifold would still refuse are
  // named with the non-manifold one, not after it.
  EXPECT_EQ(problem(mesh),
            "mesh is not closed: 3 edges used by an odd number of faces (first: 0-3, 0-7, 3-7); "
            "1 non-manifold edge (used by more than two faces; first: 3-7)");
  EXPECT_EQ(problem(mesh, true),
            "mesh is not closed: 3 edges used by an odd number of faces (first: 0-3, 0-7, 3-7)");
}

TEST(MeshCheck, MovedVertexMakesItsThreeQuadsNonPlanar) {
  Mesh mesh = box({2, 2, 2}, {4, 4, 4});
  mesh.vertices[7] = {5, 6, 7};  // corner (1,1,1): in the top, y-upper and x-upper quads
  const MeshCheck c = check_mesh(mesh);
  EXPECT_EQ(c.non_planar_quads.count, 3u);
  EXPECT_EQ(c.non_planar_quads.first, (std::vector<std::size_t>{1, 3, 5}));
  EXPECT_EQ(c.degenerate_faces.count, 0u);
  EXPECT_EQ(c.bounding_box->upper, (Point3{5, 6, 7}));
  EXPECT_EQ(closed_surface_problem(c), std::nullopt);  // skew quads are bilinear patches
}

TEST(MeshCheck, OneUlpOffItsPlaneIsNonPlanar) {
  Mesh mesh = box({1, 1, 1}, {2, 2, 2});
  // Moving x of corner (1,1,1) leaves it in the planes y = 2 and z = 2: only the x = 2 quad
  // (face 5) bends, by one ulp.
  mesh.vertices[7][0] = std::nextafter(2.0, 3.0);
  MeshCheck c = check_mesh(mesh);
  EXPECT_EQ(c.non_planar_quads.count, 1u);
  EXPECT_EQ(c.non_planar_quads.first, (std::vector<std::size_t>{5}));
  mesh.vertices[7][0] = std::nextafter(2.0, 1.0);
  c = check_mesh(mesh);
  EXPECT_EQ(c.non_planar_quads.first, (std::vector<std::size_t>{5}));
  mesh.vertices[7][0] = 2.0;
  EXPECT_EQ(check_mesh(mesh).non_planar_quads.count, 0u);
}

TEST(MeshCheck, OctahedronOfTriangles) {
  Mesh mesh;
  mesh.vertices = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  // Outward: (+x, +y, +z) and its images; each is counter-clockwise seen from outside.
  mesh.faces = {make_triangle(0, 2, 4), make_triangle(2, 1, 4), make_triangle(1, 3, 4),
                make_triangle(3, 0, 4), make_triangle(2, 0, 5), make_triangle(1, 2, 5),
                make_triangle(3, 1, 5), make_triangle(0, 3, 5)};
  const MeshCheck c = check_mesh(mesh);
  EXPECT_EQ(c.faces, 8u);
  EXPECT_EQ(c.triangles, 8u);
  EXPECT_EQ(c.quads, 0u);
  expect_closed_manifold_oriented(c);
  EXPECT_EQ(c.degenerate_faces.count, 0u);
  EXPECT_EQ(c.non_planar_quads.count, 0u);
  EXPECT_EQ(c.components, 1u);
  EXPECT_EQ(c.bounding_box->lower, (Point3{-1, -1, -1}));
  EXPECT_EQ(c.bounding_box->upper, (Point3{1, 1, 1}));
  EXPECT_EQ(closed_surface_problem(c), std::nullopt);
}

TEST(MeshCheck, ClassifyPatchCallsCollinearTrianglesSegments) {
  // What check_mesh relies on: the triangle patch {a, b, c, c} collapses exactly when
  // a, b, c are collinear, even one ulp away from it.
  const Point3 a{0, 0, 0}, b{1, 1, 1}, c{3, 3, 3};
  EXPECT_EQ(classify_patch({a, b, c, c}), PatchShape::segment);
  EXPECT_EQ(classify_patch({a, a, a, a}), PatchShape::point);
  const Point3 off{3, 3, std::nextafter(3.0, 4.0)};
  EXPECT_EQ(classify_patch({a, b, off, off}), PatchShape::degenerate_planar);
}

TEST(MeshCheck, DegenerateFaces) {
  Mesh mesh;
  mesh.vertices = {{0, 0, 0},     {1, 0, 0}, {1, 1, 0},
                   {0, 1, 0},     {2, 0, 0}, {3, 0, 0},
                   {0.5, 0.5, 0}, {2, 2, 0}, {3, std::nextafter(0.0, 1.0), 0}};
  mesh.faces = {
      make_quad(0, 1, 2, 3),   // 0: square
      make_quad(0, 1, 2, 2),   // 1: repeated index
      make_triangle(0, 1, 4),  // 2: three collinear corners
      make_quad(0, 1, 4, 5),   // 3: four collinear corners
      make_quad(0, 1, 3, 2),   // 4: butterfly: not degenerate
      make_quad(0, 1, 6, 3),   // 5: concave (dart): not degenerate
      make_triangle(0, 4, 8),  // 6: one subnormal ulp off the line: not degenerate
      make_triangle(0, 6, 7),  // 7: collinear along the diagonal
      make_triangle(3, 3, 1),  // 8: repeated index in a triangle
      make_quad(0, 1, 4, 2),   // 9: three collinear corners of a quad: a triangle's area
  };
  const MeshCheck c = check_mesh(mesh);
  EXPECT_EQ(c.degenerate_faces.count, 5u);
  EXPECT_EQ(c.degenerate_faces.first, (std::vector<std::size_t>{1, 2, 3, 7, 8}));
  // Face 1 is a triangle written as a quad: it repeats a corner but spans an area.
  EXPECT_EQ(c.zero_area_faces.first, (std::vector<std::size_t>{2, 3, 7, 8}));
  EXPECT_EQ(c.repeated_corner_faces.first, (std::vector<std::size_t>{1}));
  EXPECT_EQ(c.non_planar_quads.count, 0u);
  // Classification drops the faces of zero area and refuses the other.
  const std::string message = closed_surface_problem(c).value_or("");
  EXPECT_NE(message.find("1 face repeats a corner (first: 1)"), std::string::npos) << message;
  EXPECT_EQ(message.find("zero area"), std::string::npos) << message;
  // Numbered as an OBJ file numbers them, from 1.
  const std::string from_one = closed_surface_problem(c, false, {.first = 1}).value_or("");
  EXPECT_NE(from_one.find("1 face repeats a corner (first: 2)"), std::string::npos) << from_one;
  EXPECT_EQ(zero_area_note(c.zero_area_faces, {.first = 1}),
            "4 faces of zero area (first: 3, 4, 8, 9) bound nothing: dropped (faces numbered from "
            "1, as in the file)");
}

TEST(MeshCheck, OnlyZeroAreaFaces) {
  Mesh mesh;
  mesh.vertices = {{0, 0, 0}, {1, 1, 1}, {3, 3, 3}};
  mesh.faces = {make_triangle(0, 1, 2), make_triangle(0, 2, 1)};
  EXPECT_EQ(closed_surface_problem(check_mesh(mesh)), "every face has zero area");
  EXPECT_EQ(orientable_surface_problem(check_mesh(mesh)), "every face has zero area");
}

/// The faces whose findings have `flag` set.
template <class Flag>
std::vector<std::size_t> faces_with(const MeshCheck& c, Flag flag) {
  std::vector<std::size_t> faces;
  for (std::size_t f = 0; f < c.face_findings.size(); ++f)
    if (c.face_findings[f].*flag) faces.push_back(f);
  return faces;
}

/// For each face, whether one of its edges is used by exactly `uses` faces (or more than
/// two when `uses` is 3), counted pair by pair over every face: independent of the sort.
std::vector<std::size_t> faces_with_edge_used(const Mesh& mesh, std::size_t uses) {
  const auto same_edge = [](VertexIndex a, VertexIndex b, VertexIndex c, VertexIndex d) {
    return (a == c && b == d) || (a == d && b == c);
  };
  std::vector<std::size_t> faces;
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    const Face& face = mesh.faces[f];
    bool found = false;
    for (std::size_t i = 0; i < face.size(); ++i) {
      const VertexIndex a = face.corner(i), b = face.corner(i + 1);
      if (a == b) continue;
      std::size_t count = 0;
      for (const Face& other : mesh.faces)
        for (std::size_t j = 0; j < other.size(); ++j)
          count += same_edge(a, b, other.corner(j), other.corner(j + 1)) ? 1 : 0;
      found = found || (uses == 3 ? count > 2 : count == uses);
    }
    if (found) faces.push_back(f);
  }
  return faces;
}

TEST(MeshCheck, FaceFindingsNameEveryFaceNotJustTheFirstFew) {
  // A cube with a fin on edge 3-7, an open box beside it, and some degenerate and skew faces.
  Mesh mesh = unit_cube();
  mesh.faces.push_back(make_triangle(3, 7, 0));
  Mesh open = box({3, 0, 0}, {4, 1, 1});
  open.faces.pop_back();
  open.faces.pop_back();
  for (Face face : open.faces) {
    for (std::size_t k = 0; k < face.size(); ++k)
      face.corners[k] += 8;
    mesh.faces.push_back(face);
  }
  mesh.vertices.insert(mesh.vertices.end(), open.vertices.begin(), open.vertices.end());
  mesh.vertices[9] = {4, 0, 0.5};  // makes the open box's quads at vertex 9 skew
  mesh.vertices.push_back({9, 9, 9});
  const auto alone = static_cast<VertexIndex>(mesh.vertices.size() - 1);
  mesh.faces.push_back(make_triangle(alone, alone, alone));  // degenerate, and no edges
  const MeshCheck c = check_mesh(mesh);
  ASSERT_EQ(c.face_findings.size(), mesh.faces.size());
  const std::vector<std::size_t> boundary = faces_with(c, &FaceFindings::boundary_edge);
  EXPECT_EQ(boundary, faces_with_edge_used(mesh, 1));
  EXPECT_GT(c.boundary_edges.count, Examples<Edge>::kKept);  // more than the examples keep
  EXPECT_EQ(boundary.size(), 5u);                            // four open-box quads, the fin
  EXPECT_EQ(faces_with(c, &FaceFindings::non_manifold_edge), faces_with_edge_used(mesh, 3));
  EXPECT_EQ(faces_with(c, &FaceFindings::non_manifold_edge).size(), 3u);  // two quads, the fin
  EXPECT_EQ(faces_with(c, &FaceFindings::degenerate).size(), c.degenerate_faces.count);
  EXPECT_EQ(faces_with(c, &FaceFindings::degenerate).front(), c.degenerate_faces.first.front());
  EXPECT_EQ(faces_with(c, &FaceFindings::non_planar).size(), c.non_planar_quads.count);
  EXPECT_GT(c.non_planar_quads.count, 0u);
}

TEST(MeshCheck, DegenerateFacesInAClosedMesh) {
  Mesh mesh = unit_cube();
  // A flat sliver on three collinear vertices, both sides: closed, manifold and oriented,
  // but of zero area.
  mesh.vertices.insert(mesh.vertices.end(), {{5, 5, 5}, {6, 7, 8}, {8, 11, 14}});
  mesh.faces.push_back(make_triangle(8, 9, 10));
  mesh.faces.push_back(make_triangle(8, 10, 9));
  const MeshCheck c = check_mesh(mesh);
  expect_closed_manifold_oriented(c);
  EXPECT_EQ(c.triangles, 2u);
  EXPECT_EQ(c.quads, 6u);
  EXPECT_EQ(c.components, 2u);
  EXPECT_EQ(c.degenerate_faces.first, (std::vector<std::size_t>{6, 7}));
  EXPECT_EQ(c.zero_area_faces.first, (std::vector<std::size_t>{6, 7}));
  EXPECT_EQ(problem(mesh), "");  // dropped by classification, not refused
  EXPECT_EQ(zero_area_note(c.zero_area_faces, {}),
            "2 faces of zero area (first: 6, 7) bound nothing: dropped (faces numbered from 0)");
}

TEST(MeshCheck, OutOfRangeIndex) {
  Mesh mesh = unit_cube();
  mesh.faces.push_back(make_quad(0, 1, 99, 2));
  const MeshCheck c = check_mesh(mesh);
  EXPECT_EQ(c.out_of_range_faces.count, 1u);
  EXPECT_EQ(c.out_of_range_faces.first, (std::vector<std::size_t>{6}));
  EXPECT_EQ(c.first_out_of_range_corner, 99u);
  EXPECT_TRUE(c.closed());  // the bad face is left out of the edge checks
  EXPECT_EQ(c.faces, 7u);
  EXPECT_EQ(c.quads, 7u);
  EXPECT_EQ(problem(mesh), "face 6 has corner index 99, but there are 8 vertices");

  mesh.faces.push_back(make_triangle(kNoVertex, 0, 1));
  mesh.faces.push_back(make_triangle(8, 0, 1));
  EXPECT_EQ(problem(mesh),
            "3 faces have corner indices out of range (first: 6, 7, 8): face 6 has corner "
            "index 99, but there are 8 vertices");
}

TEST(MeshCheck, NonFiniteCoordinates) {
  Mesh mesh = unit_cube();
  mesh.vertices[0][1] = std::numeric_limits<double>::quiet_NaN();
  mesh.vertices[4][2] = std::numeric_limits<double>::infinity();
  mesh.vertices.push_back({-std::numeric_limits<double>::infinity(), 0, 0});
  const MeshCheck c = check_mesh(mesh);
  EXPECT_EQ(c.non_finite_vertices.count, 3u);
  EXPECT_EQ(c.non_finite_vertices.first, (std::vector<std::size_t>{0, 4, 8}));
  // The box is of the finite vertices; faces through non-finite vertices get no geometry.
  ASSERT_TRUE(c.bounding_box);
  EXPECT_EQ(c.bounding_box->lower, (Point3{0, 0, 0}));
  EXPECT_EQ(c.bounding_box->upper, (Point3{1, 1, 1}));
  EXPECT_EQ(c.non_planar_quads.count, 0u);
  EXPECT_EQ(c.degenerate_faces.count, 0u);
  EXPECT_TRUE(c.closed());
  EXPECT_EQ(c.unreferenced_vertices, 1u);
  EXPECT_EQ(problem(mesh), "3 vertices have non-finite coordinates (first: 0, 4, 8)");

  Mesh all_nan;
  all_nan.vertices = {{std::nan(""), 0, 0}, {0, std::nan(""), 0}, {0, 0, std::nan("")}};
  all_nan.faces = {make_triangle(0, 1, 2)};
  EXPECT_FALSE(check_mesh(all_nan).bounding_box);
}

TEST(MeshCheck, EmptyMesh) {
  const MeshCheck c = check_mesh(Mesh{});
  EXPECT_EQ(c.vertices, 0u);
  EXPECT_EQ(c.faces, 0u);
  EXPECT_FALSE(c.bounding_box);
  EXPECT_EQ(c.components, 0u);
  EXPECT_EQ(c.consistently_oriented, std::nullopt);
  EXPECT_EQ(closed_surface_problem(c), "mesh has no faces");

  Mesh points_only;
  points_only.vertices = {{1, 2, 3}};
  const MeshCheck p = check_mesh(points_only);
  EXPECT_EQ(p.unreferenced_vertices, 1u);
  EXPECT_EQ(p.components, 0u);  // an unreferenced vertex is not a component
  EXPECT_EQ(closed_surface_problem(p), "mesh has no faces");
}

TEST(MeshCheck, ComponentsAndUnreferencedVertices) {
  Mesh mesh = unit_cube();
  add_box(mesh, {3, 0, 0}, {4, 1, 1});
  mesh.vertices.push_back({10, 10, 10});  // unreferenced
  const MeshCheck c = check_mesh(mesh);
  EXPECT_EQ(c.components, 2u);
  EXPECT_EQ(c.unreferenced_vertices, 1u);
  expect_closed_manifold_oriented(c);
  EXPECT_EQ(c.bounding_box->upper, (Point3{10, 10, 10}));
  EXPECT_EQ(closed_surface_problem(c), std::nullopt);
}

TEST(MeshCheck, SameFactsAtEveryScale) {
  // A box with one corner moved off all three of its planes, one with a corner moved by
  // one ulp, and collinear / almost collinear triangles: exact at every exponent.
  for (const int exponent : {0, 1000, -1000, -1074}) {
    SCOPED_TRACE("scale 2^" + std::to_string(exponent));
    Mesh moved = scaled(box({2, 2, 2}, {4, 4, 4}), exponent);
    moved.vertices[7] = {std::ldexp(5.0, exponent), std::ldexp(6.0, exponent),
                         std::ldexp(7.0, exponent)};
    MeshCheck c = check_mesh(moved);
    expect_closed_manifold_oriented(c);
    EXPECT_EQ(c.non_planar_quads.first, (std::vector<std::size_t>{1, 3, 5}));
    EXPECT_EQ(c.degenerate_faces.count, 0u);
    EXPECT_EQ(c.bounding_box->lower[0], std::ldexp(2.0, exponent));
    EXPECT_EQ(c.bounding_box->upper[2], std::ldexp(7.0, exponent));
    EXPECT_EQ(closed_surface_problem(c), std::nullopt);

    Mesh ulp = scaled(box({2, 2, 2}, {4, 4, 4}), exponent);
    ulp.vertices[7][0] = std::nextafter(ulp.vertices[7][0], 0.0);
    c = check_mesh(ulp);
    EXPECT_EQ(c.non_planar_quads.first, (std::vector<std::size_t>{5}));
    EXPECT_EQ(check_mesh(scaled(box({2, 2, 2}, {4, 4, 4}), exponent)).non_planar_quads.count, 0u);

    Mesh lines =
        scaled(Mesh{{{0, 0, 0}, {1, 1, 1}, {3, 3, 3}, {2, 3, 4}, {4, 6, 8}}, {}}, exponent);
    Point3 off = lines.vertices[2];
    off[2] = std::nextafter(off[2], 1.0);
    lines.vertices.push_back(off);  // 5
    lines.faces = {make_triangle(0, 1, 2), make_triangle(0, 1, 5), make_quad(0, 3, 4, 0),
                   make_quad(1, 2, 4, 3), make_quad(0, 1, 2, 4)};
    c = check_mesh(lines);
    // 0: collinear; 1: one ulp off the line; 2: repeated index; 3: planar, three corners
    // collinear, the fourth off the line; 4: the same with a quad's first three corners.
    EXPECT_EQ(c.degenerate_faces.first, (std::vector<std::size_t>{0, 2}));
  }
}

TEST(MeshCheck, SelfIntersectionProblemNamesThePairsInTheFilesNumbering) {
  EXPECT_EQ(self_intersection_problem(SelfIntersections{}, {}), std::nullopt);
  SelfIntersections found;
  found.intersecting = {{1, 2}, {1, 5}};
  found.undecided = {{2, 3}};
  // OBJ numbers faces from 1.
  EXPECT_EQ(self_intersection_problem(found, FileNumbering{1, {}}),
            "2 pairs of faces intersect (first: 2-3, 2-6); 1 pair undecided (first: 3-4) (faces "
            "numbered from 1, as in the file)");
  // Mesh faces 1 and 2 are the triangles of the file's face 1: the pair is named 1-1.
  SelfIntersections split;
  split.intersecting = {{1, 2}};
  EXPECT_EQ(self_intersection_problem(split, FileNumbering{0, {0, 1, 1}}),
            "1 pair of faces intersects (first: 1-1) (faces numbered from 0; the triangles of a "
            "split polygon by its number)");
  // More pairs than are named.
  SelfIntersections many;
  for (std::size_t f = 1; f <= 7; ++f)
    many.undecided.push_back({0, f});
  const auto message = self_intersection_problem(many, {});
  ASSERT_TRUE(message.has_value());
  EXPECT_NE(message->find("7 pairs undecided"), std::string::npos) << *message;
  EXPECT_EQ(message->find("0-6"), std::string::npos) << *message;  // only the first few
}

}  // namespace
}  // namespace exactgeo::mesh
