// The entry points of ccd.hpp, exact (any-root) method: the cases parity cannot see, time of
// impact against exact root times, symmetries, agreement with parity where parity decides,
// and the public data.

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "ccd/query_transforms.hpp"
#include "exactgeo/ccd/ccd.hpp"
#include "exactgeo/ccd/files/query_files.hpp"
#include "exactgeo/ccd/root_parity.hpp"
#include "support/generators.hpp"
#include "support/seed.hpp"

namespace exactgeo::ccd {
namespace {

namespace fs = std::filesystem;
using testing::Rng;

Result exact(const VertexFaceQuery& q, const Options& o = {}) {
  return vertex_face_ccd(q, o);
}
Result exact(const EdgeEdgeQuery& q, const Options& o = {}) {
  return edge_edge_ccd(q, o);
}
RootParity parity(const VertexFaceQuery& q) {
  return vertex_face_root_parity(q).parity;
}
RootParity parity(const EdgeEdgeQuery& q) {
  return edge_edge_root_parity(q).parity;
}

TEST(ExactCcd, HourglassIsACollision) {
  const VertexFaceQuery q{{0.1, 0.1, 0.1}, {0, 0, 1}, {1, 0, 1}, {0, 1, 1},
                          {0.1, 0.1, 0.1}, {0, 0, 0}, {0, 1, 0}, {1, 0, 0}};
  EXPECT_TRUE(exact(q).collision);
}

/// One query of a data file.
struct DataQuery {
  std::string where;
  bool edge_edge;
  ccd::QueryRecord record;
};

std::vector<DataQuery> queries_under(const fs::path& root) {
  std::vector<DataQuery> out;
  for (const ccd::QueryFile& file : ccd::read_query_files({root.string()})) {
    for (std::size_t i = 0; i < file.records.size(); ++i) {
      out.push_back({file.path + " #" + std::to_string(i), file.type == ccd::QueryType::edge_edge,
                     file.records[i]});
    }
  }
  return out;
}

std::vector<DataQuery> bundled_queries() {
  return queries_under(fs::path(EXACTGEO_TEST_DATA_DIR) / "ccd");
}

template <class F>
auto on_query(const DataQuery& d, F&& f) {
  return d.edge_edge ? f(ccd::edge_edge_query(d.record)) : f(ccd::vertex_face_query(d.record));
}

TEST(ExactCcdData, BundledDataHasNoErrorsAndSeesWhatParityMisses) {
  int queries = 0, two_root_cases = 0, subdivided = 0;
  for (const DataQuery& d : bundled_queries()) {
    const Result r = on_query(d, [](const auto& q) { return exact(q); });
    const RootParity p = on_query(d, [](const auto& q) { return parity(q); });
    ASSERT_EQ(r.collision, *d.record.truth) << d.where;
    ASSERT_NE(r.decided_by, DecidedBy::depth_limit) << d.where;
    if (p != RootParity::even) {
      ASSERT_TRUE(r.collision) << d.where;  // exact never contradicts parity
    } else if (r.collision) {
      // Parity missed it: an even number of interior roots, found by splitting time
      // (pieces, or polynomials alone).
      ASSERT_TRUE(r.decided_by == DecidedBy::subdivision || r.decided_by == DecidedBy::polynomials)
          << d.where;
      ++two_root_cases;
    }
    subdivided += r.decided_by == DecidedBy::subdivision || r.decided_by == DecidedBy::polynomials;
    ++queries;
  }
  std::printf("[ info     ] %d bundled queries, %d two-root collisions, %d decided by splitting\n",
              queries, two_root_cases, subdivided);
  EXPECT_GT(two_root_cases, 0);
}

template <class Query>
Query scaled_query(const Query& q, int k) {
  return mapped(q, [&](const Point3& p) { return testing::scaled(p, k); });
}

template <class Query>
bool exactly_scalable(Query q, int k) {
  for (Point3* p : points(q)) {
    for (const double x : *p) {
      const double y = std::ldexp(x, k);
      if (!std::isfinite(y) || std::ldexp(y, -k) != x) return false;
    }
  }
  return true;
}

TEST(ExactCcdData, SymmetriesChangeNothing) {
  Rng rng = testing::seeded_engine("exact-ccd-symmetries");
  int scaled = 0;
  const std::vector<DataQuery> data = bundled_queries();
  for (std::size_t i = 0; i < data.size(); i += 7) {
    const DataQuery& d = data[i];
    const bool expected = *d.record.truth;
    on_query(d, [&](const auto& q) {
      // Scaling by 2^k, toward both ends of the double range; when some coordinate would
      // lose bits (subnormal) the scaled query is another query, so k is halved until
      // scaling is exact.
      int k = testing::uniform_int(rng, -1000, 1000);
      while (!exactly_scalable(q, k))
        k /= 2;
      ++scaled;
      EXPECT_EQ(exact(scaled_query(q, k)).collision, expected) << d.where << " scaled 2^" << k;
      EXPECT_EQ(exact(mapped(q,
                             [](const Point3& p) {
                               return Point3{-p[0], p[1], p[2]};
                             }))
                    .collision,
                expected)
          << d.where << " mirrored";
      EXPECT_EQ(exact(mapped(q,
                             [](const Point3& p) {
                               return Point3{p[2], p[0], p[1]};
                             }))
                    .collision,
                expected)
          << d.where << " axes permuted";
      EXPECT_EQ(exact(time_reversed(q)).collision, expected) << d.where << " time reversed";
      return 0;
    });
  }
  EXPECT_GT(scaled, 100);
}

/// A query far from magnitude 1 is decided as its copy at magnitude 1 (largest coordinate
/// in [1/2, 1)): the same stage, depth and time of impact, so the filters do their work at
/// 2^±900 as at 1 instead of every sign falling through to expansions.
TEST(ExactCcdData, ExtremeMagnitudesAreDecidedAsAtMagnitudeOne) {
  int compared = 0;
  const std::vector<DataQuery> data = bundled_queries();
  Options toi;
  toi.time_of_impact_width = 0x1p-20;
  for (std::size_t i = 0; i < data.size(); i += 3) {
    on_query(data[i], [&](const auto& q) {
      double largest = 0;
      auto copy = q;
      for (Point3* p : points(copy))
        for (const double x : *p)
          largest = std::max(largest, std::fabs(x));
      int e = 0;
      std::frexp(largest, &e);
      const auto unit = scaled_query(q, -e);
      for (const int k : {-900, 900}) {
        if (!exactly_scalable(unit, k)) continue;
        const auto far = scaled_query(unit, k);
        for (const Options& options : {Options{}, toi}) {
          const Result a = exact(far, options), b = exact(unit, options);
          EXPECT_EQ(a.collision, b.collision) << data[i].where << " 2^" << k;
          EXPECT_EQ(a.decided_by, b.decided_by) << data[i].where << " 2^" << k;
          EXPECT_EQ(a.depth, b.depth) << data[i].where << " 2^" << k;
          EXPECT_EQ(a.time_of_impact.has_value(), b.time_of_impact.has_value());
          if (a.time_of_impact && b.time_of_impact) {
            EXPECT_EQ(a.time_of_impact->start, b.time_of_impact->start) << data[i].where;
            EXPECT_EQ(a.time_of_impact->end, b.time_of_impact->end) << data[i].where;
          }
        }
        ++compared;
      }
      return 0;
    });
  }
  EXPECT_GT(compared, 400);
}

TEST(ExactCcd, RandomDyadicQueriesAgreeWithParityWhereParityDecides) {
  Rng rng = testing::seeded_engine("exact-ccd-dyadic");
  int even = 0;
  for (int i = 0; i < 3000; ++i) {
    const auto vfq = random_dyadic_query<VertexFaceQuery>(rng);
    const auto eeq = random_dyadic_query<EdgeEdgeQuery>(rng);
    for (const auto& [r, p] :
         {std::pair{exact(vfq), parity(vfq)}, std::pair{exact(eeq), parity(eeq)}}) {
      if (p != RootParity::even) {
        ASSERT_TRUE(r.collision);
      } else {
        ++even;
      }
    }
    // Relabelled and mirrored queries give the same exact answer.
    const VertexFaceQuery flipped{vfq.v_t0, vfq.f0_t0, vfq.f2_t0, vfq.f1_t0,
                                  vfq.v_t1, vfq.f0_t1, vfq.f2_t1, vfq.f1_t1};
    ASSERT_EQ(exact(flipped).collision, exact(vfq).collision);
    const EdgeEdgeQuery swapped{eeq.eb0_t0, eeq.eb1_t0, eeq.ea0_t0, eeq.ea1_t0,
                                eeq.eb0_t1, eeq.eb1_t1, eeq.ea0_t1, eeq.ea1_t1};
    ASSERT_EQ(exact(swapped).collision, exact(eeq).collision);
  }
  EXPECT_GT(even, 1000);
}

/// A vertex falling straight through the triangle from height h0 > 0 to h1 < 0 hits it at
/// t* = h0 / (h0 - h1). The interval must contain t*, be at most the requested width, and
/// (since t* is the only root) start no later than t*.
TEST(ExactCcd, TimeOfImpactBracketsTheExactRootTime) {
  Rng rng = testing::seeded_engine("exact-ccd-toi");
  for (int i = 0; i < 500; ++i) {
    const double h0 = testing::uniform(rng, 1e-3, 2);
    const double h1 = -testing::uniform(rng, 1e-3, 2);
    const double width = std::ldexp(1.0, -testing::uniform_int(rng, 1, 40));
    const VertexFaceQuery q{{0.25, 0.25, h0}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0},
                            {0.25, 0.25, h1}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    Options o;
    o.time_of_impact_width = width;
    const Result r = exact(q, o);
    ASSERT_TRUE(r.collision);
    ASSERT_TRUE(r.time_of_impact.has_value());
    const mpq_class t_star = mpq_class(h0) / (mpq_class(h0) - mpq_class(h1));
    ASSERT_LE(mpq_class(r.time_of_impact->start), t_star);
    ASSERT_GE(mpq_class(r.time_of_impact->end), t_star);
    ASSERT_LE(r.time_of_impact->end - r.time_of_impact->start, width);
  }
}

/// On every bundled two-root collision (parity even) the interval is as narrow as asked,
/// and a coarser request returns an interval containing the finer one: both searches find
/// the same earliest root.
TEST(ExactCcd, TimeOfImpactOnTwoRootCasesIsNestedAcrossWidths) {
  int checked = 0;
  for (const DataQuery& d : bundled_queries()) {
    const RootParity p = on_query(d, [](const auto& q) { return parity(q); });
    if (p != RootParity::even || !*d.record.truth) continue;
    Options o;
    o.time_of_impact_width = 0x1p-20;
    const Result r = on_query(d, [&](const auto& q) { return exact(q, o); });
    ASSERT_TRUE(r.collision) << d.where;
    ASSERT_TRUE(r.time_of_impact) << d.where;
    ASSERT_LE(r.time_of_impact->end - r.time_of_impact->start, 0x1p-20) << d.where;
    Options coarse = o;
    coarse.time_of_impact_width = 0x1p-10;
    const Result c = on_query(d, [&](const auto& q) { return exact(q, coarse); });
    ASSERT_LE(c.time_of_impact->start, r.time_of_impact->start) << d.where;
    ASSERT_GE(c.time_of_impact->end, r.time_of_impact->end) << d.where;
    ++checked;
  }
  EXPECT_GT(checked, 0);
}

/// The split depth limit: the search halves the step at most max_depth times. A vertex
/// falls through a still triangle at t* = 3/10 (not dyadic, so every level splits); asked
/// for an interval far narrower than 2^-max_depth, the search must stop exactly at the
/// limit: depth == max_depth and an interval 2^-max_depth wide that still holds t*. One
/// level more or less is what an off-by-one in the limit gives.
TEST(ExactCcd, DepthLimitIsHonouredExactly) {
  const VertexFaceQuery q{{0.25, 0.25, 3},  {0, 0, 0}, {1, 0, 0}, {0, 1, 0},
                          {0.25, 0.25, -7}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  const mpq_class t_star(3, 10);
  for (const int limit : {0, 1, 2, 3, 10}) {
    Options o;
    o.time_of_impact_width = 0x1p-40;
    o.max_depth = limit;
    const Result r = exact(q, o);
    ASSERT_TRUE(r.collision) << "max_depth " << limit;
    EXPECT_EQ(r.depth, limit) << "max_depth " << limit;
    EXPECT_EQ(r.decided_by, DecidedBy::parity) << "max_depth " << limit;  // a root, proven
    ASSERT_TRUE(r.time_of_impact.has_value());
    EXPECT_EQ(r.time_of_impact->end - r.time_of_impact->start, std::ldexp(1.0, -limit))
        << "max_depth " << limit;
    EXPECT_LE(mpq_class(r.time_of_impact->start), t_star) << "max_depth " << limit;
    EXPECT_GE(mpq_class(r.time_of_impact->end), t_star) << "max_depth " << limit;
  }
}

/// With even parity (two roots: parity cannot see them) the search needs splits to find a
/// piece with a root; at max_depth 0 it cannot split at all and must report the whole step
/// as a collision without proof (depth_limit), never as free.
TEST(ExactCcd, DepthLimitZeroOnTwoRootCasesIsConservative) {
  int checked = 0;
  for (const DataQuery& d : bundled_queries()) {
    const RootParity p = on_query(d, [](const auto& q) { return parity(q); });
    if (p != RootParity::even || !*d.record.truth) continue;
    Options o;
    o.time_of_impact_width = 0x1p-20;  // no shortcut by polynomials: the search runs
    o.max_depth = 0;
    const Result r = on_query(d, [&](const auto& q) { return exact(q, o); });
    ASSERT_TRUE(r.collision) << d.where;
    EXPECT_EQ(r.decided_by, DecidedBy::depth_limit) << d.where;
    EXPECT_EQ(r.depth, 0) << d.where;
    ASSERT_TRUE(r.time_of_impact.has_value()) << d.where;
    EXPECT_EQ(r.time_of_impact->start, 0.0) << d.where;
    EXPECT_EQ(r.time_of_impact->end, 1.0) << d.where;
    // One level deeper finds a proven root in a half (or reports that half at the limit).
    o.max_depth = 1;
    const Result deeper = on_query(d, [&](const auto& q) { return exact(q, o); });
    ASSERT_TRUE(deeper.collision) << d.where;
    EXPECT_EQ(deeper.depth, 1) << d.where;
    ASSERT_TRUE(deeper.time_of_impact.has_value()) << d.where;
    EXPECT_EQ(deeper.time_of_impact->end - deeper.time_of_impact->start, 0.5) << d.where;
    ++checked;
  }
  // The bundled two-root collisions: five edge-edge unit tests of sample-queries, one
  // edge-edge query of the cloth-funnel sample.
  EXPECT_EQ(checked, 6);
}

TEST(ExactCcdData, FullSharedSetsHaveNoErrors) {
  const fs::path root = fs::path(EXACTGEO_SHARED_DATA_DIR) / "ccd";
  if (!fs::exists(root)) GTEST_SKIP() << root << " not present";
  int queries = 0, false_positives = 0, false_negatives = 0;
  for (const DataQuery& d : queries_under(root)) {
    const Result result = on_query(d, [](const auto& q) { return exact(q); });
    ASSERT_NE(result.decided_by, DecidedBy::depth_limit) << d.where;  // every answer proven
    const bool r = result.collision;
    false_positives += r && !*d.record.truth;
    false_negatives += !r && *d.record.truth;
    ++queries;
  }
  std::printf("[ info     ] exact on %d shared queries: %d false positives, %d false negatives\n",
              queries, false_positives, false_negatives);
  EXPECT_EQ(false_positives, 0);
  EXPECT_EQ(false_negatives, 0);
  EXPECT_EQ(queries, 26917);
}

}  // namespace
}  // namespace exactgeo::ccd
