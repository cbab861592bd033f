// The coplanarity certificate (internal/coplanarity.hpp): whenever it says the cubic has no
// zero on a piece of the step, the exact cubic, built here in GMP rationals and checked
// with Sturm sequences, has none there; whenever it says the cubic changes sign, the exact
// values at the piece's ends have opposite signs. Pieces are reached by the certificate's
// own midpoint splits along random paths, down to depth 48, on data, random dyadic-grid
// queries (often exactly degenerate), the same one ulp away, and extreme magnitudes.

#include "exactgeo/ccd/internal/coplanarity.hpp"

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <array>
#include <filesystem>
#include <vector>

#include "ccd/exact_polynomial.hpp"
#include "ccd/query_transforms.hpp"
#include "exactgeo/ccd/files/query_files.hpp"
#include "exactgeo/ccd/internal/boundary_image.hpp"
#include "support/generators.hpp"
#include "support/seed.hpp"

namespace exactgeo::ccd {
namespace {

namespace fs = std::filesystem;
using testing::Rng;
using namespace testing_polynomials;

/// The coplanarity cubic, straight from its definition: vertex-face det[v - f0, v - f1,
/// v - f2]; edge-edge det[a0 - b0, a0 - b1, a1 - b0].
Polynomial coplanarity_oracle(const VertexFaceQuery& q) {
  return det3(difference(q.v_t0, q.v_t1, q.f0_t0, q.f0_t1),
              difference(q.v_t0, q.v_t1, q.f1_t0, q.f1_t1),
              difference(q.v_t0, q.v_t1, q.f2_t0, q.f2_t1));
}
Polynomial coplanarity_oracle(const EdgeEdgeQuery& q) {
  return det3(difference(q.ea0_t0, q.ea0_t1, q.eb0_t0, q.eb0_t1),
              difference(q.ea0_t0, q.ea0_t1, q.eb1_t0, q.eb1_t1),
              difference(q.ea1_t0, q.ea1_t1, q.eb0_t0, q.eb0_t1));
}

struct Tally {
  int queries = 0;
  int certified = 0;  ///< queries whose cubic got an error bound (corners within the guard)
  int pieces = 0;
  int proven_nonzero = 0;
  int sign_changes = 0;
};

/// Walks `paths` random split paths of the query's step and checks every claim made.
template <class Query>
void check_claims(const Query& q, Rng& rng, int paths, Tally& tally) {
  const auto corners = internal::corner_images(q);
  const auto certificate = internal::Coplanarity::of(corners);
  ++tally.queries;
  if (!certificate) return;
  ++tally.certified;
  Polynomial p = coplanarity_oracle(q);
  trim(p);
  for (int path = 0; path < paths; ++path) {
    walk_random_split_path(rng, 48, certificate->whole_step(), internal::split_coefficients,
                           [&](const internal::CoplanarityCoefficients& b, const mpq_class& start,
                               const mpq_class& end) {
                             ++tally.pieces;
                             if (certificate->nonzero(b)) {
                               ++tally.proven_nonzero;
                               ASSERT_FALSE(p.empty() || has_root_in(p, start, end))
                                   << "claimed no zero on [" << start << ", " << end << "]";
                             }
                             if (certificate->changes_sign(b)) {
                               ++tally.sign_changes;
                               ASSERT_FALSE(p.empty());
                               ASSERT_LT(sgn(evaluate(p, start)) * sgn(evaluate(p, end)), 0)
                                   << "claimed a sign change on [" << start << ", " << end << "]";
                             }
                           });
  }
}

TEST(Coplanarity, ClaimsHoldOnTheBundledData) {
  Rng rng = testing::seeded_engine("Coplanarity.Data");
  Tally tally;
  for (const ccd::QueryFile& file :
       ccd::read_query_files({(fs::path(EXACTGEO_TEST_DATA_DIR) / "ccd").string()})) {
    for (const ccd::QueryRecord& record : file.records) {
      if (file.type == ccd::QueryType::edge_edge) {
        check_claims(ccd::edge_edge_query(record), rng, 4, tally);
      } else {
        check_claims(ccd::vertex_face_query(record), rng, 4, tally);
      }
      if (::testing::Test::HasFatalFailure()) return;
    }
  }
  std::printf(
      "data: %d of %d queries certified, %d pieces, %d proven free of coplanarity, %d "
      "sign changes\n",
      tally.certified, tally.queries, tally.pieces, tally.proven_nonzero, tally.sign_changes);
  // A query gets no certificate when the largest coordinate of its corners on some axis
  // is outside the guard [2^-242, 2^242]: 38 of the 1,179 bundled ones, every one with an
  // axis on which all corners are zero (primitives moving in a coordinate plane).
  EXPECT_GT(tally.certified, tally.queries * 9 / 10);
  EXPECT_GT(tally.proven_nonzero, tally.pieces / 10);  // the certificate does work
  EXPECT_GT(tally.sign_changes, 0);
}

template <class Query>
void check_random_queries(const char* stream) {
  Rng rng = testing::seeded_engine(stream);
  Tally tally;
  // 1500 at full effort (tests/support/seed.hpp), at least one of each five kinds.
  const auto count = static_cast<int>(testing::scaled_trials(1500, 5));
  for (int i = 0; i < count; ++i) {
    const Query q = varied_query<Query>(rng, i);
    check_claims(q, rng, 3, tally);
    if (::testing::Test::HasFatalFailure()) return;
  }
  std::printf(
      "%s: %d of %d queries certified, %d pieces, %d proven free of coplanarity, %d "
      "sign changes\n",
      stream, tally.certified, tally.queries, tally.pieces, tally.proven_nonzero,
      tally.sign_changes);
  // The mix includes scalings far beyond the cubic's guard (2^+-242), where no certificate
  // is made: claims are checked on the others.
  EXPECT_GT(tally.certified, tally.queries / 2);
  EXPECT_GT(tally.proven_nonzero, tally.pieces / 10);
  EXPECT_GT(tally.sign_changes, 0);
}

TEST(Coplanarity, ClaimsHoldOnRandomVertexFaceQueries) {
  check_random_queries<VertexFaceQuery>("Coplanarity.VertexFace");
}

TEST(Coplanarity, ClaimsHoldOnRandomEdgeEdgeQueries) {
  check_random_queries<EdgeEdgeQuery>("Coplanarity.EdgeEdge");
}

/// Every computed coefficient, on every piece along random split paths, is within the
/// threshold of the exact one (3 times the exact Bernstein coefficient): the bound the
/// certificate rests on, measured. The largest error, as a fraction of the threshold, is
/// printed (docs/predicates.md, "How tight the bounds are").
template <class Query>
double worst_error_ratio(const Query& q, Rng& rng) {
  const auto certificate = internal::Coplanarity::of(internal::corner_images(q));
  if (!certificate) return 0.0;
  return worst_coefficient_error(
      rng, 48, certificate->whole_step(), internal::split_coefficients, {coplanarity_oracle(q)}, 3,
      3, certificate->threshold(),
      [](const internal::CoplanarityCoefficients& c, std::size_t) -> const auto& { return c; });
}

TEST(Coplanarity, CoefficientErrorsStayWithinTheThreshold) {
  Rng rng = testing::seeded_engine("Coplanarity.CoefficientErrors");
  double worst = 0.0;
  // 1500 at full effort (tests/support/seed.hpp), at least one of each five kinds.
  const auto cases = static_cast<int>(testing::scaled_trials(1500, 5));
  for (int i = 0; i < cases; ++i) {
    worst = std::max(worst, worst_error_ratio(varied_query<VertexFaceQuery>(rng, i), rng));
    worst = std::max(worst, worst_error_ratio(varied_query<EdgeEdgeQuery>(rng, i), rng));
    ASSERT_LE(worst, 1.0) << "case " << i;
  }
  std::printf("largest coefficient error: %.3g of the threshold\n", worst);
  EXPECT_GT(worst, 0.0);  // the computation does round
}

TEST(Coplanarity, NoCertificateBeyondTheFilterGuard) {
  // Corners near the top of the double range: the products would overflow.
  const VertexFaceQuery q{{0x1p1000, 0, 0}, {0, 0x1p1000, 0}, {0, 0, 0x1p1000}, {1, 1, 1},
                          {0x1p1000, 1, 0}, {0, 0x1p1000, 1}, {1, 0, 0x1p1000}, {2, 1, 1}};
  EXPECT_FALSE(internal::Coplanarity::of(internal::corner_images(q)).has_value());
}

}  // namespace
}  // namespace exactgeo::ccd
