// Certified space cells against rays: wherever a cell answers, its label must be the
// exact label of the point by rays without cells (brute force where it is affordable),
// for random points, points exactly on the grid's planes, edges and corners, and one ulp
// off them, at magnitudes 1, 2^+-1000 and subnormal; points on faces must never be
// answered by a cell. The classifier with cells on must give the labels it gives with
// cells off.

#include "exactgeo/inside/internal/space_cells.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "exactgeo/inside/classifier.hpp"
#include "exactgeo/inside/location.hpp"
#include "exactgeo/mesh/check.hpp"
#include "exactgeo/mesh/load.hpp"
#include "inside/polycube.hpp"
#include "support/generators.hpp"
#include "support/seed.hpp"

namespace exactgeo::inside {
namespace {

using internal::SpaceCells;
using mesh::Mesh;

const std::string kMeshes = EXACTGEO_TEST_DATA_DIR "/meshes/";

Mesh scaled_mesh(Mesh mesh, int k, double shift) {
  for (Point3& v : mesh.vertices) {
    for (double& x : v)
      x = std::ldexp(x, k) + shift;
  }
  return mesh;
}

/// A point uniform in the box (per coordinate, between the bounds).
Point3 random_in(const mesh::Box& box, std::mt19937_64& rng) {
  Point3 p;
  for (int i = 0; i < 3; ++i)
    p[i] = std::clamp(box.lower[i] + (box.upper[i] - box.lower[i]) *
                                         std::uniform_real_distribution<double>(0, 1)(rng),
                      box.lower[i], box.upper[i]);
  return p;
}

struct Tally {
  std::size_t probes = 0;
  std::size_t answered = 0;
  std::size_t answered_on_planes = 0;
};

/// Checks every probe kind on one mesh, its grid sized for `expected_points` (nullopt: by
/// its faces alone); returns how many probes the cells answered.
Tally check_cells(const std::string& name, const Mesh& mesh, std::mt19937_64& rng,
                  std::optional<std::size_t> expected_points = std::nullopt) {
  SCOPED_TRACE(name);
  const mesh::Box box = *mesh::check_mesh(mesh).bounding_box;
  // The reference: rays for every point, every face a candidate (brute force) for the
  // small meshes; Embree's candidates for Spot, where brute force costs a pass over all
  // 2,928 faces per probe (they are checked against brute force in candidates_test.cpp,
  // classifier_test.cpp and unit_frame_test.cpp).
  const CandidateSearch reference =
      mesh.faces.size() < 1000 ? CandidateSearch::brute_force : CandidateSearch::embree;
  const Classifier rays(
      mesh, {.candidates = reference, .allow_non_manifold = true, .space_cells = false});
  const Classifier with_cells(
      mesh,
      {.candidates = CandidateSearch::embree, .allow_non_manifold = true, .space_cells = true});
  const SpaceCells cells(
      mesh, box, [&](const Point3& p) { return rays.winding_number(p); }, expected_points);
  EXPECT_GE(cells.components(), 2u);  // inside and outside at least
  EXPECT_LT(cells.surface_cells(), cells.cells());

  Tally t;
  const auto probe = [&](const Point3& p, bool on_plane) {
    ++t.probes;
    const Location truth = rays.classify(p);
    ASSERT_EQ(with_cells.classify(p), truth) << std::hexfloat << p[0] << " " << p[1] << " " << p[2];
    const auto known = cells.lookup(p);
    if (!known) return;
    ++t.answered;
    t.answered_on_planes += on_plane;
    ASSERT_EQ(known, rays.winding_number(p)) << std::hexfloat << p[0] << " " << p[1] << " " << p[2];
  };
  const auto plane = [&](int axis) {
    const auto& b = cells.planes(axis);
    return b[std::uniform_int_distribution<std::size_t>(0, b.size() - 1)(rng)];
  };
  for (int i = 0; i < 300; ++i)
    probe(random_in(box, rng), false);
  // On one, two or three planes (a facet, an edge or a corner of cells), and one ulp
  // to either side of the first.
  for (int i = 0; i < 300; ++i) {
    Point3 p = random_in(box, rng);
    const int planes_on = 1 + i % 3;
    for (int axis = 0; axis < planes_on; ++axis)
      p[axis] = plane(axis);
    probe(p, true);
    for (const double toward : {-INFINITY, INFINITY}) {
      Point3 q = p;
      q[0] = std::nextafter(q[0], toward);
      if (q[0] >= box.lower[0] && q[0] <= box.upper[0]) probe(q, false);
    }
  }
  // On the surface: a cell containing a face point is reached by that face. (Edge
  // midpoints rounded off the face are skipped.)
  for (std::size_t v = 0; v < mesh.vertices.size(); v += 1 + mesh.vertices.size() / 200) {
    EXPECT_FALSE(cells.lookup(mesh.vertices[v]).has_value()) << "vertex " << v;
  }
  for (std::size_t f = 0; f < mesh.faces.size(); f += 1 + mesh.faces.size() / 200) {
    const Point3& a = mesh.vertices[mesh.faces[f].corners[0]];
    const Point3& b = mesh.vertices[mesh.faces[f].corners[1]];
    const Point3 mid{a[0] / 2 + b[0] / 2, a[1] / 2 + b[1] / 2, a[2] / 2 + b[2] / 2};
    if (rays.classify(mid) == Location::boundary) {
      EXPECT_FALSE(cells.lookup(mid).has_value());
    }
  }
  std::printf(
      "[ info     ] %s: %zu cells (%zu reached by faces, %zu components); %zu of %zu "
      "probes answered by a cell, %zu of them on planes\n",
      name.c_str(), cells.cells(), cells.surface_cells(), cells.components(), t.answered, t.probes,
      t.answered_on_planes);
  return t;
}

TEST(SpaceCells, LabelsAreTheRaysLabelsAtEveryMagnitude) {
  auto rng = testing::seeded_engine("inside.space_cells");
  const Mesh spot = mesh::load_mesh(kMeshes + "spot/spot_quadrangulated.obj").mesh;
  const Mesh torus = mesh::load_mesh(kMeshes + "cgal/torus_quad.off").mesh;
  const polycube::Voxels voxels = polycube::random_voxels(rng, 5, 0.5);
  const Mesh cube = polycube::build_polycube(voxels).mesh;
  for (const auto& [name, mesh] :
       {std::pair{"spot", &spot}, std::pair{"torus", &torus}, std::pair{"polycube", &cube}}) {
    // 2^-1060: coordinates are subnormal, the planes fall on the subnormal grid.
    for (const int k : {0, 1000, -1000, -1060}) {
      const double shift = k == 0 ? 0.75 : 0.0;
      const Tally t = check_cells(std::string(name) + " at 2^" + std::to_string(k),
                                  scaled_mesh(*mesh, k, shift), rng);
      // The cells do answer: most probes for the fine meshes; the torus has 50 faces, whose
      // boxes reach most of its cells.
      EXPECT_GT(t.answered, std::string(name) == "torus" ? t.probes / 20 : t.probes / 2);
      EXPECT_GT(t.answered_on_planes, 0u);
    }
  }
}

// Sized to the points: kCellsPerPoint per expected point, between the few-points floor and
// what the faces ask for; the coarse grid is as exact as the fine one (the same probes,
// at 1 and 2^+-1000).
TEST(SpaceCells, GridSizedToTheExpectedPoints) {
  EXPECT_EQ(SpaceCells::cell_count(10, std::nullopt), SpaceCells::kMinCells);
  EXPECT_EQ(SpaceCells::cell_count(1 << 20, std::nullopt), SpaceCells::kMaxCells);
  EXPECT_EQ(SpaceCells::cell_count(10, 1000), SpaceCells::kMinCellsForFewPoints);
  EXPECT_EQ(SpaceCells::cell_count(10, 25000), SpaceCells::kCellsPerPoint * 25000);
  EXPECT_EQ(SpaceCells::cell_count(10, 1000000), SpaceCells::kMinCells);
  EXPECT_EQ(SpaceCells::cell_count(1 << 20, 1000000), SpaceCells::kCellsPerPoint * 1000000);
  auto rng = testing::seeded_engine("inside.space_cells.expected_points");
  const Mesh spot = mesh::load_mesh(kMeshes + "spot/spot_quadrangulated.obj").mesh;
  for (const int k : {0, 1000, -1000}) {
    const Tally t = check_cells("spot for 1,000 points at 2^" + std::to_string(k),
                                scaled_mesh(spot, k, k == 0 ? 0.75 : 0.0), rng, 1000);
    EXPECT_GT(t.answered, t.probes / 10);
  }
  // The classifier passes the hint on, and labels as without cells.
  const Classifier hinted(spot, {.expected_points = 1000});
  const Classifier unhinted(spot);
  ASSERT_TRUE(hinted.space_cells() && unhinted.space_cells());
  EXPECT_LT(hinted.space_cells()->cells, unhinted.space_cells()->cells / 8);
  const Classifier rays(spot, {.space_cells = false});
  const mesh::Box box = *mesh::check_mesh(spot).bounding_box;
  for (int i = 0; i < 2000; ++i) {
    const Point3 p = random_in(box, rng);
    ASSERT_EQ(hinted.classify(p), rays.classify(p)) << p[0] << " " << p[1] << " " << p[2];
  }
}

TEST(SpaceCells, EnclosedCavityIsItsOwnComponent) {
  // A 3x3x3 block of voxels without its centre: the cavity is outside, with its own
  // component of cells, labelled by its own exact ray. The block fills its box, so the
  // only other component is the solid's interior.
  polycube::Voxels voxels(3);
  for (int z = 0; z < 3; ++z)
    for (int y = 0; y < 3; ++y)
      for (int x = 0; x < 3; ++x)
        voxels.cells[voxels.index({x, y, z})] = !(x == 1 && y == 1 && z == 1);
  Mesh mesh = polycube::build_polycube(voxels).mesh;
  const Classifier classifier(mesh);
  const auto summary = classifier.space_cells();
  ASSERT_TRUE(summary.has_value());
  EXPECT_EQ(summary->components, 2u);
  EXPECT_EQ(classifier.classify({1.5, 1.5, 1.5}), Location::outside);
  EXPECT_EQ(classifier.classify({0.5, 0.5, 0.5}), Location::inside);
  EXPECT_EQ(classifier.classify({2.9, 2.9, 2.9}), Location::inside);
  const Classifier without(
      mesh,
      {.candidates = CandidateSearch::embree, .allow_non_manifold = false, .space_cells = false});
  EXPECT_FALSE(without.space_cells().has_value());
}

}  // namespace
}  // namespace exactgeo::inside
