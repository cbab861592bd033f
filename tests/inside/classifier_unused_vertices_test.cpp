// Vertices no face uses bound nothing: the classifier's box, its candidate search's float
// frame and its space cells are all built on the box of the faces' corners. A point
// between that box and a far unused vertex is outside, and its rays must find every face
// (the float frame's rounding argument holds only inside the box it was built on).
// Labels are checked against the truth of a cube (inside iff strictly inside it) and
// against the same mesh without the unused vertices, with space cells on and off, at
// scales 2^0 and 2^+-1000.

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
#include "support/seed.hpp"
#include "support/solid_angle_oracle.hpp"

namespace exactgeo::inside::unused_vertices {
namespace {

using mesh::Mesh;

using testing::cube_truth;
using testing::hex;
using testing::scaled_cube;

TEST(UnusedVertices, AFarUnusedVertexIsOutsideTheCube) {
  // The reported case: a unit cube of twelve triangles and one vertex no face uses.
  const Point3 unused{-0x1p+20, -0x1.83ef5723b83a2p+17, -0x1.327705516eb07p+15};
  Mesh mesh = scaled_cube(0, true);
  mesh.vertices.push_back(unused);
  for (const bool cells : {true, false}) {
    const Classifier classifier(mesh, {.space_cells = cells});
    EXPECT_EQ(to_string(classifier.classify(unused)), "outside") << "space cells " << cells;
    EXPECT_EQ(to_string(classifier.classify({0.5, 0.5, 0.5})), "inside");
    EXPECT_EQ(to_string(classifier.classify({-1000, -1000, -100})), "outside");
  }
}

struct Setting {
  int scale_exponent;
  bool triangles;
};

class UnusedVerticesFamily : public ::testing::TestWithParam<Setting> {};

TEST_P(UnusedVerticesFamily, LabelsAreThoseOfTheMeshWithoutThem) {
  const auto [k, triangles] = GetParam();
  auto rng = testing::seeded_engine("inside.unused_vertices." + std::to_string(k) +
                                    (triangles ? ".triangles" : ".quads"));
  std::uniform_real_distribution<double> mantissa(0.5, 1.0);
  std::uniform_int_distribution<int> far_exponent(3, std::min(40, 1020 - k));
  std::uniform_int_distribution<int> coin(0, 1);
  std::uniform_int_distribution<int> unused_count(1, 3);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::uniform_int_distribution<std::size_t> direction(0, 7);
  const double side = std::ldexp(1.0, k);
  const Mesh plain = scaled_cube(k, triangles);
  const Classifier reference(plain, {.space_cells = false});

  // Extreme magnitudes take the rational stage for many signs: fewer points there.
  const int meshes = 6, points = k == 0 ? 500 : 60;
  std::size_t compared = 0, far_from_the_cube = 0;
  for (int m = 0; m < meshes; ++m) {
    Mesh mesh = plain;
    const int count = unused_count(rng);
    for (int u = 0; u < count; ++u) {
      Point3 v;
      for (double& x : v) {
        const double magnitude = std::ldexp(mantissa(rng), k + far_exponent(rng));
        x = coin(rng) ? -magnitude : side + magnitude;
      }
      mesh.vertices.push_back(v);
    }
    // The box of every vertex: where the old classifier took its float frame from.
    Point3 lower = mesh.vertices[0], upper = mesh.vertices[0];
    for (const Point3& v : mesh.vertices) {
      for (int i = 0; i < 3; ++i) {
        lower[i] = std::min(lower[i], v[i]);
        upper[i] = std::max(upper[i], v[i]);
      }
    }
    for (const bool cells : {true, false}) {
      const Classifier classifier(mesh, {.space_cells = cells});
      const auto expect_label = [&](const Point3& p) {
        const Location truth = cube_truth(p, k);
        ASSERT_EQ(to_string(classifier.classify(p)), to_string(truth))
            << "point " << hex(p) << ", mesh " << m << ", space cells " << cells;
        ASSERT_EQ(to_string(reference.classify(p)), to_string(truth)) << "point " << hex(p);
        ++compared;
        far_from_the_cube += truth == Location::outside;
      };
      // The unused vertices themselves.
      for (std::size_t v = plain.vertices.size(); v < mesh.vertices.size(); ++v)
        expect_label(mesh.vertices[v]);
      for (int p = 0; p < points; ++p) {
        // Anywhere in the box of every vertex.
        Point3 q;
        for (int i = 0; i < 3; ++i)
          q[i] = lower[i] + unit(rng) * (upper[i] - lower[i]);
        expect_label(q);
        // Far points whose ray k passes (up to the rounding of the origin) through a point
        // of a cube edge: the rays the float frame rounded past the cube's faces.
        Point3 on_edge{unit(rng) * side, coin(rng) * side, coin(rng) * side};
        std::swap(on_edge[0], on_edge[std::uniform_int_distribution<std::size_t>(0, 2)(rng)]);
        const Vector3 d = ray_direction(direction(rng));
        const double s = std::ldexp(mantissa(rng), k + far_exponent(rng));
        expect_label({on_edge[0] - s * d[0], on_edge[1] - s * d[1], on_edge[2] - s * d[2]});
        // And the cube's inside, which must not change.
        expect_label({side * (0.01 + 0.98 * unit(rng)), side * (0.01 + 0.98 * unit(rng)),
                      side * (0.01 + 0.98 * unit(rng))});
      }
    }
  }
  EXPECT_GT(far_from_the_cube, compared / 2);
}

INSTANTIATE_TEST_SUITE_P(Scales, UnusedVerticesFamily,
                         ::testing::Values(Setting{0, true}, Setting{0, false}, Setting{1000, true},
                                           Setting{-1000, false}),
                         [](const ::testing::TestParamInfo<Setting>& param_info) {
                           const Setting& s = param_info.param;
                           std::string name = s.scale_exponent < 0 ? "scale_2m" : "scale_2p";
                           name += std::to_string(std::abs(s.scale_exponent));
                           name += s.triangles ? "_triangles" : "_quads";
                           return name;
                         });

}  // namespace
}  // namespace exactgeo::inside::unused_vertices
