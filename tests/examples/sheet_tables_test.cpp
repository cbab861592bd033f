// The cloth remesher's tables patched after a pass (SheetEdgeTable::update,
// update_vertex_sizes) equal the same tables built afresh on the surface the pass left:
// random passes of splits, collapses and flips (the library's, reporting what they
// changed) on crumpled stacks of bumpy sheets whose lowest sheet is fixed (an obstacle, its
// triangles no sheet's), at 2^0 and 2^+-1000, the sizes patched after every other pass
// (the changed vertices of two passes gathered, as the remesher does when a pass reads no
// sizes). A collapse to its edge's midpoint moves a vertex that stays on the sheet: the
// sizes' patch must then decline, and does only then. A table renumbered as the cloth
// writes its mesh back is that mesh's, and a kept table is taken for that mesh only.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "exactgeo/remesh/operations.hpp"
#include "remesh/stacked_sheets.hpp"
#include "remesher.hpp"
#include "sheet_edges.hpp"
#include "support/scale_names.hpp"
#include "support/seed.hpp"
#include "vertex_sizes.hpp"

namespace exactgeo::cloth {
namespace {

using remesh::Surface;
using remesh::VertexIndex;

/// Proposals of one pass over every sheet edge of `s`, in a random order.
struct SheetProposals {
  std::vector<remesh::Split> splits;
  std::vector<remesh::Collapse> collapses;
  std::vector<remesh::Edge> flips;
};

SheetProposals sheet_proposals(const Surface& s, int exponent, std::mt19937_64& rng) {
  std::uniform_int_distribution<int> lift(-40, 40);
  std::bernoulli_distribution lifted(0.5), to_middle(0.2);
  std::vector<remesh::Edge> edges = s.edges();
  std::shuffle(edges.begin(), edges.end(), rng);
  SheetProposals out;
  for (const remesh::Edge& e : edges) {
    const Point3& a = s.vertices[e[0]];
    const Point3& b = s.vertices[e[1]];
    const double up = lifted(rng) ? std::ldexp(lift(rng), exponent - 7) : 0.0;
    const Point3 mid{(a[0] + b[0]) / 2, (a[1] + b[1]) / 2, (a[2] + b[2]) / 2 + up};
    out.splits.push_back({e[0], e[1], mid});
    out.collapses.push_back({e[0], e[1], to_middle(rng) ? mid : a});
    out.flips.push_back(e);
  }
  return out;
}

/// A stack of three bumpy sheets, the lowest fixed, at 2^exponent; the material
/// coordinates are the start's x and y at 2^0.
struct Sheets {
  Surface surface;
  std::vector<Material> material;
};

Sheets sheets(int exponent, std::mt19937_64& rng) {
  Sheets out;
  Surface s = testing::stack(3, 5, rng, 0.2);
  testing::crumple(s, rng);
  const std::size_t per_sheet = s.vertices.size() / 3;
  s.fixed.assign(s.vertices.size(), false);
  std::fill(s.fixed.begin(), s.fixed.begin() + static_cast<std::ptrdiff_t>(per_sheet), true);
  for (Point3& p : s.vertices) {
    out.material.push_back({p[0], p[1]});
    for (double& x : p)
      x = std::ldexp(x, exponent);
  }
  out.surface = std::move(s);
  return out;
}

struct TableTally {
  std::size_t edges_patched = 0, sizes_patched = 0, sizes_declined = 0, sizes_below_max = 0;
};

class SheetTablesAt : public ::testing::TestWithParam<int> {};

TEST_P(SheetTablesAt, PatchedTablesEqualFreshOnes) {
  const int exponent = GetParam();
  auto rng = testing::seeded_engine("examples.sheet_tables." + std::to_string(exponent));
  RemeshParameters parameters;
  parameters.max_length = 0.5;
  parameters.min_length = 0.05;
  parameters.turn_per_edge = 0.5;
  remesh::PassWorkspace workspace;
  remesh::TriangleChanges changes;
  std::vector<VertexIndex> touched, gathered, moved;
  std::vector<char> marks;
  TableTally tally;
  const std::size_t surfaces = testing::scaled_trials(4, 2);
  for (std::size_t k = 0; k < surfaces; ++k) {
    Sheets w = sheets(exponent, rng);
    Surface& s = w.surface;
    SheetEdgeTable table(s);
    std::vector<double> size = vertex_sizes(s, w.material, table.edges(), parameters);
    gathered.clear();
    moved.clear();
    for (int pass = 0; pass < 9; ++pass) {
      const std::string where = "2^" + std::to_string(exponent) + ", surface " + std::to_string(k) +
                                ", pass " + std::to_string(pass);
      const SheetProposals p = sheet_proposals(s, exponent, rng);
      if (pass % 3 == 0) {
        const std::vector<remesh::Outcome> outcomes =
            remesh::split_edges(s, p.splits, &workspace, &changes);
        for (std::size_t i = 0; i < outcomes.size(); ++i) {
          if (!outcomes[i].applied()) continue;
          const Material &a = w.material[p.splits[i].a], &b = w.material[p.splits[i].b];
          w.material.push_back({0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1])});
        }
      } else if (pass % 3 == 1) {
        remesh::collapse_edges(s, p.collapses, &workspace, &changes);
      } else {
        remesh::flip_edges(s, p.flips, &workspace, &changes);
      }
      ASSERT_EQ(w.material.size(), s.vertices.size()) << where;
      const bool patched = table.update(s, changes, touched);
      const SheetEdgeTable fresh(s);
      ASSERT_EQ(table.edges(), fresh.edges()) << where;
      EXPECT_TRUE(patched) << where << ": no sheet edge has more than two triangles";
      tally.edges_patched += patched ? 1 : 0;
      gathered.insert(gathered.end(), touched.begin(), touched.end());
      moved.insert(moved.end(), changes.moved.begin(), changes.moved.end());
      if (pass % 2 == 0) continue;  // the sizes wait for the next pass
      const std::vector<double> fresh_size = vertex_sizes(s, w.material, fresh.edges(), parameters);
      if (update_vertex_sizes(size, s, w.material, table.edges(), parameters, gathered, moved,
                              marks)) {
        ASSERT_EQ(size, fresh_size) << where;
        ++tally.sizes_patched;
      } else {
        // Declined: a moved vertex is an end of a sheet edge.
        const bool moved_on_sheet =
            std::any_of(table.edges().begin(), table.edges().end(), [&](const SheetEdge& e) {
              return std::find(moved.begin(), moved.end(), e.a) != moved.end() ||
                     std::find(moved.begin(), moved.end(), e.b) != moved.end();
            });
        EXPECT_TRUE(moved_on_sheet) << where;
        size = fresh_size;
        ++tally.sizes_declined;
      }
      tally.sizes_below_max += static_cast<std::size_t>(std::count_if(
          size.begin(), size.end(), [&](double x) { return x < parameters.max_length; }));
      gathered.clear();
      moved.clear();
    }
  }
  std::cout << "edge tables patched " << tally.edges_patched << ", sizes patched "
            << tally.sizes_patched << ", declined " << tally.sizes_declined
            << ", sizes below the largest " << tally.sizes_below_max << "\n";
  EXPECT_GT(tally.sizes_patched, 0U);
  EXPECT_GT(tally.sizes_declined, 0U);
  // The sheets' curvature asks for something at 2^0. (At 2^+-1000 the remesher's float
  // normals overflow or vanish, its sizing being made for metres: every size is the
  // largest there, patched or not.)
  if (exponent == 0) {
    EXPECT_GT(tally.sizes_below_max, 0U);
  }
}

