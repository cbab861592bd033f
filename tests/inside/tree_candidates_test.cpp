// The box tree's candidates (internal/tree_candidates.hpp) against the exact truth
// (candidate_oracle.hpp): for every ray, every face whose corners' convex hull the exact
// ray touches must be proposed. Meshes: a bumpy torus (skew quads, flat rings, triangles),
// random soups of triangles and quads, and an axis-aligned box split in a grid whose
// coordinates fall halfway between floats. Rays: random, through vertices and edge
// midpoints, from vertices, edge points and points on faces, along directions past those
// a float tracer can take, at magnitudes 2^0, 2^1000 and 2^-1000 and with offsets.

#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "candidate_oracle.hpp"
#include "exactgeo/inside/internal/corner_boxes.hpp"
#include "exactgeo/inside/internal/tree_candidates.hpp"
#include "exactgeo/predicates/ray_directions.hpp"
#include "support/seed.hpp"

namespace exactgeo::inside {
namespace {

using candidate_oracle::bumpy_torus;
using candidate_oracle::expect_complete;
using internal::TreeCandidates;
using mesh::Face;
using mesh::Mesh;

using candidate_oracle::Magnitude;

/// `faces` random triangles and quads (every third a triangle) over 64 random vertices
/// with dyadic coordinates in [-1, 1] (24 bits), scaled by 2^exponent and moved by
/// `offset`: faces crossing each other, sharing corners, some degenerate.
Mesh random_soup(std::mt19937_64& rng, std::size_t faces, int exponent, double offset) {
  std::uniform_int_distribution<int> coordinate(-(1 << 23), 1 << 23);
  Mesh mesh;
  for (int v = 0; v < 64; ++v) {
    Point3 p;
    for (double& c : p)
      c = std::ldexp(std::ldexp(coordinate(rng), -23), exponent) + offset;
    mesh.vertices.push_back(p);
  }
  std::uniform_int_distribution<VertexIndex> corner(0, 63);
  for (std::size_t f = 0; f < faces; ++f) {
    if (f % 3 == 0) {
      mesh.faces.push_back(mesh::make_triangle(corner(rng), corner(rng), corner(rng)));
    } else {
      mesh.faces.push_back(mesh::make_quad(corner(rng), corner(rng), corner(rng), corner(rng)));
    }
  }
  return mesh;
}

/// Casts rays at `mesh` the way the classifier's grazing cases do and checks each against
/// the oracle; returns the faces touched in all.
std::size_t check_rays(std::mt19937_64& rng, const Mesh& mesh, const TreeCandidates& tree,
                       const Magnitude& m, int trials) {
  const mesh::Box box = *internal::corner_box(mesh);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  // Mostly the first directions, which almost every ray uses; some beyond the 2,047 a
  // float tracer can take, which only this finder serves.
  std::uniform_int_distribution<std::size_t> direction(0, 40);
  std::uniform_int_distribution<std::size_t> far_direction(2047, 1 << 20);
  std::uniform_int_distribution<std::size_t> face(0, mesh.faces.size() - 1);
  std::uniform_int_distribution<int> step(1, 64);
  // A point on the line through `target` along direction k, a dyadic distance before it
  // (exact for these dyadic coordinates): the ray from it passes through the target. It
  // may lie outside the box, where no origin is asked about: then the target itself.
  const auto before = [&](const Point3& target, std::size_t k) {
    const Vector3 d = ray_direction(k);
    const double s = std::ldexp(step(rng), m.exponent - 8);
    const Point3 p{target[0] - s * d[0], target[1] - s * d[1], target[2] - s * d[2]};
    return box.holds(p) ? p : target;
  };
  std::size_t touched = 0;
  for (int trial = 0; trial < trials; ++trial) {
    const std::size_t k = trial % 8 == 7 ? far_direction(rng) : direction(rng);
    Point3 random;
    for (int i = 0; i < 3; ++i)
      random[i] = box.lower[i] + unit(rng) * (box.upper[i] - box.lower[i]);
    touched += expect_complete(mesh, tree, random, k);
    // Through a face's corner, and from it.
    const Face& f = mesh.faces[face(rng)];
    const Point3& a = mesh.vertices[f.corners[0]];
    touched += expect_complete(mesh, tree, before(a, k), k);
    touched += expect_complete(mesh, tree, a, k);
    // Through the midpoint of the face's first edge, and from it.
    const Point3& b = mesh.vertices[f.corners[1]];
    const Point3 mid{a[0] / 2 + b[0] / 2, a[1] / 2 + b[1] / 2, a[2] / 2 + b[2] / 2};
    touched += expect_complete(mesh, tree, before(mid, k), k);
    touched += expect_complete(mesh, tree, mid, k);
  }
  return touched;
}

class TreeCandidatesTest : public ::testing::TestWithParam<Magnitude> {};

TEST_P(TreeCandidatesTest, IncludeEveryFaceTheExactRayTouchesOnATorus) {
  auto rng = testing::seeded_engine("inside.tree_candidates.torus");
  const Magnitude m = GetParam();
  const Mesh mesh = bumpy_torus(rng, 24, 12, m.exponent, m.offset);
  const TreeCandidates tree(mesh, *internal::corner_box(mesh));
  // Extreme magnitudes send the exact predicates to GMP: fewer rays there. Scaled with the
  // effort (tests/support/seed.hpp), at least one cycle of eight (seven near directions,
  // one far).
  const auto trials =
      static_cast<int>(testing::scaled_trials(std::abs(m.exponent) > 100 ? 24 : 300, 8));
  // The test is only meaningful if rays touch faces.
  EXPECT_GT(check_rays(rng, mesh, tree, m, trials), 10u * static_cast<std::size_t>(trials));
}

TEST_P(TreeCandidatesTest, IncludeEveryFaceTheExactRayTouchesInRandomSoups) {
  auto rng = testing::seeded_engine("inside.tree_candidates.soup");
  const Magnitude m = GetParam();
  std::size_t touched = 0;
  const int trials = std::abs(m.exponent) > 100 ? 8 : 60;
  for (const std::size_t faces : {1, 7, 40, 300}) {
    SCOPED_TRACE(faces);
    const Mesh mesh = random_soup(rng, faces, m.exponent, m.offset);
    const TreeCandidates tree(mesh, *internal::corner_box(mesh));
    touched += check_rays(rng, mesh, tree, m, trials);
  }
  EXPECT_GT(touched, 10u * static_cast<std::size_t>(trials));
}

INSTANTIATE_TEST_SUITE_P(Magnitudes, TreeCandidatesTest, candidate_oracle::magnitudes(),
                         candidate_oracle::magnitude_name);

/// Axis-parallel faces whose coordinates map halfway between floats (split_box), origins
/// on the faces, edges and corners (candidate_oracle.hpp): every face the exact ray touches
/// is proposed, at 2^0, 2^+-1000 and off centre.
TEST(TreeCandidates, OriginsOnAxisParallelFacesWhoseCoordinatesAreNotFloats) {
  auto rng = testing::seeded_engine("inside.tree_candidates.ties");
  candidate_oracle::expect_complete_from_split_box(
      rng, [](const Mesh& mesh) { return TreeCandidates(mesh, *internal::corner_box(mesh)); });
}

/// The tree prunes: on the torus, a random ray gets a small share of the faces, and a
/// ray from outside the torus's hole that misses it gets none. (A finder that proposed
/// every face would pass the completeness tests.)
TEST(TreeCandidates, ProposesFewFacesAndNoneForARayThatMissesEverything) {
  auto rng = testing::seeded_engine("inside.tree_candidates.prunes");
  const Mesh mesh = bumpy_torus(rng, 48, 24, 0, 0.0);
  const mesh::Box box = *internal::corner_box(mesh);
  const TreeCandidates tree(mesh, box);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<FaceIndex> out;
  std::size_t proposed = 0;
  constexpr int kRays = 200;
  for (int r = 0; r < kRays; ++r) {
    Point3 p;
    for (int i = 0; i < 3; ++i)
      p[i] = box.lower[i] + unit(rng) * (box.upper[i] - box.lower[i]);
    tree.find(p, 0, out);
    proposed += out.size();
  }
  EXPECT_LT(proposed, kRays * mesh.faces.size() / 10);
  // From the box's top corner along (1, t, t^2): away from every face.
  tree.find(box.upper, 0, out);
  EXPECT_TRUE(out.empty()) << out.size() << " candidates";
}

}  // namespace
}  // namespace exactgeo::inside
