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
//
// Beside an open surface (zero_area_beside_open): a surface that is open even with them
// counted has the kept faces' boundary alone. Checked against the solid-angle oracle on the kept
// faces, at 2^0 and 2^+-1000: collinear triangles sharing a corner with an open sheet or apart from
// it; points whose first ray passes exactly through a corner of one (once `undecided`, w far from
// 1/2: both edges at that corner gave 0/0 at every precision); points on their edges, labelled as
// on the same mesh without them (once `boundary` on an open mesh, while a closed mesh gave inside
// or outside).

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <limits>
#include <map>
#include <optional>
#include <ostream>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "exactgeo/inside/batch.hpp"
#include "exactgeo/inside/classifier.hpp"
#include "exactgeo/inside/fill_rule.hpp"
#include "exactgeo/inside/location.hpp"
#include "exactgeo/mesh/check.hpp"
#include "exactgeo/mesh/load.hpp"
#include "exactgeo/mesh/mesh.hpp"
#include "exactgeo/mesh/off_reader.hpp"
#include "exactgeo/predicates/bilinear_patch.hpp"
#include "exactgeo/predicates/ray_directions.hpp"
#include "exactgeo/predicates/ray_triangle.hpp"
#include "inside/polycube.hpp"
#include "inside/scaled_cube.hpp"
#include "mesh/hexahedron.hpp"
#include "support/generators.hpp"
#include "support/hexahedron.hpp"
#include "support/polygon_oracle.hpp"
#include "support/rational_oracle.hpp"
#include "support/scale_names.hpp"
#include "support/seed.hpp"
#include "support/solid_angle_oracle.hpp"

namespace exactgeo::inside::zero_area {
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
                         exactgeo::testing::scale_name);

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
}  // namespace exactgeo::inside::zero_area

