// Faces of zero area bound nothing: the classifier counts them in the edges (where they
// keep the edges around them balanced) and then drops them. Planted into a cube of known
// truth, at scales 2^0 and 2^+-1000, space cells on and off:
//   - slivers closing T-junctions: a cube face's triangle split at a point of its
//     diagonal, and the flat triangle (f0, f2, m) that keeps the diagonal's edges
//     balanced (without it the mesh would be open);
//   - spikes: a triangle with a repeated corner (a, a, b), a segment from a cube corner
//     to anywhere;
//   - a flat triangle on three collinear points and its reverse.
// Every label equals the cube's truth, points on the planted segments included (on the
// cube's surface they are boundary, elsewhere they are the cube's inside or outside).

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "exactgeo/inside/classifier.hpp"
#include "exactgeo/inside/location.hpp"
#include "inside/scaled_cube.hpp"
#include "support/seed.hpp"

namespace exactgeo::inside {
namespace {

using mesh::Mesh;
using testing::cube_truth;
using testing::hex;
using testing::scaled_cube;

/// a + t (b - a) for a dyadic t = j / 2^10 and corners a, b of the cube [0, 2^k]^3: exact,
/// and exactly on the segment.
Point3 on_segment(const Point3& a, const Point3& b, int j) {
  Point3 p;
  for (int i = 0; i < 3; ++i)
    p[i] = a[i] + std::ldexp(static_cast<double>(j), -10) * (b[i] - a[i]);
  return p;
}

struct Planted {
  Mesh mesh;
  std::size_t zero_area = 0;
  /// Points on the planted segments.
  std::vector<Point3> on_segments;
};

/// The cube of triangles with every face's second triangle split at a point of the face's
/// diagonal, a sliver per split, `spikes` spikes and one collinear pair.
Planted planted_cube(int k, int spikes, std::mt19937_64& rng) {
  std::uniform_int_distribution<int> step(1, 1023);
  std::uniform_int_distribution<int> lattice(-4, 8);
  std::uniform_int_distribution<VertexIndex> corner(0, 7);
  const double unit = std::ldexp(1.0, k - 2);  // a quarter of the side
  Planted out;
  Mesh& mesh = out.mesh;
  const Mesh cube = scaled_cube(k, true);
  mesh.vertices = cube.vertices;
  for (std::size_t f = 0; f < cube.faces.size(); f += 2) {
    // (f0, f1, f2) and (f0, f2, f3): split the second at m on the diagonal f0-f2.
    const auto& first = cube.faces[f].corners;
    const auto& second = cube.faces[f + 1].corners;
    const VertexIndex f0 = second[0], f2 = second[1], f3 = second[2];
    const auto m = static_cast<VertexIndex>(mesh.vertices.size());
    mesh.vertices.push_back(on_segment(mesh.vertices[f0], mesh.vertices[f2], step(rng)));
    out.on_segments.push_back(on_segment(mesh.vertices[f0], mesh.vertices[f2], step(rng)));
    mesh.faces.push_back(mesh::make_triangle(first[0], first[1], first[2]));
    mesh.faces.push_back(mesh::make_triangle(f0, m, f3));
    mesh.faces.push_back(mesh::make_triangle(m, f2, f3));
    // Balances f2 -> f0 (the first triangle), f0 -> m and m -> f2 (the split ones).
    mesh.faces.push_back(mesh::make_triangle(f0, f2, m));
    ++out.zero_area;
  }
  for (int s = 0; s < spikes; ++s) {
    // From a cube corner to a lattice point of spacing 2^(k-2), in or out of the cube;
    // its midpoint is exact.
    const VertexIndex a = corner(rng);
    const Point3 b{lattice(rng) * unit, lattice(rng) * unit, lattice(rng) * unit};
    const auto bi = static_cast<VertexIndex>(mesh.vertices.size());
    mesh.vertices.push_back(b);
    mesh.faces.push_back(mesh::make_triangle(a, a, bi));
    ++out.zero_area;
    const Point3& pa = mesh.vertices[a];
    out.on_segments.push_back(b);
    out.on_segments.push_back({(pa[0] + b[0]) / 2, (pa[1] + b[1]) / 2, (pa[2] + b[2]) / 2});
  }
  // Three collinear lattice points through the cube, both orientations.
  const Point3 p{lattice(rng) * unit, lattice(rng) * unit, lattice(rng) * unit};
  const Vector3 d{unit, 2 * unit, -unit};
  const auto first = static_cast<VertexIndex>(mesh.vertices.size());
  for (int i = 0; i < 3; ++i)
    mesh.vertices.push_back({p[0] + i * d[0], p[1] + i * d[1], p[2] + i * d[2]});
  mesh.faces.push_back(mesh::make_triangle(first, first + 1, first + 2));
  mesh.faces.push_back(mesh::make_triangle(first, first + 2, first + 1));
  out.zero_area += 2;
  out.on_segments.push_back(mesh.vertices[first + 1]);
  return out;
}

class ZeroAreaFaces : public ::testing::TestWithParam<int> {};

TEST_P(ZeroAreaFaces, AreDroppedAndChangeNoLabel) {
  const int k = GetParam();
  auto rng = testing::seeded_engine("inside.zero_area." + std::to_string(k));
  std::uniform_real_distribution<double> unit(-0.25, 1.25);
  const double side = std::ldexp(1.0, k);
  // Extreme magnitudes take the rational stage for many signs: fewer points there.
  const int meshes = 4, points = k == 0 ? 400 : 60;
  std::size_t inside = 0, outside = 0, boundary = 0;
  for (int m = 0; m < meshes; ++m) {
    const Planted planted = planted_cube(k, 6, rng);
    for (const bool cells : {true, false}) {
      const Classifier classifier(planted.mesh, {.space_cells = cells});
      EXPECT_EQ(classifier.zero_area_faces().count, planted.zero_area);
      EXPECT_EQ(classifier.mesh().faces.size(), planted.mesh.faces.size() - planted.zero_area);
      const auto expect_label = [&](const Point3& p) {
        const Location truth = cube_truth(p, k);
        ASSERT_EQ(to_string(classifier.classify(p)), to_string(truth))
            << "point " << hex(p) << ", mesh " << m << ", space cells " << cells;
        ASSERT_EQ(classifier.winding_number(p).value_or(-7), truth == Location::boundary ? -7
                                                             : truth == Location::inside ? 1
                                                                                         : 0)
            << "point " << hex(p);
        inside += truth == Location::inside;
        outside += truth == Location::outside;
        boundary += truth == Location::boundary;
      };
      for (const Point3& p : planted.on_segments)
        expect_label(p);
      for (const Point3& v : planted.mesh.vertices)
        expect_label(v);
      for (int p = 0; p < points; ++p)
        expect_label({side * unit(rng), side * unit(rng), side * unit(rng)});
    }
  }
  EXPECT_GT(inside, 0u);
  EXPECT_GT(outside, 0u);
  EXPECT_GT(boundary, 0u);
}

INSTANTIATE_TEST_SUITE_P(Scales, ZeroAreaFaces, ::testing::Values(0, 1000, -1000),
                         [](const ::testing::TestParamInfo<int>& param_info) {
                           const int k = param_info.param;
                           return (k < 0 ? "scale_2m" : "scale_2p") + std::to_string(std::abs(k));
                         });

TEST(ZeroAreaFaces, EveryFaceOfZeroAreaIsRefused) {
  Mesh mesh;
  mesh.vertices = {{0, 0, 0}, {1, 1, 1}, {3, 3, 3}};
  mesh.faces = {mesh::make_triangle(0, 1, 2), mesh::make_triangle(0, 2, 1)};
  try {
    const Classifier classifier(mesh);
    FAIL() << "accepted a mesh of zero-area faces";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "every face has zero area");
  }
}

}  // namespace
}  // namespace exactgeo::inside
