// Uses an installed exactgeo: one exact predicate, one CCD query type and the
// point-in-volume classifier, each with answers that are known in advance.

#include <cstdio>
#include <exception>
#include <utility>
#include <vector>

#include "exactgeo/ccd/ccd.hpp"
#include "exactgeo/ccd/mesh/mesh_ccd.hpp"
#include "exactgeo/inside/classifier.hpp"
#include "exactgeo/inside/location.hpp"
#include "exactgeo/mesh/check.hpp"
#include "exactgeo/predicates/orient3d.hpp"

namespace {

int failures = 0;

void check(bool ok, const char* what) {
  std::printf("%s: %s\n", ok ? "ok  " : "FAIL", what);
  if (!ok) ++failures;
}

void predicates() {
  using exactgeo::orient3d;
  using exactgeo::Sign;
  check(orient3d({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}) == Sign::positive,
        "orient3d positive");
  check(orient3d({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, -1}) == Sign::negative,
        "orient3d negative");
  // d in the plane z = 0 of a, b, c.
  check(orient3d({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.1, 0.7, 0}) == Sign::zero,
        "orient3d zero (coplanar)");
}

void ccd() {
  using exactgeo::ccd::VertexFaceQuery;
  // A still triangle in z = 0; the vertex moves from z = 1 to z = -1.
  const VertexFaceQuery through{
      {0.25, 0.25, 1},  {0, 0, 0}, {1, 0, 0}, {0, 1, 0},  // t = 0: v, f0, f1, f2
      {0.25, 0.25, -1}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0},  // t = 1
  };
  // The same motion beside the triangle: it crosses the plane, not the triangle.
  const VertexFaceQuery beside{
      {2, 2, 1},  {0, 0, 0}, {1, 0, 0}, {0, 1, 0},  // t = 0
      {2, 2, -1}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0},  // t = 1
  };
  check(exactgeo::ccd::vertex_face_ccd(through).collision, "vertex_face_ccd through: collision");
  check(!exactgeo::ccd::vertex_face_ccd(beside).collision, "vertex_face_ccd beside: no collision");
}

void mesh_ccd() {
  using namespace exactgeo::ccd;
  // Two triangles: the first lies still in z = 0, the second falls through it; vertex 3
  // passes through (0.25, 0.25, 0) at t = 1/2.
  const std::vector<Triangle> faces{{0, 1, 2}, {3, 4, 5}};
  const std::vector<double> t0{0, 0, 0, 1, 0, 0, 0, 1, 0, 0.25, 0.25, 1, 5, 5, 1, 6, 5, 1};
  std::vector<double> t1 = t0;
  for (int v = 3; v < 6; ++v)
    t1[3 * v + 2] = -1;
  MeshCcd mesh(6, faces);
  const MeshCcdResult result = mesh.step({t0, t1}, {Method::exact, 1e-3, 1});
  check(result.vertex_face == std::vector<VertexFacePair>{{3, 0}}, "MeshCcd: vertex 3 hits face 0");
  check(result.time_of_impact && result.time_of_impact->start <= 0.5 &&
            0.5 <= result.time_of_impact->end,
        "MeshCcd: the time of impact brackets 1/2");
}

void inside() {
  using namespace exactgeo::inside;
  using exactgeo::mesh::make_quad;
  // The unit cube [0, 1]^3 as six quads; the bits of vertex c are its x, y, z.
  exactgeo::mesh::Mesh cube;
  for (int c = 0; c < 8; ++c)
    cube.vertices.push_back({double(c & 1), double((c >> 1) & 1), double((c >> 2) & 1)});
  cube.faces = {make_quad(0, 2, 3, 1), make_quad(4, 5, 7, 6), make_quad(0, 1, 5, 4),
                make_quad(2, 6, 7, 3), make_quad(0, 4, 6, 2), make_quad(1, 3, 7, 5)};
  check(exactgeo::mesh::check_mesh(cube).closed(), "cube: the mesh check calls it closed");
  const Classifier classifier(std::move(cube));
  check(classifier.classify({0.5, 0.5, 0.5}) == Location::inside, "cube: centre is inside");
  check(classifier.classify({2, 0.5, 0.5}) == Location::outside, "cube: (2, .5, .5) is outside");
  check(classifier.classify({1, 0.5, 0.25}) == Location::boundary,
        "cube: (1, .5, .25) is on the boundary");
}

}  // namespace

int main() {
  try {
    predicates();
    ccd();
    mesh_ccd();
    inside();
  } catch (const std::exception& e) {
    std::printf("FAIL: exception: %s\n", e.what());
    return 1;
  }
  if (failures != 0) {
    std::printf("%d check(s) failed\n", failures);
    return 1;
  }
  std::printf("all checks passed\n");
  return 0;
}
