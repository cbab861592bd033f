// Classifying many points against an open surface (batch.hpp), which visits them in a
// spatial order: every point gets the label of its own call in input order, one call
// each with fresh scratch (no work carried from any other point), on any number of
// threads. A ribbon whose two rims have 1,100 edges each and a wavy sheet with hundreds
// of holes and long slits (both with at least kSpatialOrderEdges boundary edges, so that
// the batch takes the spatial order); points anywhere in the box grown by a fifth, points next to
// rim edges (a relative offset of 2^-20 and 2^-40 from an edge's midpoint) and points beyond the
// box; at 2^0 and 2^+-1000. A sample of the batch's labels is also checked against the
// definition: the solid-angle oracle's w on the same triangles, unscaled.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "exactgeo/inside/batch.hpp"
#include "exactgeo/inside/classifier.hpp"
#include "exactgeo/inside/location.hpp"
#include "open_meshes.hpp"
#include "oracle_label.hpp"
#include "oracle_triangles.hpp"
#include "support/hexfloat.hpp"
#include "support/seed.hpp"

namespace exactgeo::inside::spatial_order {
namespace {

using mesh::Mesh;

constexpr unsigned kThreadCounts[] = {1, 2, 3};

/// Random points in the vertices' box grown by a fifth on each side (some beyond it),
/// then points next to the classifier's rim edges: each edge's midpoint moved by a random
/// offset of relative size 2^-20 or 2^-40.
std::vector<Point3> probes(std::mt19937_64& rng, const Classifier& classifier, std::size_t random) {
  const Mesh& mesh = classifier.mesh();
  Point3 lower = mesh.vertices[0], upper = mesh.vertices[0];
  for (const Point3& v : mesh.vertices) {
    for (int i = 0; i < 3; ++i) {
      lower[i] = std::min(lower[i], v[i]);
      upper[i] = std::max(upper[i], v[i]);
    }
  }
  std::vector<Point3> points;
  std::uniform_real_distribution<double> unit(-0.2, 1.2);
  for (std::size_t k = 0; k < random; ++k) {
    Point3 p;
    for (int i = 0; i < 3; ++i)
      p[i] = lower[i] + unit(rng) * (upper[i] - lower[i]);
    points.push_back(p);
  }
  std::uniform_real_distribution<double> offset(-1.0, 1.0);
  for (const BoundaryEdge& e : classifier.boundary()) {
    const Point3& a = mesh.vertices[e.from];
    const Point3& b = mesh.vertices[e.to];
    for (const int bits : {20, 40}) {
      Point3 p;
      for (int i = 0; i < 3; ++i) {
        const double size = std::ldexp(upper[i] - lower[i], -bits);
        p[i] = a[i] / 2 + b[i] / 2 + offset(rng) * size;
      }
      points.push_back(p);
    }
  }
  return points;
}

/// Points of the batch checked against the definition (the oracle integrates every
/// triangle for each, so a sample): every kOracleEvery-th.
constexpr std::size_t kOracleEvery = 320;

/// Every point's label from classify_batch equals its own call's, on every thread count,
/// and, on a sample, the label of the generalized winding number's definition (`unscaled`:
/// the mesh before its scaling by 2^scale, whose triangles the oracle integrates). The
/// `random` points scale with the effort (tests/support/seed.hpp); the points next to the
/// rim edges are all kept.
void expect_batch_equals_one_by_one(const Mesh& unscaled, int scale, std::mt19937_64& rng,
                                    std::size_t random) {
  const Mesh mesh = testing::scaled(unscaled, scale);
  const Classifier classifier(mesh);
  ASSERT_TRUE(classifier.open());
  ASSERT_GE(classifier.boundary().size(), kSpatialOrderEdges);
  const std::vector<Point3> points = probes(rng, classifier, testing::scaled_trials(random));
  std::vector<Location> one_by_one(points.size());
  for (std::size_t i = 0; i < points.size(); ++i)
    one_by_one[i] = classifier.classify(points[i], Arithmetic::exact);
  for (const unsigned threads : kThreadCounts) {
    std::vector<Location> batch(points.size(), Location::boundary);
    classify_batch(classifier, points, batch, Arithmetic::exact, threads);
    for (std::size_t i = 0; i < points.size(); ++i) {
      ASSERT_EQ(batch[i], one_by_one[i])
          << "point " << i << " " << testing::hex(points[i]) << ", " << threads << " threads";
    }
    if (threads != kThreadCounts[0]) continue;
    const std::vector<testing::Triangle> triangles = testing::triangles_of(unscaled);
    std::size_t compared = 0;
    for (std::size_t i = 0; i < points.size(); i += kOracleEvery) {
      if (batch[i] == Location::boundary) continue;  // the oracle needs a point off the faces
      Point3 p = points[i];
      for (double& x : p)
        x = std::ldexp(x, -scale);  // exact: the points are normal doubles at every scale
      const auto want = testing::label_from_oracle(
          classifier.rule(), testing::generalized_winding_oracle(p, triangles, 0.5));
      if (!want) continue;
      ASSERT_EQ(to_string(batch[i]), to_string(*want))
          << "point " << i << " " << testing::hex(points[i]);
      ++compared;
    }
    EXPECT_GE(compared, points.size() / kOracleEvery / 2) << "too few points the oracle could tell";
  }
}

class SpatialOrder : public ::testing::TestWithParam<int> {};

TEST_P(SpatialOrder, RibbonBatchEqualsEachPointsOwnCall) {
  const int scale = GetParam();
  auto rng = testing::seeded_engine("inside.batch_order.ribbon." + std::to_string(scale));
  expect_batch_equals_one_by_one(testing::triangulated(testing::ribbon(1100)), scale, rng, 3000);
}

TEST_P(SpatialOrder, PerforatedSheetBatchEqualsEachPointsOwnCall) {
  const int scale = GetParam();
  auto rng = testing::seeded_engine("inside.batch_order.sheet." + std::to_string(scale));
  expect_batch_equals_one_by_one(testing::triangulated(testing::perforated_sheet(rng, 56, 14)),
                                 scale, rng, 3000);
}

INSTANTIATE_TEST_SUITE_P(Scales, SpatialOrder, ::testing::Values(0, 1000, -1000));

}  // namespace
}  // namespace exactgeo::inside::spatial_order
