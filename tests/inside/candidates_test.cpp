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

struct Magnitude {
  int exponent;
  double offset;
};

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
  // range), about 100 times slower: fewer rays there.
  const int trials = std::abs(m.exponent) > 100 ? 24 : 400;
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

INSTANTIATE_TEST_SUITE_P(Magnitudes, EmbreeCandidatesTest,
                         ::testing::Values(Magnitude{0, 0.0}, Magnitude{1000, 0.0},
                                           Magnitude{-1000, 0.0}, Magnitude{0, 0x1p30},
                                           Magnitude{-40, -0x1p-10}),
                         [](const ::testing::TestParamInfo<Magnitude>& param_info) {
                           const Magnitude& m = param_info.param;
                           std::string name = m.exponent < 0 ? "scale_2m" : "scale_2p";
                           name.append(std::to_string(std::abs(m.exponent)));
                           if (m.offset != 0) name.append("_offset");
                           return name;
                         });

/// The padding at its edge: an axis-aligned box, its faces split in a grid, whose face
/// and grid coordinates map into the float frame exactly halfway between two floats, so
/// that the nearest float (ties to even) moves an origin on them off the box by the full
/// rounding, 2^-25 in frame units (for |x| in [1/2, 1)), outward on half of them. Origins
/// on the faces, edges and corners then sit on or beyond a float box's face, and Embree's
/// slab arithmetic decides the rest: every face the exact ray touches must still be
/// proposed. (With kPad at 2^-25 or below, or 0, this test finds misses.)
TEST(EmbreeCandidates, OriginsOnAxisAlignedFacesWhoseCoordinatesAreNotFloats) {
  auto rng = testing::seeded_engine("inside.candidates.ties");
  const double h = candidate_oracle::kTieHalfExtent;
  const auto& lines = candidate_oracle::kTieLines;
  for (const auto& [k, centre] :
       {std::pair{0, 0.0}, std::pair{1000, 0.0}, std::pair{-1000, 0.0}, std::pair{0, 3.0}}) {
    SCOPED_TRACE(k);
    const auto at = [&](double x) { return std::ldexp(x, k) + centre; };
    const Mesh mesh = candidate_oracle::split_box(k, centre);
    const internal::EmbreeCandidates embree(mesh, *internal::corner_box(mesh));
    std::uniform_int_distribution<std::size_t> line(0, lines.size() - 1);
    std::uniform_int_distribution<int> odd(0, (1 << 20) - 1);
    std::uniform_int_distribution<std::size_t> direction(0, 40);
    std::size_t touched = 0;
    for (int trial = 0; trial < 400; ++trial) {
      // On a face: its coordinate +-h; the others on grid lines (edges and corners) or
      // odd multiples of 2^-26 (ties too, inside a grid cell).
      Point3 p;
      const int axis = trial % 3;
      p[axis] = trial % 2 ? h : -h;
      for (const int other : {(axis + 1) % 3, (axis + 2) % 3}) {
        p[other] = trial % 4 < 2 ? lines[line(rng)] : (2.0 * odd(rng) + 1) * 0x1p-26 - 0.5 * h;
      }
      touched += expect_complete(mesh, embree, {at(p[0]), at(p[1]), at(p[2])}, direction(rng));
    }
    EXPECT_GE(touched, 400u);  // every origin lies on at least one face
  }
}

}  // namespace
}  // namespace exactgeo::inside
