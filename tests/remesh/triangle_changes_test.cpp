// What a pass reports it changed (TriangleChanges, operations.hpp) is what it changed:
// random passes of splits, collapses and flips on crumpled stacks of bumpy sheets (at 2^0
// and 2^+-1000, one TriangleChanges reused by every pass), each report checked against the
// surfaces before and after the pass. Every triangle the report does not name is found,
// with the same corners, at index_after of its index, every rewritten one there with new
// corners, the removed ones are gone, the appended ones come last, and the moved vertices
// are exactly those whose position changed. A pass asked for a report makes the same
// operations as one that is not.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "exactgeo/remesh/operations.hpp"
#include "remesh/stacked_sheets.hpp"
#include "support/scale_names.hpp"
#include "support/seed.hpp"

namespace exactgeo::remesh {
namespace {

using testing::crumple;
using testing::stack;
using testing::times_power_of_two;

/// Every edge of `s` in a random order, with a point for a split (the midpoint, lifted by a
/// random multiple of 2^(exponent - 7) or not) or a collapse (its first end, or that point).
struct ReportProposals {
  std::vector<Split> splits;
  std::vector<Collapse> collapses;
  std::vector<Edge> flips;
};

ReportProposals report_proposals(const Surface& s, int exponent, std::mt19937_64& rng) {
  std::uniform_int_distribution<int> lift(-40, 40);
  std::bernoulli_distribution lifted(0.5), at_end(0.5);
  std::vector<Edge> edges = s.edges();
  std::shuffle(edges.begin(), edges.end(), rng);
  ReportProposals out;
  for (const Edge& e : edges) {
    const Point3& a = s.vertices[e[0]];
    const Point3& b = s.vertices[e[1]];
    const double up = lifted(rng) ? std::ldexp(lift(rng), exponent - 7) : 0.0;
    const Point3 mid{(a[0] + b[0]) / 2, (a[1] + b[1]) / 2, (a[2] + b[2]) / 2 + up};
    out.splits.push_back({e[0], e[1], mid});
    out.collapses.push_back({e[0], e[1], at_end(rng) ? a : mid});
  }
  out.flips = std::move(edges);
  return out;
}

/// What the reports of the test held, summed.
struct ReportTally {
  std::size_t removed = 0, rewritten = 0, added = 0, moved = 0, passes_changing_nothing = 0;
};

/// The report of a pass from `before` to `after` against the two surfaces.
void expect_report_of(const Surface& before, const Surface& after, const TriangleChanges& c,
                      const std::string& where, ReportTally& tally) {
  const std::size_t n = before.triangles.size();
  ASSERT_EQ(c.triangles_before, n) << where;
  std::vector<char> removed(n, 0), rewritten(n, 0);
  for (std::size_t i = 0; i < c.removed.size(); ++i) {
    const TriangleChanges::Was& w = c.removed[i];
    ASSERT_LT(w.triangle, n) << where;
    if (i > 0) {
      EXPECT_LT(c.removed[i - 1].triangle, w.triangle) << where << ": not ascending";
    }
    EXPECT_EQ(w.corners, before.triangles[w.triangle]) << where << ", removed " << w.triangle;
    removed[w.triangle] = 1;
  }
  for (std::size_t i = 0; i < c.rewritten.size(); ++i) {
    const TriangleChanges::Was& w = c.rewritten[i];
    ASSERT_LT(w.triangle, n) << where;
    if (i > 0) {
      EXPECT_LT(c.rewritten[i - 1].triangle, w.triangle) << where << ": not ascending";
    }
    EXPECT_EQ(w.corners, before.triangles[w.triangle]) << where << ", rewritten " << w.triangle;
    EXPECT_FALSE(removed[w.triangle]) << where << ", rewritten and removed " << w.triangle;
    rewritten[w.triangle] = 1;
  }
  // The triangles kept, in order, at their indices less the removed ones below them.
  std::size_t below = 0;
  for (std::size_t t = 0; t < n; ++t) {
    if (removed[t]) {
      ++below;
      continue;
    }
    const std::size_t now = t - below;
    EXPECT_EQ(c.index_after(t), now) << where << ", triangle " << t;
    ASSERT_LT(now, after.triangles.size()) << where;
    if (rewritten[t]) {
      EXPECT_NE(after.triangles[now], before.triangles[t]) << where << ", triangle " << t;
    } else {
      EXPECT_EQ(after.triangles[now], before.triangles[t]) << where << ", triangle " << t;
    }
  }
  EXPECT_EQ(c.first_added(), n - below) << where;
  // Vertices: appended, or moved as reported.
  ASSERT_GE(after.vertices.size(), before.vertices.size()) << where;
  std::vector<VertexIndex> moved;
  for (VertexIndex v = 0; v < before.vertices.size(); ++v)
    if (after.vertices[v] != before.vertices[v]) moved.push_back(v);
  EXPECT_EQ(c.moved, moved) << where;
  tally.removed += c.removed.size();
  tally.rewritten += c.rewritten.size();
  tally.added += after.triangles.size() - c.first_added();
  tally.moved += c.moved.size();
  if (before.triangles == after.triangles) ++tally.passes_changing_nothing;
}

void expect_same_outcomes(const std::vector<Outcome>& reported,
                          const std::vector<Outcome>& unreported, const std::string& where) {
  ASSERT_EQ(reported.size(), unreported.size()) << where;
  for (std::size_t i = 0; i < reported.size(); ++i) {
    EXPECT_EQ(reported[i].verdict, unreported[i].verdict) << where << ", operation " << i;
    EXPECT_EQ(reported[i].reason, unreported[i].reason) << where << ", operation " << i;
    EXPECT_EQ(reported[i].blocker, unreported[i].blocker) << where << ", operation " << i;
    EXPECT_EQ(reported[i].new_vertex, unreported[i].new_vertex) << where << ", operation " << i;
  }
}

class TriangleChangesAt : public ::testing::TestWithParam<int> {};

TEST_P(TriangleChangesAt, APassReportsWhatItChanged) {
  const int exponent = GetParam();
  auto rng = testing::seeded_engine("remesh.triangle_changes." + std::to_string(exponent));
  TriangleChanges changes;  // one for every pass: each fills it anew
  PassWorkspace workspace;
  ReportTally tally;
  const std::size_t surfaces = testing::scaled_trials(4, 2);
  for (std::size_t k = 0; k < surfaces; ++k) {
    Surface start = stack(3, 5, rng, 0.2);
    crumple(start, rng);
    Surface s = times_power_of_two(start, exponent);
    for (int pass = 0; pass < 4; ++pass) {
      const std::string where = "2^" + std::to_string(exponent) + ", surface " + std::to_string(k) +
                                ", pass " + std::to_string(pass);
      // Each kind of pass, on the surface the one before left, reported and not.
      for (int kind = 0; kind < 3; ++kind) {
        const ReportProposals p = report_proposals(s, exponent, rng);
        const Surface before = s;
        Surface unreported = s;
        std::vector<Outcome> with, without;
        if (kind == 0) {
          with = split_edges(s, p.splits, &workspace, &changes);
          without = split_edges(unreported, p.splits);
        } else if (kind == 1) {
          with = collapse_edges(s, p.collapses, &workspace, &changes);
          without = collapse_edges(unreported, p.collapses);
        } else {
          with = flip_edges(s, p.flips, &workspace, &changes);
          without = flip_edges(unreported, p.flips);
        }
        const std::string what = where + (kind == 0   ? ", splits"
                                          : kind == 1 ? ", collapses"
                                                      : ", flips");
        expect_same_outcomes(with, without, what);
        EXPECT_EQ(s.triangles, unreported.triangles) << what;
        EXPECT_EQ(s.vertices, unreported.vertices) << what;
        expect_report_of(before, s, changes, what, tally);
        if (::testing::Test::HasFailure()) return;
      }
    }
    // A pass that applies nothing reports nothing (the last report forgotten).
    const Surface before = s;
    flip_edges(s, std::vector<Edge>{}, &workspace, &changes);
    expect_report_of(before, s, changes, "an empty pass", tally);
    EXPECT_TRUE(changes.removed.empty() && changes.rewritten.empty() && changes.moved.empty());
  }
  std::cout << "removed " << tally.removed << ", rewritten " << tally.rewritten << ", added "
            << tally.added << ", moved " << tally.moved << "\n";
  // Every part of a report was filled.
  EXPECT_GT(tally.removed, 0U);
  EXPECT_GT(tally.rewritten, 0U);
  EXPECT_GT(tally.added, 0U);
  EXPECT_GT(tally.moved, 0U);
}

INSTANTIATE_TEST_SUITE_P(Scales, TriangleChangesAt, ::testing::Values(0, 1000, -1000),
                         exactgeo::testing::scale_name);

}  // namespace
}  // namespace exactgeo::remesh
