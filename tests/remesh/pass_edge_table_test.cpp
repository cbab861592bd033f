// The split and flip passes find a proposed edge's triangles, and whether a flip's new
// edge exists, in a table of the triangles around the proposals' vertices only
// (EdgeTriangles::assign_marked), not of the whole surface. Passes proposing a few of
// the edges of a crumpled stack (its lowest sheet fixed, with vertices of three
// triangles, whose edges no flip may take: the new edge exists), random pairs of vertices
// (mostly no edge), pairs with an end out of range and pairs of one vertex, at 2^0 and
// 2^+-1000: every operation the pass does not defer has the outcome (verdict, reason and
// blocker) that the single operation, which searches the whole surface, has on the
// surface before the pass. And a flip whose new edge exists in a triangle away from
// the flipped edge's ends (a fin under a tent) is refused by the pass as alone.

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

using testing::crumple;
using testing::stack;

/// `count` triangles of the top sheet (the last `per_sheet` triangles) each split into
/// three at its centroid: a vertex of three triangles, each of whose edges a flip would
/// turn into an edge that exists.
void add_vertices_of_three_triangles(Surface& s, std::size_t per_sheet, std::size_t count,
                                     std::mt19937_64& rng) {
  const std::size_t first = s.triangles.size() - per_sheet;
  std::uniform_int_distribution<std::size_t> pick(first, s.triangles.size() - 1);
  for (std::size_t k = 0; k < count; ++k) {
    const std::size_t t = pick(rng);
    const Triangle tri = s.triangles[t];
    if (std::max({tri[0], tri[1], tri[2]}) >= s.vertices.size()) continue;
    Point3 centre{};
    for (const VertexIndex v : tri) {
      for (int i = 0; i < 3; ++i)
        centre[i] += s.vertices[v][i] / 3.0;
    }
    const auto p = static_cast<VertexIndex>(s.vertices.size());
    s.vertices.push_back(centre);
    if (!s.fixed.empty()) s.fixed.push_back(false);
    s.triangles[t] = {tri[0], tri[1], p};
    s.triangles.push_back({tri[1], tri[2], p});
    s.triangles.push_back({tri[2], tri[0], p});
  }
}

/// A pass's proposed edges: a quarter of the surface's edges, the edges of the vertices of
/// three triangles, random pairs, pairs with an end out of range, pairs of one vertex; in
/// a random order.
std::vector<Edge> proposed_edges(const Surface& s, std::mt19937_64& rng) {
  std::vector<Edge> proposed;
  std::vector<std::size_t> degree(s.vertices.size(), 0);
  for (const Edge& e : s.edges()) {
    ++degree[e[0]];
    ++degree[e[1]];
    if (rng() % 4 == 0) proposed.push_back(e);
  }
  for (const Edge& e : s.edges()) {
    if (degree[e[0]] == 3 || degree[e[1]] == 3) proposed.push_back(e);
  }
  const auto n = static_cast<VertexIndex>(s.vertices.size());
  std::uniform_int_distribution<VertexIndex> any(0, n - 1);
  for (int k = 0; k < 30; ++k)
    proposed.push_back({any(rng), any(rng)});  // mostly no edge; now and then one vertex
  for (int k = 0; k < 3; ++k) {
    proposed.push_back({any(rng), n + static_cast<VertexIndex>(k)});
    proposed.push_back({n + static_cast<VertexIndex>(k), any(rng)});
    const VertexIndex v = any(rng);
    proposed.push_back({v, v});
  }
  std::shuffle(proposed.begin(), proposed.end(), rng);
  return proposed;
}

/// The outcomes of a pass against those of its operations alone on `before`.
template <class Alone>
void expect_as_alone(const Surface& before, const std::vector<Outcome>& done, const Alone& alone,
                     const std::string& where, std::map<std::string, int>& tally) {
  for (std::size_t i = 0; i < done.size(); ++i) {
    ++tally[std::string(to_string(done[i].verdict))];
    if (done[i].reason.find("duplicate") != std::string::npos) ++tally["duplicate edge"];
    if (done[i].reason.find("is no edge") != std::string::npos) ++tally["no edge"];
    if (done[i].reason.find("does not exist") != std::string::npos) ++tally["no vertex"];
    if (done[i].reason.find("fixed") != std::string::npos) ++tally["fixed"];
    if (done[i].verdict == Verdict::deferred) continue;
    Surface copy = before;
    const Outcome single = alone(copy, i);
    EXPECT_EQ(single.verdict, done[i].verdict) << where << ", operation " << i;
    EXPECT_EQ(single.reason, done[i].reason) << where << ", operation " << i;
    EXPECT_EQ(single.blocker, done[i].blocker) << where << ", operation " << i;
  }
}

