// What operations.hpp promises of every operation alike: topology is checked first, and a
// refusal says why (a boundary edge, a pinch, no such edge, a fixed vertex, a split point
// off the edge's segment); flipping a square's diagonal twice gives it back; the verdicts
// have distinct names, and an outcome is applied only with the verdict `applied`.
//
// The scene the operations' own tests share (two_sheets.hpp, the Scales/Operations tests
// of relocation_test.cpp, collapse_test.cpp, flip_test.cpp and split_test.cpp) is
// instantiated here, once for the binary, at 2^0 and 2^+-1000.

#include <gtest/gtest.h>

#include "support/scale_names.hpp"

#include <array>
#include <cmath>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "exactgeo/remesh/operations.hpp"
#include "remesh/two_sheets.hpp"

namespace exactgeo::remesh {
namespace {

using testing::kInner;
using testing::Operations;
using testing::sheets;

TEST(OperationsTopology, RefusalsSayWhy) {
  Surface surface = sheets(4, 1.0, 1.0);
  // A boundary edge cannot be flipped; a boundary vertex's inner edge cannot collapse.
  EXPECT_EQ(flip_edge(surface, 0, 1).verdict, Verdict::refused_topology);
  const Outcome pinch = collapse_edge(surface, 1, 6, {1, 1, 0});
  EXPECT_EQ(pinch.verdict, Verdict::refused_topology);
  EXPECT_NE(pinch.reason.find("pinch"), std::string::npos) << pinch.reason;
  // No such edge; a fixed vertex.
  EXPECT_EQ(split_edge(surface, 0, 24, {1, 1, 0}).verdict, Verdict::refused_topology);
  surface.fixed.assign(surface.vertices.size(), false);
  surface.fixed[kInner] = true;
  const Outcome fixed = relocate_vertex(surface, kInner, {1, 1, 0.5});
  EXPECT_EQ(fixed.verdict, Verdict::refused_topology);
  EXPECT_NE(fixed.reason.find("fixed"), std::string::npos) << fixed.reason;
  // Flipping the diagonal of a flat square twice gives it back.
  surface.fixed.clear();
  ASSERT_TRUE(flip_edge(surface, kInner, kInner + 6).applied());
  ASSERT_TRUE(flip_edge(surface, kInner + 1, kInner + 5).applied());
  EXPECT_FALSE(surface.triangles_on_edge(kInner, kInner + 6).empty());
  // A split point on the edge's line but beyond its end is refused.
  EXPECT_EQ(split_edge(surface, kInner, kInner + 1, {3, 1, 0}).verdict, Verdict::refused_topology);
}

TEST(OperationsVerdicts, NamesAreDistinctAndOnlyAppliedIsApplied) {
  EXPECT_EQ(to_string(Verdict::applied), "applied");
  EXPECT_EQ(to_string(Verdict::refused_topology), "refused (topology)");
  EXPECT_EQ(to_string(Verdict::refused_collision), "refused (collision)");
  EXPECT_EQ(to_string(Verdict::deferred), "deferred");
  std::set<std::string_view> names;
  for (const Verdict v : {Verdict::applied, Verdict::refused_topology, Verdict::refused_collision,
                          Verdict::deferred}) {
    names.insert(to_string(v));
    Outcome outcome;
    outcome.verdict = v;
    EXPECT_EQ(outcome.applied(), v == Verdict::applied) << to_string(v);
  }
  EXPECT_EQ(names.size(), 4u);
  EXPECT_TRUE(Outcome{}.applied());  // the default outcome is an applied one
  // In a pass: a refused or deferred outcome says why, an applied one says nothing. (The
  // diagonals (1, 1)-(2, 2) and (2, 1)-(3, 2) are neighbours: the second waits.)
  Surface surface = sheets(4, 1.0, 1.0);
  const std::vector<Outcome> flips = flip_edges(
      surface, std::array{Edge{0, 1}, Edge{kInner, kInner + 6}, Edge{kInner + 1, kInner + 7}});
  ASSERT_EQ(flips.size(), 3u);
  EXPECT_EQ(flips[0].verdict, Verdict::refused_topology);
  EXPECT_FALSE(flips[0].reason.empty());
  EXPECT_TRUE(flips[1].applied()) << flips[1].reason;
  EXPECT_TRUE(flips[1].reason.empty()) << flips[1].reason;
  EXPECT_EQ(flips[2].verdict, Verdict::deferred) << flips[2].reason;
  EXPECT_FALSE(flips[2].reason.empty());
}

// The one instantiation of the Operations fixture (two_sheets.hpp): it covers the TEST_Ps
// of every file of remesh_tests.
INSTANTIATE_TEST_SUITE_P(Scales, Operations, ::testing::Values(0, 1000, -1000),
                         exactgeo::testing::scale_name);

}  // namespace
}  // namespace exactgeo::remesh