INSTANTIATE_TEST_SUITE_P(Scales, SheetTablesAt, ::testing::Values(0, 1000, -1000),
                         exactgeo::testing::scale_name);

/// `s` numbered as the cloth writes a mesh back: the used vertices that are not fixed
/// first, in order, then the fixed ones; the sheets' triangles (no corner fixed) first, in
/// order, then the others. The maps into `vertex` and `sheet_face`.
Surface written_back(const Surface& s, std::vector<VertexIndex>& vertex,
                     std::vector<std::size_t>& sheet_face) {
  std::vector<char> used(s.vertices.size(), 0);
  for (const remesh::Triangle& t : s.triangles)
    for (const VertexIndex v : t)
      used[v] = 1;
  Surface out;
  vertex.assign(s.vertices.size(), remesh::kNoVertex);
  for (const bool fixed : {false, true}) {
    for (VertexIndex v = 0; v < s.vertices.size(); ++v) {
      if (s.is_fixed(v) != fixed || (!fixed && !used[v])) continue;
      vertex[v] = static_cast<VertexIndex>(out.vertices.size());
      out.vertices.push_back(s.vertices[v]);
      out.fixed.push_back(fixed);
    }
  }
  sheet_face.assign(s.triangles.size(), 0);
  const auto sheet = [&](const remesh::Triangle& t) {
    return !s.is_fixed(t[0]) && !s.is_fixed(t[1]) && !s.is_fixed(t[2]);
  };
  for (const bool obstacle : {false, true}) {
    for (std::size_t t = 0; t < s.triangles.size(); ++t) {
      const remesh::Triangle& tri = s.triangles[t];
      if (sheet(tri) == obstacle) continue;
      if (!obstacle) sheet_face[t] = out.triangles.size();
      out.triangles.push_back({vertex[tri[0]], vertex[tri[1]], vertex[tri[2]]});
    }
  }
  return out;
}

