// Classifying many points at once (batch.hpp): every batch, on any number of threads (one,
// a few, more than there are blocks of points, one per hardware thread), gives each point
// the answer of its own call, and that answer is the truth of solids known by
// construction: a cube and two overlapping cubes (winding number 2 in the overlap), on a
// grid of half-integer points (many on faces, edges and corners) and random ones, over
// several blocks. Spans of different sizes are refused; empty ones are fine.

#include "exactgeo/inside/batch.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <optional>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "exactgeo/inside/classifier.hpp"
#include "exactgeo/inside/float_ray_parity.hpp"
#include "exactgeo/inside/location.hpp"
#include "inside/scaled_cube.hpp"
#include "support/seed.hpp"

namespace exactgeo::inside {
namespace {

using mesh::Mesh;
using testing::cube_truth;
using testing::hex;

constexpr unsigned kThreadCounts[] = {1, 2, 3, 64, 0};

/// Points of [-1, 3]^3 on a grid of halves (9^3, many of them on the cube [0, 2]^3's faces,
/// edges and corners), then random ones in [-1, 3]^3: more than four blocks of 512.
std::vector<Point3> probes(std::mt19937_64& rng) {
  std::vector<Point3> points;
  for (int i = -2; i <= 6; ++i) {
    for (int j = -2; j <= 6; ++j) {
      for (int k = -2; k <= 6; ++k)
        points.push_back({i / 2.0, j / 2.0, k / 2.0});
    }
  }
  std::uniform_real_distribution<double> anywhere(-1.0, 3.0);
  while (points.size() < 2500)
    points.push_back({anywhere(rng), anywhere(rng), anywhere(rng)});
  return points;
}

/// The cube [lower, lower + 2]^3 as six outward quads, appended to `mesh`.
void add_cube(Mesh& mesh, double lower) {
  const Mesh cube = testing::scaled_cube(1, false);
  const auto base = static_cast<VertexIndex>(mesh.vertices.size());
  for (const Point3& v : cube.vertices)
    mesh.vertices.push_back({v[0] + lower, v[1] + lower, v[2] + lower});
  for (mesh::Face f : cube.faces) {
    for (VertexIndex& c : f.corners)
      c += base;
    mesh.faces.push_back(f);
  }
}

/// The winding number of p against cubes [l, l + 2]^3 for each l in `lowers` (outward):
/// nullopt on any cube's surface, else the number of cubes holding p.
std::optional<std::int64_t> winding_truth(const Point3& p, std::initializer_list<double> lowers) {
  std::int64_t w = 0;
  for (const double l : lowers) {
    const Point3 q{p[0] - l, p[1] - l, p[2] - l};  // exact: halves and small shifts
    const Location where = cube_truth(q, 1);
    if (where == Location::boundary) return std::nullopt;
    w += where == Location::inside;
  }
  return w;
}

TEST(Batch, LocationsAreTheTruthOnEveryThreadCount) {
  auto rng = testing::seeded_engine("inside.batch.cube");
  const std::vector<Point3> points = probes(rng);
  Mesh mesh;
  add_cube(mesh, 0.0);
  const Classifier classifier(mesh);
  for (const Arithmetic arithmetic : {Arithmetic::exact, Arithmetic::plain_double}) {
    std::vector<Location> one_by_one(points.size());
    for (std::size_t i = 0; i < points.size(); ++i)
      one_by_one[i] = classifier.classify(points[i], arithmetic);
    for (const unsigned threads : kThreadCounts) {
      std::vector<Location> batch(points.size(), Location::undecided);
      classify_batch(classifier, points, batch, arithmetic, threads);
      ASSERT_EQ(batch, one_by_one) << threads << " threads";
    }
    if (arithmetic != Arithmetic::exact) continue;
    for (std::size_t i = 0; i < points.size(); ++i)
      ASSERT_EQ(one_by_one[i], cube_truth(points[i], 1)) << hex(points[i]);
  }
}

TEST(Batch, WindingNumbersOfOverlappingCubesOnEveryThreadCount) {
  auto rng = testing::seeded_engine("inside.batch.overlap");
  const std::vector<Point3> points = probes(rng);
  Mesh mesh;
  add_cube(mesh, 0.0);
  add_cube(mesh, 1.0);  // overlapping [1, 2]^3: winding number 2 there
  const Classifier classifier(mesh);
  ASSERT_TRUE(classifier.oriented());
  std::size_t twice = 0;
  for (const unsigned threads : kThreadCounts) {
    std::vector<std::optional<std::int64_t>> windings(points.size(), -7);
    winding_number_batch(classifier, points, windings, Arithmetic::exact, threads);
    for (std::size_t i = 0; i < points.size(); ++i) {
      ASSERT_EQ(windings[i], winding_truth(points[i], {0.0, 1.0}))
          << hex(points[i]) << ", " << threads << " threads";
      twice += windings[i] == 2;
    }
  }
  EXPECT_GT(twice, 0u);
}

TEST(Batch, TheFloatBaselineGivesItsPointByPointLabels) {
  auto rng = testing::seeded_engine("inside.batch.baseline");
  const std::vector<Point3> points = probes(rng);
  Mesh mesh;
  add_cube(mesh, 0.0);
  const FloatRayParity baseline(mesh);
  std::vector<Location> one_by_one(points.size());
  for (std::size_t i = 0; i < points.size(); ++i)
    one_by_one[i] = baseline.classify(points[i]);
  for (const unsigned threads : kThreadCounts) {
    std::vector<Location> batch(points.size(), Location::undecided);
    classify_batch(baseline, points, batch, threads);
    ASSERT_EQ(batch, one_by_one) << threads << " threads";
  }
}

TEST(Batch, SpansOfDifferentSizesAreRefusedAndEmptyOnesAreFine) {
  Mesh mesh;
  add_cube(mesh, 0.0);
  const Classifier classifier(mesh);
  const FloatRayParity baseline(mesh);
  const std::vector<Point3> points(3, Point3{1, 1, 1});
  std::vector<Location> two(2);
  std::vector<std::optional<std::int64_t>> four(4);
  EXPECT_THROW(classify_batch(classifier, points, two, Arithmetic::exact), std::invalid_argument);
  EXPECT_THROW(winding_number_batch(classifier, points, four, Arithmetic::exact),
               std::invalid_argument);
  EXPECT_THROW(classify_batch(baseline, points, two), std::invalid_argument);
  std::vector<Location> none;
  std::vector<std::optional<std::int64_t>> no_windings;
  EXPECT_NO_THROW(classify_batch(classifier, {}, none, Arithmetic::exact));
  EXPECT_NO_THROW(winding_number_batch(classifier, {}, no_windings, Arithmetic::exact));
  EXPECT_NO_THROW(classify_batch(baseline, {}, none));
}

}  // namespace
}  // namespace exactgeo::inside
