// Open surfaces, labelled by their generalized winding number w: inside where |w| >= 1/2
// (nonzero) or w >= 1/2 (positive). Checked against oracles that share no code with the
// library (support/solid_angle_oracle.hpp, 512-bit MPFR):
//   - triangle meshes (a jittered, subdivided octahedron with faces cut out) against the
//     definition, w = (1/4 pi) sum of the faces' solid angles, at 2^0 and 2^+-1000, points
//     anywhere, near the holes and far beyond the mesh's box, Embree and every face;
//   - bilinear patches (a hexahedron of skew patches with a face cut out) against the
//     decomposition written out independently: the rational ray-patch oracle's signed
//     crossings plus the cone term over the hole;
//   - cases with a known answer: w = 1/2 exactly is undecided, a point on a boundary edge
//     is boundary, and stacked copies of a bowl hold points outside their box.

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <limits>
#include <map>
#include <numbers>
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
#include "oracle_triangles.hpp"
#include "support/generators.hpp"
#include "support/hexahedron.hpp"
#include "support/polygon_oracle.hpp"
#include "support/rational_oracle.hpp"
#include "support/scale_names.hpp"
#include "support/seed.hpp"
#include "support/solid_angle_oracle.hpp"

namespace exactgeo::inside::open_surface {
namespace {

using mesh::Mesh;
using testing::hex;
using testing::Triangle;
using testing::triangles_of;

/// The label a rule gives a point with the oracle's w - 1/2 and w + 1/2; nullopt when w
/// is too near a level for the oracle's double to tell (then any label but boundary goes).
std::optional<Location> expected(FillRule rule, double above_half, double above_minus_half) {
  constexpr double kTooNear = 0x1p-400;
  if (std::abs(above_half) < kTooNear) return std::nullopt;
  if (rule == FillRule::positive) return above_half > 0 ? Location::inside : Location::outside;
  if (std::abs(above_minus_half) < kTooNear) return std::nullopt;
  return above_half > 0 || above_minus_half < 0 ? Location::inside : Location::outside;
}

ClassifierOptions with(FillRule rule, CandidateSearch candidates = CandidateSearch::embree) {
  ClassifierOptions options;
  options.rule = rule;
  options.candidates = candidates;
  return options;
}

/// The octahedron with every face split into four, its vertices pushed towards the unit
/// sphere and jittered by up to 0.05, scaled by 2^k: a closed surface of 32 triangles,
/// counter-clockwise seen from outside.
Mesh subdivided_octahedron(std::mt19937_64& rng, int k) {
  std::uniform_real_distribution<double> jitter(-0.05, 0.05);
  Mesh mesh;
  mesh.vertices = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  const std::array<std::array<VertexIndex, 3>, 8> faces{
      {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}}};
  std::map<std::pair<VertexIndex, VertexIndex>, VertexIndex> middle;
  const auto midpoint = [&](VertexIndex a, VertexIndex b) {
    const auto key = std::minmax(a, b);
    if (const auto it = middle.find(key); it != middle.end()) return it->second;
    const Point3& p = mesh.vertices[a];
    const Point3& q = mesh.vertices[b];
    Point3 m{(p[0] + q[0]) / 2, (p[1] + q[1]) / 2, (p[2] + q[2]) / 2};
    const double length = std::sqrt(m[0] * m[0] + m[1] * m[1] + m[2] * m[2]);
    for (double& x : m)
      x /= length;
    const auto index = static_cast<VertexIndex>(mesh.vertices.size());
    mesh.vertices.push_back(m);
    middle.emplace(key, index);
    return index;
  };
  for (const auto& f : faces) {
    const VertexIndex ab = midpoint(f[0], f[1]), bc = midpoint(f[1], f[2]),
                      ca = midpoint(f[2], f[0]);
    for (const auto& t : std::array<std::array<VertexIndex, 3>, 4>{
             {{f[0], ab, ca}, {ab, f[1], bc}, {ca, bc, f[2]}, {ab, bc, ca}}}) {
      mesh.faces.push_back(mesh::make_triangle(t[0], t[1], t[2]));
    }
  }
  for (Point3& v : mesh.vertices) {
    for (double& x : v)
      x = std::ldexp(x + jitter(rng), k);
  }
  return mesh;
}

struct Tally {
  std::size_t compared = 0;
  std::size_t inside = 0;
  std::size_t undecided = 0;
};

class OpenTriangles : public ::testing::TestWithParam<int> {};

TEST_P(OpenTriangles, LabelsAreThoseOfTheDefinition) {
  const int k = GetParam();
  auto rng = testing::seeded_engine("inside.open.triangles." + std::to_string(k));
  std::uniform_real_distribution<double> anywhere(-1.3, 1.3), unit(0.0, 1.0);
  // Extreme magnitudes take the exact stages for many signs: fewer points there. Meshes
  // and points scale with the effort (tests/support/seed.hpp), at least one mesh of each
  // number of holes.
  const int meshes = static_cast<int>(testing::scaled_trials(6, 3));
  const int points = static_cast<int>(testing::scaled_trials(k == 0 ? 120 : 40, 10));
  Tally tally;
  for (int m = 0; m < meshes; ++m) {
    Mesh mesh = subdivided_octahedron(rng, k);
    // Cut 1 to 3 faces out.
    std::vector<mesh::Face> removed;
    const int holes = 1 + m % 3;
    for (int h = 0; h < holes; ++h) {
      const auto f = std::uniform_int_distribution<std::size_t>(0, mesh.faces.size() - 1)(rng);
      removed.push_back(mesh.faces[f]);
      mesh.faces.erase(mesh.faces.begin() + static_cast<std::ptrdiff_t>(f));
    }
    const std::vector<Triangle> triangles = triangles_of(mesh);
    std::vector<Point3> queries;
    for (int p = 0; p < points; ++p) {
      queries.push_back({std::ldexp(anywhere(rng), k), std::ldexp(anywhere(rng), k),
                         std::ldexp(anywhere(rng), k)});
    }
    for (const mesh::Face& f : removed) {
      // Near the hole: its centroid moved along the axis through the centre, by a little.
      const Point3& a = mesh.vertices[f.corners[0]];
      const Point3& b = mesh.vertices[f.corners[1]];
      const Point3& c = mesh.vertices[f.corners[2]];
      for (int p = 0; p < 6; ++p) {
        const double s = 1.0 + (unit(rng) - 0.5) * std::ldexp(1.0, -2 * p);
        queries.push_back({s * (a[0] + b[0] + c[0]) / 3, s * (a[1] + b[1] + c[1]) / 3,
                           s * (a[2] + b[2] + c[2]) / 3});
      }
    }
    for (int p = 0; p < 6; ++p)
      queries.push_back({std::ldexp(8 * anywhere(rng), k), std::ldexp(anywhere(rng), k), 0.0});

    for (const FillRule rule : {FillRule::nonzero, FillRule::positive}) {
      const Classifier classifier(mesh, with(rule));
      const Classifier every_face(mesh, with(rule, CandidateSearch::brute_force));
      ASSERT_TRUE(classifier.open());
      for (const Point3& p : queries) {
        const auto want = expected(rule, testing::generalized_winding_oracle(p, triangles, 0.5),
                                   testing::generalized_winding_oracle(p, triangles, -0.5));
        const Location got = classifier.classify(p);
        ASSERT_EQ(every_face.classify(p), got) << hex(p);
        ASSERT_NE(got, Location::boundary) << hex(p);
        if (want) {
          ASSERT_EQ(to_string(got), to_string(*want))
              << "point " << hex(p) << ", rule " << to_string(rule) << ", mesh " << m;
          ++tally.compared;
          tally.inside += got == Location::inside;
        }
        tally.undecided += got == Location::undecided;
      }
    }
  }
  EXPECT_EQ(tally.undecided, 0u);
  EXPECT_GT(tally.inside, tally.compared / 10);
  EXPECT_GT(tally.compared - tally.inside, tally.compared / 10);
}

/// Whether `w` (the oracle's w rounded to a double) lies in the certified bounds, which
/// then hold that double too (rounding to nearest is monotone and keeps doubles), and
/// the bounds are as narrow as promised.
::testing::AssertionResult holds(const std::optional<Enclosure>& bounds, double w) {
  if (!bounds) return ::testing::AssertionFailure() << "no bounds, w = " << w;
  if (!(bounds->lower <= w && w <= bounds->upper)) {
    return ::testing::AssertionFailure() << std::hexfloat << "w = " << w << " outside ["
                                         << bounds->lower << ", " << bounds->upper << "]";
  }
  // 2^-40 for the boundary term, then the sum with S rounded outward.
  if (bounds->upper - bounds->lower > 0x1p-39) {
    return ::testing::AssertionFailure() << "bounds " << bounds->upper - bounds->lower << " wide";
  }
  return ::testing::AssertionSuccess();
}

TEST_P(OpenTriangles, GeneralizedWindingNumbersHoldTheDefinitionsValue) {
  const int k = GetParam();
  auto rng = testing::seeded_engine("inside.open.triangles.values." + std::to_string(k));
  std::uniform_real_distribution<double> anywhere(-1.3, 1.3);
  std::size_t away_from_integers = 0;
  for (int m = 0; m < 3; ++m) {
    Mesh mesh = subdivided_octahedron(rng, k);
    for (int h = 0; h <= m; ++h)
      mesh.faces.erase(mesh.faces.begin() + 7 * h + 3);
    const std::vector<Triangle> triangles = triangles_of(mesh);
    std::vector<Point3> queries;
    for (int p = 0; p < 60; ++p) {
      queries.push_back({std::ldexp(anywhere(rng), k), std::ldexp(anywhere(rng), k),
                         std::ldexp(anywhere(rng), k)});
    }
    for (int p = 0; p < 6; ++p)  // beyond the box: no ray, the boundary term alone
      queries.push_back({std::ldexp(8 * anywhere(rng), k), std::ldexp(anywhere(rng), k), 0.0});
    const Classifier classifier(mesh);
    std::vector<std::optional<Enclosure>> batch(queries.size());
    generalized_winding_number_batch(classifier, queries, batch, Arithmetic::exact, 3);
    for (std::size_t i = 0; i < queries.size(); ++i) {
      const Point3& p = queries[i];
      const double w = testing::generalized_winding_oracle(p, triangles);
      const std::optional<Enclosure> bounds = classifier.generalized_winding_number(p);
      ASSERT_TRUE(holds(bounds, w)) << "point " << hex(p) << ", mesh " << m;
      ASSERT_TRUE(batch[i]);
      EXPECT_EQ(batch[i]->lower, bounds->lower);
      EXPECT_EQ(batch[i]->upper, bounds->upper);
      away_from_integers += std::abs(w - std::round(w)) > 0.01;
    }
  }
  EXPECT_GT(away_from_integers, 100u);  // the values are not just the crossings
}

INSTANTIATE_TEST_SUITE_P(Scales, OpenTriangles, ::testing::Values(0, 1000, -1000),
                         exactgeo::testing::scale_name);

TEST(OpenPatches, LabelsAndValuesAreThoseOfTheDecomposition) {
  auto rng = testing::seeded_engine("inside.open.patches");
  std::uniform_real_distribution<double> jitter(-0.2, 0.2), anywhere(-0.3, 1.3);
  Tally tally;
  for (int m = 0; m < 6; ++m) {
    // The unit cube's corners moved: skew patches.
    std::array<Point3, 8> corners = testing::unit_cube_corners();
    for (Point3& c : corners) {
      for (double& x : c)
        x += jitter(rng);
    }
    Mesh mesh;
    mesh.vertices.assign(corners.begin(), corners.end());
    const std::size_t cut = static_cast<std::size_t>(m);
    std::vector<BilinearPatch> patches;
    std::vector<testing::Segment> hole;
    for (std::size_t f = 0; f < 6; ++f) {
      const auto& q = testing::kHexahedronFaces[f];
      if (f == cut) {
        // The faces around the hole run its edges the other way.
        for (std::size_t i = 0; i < 4; ++i)
          hole.push_back({corners[q[(i + 1) % 4]], corners[q[i]]});
        continue;
      }
      mesh.faces.push_back(mesh::make_quad(q[0], q[1], q[2], q[3]));
      patches.push_back({corners[q[0]], corners[q[1]], corners[q[2]], corners[q[3]]});
    }
    for (const FillRule rule : {FillRule::nonzero, FillRule::positive}) {
      const Classifier classifier(mesh, with(rule));
      const int points = static_cast<int>(testing::scaled_trials(150, 10));  // every cut face
      for (int p = 0; p < points; ++p) {
        const Point3 q{anywhere(rng), anywhere(rng), anywhere(rng)};
        // The oracle's own ray: the first one every patch answers even or odd along.
        std::optional<std::int64_t> crossings;
        Vector3 ray{};
        bool on_surface = false;
        for (std::size_t r = 0; !crossings && !on_surface; ++r) {
          ray = ray_direction(r);
          std::int64_t s = 0;
          bool clean = true;
          for (const BilinearPatch& patch : patches) {
            const RayPatchCrossings c = testing::ray_patch_signed_crossings_oracle(q, ray, patch);
            on_surface = on_surface || c.parity == RayPatch::origin_on_patch;
            clean = clean && (c.parity == RayPatch::even || c.parity == RayPatch::odd);
            s += to_int(c.signed_count);
          }
          if (clean) crossings = s;
        }
        const Location got = classifier.classify(q);
        if (on_surface) {
          ASSERT_EQ(got, Location::boundary) << hex(q);
          EXPECT_FALSE(classifier.generalized_winding_number(q)) << hex(q);
          continue;
        }
        // The value itself, whatever ray each side took.
        ASSERT_TRUE(holds(classifier.generalized_winding_number(q),
                          testing::decomposed_winding_oracle(q, ray, *crossings, hole)))
            << "point " << hex(q) << ", cut face " << cut;
        const auto want =
            expected(rule, testing::decomposed_winding_oracle(q, ray, *crossings, hole, 0.5),
                     testing::decomposed_winding_oracle(q, ray, *crossings, hole, -0.5));
        if (!want) continue;
        ASSERT_EQ(to_string(got), to_string(*want))
            << "point " << hex(q) << ", rule " << to_string(rule) << ", cut face " << cut;
        ++tally.compared;
        tally.inside += got == Location::inside;
      }
    }
  }
  EXPECT_GT(tally.inside, tally.compared / 10);
  EXPECT_GT(tally.compared - tally.inside, tally.compared / 10);
}

/// The unit cube [0, 1]^3 of quads without the face z = 1.
Mesh open_box() {
  Mesh mesh = testing::scaled_cube(0, false);
  mesh.faces.erase(mesh.faces.begin() + 1);  // {4, 5, 7, 6}: z = upper
  return mesh;
}

TEST(OpenSurface, WindingNumbersOfExactlyOneHalfAreUndecided) {
  // The centre of the missing face sees the other five cover half the sphere: w = 1/2.
  for (const FillRule rule : {FillRule::nonzero, FillRule::positive}) {
    const Classifier classifier(open_box(), with(rule));
    EXPECT_EQ(classifier.classify({0.5, 0.5, 1.0}), Location::undecided);
    EXPECT_EQ(classifier.classify({0.5, 0.5, 0.5}), Location::inside);
    EXPECT_EQ(classifier.classify({0.5, 0.5, 1.5}), Location::outside);
    EXPECT_EQ(classifier.classify({0.5, 0.5, -0.5}), Location::outside);
    // One ulp above and below the missing face's centre: decided, by more precision.
    EXPECT_EQ(classifier.classify({0.5, 0.5, std::nextafter(1.0, 0.0)}), Location::inside);
    EXPECT_EQ(classifier.classify({0.5, 0.5, std::nextafter(1.0, 2.0)}), Location::outside);
  }
}

TEST(OpenSurface, GeneralizedWindingNumbersOfKnownPoints) {
  const Classifier classifier(open_box());
  // The five faces seen from the centre: 5/6 of the sphere. The missing face's centre:
  // half of it. Above the hole at height d, the missing square's own solid angle
  // 4 asin(1 / (1 + 4 d^2)) over 4 pi (the closed cube's w = 0 there, less the face's
  // share, which is negative seen from outside).
  EXPECT_TRUE(holds(classifier.generalized_winding_number({0.5, 0.5, 0.5}), 5.0 / 6.0));
  EXPECT_TRUE(holds(classifier.generalized_winding_number({0.5, 0.5, 1.0}), 0.5));
  const double d = 0.75;
  const double above = std::asin(1.0 / (1.0 + 4 * d * d)) / std::numbers::pi;
  // (The bounds are up to 2^-40 wide, the first stage's when narrow enough; asin's and the
  // quotient's few ulps lie far inside them.)
  EXPECT_TRUE(holds(classifier.generalized_winding_number({0.5, 0.5, 1.0 + d}), above));
  // On a face or a boundary edge: no value.
  EXPECT_FALSE(classifier.generalized_winding_number({0.25, 0.5, 0.0}));
  EXPECT_FALSE(classifier.generalized_winding_number({0.25, 0.0, 1.0}));
  // A closed surface: the integer winding number, exactly.
  const Classifier closed(testing::scaled_cube(0, false));
  const auto one = closed.generalized_winding_number({0.5, 0.5, 0.5});
  ASSERT_TRUE(one);
  EXPECT_EQ(one->lower, 1.0);
  EXPECT_EQ(one->upper, 1.0);
  EXPECT_FALSE(closed.generalized_winding_number({0.5, 0.5, 1.0}));
}

TEST(OpenSurface, PointsOnTheBoundaryAreBoundary) {
  const Classifier classifier(open_box());
  EXPECT_EQ(classifier.classify({0.25, 0.0, 1.0}), Location::boundary);
  EXPECT_EQ(classifier.classify({1.0, 1.0, 1.0}), Location::boundary);
  EXPECT_EQ(classifier.classify({0.25, 0.5, 0.0}), Location::boundary);
}

TEST(OpenSurface, AZeroAreaFaceOnItsOwnIsNotSurface) {
  // A flat triangle on three collinear points, far from an open box: dropped, and its
  // edges no part of the box's boundary (a loop of zero solid angle). A point beyond the
  // box whose ray away from it would run along the segment is answered, and a point on
  // the segment is labelled as without it: outside (once `boundary`, while the same point
  // beside a closed box was outside).
  Mesh mesh = open_box();
  const auto base = static_cast<VertexIndex>(mesh.vertices.size());
  mesh.vertices.insert(mesh.vertices.end(), {{5, 0.5, 0.5}, {7, 0.5, 0.5}, {6, 0.5, 0.5}});
  mesh.faces.push_back(mesh::make_triangle(base, base + 1, base + 2));
  const Classifier classifier(mesh);
  EXPECT_EQ(classifier.zero_area_faces().count, 1u);
  EXPECT_EQ(classifier.classify({4, 0.5, 0.5}), Location::outside);
  EXPECT_EQ(classifier.classify({8, 0.5, 0.5}), Location::outside);
  EXPECT_EQ(classifier.classify({5.5, 0.5, 0.5}), Location::outside);
  EXPECT_EQ(classifier.classify({0.5, 0.5, 0.5}), Location::inside);
}

TEST(OpenSurface, StackedBowlsHoldPointsBeyondTheirBox) {
  // Nine copies of the open box (as triangles, for the oracle): just below its bottom, w is
  // about -9 times the missing face's solid angle over 4 pi, below -1/2. The point is
  // outside the box, where a closed surface has w = 0 and no ray is needed. (An even number
  // of copies uses every rim edge an even number of times, all one way: the checks cannot
  // tell that from a closed surface with turned faces, and the winding rules refuse it.)
  Mesh one = testing::scaled_cube(0, true);
  one.faces.erase(one.faces.begin() + 2, one.faces.begin() + 4);  // z = upper
  Mesh stacked = one;
  for (int copy = 1; copy < 9; ++copy)
    stacked.faces.insert(stacked.faces.end(), one.faces.begin(), one.faces.end());
  const std::vector<Triangle> triangles = triangles_of(stacked);
  const Point3 below{0.5, 0.5, -0.01};
  const double w = testing::generalized_winding_oracle(below, triangles);
  ASSERT_LT(w, -0.5);
  EXPECT_EQ(Classifier(stacked, with(FillRule::nonzero)).classify(below), Location::inside);
  EXPECT_EQ(Classifier(stacked, with(FillRule::positive)).classify(below), Location::outside);
  EXPECT_EQ(Classifier(one, with(FillRule::nonzero)).classify(below), Location::outside);
}

TEST(OpenSurface, ThePlainDoubleBaselineAgreesAwayFromTheLevels) {
  auto rng = testing::seeded_engine("inside.open.double");
  const Mesh mesh = subdivided_octahedron(rng, 0);
  Mesh open = mesh;
  open.faces.erase(open.faces.begin() + 5);
  const Classifier classifier(open);
  std::uniform_real_distribution<double> anywhere(-1.6, 1.6);
  std::size_t agree = 0;
  const int points = 300;
  for (int p = 0; p < points; ++p) {
    const Point3 q{anywhere(rng), anywhere(rng), anywhere(rng)};
    agree += classifier.classify(q, Arithmetic::plain_double) == classifier.classify(q);
  }
  EXPECT_GT(agree, points * 95 / 100);
}

}  // namespace
}  // namespace exactgeo::inside::open_surface