TEST(SheetEdgeTable, RenumberedAsTheMeshWrittenBackItIsThatMeshsTable) {
  auto rng = testing::seeded_engine("examples.sheet_tables.renumbered");
  remesh::PassWorkspace workspace;
  std::size_t renumbered = 0;
  const std::size_t surfaces = testing::scaled_trials(6, 2);
  for (std::size_t k = 0; k < surfaces; ++k) {
    Sheets w = sheets(0, rng);
    Surface& s = w.surface;
    // Passes that leave vertices unused (collapses) and append some after the fixed ones
    // (splits), as a remesh does.
    for (int pass = 0; pass < 3; ++pass) {
      const SheetProposals p = sheet_proposals(s, 0, rng);
      if (pass == 1) {
        remesh::collapse_edges(s, p.collapses, &workspace);
      } else {
        remesh::split_edges(s, p.splits, &workspace);
      }
    }
    std::vector<VertexIndex> vertex;
    std::vector<std::size_t> sheet_face;
    const Surface back = written_back(s, vertex, sheet_face);
    SheetEdgeTable table(s);
    const bool moved = std::any_of(
        table.edges().begin(), table.edges().end(),
        [&](const SheetEdge& e) { return vertex[e.a] != e.a || e.left != sheet_face[e.left]; });
    table.renumber(vertex, sheet_face);
    EXPECT_EQ(table.edges(), SheetEdgeTable(back).edges()) << "surface " << k;
    renumbered += moved ? 1 : 0;
  }
  EXPECT_GT(renumbered, 0U);  // the numbers did change
}

TEST(KeptSheetEdges, ATableIsTakenOnceAndOnlyForTheMeshItWasKeptFor) {
  auto rng = testing::seeded_engine("examples.sheet_tables.kept");
  // A mesh of two bumpy sheets, the second an obstacle (its vertices after the sheet's).
  const Surface s = testing::stack(2, 3, rng);
  ClothMesh mesh;
  const std::size_t sheet = s.vertices.size() / 2;
  for (const Point3& p : s.vertices)
    mesh.positions.insert(mesh.positions.end(), p.begin(), p.end());
  mesh.material.assign(sheet, Material{0.0, 0.0});
  mesh.velocity.assign(3 * sheet, 0.0);
  mesh.faces.assign(s.triangles.begin(), s.triangles.end());
  mesh.sheet_faces = s.triangles.size() / 2;
  Surface marked = s;
  marked.fixed.assign(s.vertices.size(), false);
  std::fill(marked.fixed.begin() + static_cast<std::ptrdiff_t>(sheet), marked.fixed.end(), true);
  const SheetEdgeTable table(marked);
  ASSERT_FALSE(table.edges().empty());

  KeptSheetEdges kept;
  EXPECT_FALSE(kept.take_for(mesh)) << "nothing kept yet";
  kept.keep(table, mesh);
  const std::optional<SheetEdgeTable> taken = kept.take_for(mesh);
  ASSERT_TRUE(taken);
  EXPECT_EQ(taken->edges(), table.edges());
  EXPECT_FALSE(kept.take_for(mesh)) << "taken once";

  ClothMesh other = mesh;  // a face that is not the one written
  std::swap(other.faces[1][0], other.faces[1][1]);
  kept.keep(table, mesh);
  EXPECT_FALSE(kept.take_for(other));
  other = mesh;  // one vertex more
  other.positions.insert(other.positions.end(), {0.0, 0.0, 0.0});
  kept.keep(table, mesh);
  EXPECT_FALSE(kept.take_for(other));
  other = mesh;  // one sheet vertex less (the same vertices)
  other.material.pop_back();
  kept.keep(table, mesh);
  EXPECT_FALSE(kept.take_for(other));
  other = mesh;  // the same faces, moved vertices: the table is still the mesh's
  other.positions[0] += 1.0;
  kept.keep(table, mesh);
  EXPECT_TRUE(kept.take_for(other));
}

TEST(SheetEdgeTable, AnEdgeOfThreeTrianglesIsLeftOutAndAPatchBuildsTheTableAgain) {
  auto rng = testing::seeded_engine("examples.sheet_tables.crowded");
  Surface s = testing::stack(1, 3, rng);
  // A third triangle on the diagonal of the first square (the first two triangles'),
  // up in the air.
  const remesh::Triangle first = s.triangles[0];
  s.vertices.push_back({0.1, 0.1, 2.0});
  s.triangles.push_back({first[2], first[0], static_cast<VertexIndex>(s.vertices.size() - 1)});
  SheetEdgeTable table(s);
  const remesh::Edge crowded = remesh::edge_of(first[0], first[2]);
  ASSERT_EQ(s.triangles_on_edge(first[0], first[2]).size(), 3U);
  for (const SheetEdge& e : table.edges())
    EXPECT_NE(remesh::edge_of(e.a, e.b), crowded);
  // A pass that changes the surface elsewhere: the table cannot know the crowded edge's
  // triangles, so it is built again.
  remesh::TriangleChanges changes;
  std::vector<remesh::Edge> flips;
  for (const remesh::Edge& e : s.edges())
    if (e != crowded) flips.push_back(e);
  remesh::flip_edges(s, flips, nullptr, &changes);
  ASSERT_FALSE(changes.rewritten.empty());
  std::vector<VertexIndex> touched{7};
  EXPECT_FALSE(table.update(s, changes, touched));
  EXPECT_TRUE(touched.empty());
  EXPECT_EQ(table.edges(), SheetEdgeTable(s).edges());
}

}  // namespace
}  // namespace exactgeo::cloth
