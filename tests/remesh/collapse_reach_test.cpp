// A collapse pass's reach (the triangles near its moving triangles, collapse.cpp) names a
// collapse's new point by the end it lies at, when it has that end's bits, and appends it
// after the surface's vertices otherwise. Passes whose collapses go, at random, into
// either end, to a lifted midpoint, or beyond an end (a long motion), mixed in one pass,
// on crumpled stacks at 2^0 and 2^+-1000: every collapse the pass does not defer has the
// verdict it has alone (collapse_edge, which runs pair CCD on every pair with a moving
// corner: another exact route), and a blocker when it has one alone.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "exactgeo/remesh/operations.hpp"
#include "remesh/stacked_sheets.hpp"
#include "support/seed.hpp"

namespace exactgeo::remesh {
namespace {

TEST(CollapseReach, NewPointsAtAnEndAndElsewhereInOnePassDecideAsAlone) {
  auto rng = testing::seeded_engine("remesh.collapse_reach");
  std::map<std::string, int> tally;
  for (const int exponent : {0, 1000, -1000}) {
    Surface start = testing::stack(3, 6, rng, 0.2);
    testing::crumple(start, rng);
    Surface s = testing::times_power_of_two(start, exponent);
    std::uniform_int_distribution<int> lift(-40, 40);  // in steps of 2^-7
    std::uniform_int_distribution<int> kind(0, 3);
    for (int pass = 0; pass < 5; ++pass) {
      std::vector<Edge> edges = s.edges();
      std::shuffle(edges.begin(), edges.end(), rng);
      std::vector<Collapse> collapses;
      for (const Edge& e : edges) {
        const Point3 &a = s.vertices[e[0]], &b = s.vertices[e[1]];
        const double up = std::ldexp(lift(rng), exponent - 7);
        Point3 to = a;
        switch (kind(rng)) {
          case 0:
            break;
          case 1:
            to = b;
            break;
          case 2:
            to = {(a[0] + b[0]) / 2, (a[1] + b[1]) / 2, (a[2] + b[2]) / 2 + up};
            break;
          default:  // beyond a, away from b
            to = {a[0] + (a[0] - b[0]), a[1] + (a[1] - b[1]), a[2] + up};
            break;
        }
        collapses.push_back({e[0], e[1], to});
      }
      const Surface before = s;
      const std::vector<Outcome> done = collapse_edges(s, collapses);
      for (std::size_t i = 0; i < done.size(); ++i) {
        ++tally[std::string(to_string(done[i].verdict))];
        if (done[i].verdict == Verdict::deferred) continue;
        Surface copy = before;
        const Outcome single = collapse_edge(copy, collapses[i].a, collapses[i].b, collapses[i].to);
        EXPECT_EQ(single.verdict, done[i].verdict)
            << "2^" << exponent << ", pass " << pass << ", collapse " << i << ": alone "
            << single.reason << "; in the pass " << done[i].reason;
        EXPECT_EQ(single.blocker.has_value(), done[i].blocker.has_value())
            << "2^" << exponent << ", pass " << pass << ", collapse " << i;
      }
      if (::testing::Test::HasFailure()) return;
    }
  }
  for (const auto& [what, count] : tally)
    std::cout << what << ": " << count << "\n";
  EXPECT_GT(tally["applied"], 0);
  EXPECT_GT(tally["refused (collision)"], 0);
}

}  // namespace
}  // namespace exactgeo::remesh
