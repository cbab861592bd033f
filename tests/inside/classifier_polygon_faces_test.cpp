// Solids whose faces include polygons of many corners, read from OFF text as a user's
// file would be: prisms over random concave star polygons (with corners inside straight
// edges) and a square tube whose end caps are polygons with a hole written through a
// bridge. The caps are split into triangles by the reader; every label must be that of
// the solid, decided by an exact rational oracle of the cap polygon's winding number
// (independent of the reader's triangles): points inside, outside, on the caps (among
// them points on the triangles' inner diagonals, which are no edge of the solid) and
// just above and below the caps, at 2^0 and 2^+-1000, space cells on and off.

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
#include "support/scale_names.hpp"
#include "support/seed.hpp"
#include "support/solid_angle_oracle.hpp"

namespace exactgeo::inside::polygon_faces {
namespace {

using testing::Point2;
using testing::Polygon2;

std::string number(double x) {
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.17g", x);  // 17 digits: the double back exactly
  return buffer;
}

/// The prism over the polygon from z = 0 to z = height, every coordinate times `scale`,
/// as OFF text: the two caps as polygons (the bottom one reversed, to face down), a quad
/// for every edge of the cycle that is not a bridge (an edge walked both ways).
std::string prism_off(const Polygon2& polygon, double height, double scale) {
  const std::size_t n = polygon.points.size();
  const std::size_t m = polygon.cycle.size();
  std::vector<std::array<std::uint32_t, 2>> walls;
  for (std::size_t k = 0; k < m; ++k) {
    const std::uint32_t a = polygon.cycle[k], b = polygon.cycle[(k + 1) % m];
    bool bridge = false;
    for (std::size_t j = 0; j < m; ++j)
      bridge = bridge || (polygon.cycle[j] == b && polygon.cycle[(j + 1) % m] == a);
    if (!bridge) walls.push_back({a, b});
  }
  std::string off = "OFF\n";
  off.append(std::to_string(2 * n))
      .append(" ")
      .append(std::to_string(2 + walls.size()))
      .append(" 0\n");
  for (const double z : {0.0, height}) {
    for (const Point2& q : polygon.points) {
      off.append(number(scale * q[0])).append(" ").append(number(scale * q[1])).append(" ");
      off.append(number(scale * z)).append("\n");
    }
  }
  const auto face = [&](const std::vector<std::size_t>& corners) {
    off.append(std::to_string(corners.size()));
    for (const std::size_t c : corners)
      off.append(" ").append(std::to_string(c));
    off.append("\n");
  };
  std::vector<std::size_t> bottom, top;
  for (std::size_t k = 0; k < m; ++k) {
    bottom.push_back(polygon.cycle[m - 1 - k]);
    top.push_back(n + polygon.cycle[k]);
  }
  face(bottom);
  face(top);
  for (const auto& [a, b] : walls)
    face({a, b, n + b, n + a});
  return off;
}

Location truth(const Polygon2& polygon, const Point2& q, double z, double height) {
  const int winding = *testing::winding_number_oracle(polygon, q);
  if (winding == 0 || z < 0 || z > height) return Location::outside;
  return z == 0 || z == height ? Location::boundary : Location::inside;
}

class PolygonFaces : public ::testing::TestWithParam<int> {};

TEST_P(PolygonFaces, PrismsAndTubesAreClassifiedExactly) {
  const int k = GetParam();
  auto rng = testing::seeded_engine("inside.polygon_faces." + std::to_string(k));
  const double scale = std::ldexp(1.0, k);
  std::vector<Polygon2> polygons = {testing::keyhole_polygon(false),
                                    testing::keyhole_polygon(true)};
  std::uniform_int_distribution<int> corners(5, 30);
  for (int p = 0; p < 4; ++p)
    polygons.push_back(testing::random_star_polygon(rng, corners(rng), p % 2 == 0));
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const auto dyadic = [&](double lo, double hi) {  // exact: 2^-8 steps on small integers
    return lo + std::ldexp(std::floor(std::ldexp(unit(rng), 8) * (hi - lo)), -8);
  };
  std::size_t counts[3] = {0, 0, 0};
  for (const Polygon2& polygon : polygons) {
    Point2 lower = polygon.points[0], upper = lower;
    for (const Point2& q : polygon.points) {
      for (int i = 0; i < 2; ++i) {
        lower[i] = std::min(lower[i], q[i]);
        upper[i] = std::max(upper[i], q[i]);
      }
    }
    const double height = std::max(upper[0] - lower[0], 8.0);
    const mesh::LoadedMesh loaded =
        mesh::read_off(prism_off(polygon, height, scale), "prism.off", {});
    ASSERT_TRUE(loaded.notes.empty()) << loaded.notes.front();
    ASSERT_EQ(loaded.split_polygons, 2u);
    for (const bool cells : {true, false}) {
      const Classifier classifier(loaded.mesh, {.space_cells = cells});
      const auto expect = [&](const Point2& q, double z) {
        const Location want = truth(polygon, q, z, height);
        const Point3 p{scale * q[0], scale * q[1], scale * z};
        ASSERT_EQ(to_string(classifier.classify(p)), to_string(want))
            << "(" << q[0] << ", " << q[1] << ", " << z << ") times 2^" << k << ", cells " << cells;
        ++counts[static_cast<int>(want == Location::inside) + 2 * (want == Location::boundary)];
      };
      // On the caps' triangles' edges, inner diagonals included: midpoints of the
      // bottom cap's triangle sides (in the polygon's own coordinates).
      for (std::size_t f = 0; f < loaded.mesh.faces.size(); ++f) {
        const mesh::Face& face = loaded.mesh.faces[f];
        if (!face.is_triangle() || loaded.mesh.vertices[face.corners[0]][2] != 0.0) continue;
        for (int e = 0; e < 3; ++e) {
          const Point2& a = polygon.points[face.corners[e]];
          const Point2& b = polygon.points[face.corners[(e + 1) % 3]];
          const Point2 mid{(a[0] + b[0]) / 2, (a[1] + b[1]) / 2};
          if (!testing::winding_number_oracle(polygon, mid)) continue;  // a polygon edge
          for (const double z : {0.0, height, height / 2, -height / 2})
            expect(mid, z);
        }
      }
      const int points = k == 0 ? 300 : 40;
      for (int i = 0; i < points; ++i) {
        const Point2 q{dyadic(lower[0] - 1, upper[0] + 1), dyadic(lower[1] - 1, upper[1] + 1)};
        if (!testing::winding_number_oracle(polygon, q)) continue;
        const double z = i % 4 == 0 ? 0.0 : i % 4 == 1 ? height : dyadic(-2, height + 2);
        expect(q, z);
        // One step of 2^-8 above and below a cap.
        if (i % 4 < 2) {
          expect(q, z + std::ldexp(1.0, -8));
          expect(q, z - std::ldexp(1.0, -8));
        }
      }
    }
  }
  EXPECT_GT(counts[0], 0u);  // outside
  EXPECT_GT(counts[1], 0u);  // inside
  EXPECT_GT(counts[2], 0u);  // boundary
}

INSTANTIATE_TEST_SUITE_P(Scales, PolygonFaces, ::testing::Values(0, 1000, -1000),
                         exactgeo::testing::scale_name);

}  // namespace
}  // namespace exactgeo::inside::polygon_faces