TEST(PassEdgeTable, AProposedEdgesTrianglesAreFoundAsInTheWholeSurface) {
  auto rng = testing::seeded_engine("remesh.pass_edge_table");
  std::map<std::string, int> flips, splits;
  for (const int exponent : {0, 1000, -1000}) {
    constexpr int kSheets = 3, kSide = 6;
    Surface start = stack(kSheets, kSide, rng, 0.2);
    const std::size_t per_sheet = start.triangles.size() / kSheets;
    start.fixed.assign(start.vertices.size(), false);
    for (VertexIndex v = 0; v < start.vertices.size() / kSheets; ++v)
      start.fixed[v] = true;  // the lowest sheet: an obstacle
    add_vertices_of_three_triangles(start, per_sheet, 6, rng);
    crumple(start, rng);
    Surface s = testing::times_power_of_two(start, exponent);
    std::uniform_int_distribution<int> lift(-40, 40);  // in steps of 2^-7
    for (int pass = 0; pass < 6; ++pass) {
      const std::string where = "2^" + std::to_string(exponent) + ", pass " + std::to_string(pass);
      const Surface before_flips = s;
      const std::vector<Edge> edges = proposed_edges(s, rng);
      expect_as_alone(
          before_flips, flip_edges(s, edges),
          [&](Surface& c, std::size_t i) { return flip_edge(c, edges[i][0], edges[i][1]); },
          where + ", flips", flips);
      const Surface before_splits = s;
      std::vector<Split> proposed;
      for (const Edge& e : proposed_edges(s, rng)) {
        Point3 at{};
        if (std::max(e[0], e[1]) < s.vertices.size()) {
          const Point3 &a = s.vertices[e[0]], &b = s.vertices[e[1]];
          const double up = pass % 2 == 0 ? std::ldexp(lift(rng), exponent - 7) : 0.0;
          at = {(a[0] + b[0]) / 2, (a[1] + b[1]) / 2, (a[2] + b[2]) / 2 + up};
        }
        proposed.push_back({e[0], e[1], at});
      }
      expect_as_alone(
          before_splits, split_edges(s, proposed),
          [&](Surface& c, std::size_t i) {
            return split_edge(c, proposed[i].a, proposed[i].b, proposed[i].at);
          },
          where + ", splits", splits);
      if (::testing::Test::HasFailure()) return;
    }
  }
  for (const auto& [name, tally] : {std::pair{"flips", &flips}, std::pair{"splits", &splits}}) {
    for (const auto& [what, count] : *tally)
      std::cout << name << " " << what << ": " << count << "\n";
    // Every kind of proposal was met.
    EXPECT_GT((*tally)["applied"], 0) << name;
    EXPECT_GT((*tally)["refused (collision)"], 0) << name;
    EXPECT_GT((*tally)["no edge"], 0) << name;
    EXPECT_GT((*tally)["no vertex"], 0) << name;
    EXPECT_GT((*tally)["fixed"], 0) << name;
  }
  EXPECT_GT(flips["duplicate edge"], 0);
}

// A tent: ridge ab over c and d, with a fin c d e below it, apart from the tent but for c
// and d. Flipping ab would make edge cd, which exists, in a triangle with neither a nor b
// as a corner: the pass must find it from c and d (marking the flipped edges' third
// corners). At 2^0 and 2^+-1000, alone, with other flips of the pass, and both ways round.
TEST(PassEdgeTable, AFlipWhoseNewEdgeExistsAwayFromItsEndsIsRefused) {
  for (const int exponent : {0, 1000, -1000}) {
    Surface made;
    made.vertices = {{-1, 0, 1}, {1, 0, 1}, {0, -1, 0}, {0, 1, 0},
                     {0, 0, -1}, {3, 0, 0}, {3, 1, 0}};
    made.triangles = {{0, 1, 2}, {1, 0, 3}, {2, 3, 4}, {1, 5, 6}};
    const Surface tent = testing::times_power_of_two(made, exponent);
    for (const std::vector<Edge>& edges :
         {std::vector<Edge>{{0, 1}}, std::vector<Edge>{{5, 6}, {1, 0}, {2, 4}}}) {
      Surface s = tent, alone = tent;
      const std::vector<Outcome> done = flip_edges(s, edges);
      const std::size_t i = edges.size() == 1 ? 0 : 1;
      const Outcome single = flip_edge(alone, edges[i][0], edges[i][1]);
      EXPECT_EQ(done[i].verdict, Verdict::refused_topology) << exponent << ": " << done[i].reason;
      EXPECT_EQ(done[i].reason, single.reason) << exponent;
      const std::string duplicate =
          i == 0 ? "would duplicate edge 2-3" : "would duplicate edge 3-2";
      EXPECT_NE(done[i].reason.find(duplicate), std::string::npos)
          << exponent << ": " << done[i].reason;
      EXPECT_EQ(s.triangles, tent.triangles) << exponent;
    }
  }
}

}  // namespace
}  // namespace exactgeo::remesh
