// The search by dyadic time splitting (internal/root_search.hpp): on queries whose roots
// are known exactly, the brackets (no root before the start, a root inside, as narrow as
// asked or as the depth limit or the doubles allow), the depth limit honoured exactly,
// conservative answers only where no piece can prove or exclude the root (a tangential
// contact), nothing found on misses; then on random queries against the exact oracle of
// min_separation_oracle.hpp at δ = 0.

#include "exactgeo/ccd/internal/root_search.hpp"

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include "ccd/known_roots.hpp"
#include "ccd/query_transforms.hpp"
#include "ccd/separation/min_separation_oracle.hpp"
#include "exactgeo/predicates/kernel/signs.hpp"
#include "support/generators.hpp"
#include "support/seed.hpp"

namespace exactgeo::ccd::internal {
namespace {

using testing::Rng;

struct Searched {
  std::optional<FoundRoot> found;
  int deepest = 0;
};

/// The search on the whole step of q, its parity computed first as the exact method does;
/// with or without the coplanarity certificate.
template <class Query>
Searched search(const Query& q, int max_depth, double width, bool with_coplanarity = true) {
  const auto corners = corner_images(q);
  constexpr std::size_t C = std::tuple_size_v<decltype(corners)>;
  const auto step = whole_step<C>(corners);
  EXPECT_TRUE(step.has_value());
  if (!step) return {};
  const RootParity parity = root_parity(kernel::ExactSigns{}, corners).parity;
  RootSearch<C> s(max_depth, width,
                  with_coplanarity ? Coplanarity::of(corners) : std::optional<Coplanarity>());
  Searched out;
  out.found = s.earliest(*step, parity);
  out.deepest = s.deepest();
  return out;
}

std::string bracket(const FoundRoot& f) {
  char text[128];
  std::snprintf(text, sizeof text, "[%a, %a]%s", f.start, f.end, f.conservative ? " unproven" : "");
  return text;
}

/// A proven bracket of the earliest root t0 (the earliest of the query's roots), at most
/// `width` wide unless one double spacing is wider.
void expect_bracket(const Searched& s, const mpq_class& t0, double width, const std::string& what) {
  ASSERT_TRUE(s.found.has_value()) << what;
  const FoundRoot& f = *s.found;
  EXPECT_FALSE(f.conservative) << what << " " << bracket(f);
  EXPECT_LE(mpq_class(f.start), t0) << what << " " << bracket(f);
  EXPECT_GE(mpq_class(f.end), t0) << what << " " << bracket(f);
  EXPECT_TRUE(f.end - f.start <= width || std::nextafter(f.start, 2.0) == f.end)
      << what << " " << bracket(f);
}

/// The vertex falling through the triangle at t* = 3/10, at every width.
TEST(RootSearch, OneRootIsBracketedAtEveryWidth) {
  const VertexFaceQuery q = known_roots::falling_vertex();
  const mpq_class t_star(3, 10);
  for (int k = 0; k <= 50; k += 5) {
    const double width = std::ldexp(1.0, -k);
    for (const bool cubic : {true, false}) {
      const Searched s = search(q, 64, width, cubic);
      expect_bracket(s, t_star, width, "width 2^-" + std::to_string(k));
      if (k > 0) {
        EXPECT_EQ(s.found->end - s.found->start, width);  // the dyadic piece holding t*
      }
    }
  }
  // Collision only (width 1): the whole step's odd parity answers at once.
  const Searched whole = search(q, 64, 1.0);
  ASSERT_TRUE(whole.found.has_value());
  EXPECT_EQ(whole.found->start, 0.0);
  EXPECT_EQ(whole.found->end, 1.0);
  EXPECT_EQ(whole.deepest, 0);
}

/// The depth limit, exactly: a piece 2^-max_depth wide holding t*, proven by its parity at
/// the last level, and no piece deeper.
TEST(RootSearch, DepthLimitIsHonouredExactly) {
  const VertexFaceQuery q = known_roots::falling_vertex();
  for (const int limit : {0, 1, 2, 3, 7, 8, 9, 17, 30}) {
    const Searched s = search(q, limit, 0x1p-60);
    expect_bracket(s, mpq_class(3, 10), std::ldexp(1.0, -limit), "limit " + std::to_string(limit));
    EXPECT_EQ(s.found->end - s.found->start, std::ldexp(1.0, -limit));
    EXPECT_EQ(s.deepest, limit);
  }
  // Past the doubles' resolution the pieces stop at one double spacing: 2^-54 at 3/10,
  // whatever the limit (kMaxSearchDepth bounds it too).
  for (const int limit : {54, 100, 1000}) {
    const Searched s = search(q, limit, 0.0);
    expect_bracket(s, mpq_class(3, 10), 0.0, "limit " + std::to_string(limit));
    EXPECT_EQ(s.found->end, std::nextafter(s.found->start, 1.0));
    EXPECT_EQ(s.deepest, 54);
  }
}

/// Through and back (parity even over the step): the search must find the first root
/// itself; it lands on a piece's end, a boundary root of that piece. Asked for one double
/// spacing, the pieces just before the contact are too close to it for the culling
/// planes' double normals: the first of them is reported unproven, never a piece after
/// the contact.
TEST(RootSearch, TwoRootsFoundFirstOneBracketed) {
  struct Case {
    EdgeEdgeQuery q;
    mpq_class first;
    mpq_class second;
    const char* what;
  };
  const std::vector<Case> cases{
      {known_roots::through_and_back(), mpq_class(1, 4), mpq_class(3, 4), "through and back"},
      {known_roots::through_and_back_late(), mpq_class(5, 8), mpq_class(7, 8), "late"},
      {time_reversed(known_roots::through_and_back_late()), mpq_class(1, 8), mpq_class(3, 8),
       "late reversed"},
  };
  for (const Case& c : cases) {
    for (const double width : {0.5, 0x1p-10, 0x1p-30}) {
      for (const bool cubic : {true, false}) {
        expect_bracket(search(c.q, 64, width, cubic), c.first, width,
                       std::string(c.what) + " width " + std::to_string(width));
      }
    }
    const Searched finest = search(c.q, 64, 0.0);
    ASSERT_TRUE(finest.found.has_value()) << c.what;
    EXPECT_LE(mpq_class(finest.found->start), c.first) << c.what << bracket(*finest.found);
    EXPECT_EQ(finest.found->end, std::nextafter(finest.found->start, 1.0)) << c.what;
    if (!finest.found->conservative) {
      EXPECT_GE(mpq_class(finest.found->end), c.first) << c.what << bracket(*finest.found);
    }
    // Collision only: some piece with a proven root, holding one of the two.
    const Searched any = search(c.q, 64, 1.0);
    ASSERT_TRUE(any.found.has_value()) << c.what;
    EXPECT_FALSE(any.found->conservative) << c.what;
    const mpq_class start(any.found->start), end(any.found->end);
    EXPECT_TRUE((start <= c.first && c.first <= end) || (start <= c.second && c.second <= end))
        << c.what << " " << bracket(*any.found);
    // No splitting allowed: the even step is reported, unproven.
    const Searched none = search(c.q, 0, 0x1p-10);
    ASSERT_TRUE(none.found.has_value()) << c.what;
    EXPECT_TRUE(none.found->conservative) << c.what;
    EXPECT_EQ(none.found->start, 0.0);
    EXPECT_EQ(none.found->end, 1.0);
  }
}

/// A tangential contact at t = 1/3: every piece holding it has even parity and cannot be
/// culled, so the answer at the depth limit is conservative; nothing before it is
/// reported. The misses are free once the search may split; at depth limit 0 their even
/// step is reported, unproven.
TEST(RootSearch, TangentIsConservativeMissesAreFree) {
  for (const int limit : {6, 12, 20}) {
    for (const double width : {1.0, 0x1p-40}) {
      const Searched s = search(known_roots::tangent_at_one_third(), limit, width);
      ASSERT_TRUE(s.found.has_value()) << limit;
      EXPECT_TRUE(s.found->conservative) << limit << " " << bracket(*s.found);
      EXPECT_LE(mpq_class(s.found->start), mpq_class(1, 3)) << limit;
      EXPECT_EQ(s.deepest, limit);
    }
  }
  for (const int limit : {10, 64}) {
    EXPECT_FALSE(search(known_roots::through_and_back_beside(), limit, 0x1p-20).found) << limit;
    EXPECT_FALSE(search(known_roots::near_miss(0.0625), limit, 1.0).found) << limit;
  }
  for (const EdgeEdgeQuery& miss :
       {known_roots::through_and_back_beside(), known_roots::near_miss(0.0625)}) {
    const Searched s = search(miss, 0, 1.0);
    ASSERT_TRUE(s.found.has_value());
    EXPECT_TRUE(s.found->conservative);
  }
  // A hair's breadth below the tangent: free once the depth resolves it, never a proven root.
  for (int k = 10; k <= 50; k += 10) {
    const Searched s = search(known_roots::near_miss(std::ldexp(1.0, -k)), 64, 0x1p-20);
    if (s.found) {
      EXPECT_TRUE(s.found->conservative) << "gap 2^-" << k;
    }
  }
}

/// Random queries (grid, one ulp off, generic, near-degenerate, and grid queries scaled by
/// 2^+-k, k in [200, 1000], whose truth is the unscaled query's) against the exact oracle:
/// a proven root brackets the earliest contact, an unproven one starts no later than it,
/// and nothing found means no contact.
template <class Query>
void agrees_with_the_oracle(const char* stream) {
  Rng rng = testing::seeded_engine(stream);
  int proven = 0, free = 0;
  for (int i = 0; i < 50; ++i) {
    Query q;
    Query truth_of;
    switch (i % 5) {
      case 2: {
        truth_of = random_dyadic_query<Query>(rng);
        const int magnitude = testing::uniform_int(rng, 200, 1000);
        const int k = testing::uniform_int(rng, 0, 1) ? magnitude : -magnitude;
        q = mapped(truth_of, [k](const Point3& x) { return testing::scaled(x, k); });
        break;
      }
      case 4:
        q = truth_of = near_degenerate_query<Query>(rng, 0);
        break;
      default:
        q = truth_of = i % 3 == 0 ? random_dyadic_query<Query>(rng) : varied_query<Query>(rng, i);
        break;
    }
    const testing::MinSeparationAnswer truth = testing::min_separation_oracle(truth_of, 0.0);
    for (const double width : {1.0, 0x1p-16}) {
      const Searched s = search(q, 64, width);
      const std::string what = std::string(stream) + " #" + std::to_string(i);
      if (!s.found) {
        EXPECT_FALSE(truth.within) << what;
        ++free;
        continue;
      }
      const FoundRoot& f = *s.found;
      if (truth.within) {
        EXPECT_LE(mpq_class(f.start), truth.earliest_hi) << what << bracket(f);
      }
      if (f.conservative) continue;
      EXPECT_TRUE(truth.within) << what;
      EXPECT_LE(f.end - f.start, width) << what;
      if (width < 1.0) {
        EXPECT_GE(mpq_class(f.end), truth.earliest_lo) << what << bracket(f);
      }
      ++proven;
    }
    if (::testing::Test::HasFailure()) return;
  }
  EXPECT_GT(proven, 5);
  EXPECT_GT(free, 20);
}

TEST(RootSearch, VertexFaceAgreesWithTheOracle) {
  agrees_with_the_oracle<VertexFaceQuery>("root-search-vf");
}

TEST(RootSearch, EdgeEdgeAgreesWithTheOracle) {
  agrees_with_the_oracle<EdgeEdgeQuery>("root-search-ee");
}

}  // namespace
}  // namespace exactgeo::ccd::internal
