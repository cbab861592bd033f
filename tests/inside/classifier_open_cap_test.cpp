// The cap route of an open surface's labels (classifier.hpp): w = S - w_Cap, S the signed
// crossings of a ray with F and the cap triangles (exactgeo/predicates/cap_tree.hpp)
// together, w_Cap enclosed between two half-integers. Checked against the 512-bit
// solid-angle oracle (support/solid_angle_oracle.hpp), at 2^0 and 2^+-1000, with the
// scratch's counters saying which route each label took:
//   - points anywhere near a sphere with holes take the cap (and agree with the oracle
//     and with every face and every cap triangle tried);
//   - a point on a cap triangle but not on F is not boundary: the cone's term labels it;
//   - a ray through a cap triangle's edge (F's crossings clean) is cast again;
//   - the cone's tree, built on first use, gives the same labels from four threads.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <optional>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "exactgeo/inside/batch.hpp"
#include "exactgeo/inside/classifier.hpp"
#include "exactgeo/inside/fill_rule.hpp"
#include "exactgeo/inside/location.hpp"
#include "exactgeo/predicates/cap_tree.hpp"
#include "exactgeo/predicates/ray_directions.hpp"
#include "open_meshes.hpp"
#include "oracle_triangles.hpp"
#include "support/hexfloat.hpp"
#include "support/scale_names.hpp"
#include "support/seed.hpp"
#include "support/solid_angle_oracle.hpp"

