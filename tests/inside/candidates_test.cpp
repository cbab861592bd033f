// Embree's candidates against the exact truth (candidate_oracle.hpp): for every ray, every
// face whose corners' convex hull the exact ray touches must be proposed. Rays are
// random, and grazing: through mesh vertices, through edge points, along the planes of
// flat faces, from points on faces, at magnitudes from 2^-1000 to 2^1000.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "candidate_oracle.hpp"
#include "exactgeo/inside/internal/candidates.hpp"
#include "exactgeo/inside/internal/corner_boxes.hpp"
#include "exactgeo/predicates/ray_directions.hpp"
#include "support/seed.hpp"

namespace exactgeo::inside {
namespace {

using candidate_oracle::bumpy_torus;
using candidate_oracle::expect_complete;
using mesh::Face;
using mesh::Mesh;

using candidate_oracle::Magnitude;

class EmbreeCandidatesTest : public ::testing::TestWithParam<Magnitude> {};

TEST_P(EmbreeCandidatesTest, IncludeEveryFaceTheExactRayTouches) {
  auto rng = testing::seeded_engine("inside.candidates");
  const Magnitude m = GetParam();
  const Mesh mesh = bumpy_torus(rng, 24, 12, m.exponent, m.offset);
  const internal::EmbreeCandidates embree(mesh, *internal::corner_box(mesh));
  const auto at = [&](double x) { return std::ldexp(x, m.exponent) + m.offset; };
  std::uniform_real_distribution<double> box(-3.2, 3.2);
  std::uniform_int_distribution<std::size_t> direction(0, 40);
  std::uniform_int_distribution<std::size_t> vertex(0, mesh.vertices.size() - 1);
  std::uniform_int_distribution<std::size_t> face(0, mesh.faces.size() - 1);
  std::uniform_int_distribution<int> step(1, 64);
  // An origin on the line through `target` along direction k, a dyadic distance before
  // it: the ray passes exactly through the target (when the subtraction is exact, which
  // it is for these dyadic coordinates at every tested magnitude).
  const auto before = [&](const Point3& target, std::size_t k) {
    const Vector3 d = ray_direction(k);
    const double s = std::ldexp(step(rng), m.exponent - 8);
    return Point3{target[0] - s * d[0], target[1] - s * d[1], target[2] - s * d[2]};
  };

  // Extreme magnitudes send the exact predicates to GMP (products leave the double
  // range), about 100 times slower: fewer rays there. Scaled with the effort
  // (tests/support/seed.hpp).
  const auto trials =
      static_cast<int>(testing::scaled_trials(std::abs(m.exponent) > 100 ? 24 : 400));
  std::size_t touched = 0;
  for (int trial = 0; trial < trials; ++trial) {
    const std::size_t k = direction(rng);
    // Random origins in the box.
    touched +=
        expect_complete(mesh, embree, Point3{at(box(rng)), at(box(rng)), at(box(rng) / 2)}, k);
    // Rays through a vertex, and origins at a vertex.
    const Point3& v = mesh.vertices[vertex(rng)];
    touched += expect_complete(mesh, embree, before(v, k), k);
    touched += expect_complete(mesh, embree, v, k);
    // Rays through the midpoint of a face's edge, and origins there.
    const Face& f = mesh.faces[face(rng)];
    const Point3& a = mesh.vertices[f.corners[0]];
    const Point3& b = mesh.vertices[f.corners[1]];
    const Point3 mid{a[0] / 2 + b[0] / 2, a[1] / 2 + b[1] / 2, a[2] / 2 + b[2] / 2};
    touched += expect_complete(mesh, embree, before(mid, k), k);
    touched += expect_complete(mesh, embree, mid, k);
  }
  // The test is only meaningful if rays touch faces.
  EXPECT_GT(touched, 10u * static_cast<std::size_t>(trials));
}

INSTANTIATE_TEST_SUITE_P(Magnitudes, EmbreeCandidatesTest, candidate_oracle::magnitudes(),
                         candidate_oracle::magnitude_name);

/// The padding at its edge: an axis-aligned box, its faces split in a grid, whose face
/// and grid coordinates map into the float frame exactly halfway between two floats, so
/// that the nearest float (ties to even) moves an origin on them off the box by the full
/// rounding, 2^-25 in frame units (for |x| in [1/2, 1)), outward on half of them. Origins
/// on the faces, edges and corners then sit on or beyond a float box's face, and Embree's
/// slab arithmetic decides the rest: every face the exact ray touches must still be
/// proposed. (With kPad at 2^-25 or below, or 0, this test finds misses.)
TEST(EmbreeCandidates, OriginsOnAxisAlignedFacesWhoseCoordinatesAreNotFloats) {
  auto rng = testing::seeded_engine("inside.candidates.ties");
  candidate_oracle::expect_complete_from_split_box(rng, [](const Mesh& mesh) {
    return internal::EmbreeCandidates(mesh, *internal::corner_box(mesh));
  });
}

}  // namespace
}  // namespace exactgeo::inside
