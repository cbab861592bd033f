// Real meshes (tests/data/meshes, and the shared data set when present): the Embree
// candidate search gives exactly the labels of the brute-force oracle (every face for
// every ray) on random points and on adversarial ones (vertices, edge midpoints, points on
// patches, points one ulp off them); the meshes in negative/ are refused with the right
// reasons.

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

namespace exactgeo::inside::real_meshes {
namespace {

using mesh::Face;
using mesh::Mesh;

const std::string kMeshes = std::string(EXACTGEO_TEST_DATA_DIR) + "/meshes/";
const std::string kSharedMeshes = std::string(EXACTGEO_SHARED_DATA_DIR) + "/meshes/";

/// Random points in the box, and for random faces: a corner, an edge midpoint, the patch
/// point at (1/2, 1/2) (rounded: near, maybe not on, the patch) and that point moved one
/// ulp each way along x.
std::vector<Point3> test_points(const Mesh& mesh, const mesh::Box& box, std::mt19937_64& rng,
                                std::size_t count) {
  std::vector<Point3> points;
  std::uniform_real_distribution<double> unit(-0.05, 1.05);
  std::uniform_int_distribution<std::size_t> face(0, mesh.faces.size() - 1);
  std::uniform_int_distribution<std::size_t> corner(0, 3);
  while (points.size() < count) {
    Point3 p;
    for (int i = 0; i < 3; ++i)
      p[i] = box.lower[i] + unit(rng) * (box.upper[i] - box.lower[i]);
    points.push_back(p);
    const Face& f = mesh.faces[face(rng)];
    const std::size_t k = corner(rng) % f.size();
    const Point3& a = mesh.vertices[f.corner(k)];
    const Point3& b = mesh.vertices[f.corner(k + 1)];
    points.push_back(a);
    points.push_back({a[0] / 2 + b[0] / 2, a[1] / 2 + b[1] / 2, a[2] / 2 + b[2] / 2});
    const BilinearPatch q = patch_of(mesh, f);
    Point3 centre;
    for (int i = 0; i < 3; ++i)
      centre[i] = (q.p00[i] + q.p10[i] + q.p11[i] + q.p01[i]) / 4;
    points.push_back(centre);
    for (const double toward : {-INFINITY, INFINITY}) {
      Point3 moved = centre;
      moved[0] = std::nextafter(moved[0], toward);
      points.push_back(moved);
    }
  }
  return points;
}

void expect_embree_matches_brute_force(const std::string& path, std::size_t full_count) {
  SCOPED_TRACE(path);
  // Scaled with the effort (tests/support/seed.hpp).
  const std::size_t count = testing::scaled_trials(full_count, 60);
  const Mesh mesh = mesh::load_mesh(path).mesh;
  const Classifier embree(mesh);
  const Classifier brute(mesh, {.candidates = CandidateSearch::brute_force,
                                .allow_non_manifold = false,
                                .space_cells = false});
  auto rng =
      testing::seeded_engine("inside.real_meshes." + std::filesystem::path(path).stem().string());
  const std::vector<Point3> points =
      test_points(mesh, *mesh::check_mesh(mesh).bounding_box, rng, count);

  std::vector<Location> fast(points.size());
  classify_batch(embree, points, fast, Arithmetic::exact, 2);
  std::size_t by_location[3] = {};
  for (std::size_t i = 0; i < points.size(); ++i) {
    ++by_location[static_cast<int>(fast[i])];
    ASSERT_EQ(fast[i], brute.classify(points[i]))
        << "point " << i << ": " << std::hexfloat << points[i][0] << " " << points[i][1] << " "
        << points[i][2];
  }
  // The bundled meshes are embedded, so every rule labels them alike: parity always, and
  // positive where the faces are oriented alike (outward: w = +1 inside).
  std::vector<FillRule> rules{FillRule::parity};
  if (embree.oriented()) rules.push_back(FillRule::positive);
  for (const FillRule rule : rules) {
    ClassifierOptions options;
    options.rule = rule;
    const Classifier by_rule(mesh, options);
    std::vector<Location> labels(points.size());
    classify_batch(by_rule, points, labels, Arithmetic::exact, 2);
    EXPECT_EQ(labels, fast) << to_string(rule) << " and " << to_string(embree.rule());
  }
  // The points exercise all three answers (vertices and midpoints are on the surface).
  EXPECT_GT(by_location[static_cast<int>(Location::inside)], 0u);
  EXPECT_GT(by_location[static_cast<int>(Location::outside)], 0u);
  EXPECT_GT(by_location[static_cast<int>(Location::boundary)], count / 8);
}

/// The README's examples: the C++ snippet (load, check and build, classify) and the points
/// of the command-line example, with Embree and with every face as candidates.
TEST(RealMeshes, ReadmeExamples) {
  mesh::LoadedMesh spot = mesh::load_mesh(kMeshes + "spot/spot_quadrangulated.obj");
  const Classifier brute(spot.mesh, {.candidates = CandidateSearch::brute_force,
                                     .allow_non_manifold = false,
                                     .space_cells = false});
  const Classifier classifier(std::move(spot.mesh));
  for (const Classifier* c : {&classifier, &brute}) {
    EXPECT_EQ(c->classify({0, 0.2, 0}), Location::inside);
    EXPECT_EQ(c->classify({0, 0, 2}), Location::outside);
  }
}

TEST(RealMeshes, EmbreeAgreesWithBruteForceOnBundledMeshes) {
  for (const char* name :
       {"cgal/cube_quad.off", "cgal/torus_quad.off", "cgal/3torus.off", "cgal/cross_quad.off",
        "cgal/corner.off", "negative/cube4-shuffled.off"}) {
    expect_embree_matches_brute_force(kMeshes + name, 600);
  }
  expect_embree_matches_brute_force(kMeshes + "spot/spot_quadrangulated.obj", 1500);
  expect_embree_matches_brute_force(kMeshes + "spot/spot_quad_cc1.ply", 300);
  // Pentagons split into triangles on loading: a closed mesh of quads and triangles.
  expect_embree_matches_brute_force(kMeshes + "spot/spot_control_mesh.obj", 600);
  expect_embree_matches_brute_force(kMeshes + "cgal/double-torus-example.off", 600);
}

TEST(RealMeshes, EmbreeAgreesWithBruteForceOnSharedMeshes) {
  if (!std::filesystem::exists(kSharedMeshes)) GTEST_SKIP() << "no " << kSharedMeshes;
  for (const char* name :
       {"libigl/horse_quad.obj", "quadwild/mnf07HeadFem_rem_rem_p_quadrangulation.obj"}) {
    expect_embree_matches_brute_force(kSharedMeshes + name, 300);
  }
}

/// The reason `exactgeo inside` gives for refusing a mesh.
std::string refusal(const std::string& path) {
  const mesh::MeshCheck check = mesh::check_mesh(mesh::load_mesh(path).mesh);
  return mesh::closed_surface_problem(check).value_or("");
}

/// Spot with closed shells pushed into it, as characters carry eyes and teeth: boxes
/// straddling its surface and one inside it, each a separate closed part. The truth is
/// Spot's own exact winding number plus one for each box holding the point; nonzero labels
/// the union, parity reads the overlaps outside.
TEST(RealMeshes, SpotWithClosedShellsPushedIn) {
  const Mesh spot = mesh::load_mesh(kMeshes + "spot/spot_quadrangulated.obj").mesh;
  const Classifier spot_alone(spot);
  Point3 lower = spot.vertices[0], upper = spot.vertices[0];
  for (const Point3& v : spot.vertices) {
    for (int i = 0; i < 3; ++i) {
      lower[i] = std::min(lower[i], v[i]);
      upper[i] = std::max(upper[i], v[i]);
    }
  }
  // Boxes at fractions of Spot's box (rounded to multiples of 2^-10, so their faces are
  // exact): two across the surface, one well inside.
  const auto at = [&](double fx, double fy, double fz) {
    Point3 p;
    const double f[3] = {fx, fy, fz};
    for (int i = 0; i < 3; ++i)
      p[i] = std::ldexp(std::round(std::ldexp(lower[i] + f[i] * (upper[i] - lower[i]), 10)), -10);
    return p;
  };
  const std::vector<std::array<Point3, 2>> boxes{{at(0.3, 0.3, 0.7), at(0.45, 0.5, 1.05)},
                                                 {at(0.6, 0.05, 0.3), at(0.7, 0.2, 0.45)},
                                                 {at(0.45, 0.45, 0.45), at(0.55, 0.55, 0.55)}};
  Mesh mesh = spot;
  for (const auto& [lo, hi] : boxes) {
    const auto base = static_cast<VertexIndex>(mesh.vertices.size());
    for (int c = 0; c < 8; ++c)
      mesh.vertices.push_back(
          {c & 1 ? hi[0] : lo[0], c & 2 ? hi[1] : lo[1], c & 4 ? hi[2] : lo[2]});
    for (const auto& q : testing::kHexahedronFaces)
      mesh.faces.push_back(mesh::make_quad(base + q[0], base + q[1], base + q[2], base + q[3]));
  }
  const Classifier nonzero(mesh);
  ClassifierOptions parity_options;
  parity_options.rule = FillRule::parity;
  parity_options.allow_non_manifold = true;
  const Classifier parity(mesh, parity_options);
  auto rng = testing::seeded_engine("inside.real.spot_shells");
  std::uniform_real_distribution<double> unit(-0.05, 1.05);
  std::size_t overlaps = 0;
  for (int p = 0; p < 4000; ++p) {
    Point3 q;
    for (int i = 0; i < 3; ++i)
      q[i] = lower[i] + unit(rng) * (upper[i] - lower[i]);
    const auto w_spot = spot_alone.winding_number(q);
    ASSERT_TRUE(w_spot.has_value());
    std::int64_t w = *w_spot;
    for (const auto& [lo, hi] : boxes) {
      bool in = true;
      for (int i = 0; i < 3; ++i)
        in = in && lo[i] < q[i] && q[i] < hi[i];
      w += in;
    }
    ASSERT_EQ(nonzero.winding_number(q), w) << "point " << p;
    ASSERT_EQ(nonzero.classify(q), w != 0 ? Location::inside : Location::outside);
    ASSERT_EQ(parity.classify(q), w % 2 != 0 ? Location::inside : Location::outside);
    overlaps += w == 2;
  }
  EXPECT_GT(overlaps, 0u) << "no point fell where a box overlaps Spot";
}

TEST(RealMeshes, NegativeMeshesAreRefusedForTheRightReason) {
  EXPECT_NE(refusal(kMeshes + "negative/corner_with_hole.off").find("not closed"),
            std::string::npos);
  EXPECT_NE(refusal(kMeshes + "negative/double-torus-3-holes.off").find("not closed"),
            std::string::npos);
  // Orientation does not matter to parity, the default rule's choice for such a mesh;
  // the winding rules refuse it.
  EXPECT_EQ(refusal(kMeshes + "negative/cube4-shuffled.off"), "");
  EXPECT_EQ(Classifier(mesh::load_mesh(kMeshes + "negative/cube4-shuffled.off").mesh).rule(),
            FillRule::parity);
  EXPECT_FALSE(mesh::check_mesh(mesh::load_mesh(kMeshes + "negative/cube4-shuffled.off").mesh)
                   .consistently_oriented.value_or(true));
}

TEST(RealMeshes, SharedNegativeMeshesAreRefusedForTheRightReason) {
  if (!std::filesystem::exists(kSharedMeshes)) GTEST_SKIP() << "no " << kSharedMeshes;
  const std::string negative = kSharedMeshes + "negative/";
  EXPECT_NE(refusal(negative + "inspired_mesh_quads_Conjugate.off").find("not closed"),
            std::string::npos);
  EXPECT_NE(refusal(negative + "suzanne.obj").find("not closed"), std::string::npos);
  EXPECT_NE(refusal(negative + "cube_40k_voxel_faces.obj").find("38400 non-manifold edges"),
            std::string::npos);
  // A quad soup: every edge is a boundary edge until vertices are welded by exact
  // position. Welding joins most of them; 16 edges stay open because their corners differ
  // in the last printed digit, and welding never uses a tolerance.
  const std::string soup = negative + "tref_quad_soup.off";
  EXPECT_EQ(mesh::check_mesh(mesh::load_mesh(soup).mesh).boundary_edges.count, 4u * 320u);
  mesh::LoadOptions weld;
  weld.weld = true;
  const mesh::LoadedMesh welded = mesh::load_mesh(soup, weld);
  EXPECT_EQ(welded.welded_vertices, 952u);
  EXPECT_EQ(mesh::check_mesh(welded.mesh).boundary_edges.count, 16u);
}

}  // namespace
}  // namespace exactgeo::inside::real_meshes