namespace exactgeo::inside::open_cap {
namespace {

using mesh::Mesh;
using testing::hex;
using testing::Triangle;

/// The rule's label from the oracle's w - 1/2 and w + 1/2; nullopt too near a level.
std::optional<Location> oracle_label(FillRule rule, const Point3& p,
                                     const std::vector<Triangle>& triangles) {
  constexpr double kTooNear = 0x1p-400;
  const double above_half = testing::generalized_winding_oracle(p, triangles, 0.5);
  if (std::abs(above_half) < kTooNear) return std::nullopt;
  if (rule == FillRule::positive) return above_half > 0 ? Location::inside : Location::outside;
  const double above_minus_half = testing::generalized_winding_oracle(p, triangles, -0.5);
  if (std::abs(above_minus_half) < kTooNear) return std::nullopt;
  return above_half > 0 || above_minus_half < 0 ? Location::inside : Location::outside;
}

ClassifierOptions with(FillRule rule, CandidateSearch candidates) {
  ClassifierOptions options;
  options.rule = rule;
  options.candidates = candidates;
  options.space_cells = false;  // every point through classify_open's rays
  return options;
}

Point3 times(const Point3& p, int k) {
  return {std::ldexp(p[0], k), std::ldexp(p[1], k), std::ldexp(p[2], k)};
}

/// The box [0, 4]^2 x [0, 4] of triangles without its top, its corner (0, 4, 4) raised to
/// (0, 4, 7) (the walls x = 0 and y = 4 stay flat): a rim of four edges, not flat, so
/// that w on its cap is not 1/2. Scaled by 2^k.
Mesh raised_open_box(int k) {
  Mesh mesh;
  mesh.vertices = {{0, 0, 0}, {4, 0, 0}, {4, 4, 0}, {0, 4, 0},
                   {0, 0, 4}, {4, 0, 4}, {4, 4, 4}, {0, 4, 7}};
  const std::array<std::array<VertexIndex, 4>, 5> quads{{
      {0, 3, 2, 1},  // bottom, facing down
      {0, 1, 5, 4},  // y = 0
      {1, 2, 6, 5},  // x = 4
      {2, 3, 7, 6},  // y = 4
      {3, 0, 4, 7},  // x = 0
  }};
  for (const auto& q : quads) {
    mesh.faces.push_back(mesh::make_triangle(q[0], q[1], q[2]));
    mesh.faces.push_back(mesh::make_triangle(q[0], q[2], q[3]));
  }
  for (Point3& v : mesh.vertices)
    v = times(v, k);
  return mesh;
}

class OpenCap : public ::testing::TestWithParam<int> {};

TEST_P(OpenCap, LabelsNearASphereWithHolesComeFromTheCap) {
  const int k = GetParam();
  auto rng = testing::seeded_engine("inside.open.cap.sphere." + std::to_string(k));
  const Mesh mesh = testing::scaled(testing::holed_sphere(rng, 12, 16), k);
  const std::vector<Triangle> triangles = testing::triangles_of(mesh);
  std::uniform_real_distribution<double> box(-1.05, 1.05), beyond(-3.0, 3.0);
  std::vector<Point3> points;
  for (int i = 0; i < 60; ++i)
    points.push_back(times({box(rng), box(rng), box(rng)}, k));
  for (int i = 0; i < 10; ++i)  // most beyond the box: S = 0 there, w = -w_Cap
    points.push_back(times({beyond(rng), beyond(rng), beyond(rng)}, k));
  std::size_t compared = 0, inside = 0;
  for (const FillRule rule : {FillRule::nonzero, FillRule::positive}) {
    const Classifier classifier(mesh, with(rule, CandidateSearch::box_tree));
    const Classifier every_face(mesh, with(rule, CandidateSearch::brute_force));
    ASSERT_TRUE(classifier.open());
    ClassifierScratch scratch, every_scratch;
    for (const Point3& p : points) {
      const Location got = classifier.classify(p, Arithmetic::exact, scratch);
      ASSERT_EQ(every_face.classify(p, Arithmetic::exact, every_scratch), got) << hex(p);
      const std::optional<Location> want = oracle_label(rule, p, triangles);
      if (!want) continue;
      ASSERT_EQ(to_string(got), to_string(*want)) << hex(p) << ", rule " << to_string(rule);
      ++compared;
      inside += got == Location::inside;
    }
    // Near a level only (the cap's enclosure too near a half-integer) is the cone asked.
    EXPECT_GE(scratch.routes.cap, points.size() * 9 / 10);
    EXPECT_EQ(scratch.routes.cap + scratch.routes.cone, points.size());
    EXPECT_EQ(scratch.routes.on_cap, 0u);
  }
  EXPECT_GT(compared, 100u);
  EXPECT_GT(inside, compared / 10);
  EXPECT_GT(compared - inside, compared / 10);
}

/// The raised box's two cap triangles (as the classifier builds them: same chain, same
/// halving) and the diagonal they share.
struct Cap {
  std::vector<std::array<Point3, 3>> triangles;
  std::array<Point3, 2> diagonal;
};

Cap cap_of(const Mesh& mesh, const Classifier& classifier) {
  const CapTree tree(mesh.vertices, classifier.boundary());
  Cap cap;
  for (const CapTriangle& t : tree.triangles())
    cap.triangles.push_back({mesh.vertices[t.a], mesh.vertices[t.b], mesh.vertices[t.c]});
  EXPECT_EQ(cap.triangles.size(), 2u);
  // The corners the two share.
  std::vector<Point3> shared;
  for (const Point3& a : cap.triangles[0]) {
    for (const Point3& b : cap.triangles[1]) {
      if (a == b) shared.push_back(a);
    }
  }
  EXPECT_EQ(shared.size(), 2u);
  cap.diagonal = {shared[0], shared[1]};
  return cap;
}

/// sum w_i x_i / 8, exact for these small coordinates (times a power of two).
Point3 combination(const std::vector<std::pair<int, Point3>>& terms) {
  Point3 p{0, 0, 0};
  for (const auto& [w, x] : terms) {
    for (int i = 0; i < 3; ++i)
      p[i] += w * x[i];
  }
  for (double& x : p)
    x /= 8;
  return p;
}

/// `each` points inside each of the cap's triangles (weights 1 to 6 of its corners,
/// summing to 8: exact at every scale).
std::vector<Point3> points_on_cap(const Cap& cap, int each, std::mt19937_64& rng) {
  std::uniform_int_distribution<int> weight(1, 6);
  std::vector<Point3> points;
  for (const auto& t : cap.triangles) {
    for (int i = 0; i < each; ++i) {
      const int a = weight(rng);
      const int b = std::uniform_int_distribution<int>(1, 7 - a)(rng);
      points.push_back(combination({{a, t[0]}, {b, t[1]}, {8 - a - b, t[2]}}));
    }
  }
  return points;
}

TEST_P(OpenCap, APointOnACapTriangleIsLabelledByTheCone) {
  const int k = GetParam();
  auto rng = testing::seeded_engine("inside.open.cap.on_cap." + std::to_string(k));
  const Mesh mesh = raised_open_box(k);
  const std::vector<Triangle> triangles = testing::triangles_of(mesh);
  std::size_t compared = 0;
  for (const FillRule rule : {FillRule::nonzero, FillRule::positive}) {
    for (const CandidateSearch search : {CandidateSearch::box_tree, CandidateSearch::brute_force}) {
      const Classifier classifier(mesh, with(rule, search));
      const Cap cap = cap_of(mesh, classifier);
      std::vector<Point3> points = points_on_cap(cap, 8, rng);
      for (int i = 1; i < 8; ++i)  // on the diagonal between them (no edge of F)
        points.push_back(combination({{i, cap.diagonal[0]}, {8 - i, cap.diagonal[1]}}));
      ClassifierScratch scratch;
      for (const Point3& p : points) {
        const std::size_t on_cap = scratch.routes.on_cap, cone = scratch.routes.cone;
        const Location got = classifier.classify(p, Arithmetic::exact, scratch);
        ASSERT_NE(got, Location::boundary) << hex(p);
        EXPECT_EQ(scratch.routes.on_cap, on_cap + 1) << hex(p);
        EXPECT_EQ(scratch.routes.cone, cone + 1) << hex(p);
        const std::optional<Location> want = oracle_label(rule, p, triangles);
        if (!want) continue;
        ASSERT_EQ(to_string(got), to_string(*want)) << hex(p) << ", rule " << to_string(rule);
        ++compared;
      }
      EXPECT_EQ(scratch.routes.cap, 0u);
    }
  }
  EXPECT_GT(compared, 80u);  // of 92
}

TEST_P(OpenCap, TheConesTreeBuiltOnFirstUseAnswersAlikeFromManyThreads) {
  // Points on cap triangles take the cone, whose tree the classifier builds on first use:
  // four threads asking a fresh classifier at once give the labels one thread gives (and
  // the oracle's).
  const int k = GetParam();
  auto rng = testing::seeded_engine("inside.open.cap.lazy_tree." + std::to_string(k));
  const Mesh mesh = raised_open_box(k);
  const std::vector<Triangle> triangles = testing::triangles_of(mesh);
  const std::vector<Point3> points = points_on_cap(
      cap_of(mesh, Classifier(mesh, with(FillRule::nonzero, CandidateSearch::box_tree))), 32, rng);
  const Classifier one(mesh, with(FillRule::nonzero, CandidateSearch::box_tree));
  const Classifier many(mesh, with(FillRule::nonzero, CandidateSearch::box_tree));
  std::vector<Location> alone(points.size()), together(points.size());
  classify_batch(one, points, alone, Arithmetic::exact, 1);
  classify_batch(many, points, together, Arithmetic::exact, 4);
  std::size_t compared = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    ASSERT_EQ(to_string(together[i]), to_string(alone[i])) << hex(points[i]);
    ASSERT_NE(alone[i], Location::boundary) << hex(points[i]);
    const std::optional<Location> want = oracle_label(FillRule::nonzero, points[i], triangles);
    if (!want) continue;
    ASSERT_EQ(to_string(alone[i]), to_string(*want)) << hex(points[i]);
    ++compared;
  }
  EXPECT_GT(compared, 50u);
}

TEST_P(OpenCap, ARayThroughACapTrianglesEdgeIsCastAgain) {
  const int k = GetParam();
  auto rng = testing::seeded_engine("inside.open.cap.edge_ray." + std::to_string(k));
  const Mesh mesh = raised_open_box(k);
  const std::vector<Triangle> triangles = testing::triangles_of(mesh);
  // Ray 0 from p = q - d0 / 2 passes q, a point of the cap's diagonal with x >= 1, and
  // leaves the box above its walls: F's crossings are clean, the cap's meet an edge.
  const Vector3 d = ray_direction(0);
  std::uniform_int_distribution<int> weight(2, 6);
  std::size_t compared = 0;
  for (const FillRule rule : {FillRule::nonzero, FillRule::positive}) {
    for (const CandidateSearch search : {CandidateSearch::box_tree, CandidateSearch::brute_force}) {
      const Classifier classifier(mesh, with(rule, search));
      const Cap cap = cap_of(mesh, classifier);
      ClassifierScratch scratch;
      for (int i = 0; i < 12; ++i) {
        // The diagonal's end with the larger x weighted at least 2 of 8: x >= 1 (times 2^k).
        const auto [far, near] = cap.diagonal[0][0] > cap.diagonal[1][0]
                                     ? std::pair{cap.diagonal[0], cap.diagonal[1]}
                                     : std::pair{cap.diagonal[1], cap.diagonal[0]};
        const int w = weight(rng);
        const Point3 q = combination({{w, far}, {8 - w, near}});
        Point3 p = q;
        for (int j = 0; j < 3; ++j)
          p[j] -= std::ldexp(d[j] / 2, k);
        const std::size_t again = scratch.routes.cap_degenerate_rays, by_cap = scratch.routes.cap;
        const Location got = classifier.classify(p, Arithmetic::exact, scratch);
        EXPECT_GE(scratch.routes.cap_degenerate_rays, again + 1) << hex(p);
        EXPECT_EQ(scratch.routes.cap, by_cap + 1) << hex(p);
        const std::optional<Location> want = oracle_label(rule, p, triangles);
        if (!want) continue;
        ASSERT_EQ(to_string(got), to_string(*want)) << hex(p) << ", rule " << to_string(rule);
        ++compared;
      }
    }
  }
  EXPECT_GT(compared, 30u);
}

INSTANTIATE_TEST_SUITE_P(Scales, OpenCap, ::testing::Values(0, 1000, -1000),
                         exactgeo::testing::scale_name);

}  // namespace
}  // namespace exactgeo::inside::open_cap
