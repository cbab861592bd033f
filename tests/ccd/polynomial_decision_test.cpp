// The decision by polynomials (internal/polynomial_decision.hpp): on queries whose roots
// are known exactly, its answers (a root, no root, or undecided where the polynomials
// cannot tell) and its budget of halvings and pieces; then on random queries its "root"
// must be a collision and its "no root" must not be, by the exact method's own search
// (time-of-impact mode, which never uses the decision).

#include "exactgeo/ccd/internal/polynomial_decision.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <optional>
#include <tuple>

#include "ccd/known_roots.hpp"
#include "ccd/query_transforms.hpp"
#include "exactgeo/ccd/ccd.hpp"
#include "exactgeo/ccd/internal/boundary_image.hpp"
#include "support/generators.hpp"
#include "support/seed.hpp"

namespace exactgeo::ccd {
namespace {

using internal::DecisionBudget;
using internal::PieceVerdict;
using testing::Rng;

/// The decision on the whole step of q within `budget`, and the pieces it looked at.
struct Decision {
  std::optional<PieceVerdict> verdict;
  int pieces = 0;
};

template <class Query>
Decision decide(const Query& q, DecisionBudget budget) {
  const auto corners = internal::corner_images(q);
  constexpr std::size_t C = std::tuple_size_v<decltype(corners)>;
  const auto coplanarity = internal::Coplanarity::of(corners);
  const auto sides = internal::SliceSides<C>::of(corners);
  EXPECT_TRUE(coplanarity && sides) << "coordinates near 1 have certificates";
  if (!coplanarity || !sides) return {};
  int pieces_left = budget.pieces;
  const auto verdict =
      internal::decide_by_polynomials<C>(*coplanarity, coplanarity->whole_step(), *sides,
                                         sides->whole_step(), budget.depth, pieces_left);
  // The overload for the whole step is the same decision.
  EXPECT_EQ(internal::decide_by_polynomials<C>(*coplanarity, *sides, budget), verdict);
  return {verdict, budget.pieces - pieces_left};
}

/// One crossing: the cubic changes sign over the step while the vertex is inside the
/// triangle's edges throughout, so the whole step proves the root, at no depth at all.
TEST(PolynomialDecision, OneCrossingIsARootOnTheWholeStep) {
  const VertexFaceQuery q = known_roots::falling_vertex();
  for (const DecisionBudget budget : {DecisionBudget{0, 1}, DecisionBudget{16, 64}}) {
    const Decision d = decide(q, budget);
    EXPECT_EQ(d.verdict, PieceVerdict::root);
    EXPECT_EQ(d.pieces, 1);
  }
}

/// Through and back (roots at 1/4 and 3/4, parity even): the cubic has one sign at both
/// ends of the step, so the step itself proves nothing, and its left half, where the cubic
/// changes sign with the crossing point inside both edges, proves the root. The budget is
/// honoured exactly: no halving or fewer than three pieces leave it undecided.
TEST(PolynomialDecision, ThroughAndBackNeedsOneHalvingAndThreePieces) {
  const EdgeEdgeQuery q = known_roots::through_and_back();
  EXPECT_EQ(decide(q, {0, 64}).verdict, std::nullopt);
  EXPECT_EQ(decide(q, {0, 64}).pieces, 1);
  EXPECT_EQ(decide(q, {1, 2}).verdict, std::nullopt);
  EXPECT_EQ(decide(q, {1, 2}).pieces, 1);
  const Decision d = decide(q, {1, 3});
  EXPECT_EQ(d.verdict, PieceVerdict::root);
  EXPECT_EQ(d.pieces, 2);  // the step and its left half
  EXPECT_EQ(decide(q, {16, 64}).verdict, PieceVerdict::root);
}

/// Through and back late in the step (roots at 5/8 and 7/8): the left half is free (the
/// cubic has no zero there), the right half is as the whole step above, and its left
/// quarter proves the root: two halvings and five pieces (four looked at).
TEST(PolynomialDecision, LateThroughAndBackNeedsTwoHalvingsAndFivePieces) {
  const EdgeEdgeQuery q = known_roots::through_and_back_late();
  EXPECT_EQ(decide(q, {1, 64}).verdict, std::nullopt);
  EXPECT_EQ(decide(q, {1, 64}).pieces, 3);
  EXPECT_EQ(decide(q, {2, 4}).verdict, std::nullopt);
  EXPECT_EQ(decide(q, {2, 4}).pieces, 3);
  const Decision d = decide(q, {2, 5});
  EXPECT_EQ(d.verdict, PieceVerdict::root);
  EXPECT_EQ(d.pieces, 4);
  EXPECT_EQ(decide(q, {16, 64}).verdict, PieceVerdict::root);
}

/// The same motion beside edge a: the lines still cross twice, so the cubic vanishes
/// twice, but the crossing point is outside an edge of the slice throughout: no root.
TEST(PolynomialDecision, PassingBesideIsNoRoot) {
  const EdgeEdgeQuery q = known_roots::through_and_back_beside();
  EXPECT_EQ(decide(q, {0, 1}).verdict, PieceVerdict::no_root);
  EXPECT_EQ(decide(q, {16, 64}).verdict, PieceVerdict::no_root);
}

/// A tangential contact (a double root at t = 1/3): the cubic never changes sign and the
/// contact is real, so no budget decides it; the pieces looked at stay within the budget.
/// Near misses below it are proven free once the budget reaches the gap.
TEST(PolynomialDecision, TangentialContactStaysUndecidedWithinTheBudget) {
  const EdgeEdgeQuery tangent = known_roots::tangent_at_one_third();
  for (const DecisionBudget budget :
       {DecisionBudget{0, 1}, DecisionBudget{1, 3}, DecisionBudget{4, 64}, DecisionBudget{16, 5},
        DecisionBudget{16, 64}, DecisionBudget{40, 1000}}) {
    const Decision d = decide(tangent, budget);
    EXPECT_EQ(d.verdict, std::nullopt) << budget.depth << " " << budget.pieces;
    EXPECT_GE(d.pieces, 1);
    EXPECT_LE(d.pieces, budget.pieces) << budget.depth << " " << budget.pieces;
  }
  int decided = 0;
  for (int k = 2; k <= 40; k += 2) {
    const EdgeEdgeQuery miss = known_roots::near_miss(std::ldexp(1.0, -k));
    const Decision d = decide(miss, {16, 64});
    EXPECT_NE(d.verdict, PieceVerdict::root) << "gap 2^-" << k;
    EXPECT_LE(d.pieces, 64);
    decided += d.verdict == PieceVerdict::no_root;
  }
  EXPECT_GE(decided, 2);
  EXPECT_EQ(decide(known_roots::near_miss(0.25), {16, 64}).verdict, PieceVerdict::no_root);
}

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
