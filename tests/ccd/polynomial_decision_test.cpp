// The decision by polynomials (internal/polynomial_decision.hpp): on random queries its
// "root" must be a collision and its "no root" must not be, by the exact method's own
// search (time-of-impact mode, which never uses the decision).

#include "exactgeo/ccd/internal/polynomial_decision.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <optional>
#include <tuple>

#include "ccd/query_transforms.hpp"
#include "exactgeo/ccd/ccd.hpp"
#include "exactgeo/ccd/internal/boundary_image.hpp"
#include "support/generators.hpp"
#include "support/seed.hpp"

namespace exactgeo::ccd {
namespace {

using testing::Rng;

/// The decision by polynomials against the exact search (time-of-impact mode never takes
/// the decision's shortcut).
template <class Query>
void check_decisions(const char* stream) {
  Rng rng = testing::seeded_engine(stream);
  std::array<int, 3> verdicts{};
  Options search;
  search.time_of_impact_width = 1.0 / 1024;
  for (int i = 0; i < 3000; ++i) {
    Query q = varied_query<Query>(rng, i);
    if (i % 8 == 7) q = time_reversed(q);
    const auto corners = internal::corner_images(q);
    constexpr std::size_t C = std::tuple_size_v<decltype(corners)>;
    const auto coplanarity = internal::Coplanarity::of(corners);
    const auto sides = internal::SliceSides<C>::of(corners);
    if (!coplanarity || !sides) continue;
    const std::optional<internal::PieceVerdict> verdict =
        internal::decide_by_polynomials<C>(*coplanarity, *sides, {16, 64});
    ++verdicts[verdict ? static_cast<int>(*verdict) : 2];
    if (!verdict) continue;
    Result searched;
    if constexpr (C == 6) {
      searched = vertex_face_ccd(q, search);
    } else {
      searched = edge_edge_ccd(q, search);
    }
    ASSERT_EQ(searched.collision, verdict == internal::PieceVerdict::root) << "case " << i;
  }
  std::printf("%s: %d no root, %d root, %d undecided\n", stream, verdicts[0], verdicts[1],
              verdicts[2]);
  EXPECT_GT(verdicts[0], 0);
  EXPECT_GT(verdicts[1], 0);
}

TEST(PolynomialDecision, AgreesWithTheSearchOnVertexFace) {
  check_decisions<VertexFaceQuery>("PolynomialDecision.VertexFace");
}

TEST(PolynomialDecision, AgreesWithTheSearchOnEdgeEdge) {
  check_decisions<EdgeEdgeQuery>("PolynomialDecision.EdgeEdge");
}

}  // namespace
}  // namespace exactgeo::ccd
