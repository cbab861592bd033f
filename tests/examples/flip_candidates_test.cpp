// The cloth remesher's memory of its flip candidates (flip_candidates.hpp) against asking
// every edge: passes of flips (the library's, reporting what they changed) on crumpled
// stacks of bumpy sheets whose lowest sheet is fixed, at 2^0 and 2^+-1000, each proposing
// the candidates of a rule that reads what the remesher's does (an edge's two triangles'
// corners and their positions). After every pass, the list made from the memory, asking
// only the edges whose triangles the last pass rewrote, equals the list of the rule asked
// of every edge, in the table's order. A report of another kind of pass is not read.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <iostream>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "exactgeo/remesh/operations.hpp"
#include "flip_candidates.hpp"
#include "remesh/stacked_sheets.hpp"
#include "sheet_edges.hpp"
#include "support/scale_names.hpp"
#include "support/seed.hpp"

namespace exactgeo::cloth {
namespace {

using remesh::Surface;
using remesh::VertexIndex;

/// A stand-in for the remesher's candidate rule that reads the same inputs: the corners
/// a, b, c, d (mixed into a hash) and their positions (c's height against d's).
bool rule(const Surface& s, const SheetEdge& e) {
  const VertexIndex c = remesh::third_corner(s.triangles[e.left], e.a, e.b);
  const VertexIndex d = remesh::third_corner(s.triangles[*e.right], e.a, e.b);
  const std::uint64_t mixed =
      (std::uint64_t{e.a} * 0x9E3779B97F4A7C15u) ^ (std::uint64_t{e.b} * 0xC2B2AE3D27D4EB4Fu) ^
      (std::uint64_t{c} * 0x165667B19E3779F9u) ^ (std::uint64_t{d} * 0x27D4EB2F165667C5u);
  return (mixed >> 33) % 3 == 0 && s.vertices[c][2] <= s.vertices[d][2];
}

/// The candidates of `edges` in their order: every inner edge asked.
std::vector<remesh::Edge> asked_of_every_edge(const Surface& s,
                                              const std::vector<SheetEdge>& edges) {
  std::vector<remesh::Edge> out;
  for (const SheetEdge& e : edges) {
    if (e.right && rule(s, e)) out.push_back(remesh::edge_of(e.a, e.b));
  }
  return out;
}

/// The same from the memory, as the remesher's flip pass makes it; `asked` counts the
/// edges asked.
std::vector<remesh::Edge> from_memory(const Surface& s, const std::vector<SheetEdge>& edges,
                                      FlipCandidates& memory, std::size_t& asked) {
  std::vector<remesh::Edge> out;
  for (const SheetEdge& e : edges) {
    if (!e.right) continue;
    const std::uint64_t key = UnsuitedEdges::key(e.a, e.b);
    std::optional<bool> wanted = memory.known(e, key);
    if (!wanted) {
      ++asked;
      wanted = rule(s, e);
    }
    if (*wanted) {
      out.push_back(remesh::edge_of(e.a, e.b));
      memory.add(key);
    }
  }
  return out;
}

Surface crumpled_sheets(int exponent, std::mt19937_64& rng) {
  Surface s = testing::stack(3, 6, rng, 0.2);
  testing::crumple(s, rng);
  const std::size_t per_sheet = s.vertices.size() / 3;
  s.fixed.assign(s.vertices.size(), false);
  std::fill(s.fixed.begin(), s.fixed.begin() + static_cast<std::ptrdiff_t>(per_sheet), true);
  return testing::times_power_of_two(s, exponent);
}

class FlipCandidatesAt : public ::testing::TestWithParam<int> {};

TEST_P(FlipCandidatesAt, TheRememberedListIsTheListOfEveryEdgeAsked) {
  const int exponent = GetParam();
  auto rng = testing::seeded_engine("examples.flip_candidates." + std::to_string(exponent));
  remesh::PassWorkspace workspace;
  remesh::TriangleChanges changes;
  std::vector<VertexIndex> touched;
  std::size_t asked = 0, inner = 0, passes_with_flips = 0;
  for (int k = 0; k < 4; ++k) {
    Surface s = crumpled_sheets(exponent, rng);
    SheetEdgeTable table(s);
    FlipCandidates memory;
    for (int pass = 0; pass < 8; ++pass) {
      const std::string where = "2^" + std::to_string(exponent) + ", surface " + std::to_string(k) +
                                ", pass " + std::to_string(pass);
      memory.start_pass(pass == 0 ? nullptr : &changes, s.triangles.size());
      const std::vector<remesh::Edge> expected = asked_of_every_edge(s, table.edges());
      ASSERT_EQ(from_memory(s, table.edges(), memory, asked), expected) << where;
      for (const SheetEdge& e : table.edges())
        inner += e.right ? 1 : 0;
      // The candidates proposed, as the remesher does; now and then with a random few
      // others, so that the pass flips edges the rule did not ask for.
      std::vector<remesh::Edge> proposed = expected;
      for (const SheetEdge& e : table.edges()) {
        if (e.right && rng() % 8 == 0) proposed.push_back(remesh::edge_of(e.a, e.b));
      }
      std::size_t applied = 0;
      for (const remesh::Outcome& o : remesh::flip_edges(s, proposed, &workspace, &changes))
        applied += o.applied() ? 1 : 0;
      if (applied == 0) break;  // as the remesher: no pass after one that changed nothing
      ++passes_with_flips;
      ASSERT_TRUE(table.update(s, changes, touched)) << where;
    }
    // A report of a split pass, which appends triangles, is not read: every edge is asked.
    std::vector<remesh::Split> splits;
    for (const SheetEdge& e : table.edges()) {
      const Point3 &a = s.vertices[e.a], &b = s.vertices[e.b];
      splits.push_back({e.a, e.b, {(a[0] + b[0]) / 2, (a[1] + b[1]) / 2, (a[2] + b[2]) / 2}});
    }
    remesh::split_edges(s, splits, &workspace, &changes);
    ASSERT_GT(changes.first_added(), 0u);
    ASSERT_TRUE(table.update(s, changes, touched));
    memory.start_pass(&changes, s.triangles.size());
    std::size_t asked_after_splits = 0;
    EXPECT_EQ(from_memory(s, table.edges(), memory, asked_after_splits),
              asked_of_every_edge(s, table.edges()));
    std::size_t inner_after_splits = 0;
    for (const SheetEdge& e : table.edges())
      inner_after_splits += e.right ? 1 : 0;
    EXPECT_EQ(asked_after_splits, inner_after_splits);
  }
  std::cout << "edges asked " << asked << " of " << inner << " over " << passes_with_flips
            << " passes that flipped\n";
  EXPECT_GT(passes_with_flips, 4u);
  EXPECT_LT(asked, inner / 2);  // the memory spared most of the asking
}

INSTANTIATE_TEST_SUITE_P(Scales, FlipCandidatesAt, ::testing::Values(0, 1000, -1000),
                         exactgeo::testing::scale_name);

}  // namespace
}  // namespace exactgeo::cloth
