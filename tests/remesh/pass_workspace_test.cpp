// A PassWorkspace carries nothing from one pass to the next but storage: passes of
// splits, collapses and flips on several random surfaces (crumpled stacks of bumpy
// sheets, at 2^0 and 2^+-1000), all through one workspace, give the same outcomes and
// leave the same surfaces as the same passes with none (each pass its own). The surfaces
// come in decreasing and increasing sizes, so that a pass finds the workspace's arrays
// longer, and shorter, than it needs.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "exactgeo/remesh/operations.hpp"
#include "remesh/stacked_sheets.hpp"
#include "support/seed.hpp"

namespace exactgeo::remesh {
namespace {

using testing::crumple;
using testing::stack;

/// The proposals of one pass: every edge, in a random order, with a point for a split or
/// a collapse (the midpoint, lifted by a random multiple of 2^-7 or not; for a collapse
/// on an even pass, its first end).
struct Proposals {
  std::vector<Split> splits;
  std::vector<Collapse> collapses;
  std::vector<Edge> flips;
};

Proposals propose(const Surface& s, int pass, int exponent, std::mt19937_64& rng) {
  std::uniform_int_distribution<int> lift(-40, 40);
  std::vector<Edge> edges = s.edges();
  std::shuffle(edges.begin(), edges.end(), rng);
  Proposals out;
  for (const Edge& e : edges) {
    const Point3& a = s.vertices[e[0]];
    const Point3& b = s.vertices[e[1]];
    const double up = pass % 3 == 2 ? 0.0 : std::ldexp(lift(rng), exponent - 7);
    const Point3 mid{(a[0] + b[0]) / 2, (a[1] + b[1]) / 2, (a[2] + b[2]) / 2 + up};
    out.splits.push_back({e[0], e[1], mid});
    out.collapses.push_back({e[0], e[1], pass % 2 == 0 ? a : mid});
  }
  out.flips = std::move(edges);
  return out;
}

void expect_same(const std::vector<Outcome>& kept, const std::vector<Outcome>& fresh,
                 const std::string& where, std::map<std::string, int>& tally) {
  ASSERT_EQ(kept.size(), fresh.size()) << where;
  for (std::size_t i = 0; i < kept.size(); ++i) {
    EXPECT_EQ(kept[i].verdict, fresh[i].verdict) << where << ", operation " << i;
    EXPECT_EQ(kept[i].reason, fresh[i].reason) << where << ", operation " << i;
    EXPECT_EQ(kept[i].blocker, fresh[i].blocker) << where << ", operation " << i;
    EXPECT_EQ(kept[i].new_vertex, fresh[i].new_vertex) << where << ", operation " << i;
    ++tally[std::string(to_string(kept[i].verdict))];
  }
}

void expect_same(const Surface& kept, const Surface& fresh, const std::string& where) {
  EXPECT_EQ(kept.vertices, fresh.vertices) << where;
  EXPECT_EQ(kept.triangles, fresh.triangles) << where;
  EXPECT_EQ(kept.fixed, fresh.fixed) << where;
}

TEST(PassWorkspace, AReusedWorkspaceAnswersAsAFreshOne) {
  auto rng = testing::seeded_engine("remesh.pass_workspace");
  PassWorkspace workspace;  // one for every pass below
  std::map<std::string, int> tally;
  for (const int exponent : {0, 1000, -1000}) {
    for (const int n : {7, 4, 6}) {
      Surface start = stack(3, n, rng, 0.2);
      crumple(start, rng);
      Surface kept = testing::times_power_of_two(start, exponent), fresh = kept;
      for (int pass = 0; pass < 4; ++pass) {
        const std::string where = "2^" + std::to_string(exponent) + ", n " + std::to_string(n) +
                                  ", pass " + std::to_string(pass);
        Proposals p = propose(kept, pass, exponent, rng);
        expect_same(split_edges(kept, p.splits, &workspace), split_edges(fresh, p.splits),
                    where + ", splits", tally);
        expect_same(kept, fresh, where + ", after the splits");
        // The collapses and flips of the surface as the splits left it.
        p = propose(kept, pass, exponent, rng);
        expect_same(collapse_edges(kept, p.collapses, &workspace),
                    collapse_edges(fresh, p.collapses), where + ", collapses", tally);
        expect_same(kept, fresh, where + ", after the collapses");
        p = propose(kept, pass, exponent, rng);
        expect_same(flip_edges(kept, p.flips, &workspace), flip_edges(fresh, p.flips),
                    where + ", flips", tally);
        expect_same(kept, fresh, where + ", after the flips");
        if (::testing::Test::HasFailure()) return;
      }
    }
  }
  for (const auto& [verdict, count] : tally)
    std::cout << verdict << ": " << count << "\n";
  // Every path of the passes was taken (the arrays of each were filled and read).
  EXPECT_GT(tally["applied"], 0);
  EXPECT_GT(tally["deferred"], 0);
  EXPECT_GT(tally["refused (collision)"], 0);
  EXPECT_GT(tally["refused (topology)"], 0);
}

TEST(PassWorkspace, AMovedWorkspaceAndOneMovedFromBothServe) {
  auto rng = testing::seeded_engine("remesh.pass_workspace_moved");
  Surface start = stack(2, 4, rng, 0.2);
  crumple(start, rng);
  PassWorkspace first;
  Surface a = start, b = start, c = start;
  const Proposals p = propose(start, 0, 0, rng);
  const std::vector<Outcome> by_first = split_edges(a, p.splits, &first);
  PassWorkspace second(std::move(first));
  const std::vector<Outcome> by_second = split_edges(b, p.splits, &second);
  const std::vector<Outcome> by_moved_from = split_edges(c, p.splits, &first);  // NOLINT
  std::map<std::string, int> tally;
  expect_same(by_second, by_first, "moved", tally);
  expect_same(by_moved_from, by_first, "moved from", tally);
  expect_same(b, a, "moved");
  expect_same(c, a, "moved from");
  EXPECT_GT(tally["applied"], 0);
}

}  // namespace
}  // namespace exactgeo::remesh
