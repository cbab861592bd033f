// The side quartics of a time slice (internal/slice_sides.hpp): every coefficient on every
// piece is within the threshold of the exact one; whenever they say the
// origin is outside an edge throughout a piece, the exact quartic of that edge, built here
// from its definition in GMP rationals, is negative on the whole closed piece (Sturm);
// whenever they say inside, every exact quartic is positive on it. Pieces come from the
// certificate's own midpoint splits along random paths, down to depth 40.

#include "exactgeo/ccd/internal/slice_sides.hpp"

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <optional>
#include <tuple>
#include <vector>

#include "ccd/exact_polynomial.hpp"
#include "ccd/query_transforms.hpp"
#include "exactgeo/ccd/internal/boundary_image.hpp"
#include "support/generators.hpp"
#include "support/seed.hpp"

namespace exactgeo::ccd {
namespace {

using testing::Rng;
using namespace testing_polynomials;

MovingVector minus(const MovingVector& a, const MovingVector& b) {
  return {a[0] + -b[0], a[1] + -b[1], a[2] + -b[2]};
}

/// The slice polygon in boundary order: vertex-face v - f0, v - f1, v - f2; edge-edge
/// a0 - b0, a1 - b0, a1 - b1, a0 - b1.
std::vector<MovingVector> polygon(const VertexFaceQuery& q) {
  return {difference(q.v_t0, q.v_t1, q.f0_t0, q.f0_t1),
          difference(q.v_t0, q.v_t1, q.f1_t0, q.f1_t1),
          difference(q.v_t0, q.v_t1, q.f2_t0, q.f2_t1)};
}
std::vector<MovingVector> polygon(const EdgeEdgeQuery& q) {
  return {difference(q.ea0_t0, q.ea0_t1, q.eb0_t0, q.eb0_t1),
          difference(q.ea1_t0, q.ea1_t1, q.eb0_t0, q.eb0_t1),
          difference(q.ea1_t0, q.ea1_t1, q.eb1_t0, q.eb1_t1),
          difference(q.ea0_t0, q.ea0_t1, q.eb1_t0, q.eb1_t1)};
}

/// s_i = (P_i x P_{i+1}) . N with N = (P_1 - P_0) x (P_last - P_0), from the definition.
template <class Query>
std::vector<Polynomial> side_oracle(const Query& q) {
  const std::vector<MovingVector> p = polygon(q);
  const MovingVector normal = cross(minus(p[1], p[0]), minus(p.back(), p[0]));
  std::vector<Polynomial> sides;
  for (std::size_t i = 0; i < p.size(); ++i)
    sides.push_back(dot(cross(p[i], p[(i + 1) % p.size()]), normal));
  return sides;
}

struct Tally {
  int queries = 0;
  int certified = 0;  ///< queries whose side quartics got an error bound (within the guard)
  int pieces = 0;
  int outside = 0;
  int inside = 0;
};

template <class Query>
void check_claims(const Query& q, Rng& rng, int paths, Tally& tally) {
  const auto corners = internal::corner_images(q);
  using Sides = internal::SliceSides<std::tuple_size_v<decltype(corners)>>;
  const std::optional<Sides> sides = Sides::of(corners);
  ++tally.queries;
  if (!sides) return;
  ++tally.certified;
  const std::vector<Polynomial> exact = side_oracle(q);
  for (int path = 0; path < paths; ++path) {
    walk_random_split_path(
        rng, 40, sides->whole_step(), Sides::split,
        [&](const typename Sides::Coefficients& c, const mpq_class& start, const mpq_class& end) {
          ++tally.pieces;
          if (sides->origin_outside(c)) {
            ++tally.outside;
            bool some_edge = false;
            for (const Polynomial& s : exact)
              some_edge = some_edge || of_sign_throughout(s, -1, start, end);
            ASSERT_TRUE(some_edge) << "claimed outside on [" << start << ", " << end << "]";
          }
          if (sides->origin_inside(c)) {
            ++tally.inside;
            for (const Polynomial& s : exact) {
              ASSERT_TRUE(of_sign_throughout(s, 1, start, end))
                  << "claimed inside on [" << start << ", " << end << "]";
            }
          }
        });
  }
}

/// Every computed coefficient, on every piece along random split paths, is within the
/// threshold of the exact one (times 12): the bound the certificate rests on, measured.
template <class Query>
double worst_error_ratio(const Query& q, Rng& rng) {
  const auto corners = internal::corner_images(q);
  using Sides = internal::SliceSides<std::tuple_size_v<decltype(corners)>>;
  const std::optional<Sides> sides = Sides::of(corners);
  if (!sides) return 0.0;
  return worst_coefficient_error(
      rng, 30, sides->whole_step(), Sides::split, side_oracle(q), 4, 12, sides->threshold(),
      [](const typename Sides::Coefficients& c, std::size_t i) -> const auto& { return c[i]; });
}

TEST(SliceSides, CoefficientErrorsStayWithinTheThreshold) {
  Rng rng = testing::seeded_engine("SliceSides.CoefficientErrors");
  double worst = 0.0;
  // 400 at full effort (tests/support/seed.hpp), at least one of each five kinds.
  const auto cases = static_cast<int>(testing::scaled_trials(400, 5));
  for (int i = 0; i < cases; ++i) {
    worst = std::max(worst, worst_error_ratio(varied_query<VertexFaceQuery>(rng, i), rng));
    worst = std::max(worst, worst_error_ratio(varied_query<EdgeEdgeQuery>(rng, i), rng));
    ASSERT_LE(worst, 1.0) << "case " << i;
  }
  std::printf("largest coefficient error: %.3g of the threshold\n", worst);
  EXPECT_GT(worst, 0.0);  // the computation does round
}

/// Checks the claims on `count` queries made by make(rng, i); prints and returns what was
/// claimed.
template <class Make>
Tally check_queries(const char* stream, int count, Make make) {
  Rng rng = testing::seeded_engine(stream);
  Tally tally;
  for (int i = 0; i < count; ++i) {
    check_claims(make(rng, i), rng, 3, tally);
    if (::testing::Test::HasFatalFailure()) break;
  }
  std::printf(
      "%s: %d of %d queries certified, %d pieces, %d outside an edge, %d inside every "
      "edge\n",
      stream, tally.certified, tally.queries, tally.pieces, tally.outside, tally.inside);
  return tally;
}

TEST(SliceSides, ClaimsHoldNearDegeneracies) {
  // Rounded grid degeneracies: where too small an error bound makes false claims. Scales
  // within the quartics' guard (2^+-161), so that every query gets a certificate whose
  // claims are checked, at magnitudes across that range.
  const Tally vertex_face =
      check_queries("SliceSides.NearDegenerateVertexFace", 400,
                    [](Rng& rng, int) { return near_degenerate_query<VertexFaceQuery>(rng, 150); });
  const Tally edge_edge =
      check_queries("SliceSides.NearDegenerateEdgeEdge", 400,
                    [](Rng& rng, int) { return near_degenerate_query<EdgeEdgeQuery>(rng, 150); });
  for (const Tally& t : {vertex_face, edge_edge}) {
    EXPECT_EQ(t.certified, t.queries);
    EXPECT_GT(t.outside, 100);  // claims were made, and checked
    EXPECT_GT(t.inside, 100);
  }
}

TEST(SliceSides, ClaimsHoldOnRandomVertexFaceQueries) {
  // 250 at full effort (tests/support/seed.hpp), at least one of each five kinds.
  const auto count = static_cast<int>(testing::scaled_trials(250, 5));
  const Tally t = check_queries("SliceSides.VertexFace", count, [](Rng& rng, int i) {
    return varied_query<VertexFaceQuery>(rng, i);
  });
  // The mix includes exact scalings by 2^+-200 and more, beyond the quartics' guard, where
  // no certificate is made: claims are checked on the others.
  EXPECT_GT(t.certified, t.queries / 2);
  EXPECT_GT(t.outside, t.pieces / 20);  // the certificate does work
  EXPECT_GT(t.inside, 0);
}

TEST(SliceSides, ClaimsHoldOnRandomEdgeEdgeQueries) {
  // 250 at full effort (tests/support/seed.hpp), at least one of each five kinds.
  const auto count = static_cast<int>(testing::scaled_trials(250, 5));
  const Tally t = check_queries("SliceSides.EdgeEdge", count, [](Rng& rng, int i) {
    return varied_query<EdgeEdgeQuery>(rng, i);
  });
  // The mix includes exact scalings by 2^+-200 and more, beyond the quartics' guard, where
  // no certificate is made: claims are checked on the others.
  EXPECT_GT(t.certified, t.queries / 2);
  EXPECT_GT(t.outside, t.pieces / 20);
  EXPECT_GT(t.inside, 0);
}

}  // namespace
}  // namespace exactgeo::ccd
