// The ray directions of root parity (internal/ray_directions.hpp): the first 64 of the
// shared sequence, each exactly on the moment curve; any three linearly independent
// (checked exactly over all triples, in integers); and the count of directions a query can
// make degenerate, from the domain's own faces, within the 64.

#include "exactgeo/ccd/internal/ray_directions.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <set>
#include <utility>

#include "exactgeo/ccd/internal/boundary_image.hpp"

namespace exactgeo::ccd::internal {
namespace {

/// Direction k times 256: (256, 16 (2k + 3), (2k + 3)^2), exact integers.
std::array<std::int64_t, 3> scaled_direction(std::size_t k) {
  const auto m = static_cast<std::int64_t>(2 * k + 3);
  return {256, 16 * m, m * m};
}

TEST(RayDirections, TheFirst64OfTheSequenceExactlyOnTheMomentCurve) {
  static_assert(kRayDirectionCount == 64);
  for (std::size_t k = 0; k < kRayDirectionCount; ++k) {
    EXPECT_EQ(kRayDirections[k], ray_direction(k)) << k;
    const std::array<std::int64_t, 3> exact = scaled_direction(k);
    for (int axis = 0; axis < 3; ++axis) {
      // Scaling by 256 is exact, so equal integers mean equal values.
      EXPECT_EQ(kRayDirections[k][axis] * 256, static_cast<double>(exact[axis])) << k;
      EXPECT_GT(kRayDirections[k][axis], 0.0) << "no ray in a coordinate plane";
    }
  }
}

TEST(RayDirections, AnyThreeAreLinearlyIndependent) {
  int triples = 0;
  for (std::size_t a = 0; a < kRayDirectionCount; ++a) {
    const auto x = scaled_direction(a);
    for (std::size_t b = a + 1; b < kRayDirectionCount; ++b) {
      const auto y = scaled_direction(b);
      for (std::size_t c = b + 1; c < kRayDirectionCount; ++c) {
        const auto z = scaled_direction(c);
        // |entries| < 2^14: every product of three is below 2^42, the sum exact.
        const std::int64_t det = x[0] * (y[1] * z[2] - y[2] * z[1]) -
                                 x[1] * (y[0] * z[2] - y[2] * z[0]) +
                                 x[2] * (y[0] * z[1] - y[1] * z[0]);
        ASSERT_NE(det, 0) << a << " " << b << " " << c;
        ++triples;
      }
    }
  }
  EXPECT_EQ(triples, 64 * 63 * 62 / 6);
}

/// A ray is degenerate only through a corner (one direction per corner at most), through
/// an edge or in a flat face's plane (two per edge or face at most): V + 2 (E + F), with
/// E counted here from the faces' boundaries.
template <std::size_t C>
std::size_t degenerate_bound() {
  std::set<std::pair<VertexIndex, VertexIndex>> edges;
  for (const SurfaceFace& f : kDomainFaces<C>) {
    const std::array<VertexIndex, 4> around =
        f.is_triangle()
            ? std::array<VertexIndex, 4>{f.corners[0], f.corners[1], f.corners[2], f.corners[2]}
            : std::array<VertexIndex, 4>{f.corners[0], f.corners[1], f.corners[3], f.corners[2]};
    const std::size_t n = f.is_triangle() ? 3 : 4;
    for (std::size_t i = 0; i < n; ++i) {
      const VertexIndex a = around[i], b = around[(i + 1) % n];
      edges.insert({std::min(a, b), std::max(a, b)});
    }
  }
  return C + 2 * (edges.size() + kDomainFaces<C>.size());
}

TEST(RayDirections, DegenerateDirectionsAreFewerThanTheDirections) {
  EXPECT_EQ(degenerate_bound<6>(), 34u);  // 6 + 2 (9 + 5)
  EXPECT_EQ(degenerate_bound<8>(), 44u);  // 8 + 2 (12 + 6)
  EXPECT_LT(degenerate_bound<6>(), kRayDirectionCount);
  EXPECT_LT(degenerate_bound<8>(), kRayDirectionCount);
}

}  // namespace
}  // namespace exactgeo::ccd::internal
