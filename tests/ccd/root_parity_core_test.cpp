// Root parity over a domain's corner images (internal/root_parity_core.hpp), for every
// sign policy and both kinds of corners (differences of the query's points, and the exact
// corners of time pieces): on every piece of queries whose roots are known exactly, the
// parity those roots give; exact and rational signs agree; the parities of two halves
// add up to their parent's; a piece holds the query's own parity at any magnitude; rays
// made degenerate by the corners are skipped.

#include "exactgeo/ccd/internal/root_parity_core.hpp"

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "ccd/known_roots.hpp"
#include "ccd/query_transforms.hpp"
#include "exactgeo/ccd/internal/boundary_image.hpp"
#include "exactgeo/ccd/internal/time_pieces.hpp"
#include "exactgeo/predicates/kernel/signs.hpp"
#include "support/generators.hpp"
#include "support/seed.hpp"

namespace exactgeo::ccd::internal {
namespace {

using kernel::DoubleSigns;
using kernel::ExactSigns;
using kernel::RationalSigns;
using testing::Rng;

const char* name(RootParity p) {
  switch (p) {
    case RootParity::even:
      return "even";
    case RootParity::odd:
      return "odd";
    case RootParity::boundary_root:
      return "boundary root";
  }
  return "?";
}

/// The piece's parity with exact signs (the filter where the corners allow it, as the
/// search does) and with rational signs, which must agree.
template <std::size_t C>
RootParity parity_of(const TimePiece<C>& p, const std::string& what) {
  const Offsets<C> corners = p.offsets();
  const RootParityResult rational = root_parity(RationalSigns{}, corners);
  if (p.filterable()) {
    const RootParityResult exact = root_parity(ExactSigns{}, corners);
    EXPECT_EQ(exact.parity, rational.parity) << what;
    EXPECT_EQ(exact.rays, rational.rays) << what << ": the same rays are clean";
  }
  EXPECT_GE(rational.rays, 1);
  EXPECT_LE(rational.rays, kRayDirectionCount);
  return rational.parity;
}

/// Every piece of the binary tree of splits down to `depth`.
template <std::size_t C>
void pieces_down_to(const TimePiece<C>& p, int depth, std::vector<TimePiece<C>>& out) {
  out.push_back(p);
  if (p.depth == depth) return;
  for (const Half which : {Half::left, Half::right}) {
    const auto child = half(p, which);
    ASSERT_TRUE(child.has_value());
    pieces_down_to(*child, depth, out);
  }
}

/// The parity that roots at these times (each with its multiplicity, each an interior
/// point of the primitives) give the piece [start, end].
RootParity expected_parity(const std::vector<std::pair<mpq_class, int>>& roots, double start,
                           double end) {
  int inside = 0;
  for (const auto& [t, multiplicity] : roots) {
    if (t == mpq_class(start) || t == mpq_class(end)) return RootParity::boundary_root;
    if (t > mpq_class(start) && t < mpq_class(end)) inside += multiplicity;
  }
  return inside % 2 ? RootParity::odd : RootParity::even;
}

struct Seen {
  int boundary = 0;
  int odd = 0;
};

template <class Query>
void expect_known_parities(const Query& q, const std::vector<std::pair<mpq_class, int>>& roots,
                           const std::string& what, Seen& seen) {
  const auto corners = corner_images(q);
  constexpr std::size_t C = std::tuple_size_v<decltype(corners)>;
  // The query's own corners, differences of its points.
  EXPECT_EQ(root_parity(ExactSigns{}, corners).parity, expected_parity(roots, 0, 1)) << what;
  EXPECT_EQ(root_parity(RationalSigns{}, corners).parity, expected_parity(roots, 0, 1)) << what;
  const auto whole = whole_step<C>(corners);
  ASSERT_TRUE(whole.has_value());
  std::vector<TimePiece<C>> pieces;
  pieces_down_to(*whole, 5, pieces);
  ASSERT_EQ(pieces.size(), 63u);
  for (const TimePiece<C>& p : pieces) {
    const std::string where =
        what + " on [" + std::to_string(p.t_start) + ", " + std::to_string(p.t_end) + "]";
    const RootParity expected = expected_parity(roots, p.t_start, p.t_end);
    const RootParity got = parity_of(p, where);
    EXPECT_EQ(got, expected) << where << ": " << name(got) << ", expected " << name(expected);
    seen.boundary += expected == RootParity::boundary_root;
    seen.odd += expected == RootParity::odd;
  }
}

TEST(RootParityCore, PiecesOfQueriesWithKnownRoots) {
  const mpq_class quarter(1, 4), three_quarters(3, 4);
  Seen seen;
  expect_known_parities(known_roots::falling_vertex(), {{mpq_class(3, 10), 1}}, "falling vertex",
                        seen);
  expect_known_parities(known_roots::through_and_back(), {{quarter, 1}, {three_quarters, 1}},
                        "through and back", seen);
  expect_known_parities(known_roots::through_and_back_late(),
                        {{mpq_class(5, 8), 1}, {mpq_class(7, 8), 1}}, "late through and back",
                        seen);
  expect_known_parities(known_roots::tangent_at_one_third(), {{mpq_class(1, 3), 2}}, "tangent",
                        seen);
  expect_known_parities(known_roots::through_and_back_beside(), {}, "beside", seen);
  expect_known_parities(known_roots::near_miss(0.0625), {}, "near miss", seen);
  // The same, time reversed: the roots at 1 - t.
  expect_known_parities(time_reversed(known_roots::falling_vertex()), {{mpq_class(7, 10), 1}},
                        "falling vertex reversed", seen);
  expect_known_parities(time_reversed(known_roots::through_and_back_late()),
                        {{mpq_class(3, 8), 1}, {mpq_class(1, 8), 1}}, "late reversed", seen);
  EXPECT_GT(seen.boundary, 30);  // roots at 1/4, 3/4, 5/8, ... fall on the pieces' ends
  EXPECT_GT(seen.odd, 10);
}

/// Without a boundary root in either half, the halves' parities add up to the parent's
/// (what lets the search give the right half its parity without computing it); a boundary
/// root of the parent is on the boundary of a half. Exact and rational signs agree on
/// every piece, and the whole step's parity is the query's own.
template <class Query>
void parities_add_up(const char* stream) {
  Rng rng = testing::seeded_engine(stream);
  int added = 0, odd = 0, boundary = 0;
  for (int i = 0; i < 100; ++i) {
    Query q = varied_query<Query>(rng, i);
    if (i % 4 == 3) q = random_dyadic_query<Query>(rng);  // more roots on the grid
    const auto corners = corner_images(q);
    constexpr std::size_t C = std::tuple_size_v<decltype(corners)>;
    auto piece = whole_step<C>(corners);
    ASSERT_TRUE(piece.has_value());
    const std::string what = std::string(stream) + " #" + std::to_string(i);
    RootParity parent = parity_of(*piece, what);
    EXPECT_EQ(parent, root_parity(ExactSigns{}, corners).parity) << what;
    for (int level = 0; level < 6 && splittable(*piece); ++level) {
      const auto left = half(*piece, Half::left);
      const auto right = half(*piece, Half::right);
      ASSERT_TRUE(left && right);
      const RootParity l = parity_of(*left, what), r = parity_of(*right, what);
      if (parent == RootParity::boundary_root) {
        EXPECT_TRUE(l == RootParity::boundary_root || r == RootParity::boundary_root) << what;
        ++boundary;
      } else if (l != RootParity::boundary_root && r != RootParity::boundary_root) {
        EXPECT_EQ((l == RootParity::odd) != (r == RootParity::odd), parent == RootParity::odd)
            << what << " level " << level << ": " << name(l) << " + " << name(r) << " against "
            << name(parent);
        ++added;
        odd += parent == RootParity::odd;
      }
      const bool go_left = testing::uniform_int(rng, 0, 1) == 0;
      piece = go_left ? left : right;
      parent = go_left ? l : r;
    }
    if (::testing::Test::HasFailure()) return;
  }
  EXPECT_GT(added, 300);
  EXPECT_GT(odd, 5);
  EXPECT_GT(boundary, 5);
}

TEST(RootParityCore, VertexFaceHalvesAddUp) {
  parities_add_up<VertexFaceQuery>("root-parity-core-vf");
}

TEST(RootParityCore, EdgeEdgeHalvesAddUp) {
  parities_add_up<EdgeEdgeQuery>("root-parity-core-ee");
}

/// Corner images placed on the first ray directions (each corner c_k a multiple of
/// direction k): those rays meet a corner and are degenerate, so the count comes from a
/// later ray, the same for exact and rational signs; plain double signs find one too here.
TEST(RootParityCore, RaysThroughCornersAreSkipped) {
  Rng rng = testing::seeded_engine("root-parity-core-rays");
  int later = 0;
  for (int i = 0; i < 200; ++i) {
    std::array<double, 8> s;
    for (double& x : s)
      x = testing::uniform_int(rng, 1, 8) * (testing::uniform_int(rng, 0, 1) ? 1.0 : -1.0);
    // v = 0 and fj = -c, so that v - fj = c.
    auto minus = [](const Vector3& d, double k) { return Point3{-k * d[0], -k * d[1], -k * d[2]}; };
    const Point3 o{0, 0, 0};
    const VertexFaceQuery vf{o,
                             minus(kRayDirections[0], s[0]),
                             minus(kRayDirections[1], s[1]),
                             minus(kRayDirections[2], s[2]),
                             o,
                             minus(kRayDirections[3], s[3]),
                             minus(kRayDirections[4], s[4]),
                             minus(kRayDirections[5], s[5])};
    const auto corners = corner_images(vf);
    const RootParityResult exact = root_parity(ExactSigns{}, corners);
    const RootParityResult rational = root_parity(RationalSigns{}, corners);
    EXPECT_EQ(exact.parity, rational.parity) << i;
    EXPECT_EQ(exact.rays, rational.rays) << i;
    // Rays 0 .. 5 each pass through a corner image at s > 0 when s_k > 0.
    if (s[0] > 0) {
      EXPECT_GT(exact.rays, 1) << i;
    }
    int positive = 0;
    for (std::size_t k = 0; k < 6; ++k)
      positive += s[k] > 0;
    if (positive == 6) {
      EXPECT_GT(exact.rays, 6) << i;
      ++later;
    }
    const RootParityResult plain = root_parity(DoubleSigns{}, corners);
    EXPECT_LE(plain.rays, kRayDirectionCount);
  }
  EXPECT_GT(later, 0);
}

}  // namespace
}  // namespace exactgeo::ccd::internal