namespace exactgeo::inside::zero_area_beside_open {
namespace {

using mesh::Mesh;
using testing::Triangle;

std::string text(const Point3& p) {
  char buffer[160];
  std::snprintf(buffer, sizeof buffer, "(%a, %a, %a)", p[0], p[1], p[2]);
  return buffer;
}

std::string text(Location l) {
  return std::string(to_string(l));
}

Point3 plus(const Point3& p, const Vector3& d, double s) {
  return {p[0] + s * d[0], p[1] + s * d[1], p[2] + s * d[2]};
}

/// An open sheet of two triangles on small integer corners, bent along their shared edge.
Mesh sheet(testing::Rng& rng) {
  Mesh m;
  m.vertices = {{-4, -4, 0},
                {4, -4, 0},
                {4, 4, double(testing::uniform_int(rng, -3, 3))},
                {-4, 4, double(testing::uniform_int(rng, -3, 3))}};
  m.faces = {mesh::make_triangle(0, 1, 2), mesh::make_triangle(0, 2, 3)};
  return m;
}

/// A closed tetrahedron on small integer corners, its faces turning outward.
Mesh tetrahedron() {
  Mesh m;
  m.vertices = {{-4, -4, -4}, {4, -4, -4}, {0, 4, -4}, {0, 0, 4}};
  m.faces = {mesh::make_triangle(0, 2, 1), mesh::make_triangle(0, 1, 3),
             mesh::make_triangle(1, 2, 3), mesh::make_triangle(2, 0, 3)};
  return m;
}

/// Adds the collinear triangle (c, c + d, c + 2d) to `m`, its first corner vertex `at`
/// when given (shared with the surface), else a new vertex at c.
void add_sliver(Mesh& m, const Point3& c, const Vector3& d, std::optional<VertexIndex> at) {
  const auto next = [&] { return static_cast<VertexIndex>(m.vertices.size()); };
  VertexIndex first = 0;
  if (at) {
    first = *at;
  } else {
    first = next();
    m.vertices.push_back(c);
  }
  const VertexIndex second = next();
  m.vertices.push_back(plus(c, d, 1));
  const VertexIndex third = next();
  m.vertices.push_back(plus(c, d, 2));
  m.faces.push_back(mesh::make_triangle(first, second, third));
}

Mesh scaled(Mesh m, int k) {
  for (Point3& v : m.vertices)
    v = testing::scaled(v, k);
  return m;
}

std::vector<Triangle> triangles(const Mesh& m, std::size_t count) {
  std::vector<Triangle> out;
  for (std::size_t f = 0; f < count; ++f) {
    const auto& c = m.faces[f].corners;
    out.push_back({m.vertices[c[0]], m.vertices[c[1]], m.vertices[c[2]]});
  }
  return out;
}

bool on_some_triangle(const Point3& p, const std::vector<Triangle>& kept) {
  for (const Triangle& t : kept) {
    if (testing::ray_triangle_oracle(p, ray_direction(0), t[0], t[1], t[2]).kind ==
        RayTriangle::origin_on) {
      return true;
    }
  }
  return false;
}

/// nonzero on an open surface: inside where |w| >= 1/2; nullopt too near a level to tell.
std::optional<Location> expected(const Point3& p, const std::vector<Triangle>& kept) {
  const double above_half = testing::generalized_winding_oracle(p, kept, 0.5);
  const double above_minus_half = testing::generalized_winding_oracle(p, kept, -0.5);
  constexpr double kTooNear = 0x1p-400;
  if (std::abs(above_half) < kTooNear || std::abs(above_minus_half) < kTooNear) {
    return std::nullopt;
  }
  return above_half > 0 || above_minus_half < 0 ? Location::inside : Location::outside;
}

class ZeroAreaBesideOpen : public ::testing::TestWithParam<int> {};

TEST_P(ZeroAreaBesideOpen, FirstRaysThroughASliversCornerGetTheOraclesLabel) {
  const int k = GetParam();
  testing::Rng rng = testing::seeded_engine("classifier-zero-area-ray-through-corner");
  const Vector3 r = ray_direction(0);
  std::size_t compared = 0;
  for (int i = 0; i < 60; ++i) {
    Mesh m = sheet(rng);
    const std::size_t kept_faces = m.faces.size();
    // A point off the sheet, and a corner on its first ray at a dyadic step (exact).
    const Point3 p{testing::uniform_int(rng, -12, 12) / 4.0,
                   testing::uniform_int(rng, -12, 12) / 4.0,
                   testing::uniform_int(rng, -12, 12) / 4.0};
    const Point3 corner = plus(p, r, testing::uniform_int(rng, 1, 32) / 2.0);
    const Vector3 d{double(testing::uniform_int(rng, -2, 2)),
                    double(testing::uniform_int(rng, -2, 2)),
                    double(testing::uniform_int(rng, 1, 2))};
    add_sliver(m, corner, d, std::nullopt);
    // A second sliver sharing a corner of the sheet, in every other mesh.
    if (i % 2 == 0) add_sliver(m, m.vertices[2], {1, 0, 0}, VertexIndex{2});
    const Mesh mk = scaled(m, k);
    const Point3 pk = testing::scaled(p, k);
    const std::vector<Triangle> kept = triangles(mk, kept_faces);
    if (on_some_triangle(pk, kept)) continue;
    const Classifier classifier(mk);
    const Location got = classifier.classify(pk);
    ASSERT_NE(got, Location::undecided) << text(pk) << ", mesh " << i;
    if (const auto want = expected(pk, kept)) {
      ++compared;
      EXPECT_EQ(text(got), text(*want)) << text(pk) << ", mesh " << i;
    }
  }
  EXPECT_GT(compared, 40u);
}

/// The reproducer: an open triangle and an apart collinear triangle whose corner
/// (9, 5/2, 41/32) lies on the first ray from (1, 1, 1).
TEST(ZeroAreaBesideOpen, TheReproducerIsOutside) {
  Mesh m;
  m.vertices = {{0, 0, 0},         {4, 0, 0},          {0, 4, 0},
                {9, 2.5, 1.28125}, {10, 2.5, 1.28125}, {11, 2.5, 1.28125}};
  m.faces = {mesh::make_triangle(0, 1, 2), mesh::make_triangle(3, 4, 5)};
  EXPECT_EQ(text(Classifier(m).classify({1, 1, 1})), text(Location::outside));
}

/// A point on a sliver's edge (off the kept faces) gets the solid-angle oracle's label on
/// the kept faces, beside an open sheet and beside a closed tetrahedron alike.
TEST_P(ZeroAreaBesideOpen, PointsOnASliversEdgeAreLabelledAsWithoutIt) {
  const int k = GetParam();
  testing::Rng rng = testing::seeded_engine("classifier-zero-area-point-on-edge");
  std::size_t labelled = 0;
  for (int i = 0; i < 40; ++i) {
    const bool closed = i % 2 == 1;
    const Mesh without = closed ? tetrahedron() : sheet(rng);
    Mesh with = without;
    const Point3 c{double(testing::uniform_int(rng, -6, 6)),
                   double(testing::uniform_int(rng, -6, 6)),
                   double(testing::uniform_int(rng, -6, 6))};
    const Vector3 d{double(testing::uniform_int(rng, -2, 2)),
                    double(testing::uniform_int(rng, -2, 2)),
                    double(testing::uniform_int(rng, 1, 2))};
    add_sliver(with, c, d, std::nullopt);
    const Point3 q = plus(c, d, 0.5);  // inside the sliver's first edge, exactly
    const Mesh without_k = scaled(without, k), with_k = scaled(with, k);
    const Point3 qk = testing::scaled(q, k);
    const std::vector<Triangle> kept = triangles(without_k, without_k.faces.size());
    if (on_some_triangle(qk, kept)) continue;
    // The truth from the definition on the kept faces (for the closed tetrahedron w is 0
    // or 1, and |w| >= 1/2 is its inside), never from the classifier itself.
    const std::optional<Location> want = expected(qk, kept);
    ASSERT_TRUE(want) << text(qk);
    const Location got = Classifier(with_k).classify(qk);
    EXPECT_EQ(text(got), text(*want)) << text(qk) << (closed ? ", closed" : ", open");
    labelled += got == Location::inside;
  }
  EXPECT_GT(labelled, 0u);  // some of them inside: the comparison is not all outside
}

INSTANTIATE_TEST_SUITE_P(Scales, ZeroAreaBesideOpen, ::testing::Values(0, 1000, -1000),
                         exactgeo::testing::scale_name);

}  // namespace
}  // namespace exactgeo::inside::zero_area_beside_open
