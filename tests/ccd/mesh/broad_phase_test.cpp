// The mesh broad phase (ccd/mesh/internal/broad_phase.hpp) against brute force over all
// pairs: every vertex-face pair whose vertex is not a corner of the face and every pair of
// edges that share no vertex, kept when their swept boxes (the same float boxes, the
// union of the corners' vertex_swept_box) overlap and their corners do not all move by
// one vector; each pair once, in the same order on any number of threads; trees kept and
// refitted across steps give what fresh trees give; with a separation δ every pair whose
// exact boxes come within δ is kept; at 2^+-1000 as at 1.

#include "exactgeo/ccd/mesh/internal/broad_phase.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "exactgeo/ccd/mesh/internal/swept_box.hpp"
#include "support/generators.hpp"
#include "support/seed.hpp"

namespace exactgeo::ccd::internal {
namespace {

using testing::Rng;

struct MovingMesh {
  std::vector<Triangle> faces;
  std::vector<double> t0, t1;  // x, y, z per vertex
  std::size_t vertex_count() const { return t0.size() / 3; }
  StepPositions frames() const { return {t0, t1}; }
};

/// A coordinate on the grid of 1/64 in [-range, range]: differences are exact.
double grid(Rng& rng, int range) {
  return testing::uniform_int(rng, -64 * range, 64 * range) / 64.0;
}

/// An n x n sheet, each vertex moved by a random grid vector; a block of vertices moves
/// rigidly and another stands still, so that rigid pairs are common.
MovingMesh moving_sheet(Rng& rng, int n) {
  MovingMesh m;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      m.t0.insert(m.t0.end(), {i * 0.25 + grid(rng, 0) / 4, j * 0.25, grid(rng, 1) / 8});
    }
  }
  for (int i = 0; i + 1 < n; ++i) {
    for (int j = 0; j + 1 < n; ++j) {
      const auto v = static_cast<VertexIndex>(i * n + j);
      const auto right = static_cast<VertexIndex>(v + n);
      m.faces.push_back({v, right, static_cast<VertexIndex>(v + 1)});
      m.faces.push_back(
          {static_cast<VertexIndex>(v + 1), right, static_cast<VertexIndex>(right + 1)});
    }
  }
  const std::array<double, 3> common{grid(rng, 1) / 4, grid(rng, 1) / 4, grid(rng, 1) / 4};
  m.t1 = m.t0;
  for (std::size_t v = 0; v < m.vertex_count(); ++v) {
    const std::size_t i = v / static_cast<std::size_t>(n);
    for (int k = 0; k < 3; ++k) {
      double d = grid(rng, 1) / 4;
      if (i < 2) d = common[k];                           // the first two rows move together
      if (i + 2 >= static_cast<std::size_t>(n)) d = 0.0;  // the last two stand
      m.t1[3 * v + k] += d;
    }
  }
  return m;
}

/// Triangles with corners of their own, scattered in a small box: boxes overlap often.
/// Some share vertices with another triangle, some corners coincide, some are flat.
MovingMesh triangle_soup(Rng& rng, int count) {
  MovingMesh m;
  for (int f = 0; f < count; ++f) {
    const double cx = grid(rng, 2), cy = grid(rng, 2), cz = grid(rng, 2);
    for (int c = 0; c < 3; ++c)
      m.t0.insert(m.t0.end(),
                  {cx + grid(rng, 1) / 2, cy + grid(rng, 1) / 2, cz + grid(rng, 1) / 2});
    auto first = static_cast<VertexIndex>(3 * f);
    m.faces.push_back(
        {first, static_cast<VertexIndex>(first + 1), static_cast<VertexIndex>(first + 2)});
  }
  // Shared corners, a coincident vertex and a flat triangle.
  for (int f = 1; f < count; f += 5)
    m.faces.push_back({static_cast<VertexIndex>(3 * f), static_cast<VertexIndex>(3 * f - 1),
                       static_cast<VertexIndex>(3 * f + 1)});
  for (int k = 0; k < 3; ++k) {
    m.t0[3 * 4 + k] = m.t0[3 * 7 + k];
    m.t0[3 * 11 + k] = (m.t0[3 * 9 + k] + m.t0[3 * 10 + k]) / 2;
  }
  m.t1 = m.t0;
  for (std::size_t v = 0; v < m.vertex_count(); ++v) {
    for (int k = 0; k < 3; ++k)
      m.t1[3 * v + k] += v % 4 == 0 ? 0.0 : grid(rng, 1) / 2;
  }
  return m;
}

MovingMesh scaled(MovingMesh m, int k) {
  for (std::vector<double>* frame : {&m.t0, &m.t1}) {
    for (double& x : *frame)
      x = std::ldexp(x, k);
  }
  return m;
}

double largest_of(const MovingMesh& m) {
  double largest = 0;
  for (const std::vector<double>* frame : {&m.t0, &m.t1}) {
    for (const double x : *frame)
      largest = std::max(largest, std::fabs(x));
  }
  return largest;
}

std::vector<Edge> sorted_edges(const std::vector<Triangle>& faces) {
  std::set<Edge> edges;
  for (const Triangle& t : faces) {
    for (int i = 0; i < 3; ++i) {
      const VertexIndex a = t[i], b = t[(i + 1) % 3];
      edges.insert({std::min(a, b), std::max(a, b)});
    }
  }
  return {edges.begin(), edges.end()};
}

using Pairs = std::pair<std::set<std::pair<std::uint32_t, std::uint32_t>>,
                        std::set<std::pair<std::uint32_t, std::uint32_t>>>;

/// The candidates as sets (vertex-face, edge-edge), failing on any pair listed twice.
Pairs as_sets(const MeshCandidates& c, const std::string& what) {
  Pairs out;
  for (const VertexFacePair& p : c.vertex_face)
    EXPECT_TRUE(out.first.insert({p.vertex, p.face}).second) << what << ": a pair twice";
  for (const EdgeIndexPair& p : c.edge_edge) {
    EXPECT_LT(p.a, p.b) << what;
    EXPECT_TRUE(out.second.insert({p.a, p.b}).second) << what << ": a pair twice";
  }
  return out;
}

/// All corners move by the same exact vector (standing still included).
bool rigid(const MovingMesh& m, std::initializer_list<VertexIndex> corners) {
  const VertexIndex first = *corners.begin();
  for (const VertexIndex v : corners) {
    for (int k = 0; k < 3; ++k) {
      if (m.t1[3 * v + k] - m.t0[3 * v + k] != m.t1[3 * first + k] - m.t0[3 * first + k])
        return false;
    }
  }
  return true;
}

/// Brute force: every non-adjacent, non-rigid pair whose float swept boxes overlap.
/// `rigid_overlaps` counts the rigid pairs left out although their boxes overlap.
Pairs brute_force(const MovingMesh& m, const std::vector<Edge>& edges,
                  int* rigid_overlaps = nullptr) {
  const boxes::Scale scale(largest_of(m));
  std::vector<FloatBox> box(m.vertex_count());
  for (std::size_t v = 0; v < box.size(); ++v)
    box[v] = vertex_swept_box(m.t0.data(), m.t1.data(), v, scale);
  auto face_box = [&](const Triangle& t) {
    return boxes::united(boxes::united(box[t[0]], box[t[1]]), box[t[2]]);
  };
  auto edge_box = [&](const Edge& e) { return boxes::united(box[e[0]], box[e[1]]); };
  Pairs out;
  for (VertexIndex v = 0; v < m.vertex_count(); ++v) {
    for (std::size_t f = 0; f < m.faces.size(); ++f) {
      const Triangle& t = m.faces[f];
      if (v == t[0] || v == t[1] || v == t[2]) continue;
      if (!boxes::overlap(box[v], face_box(t))) continue;
      if (rigid(m, {v, t[0], t[1], t[2]})) {
        if (rigid_overlaps) ++*rigid_overlaps;
        continue;
      }
      out.first.insert({v, static_cast<std::uint32_t>(f)});
    }
  }
  for (std::size_t i = 0; i < edges.size(); ++i) {
    for (std::size_t j = i + 1; j < edges.size(); ++j) {
      const Edge &a = edges[i], &b = edges[j];
      if (a[0] == b[0] || a[0] == b[1] || a[1] == b[0] || a[1] == b[1]) continue;
      if (!boxes::overlap(edge_box(a), edge_box(b))) continue;
      if (rigid(m, {a[0], a[1], b[0], b[1]})) {
        if (rigid_overlaps) ++*rigid_overlaps;
        continue;
      }
      out.second.insert({static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(j)});
    }
  }
  return out;
}

/// One step of a kept broad phase against brute force and against fresh trees, on 1, 2
/// and 3 threads (the same list, in the same order).
MeshCandidates expect_step(MeshBroadPhase& kept, const MovingMesh& m,
                           const std::vector<Edge>& edges, const std::string& what) {
  const MeshCandidates got = kept.candidates(m.frames(), largest_of(m), 1);
  const Pairs sets = as_sets(got, what);
  const Pairs expected = brute_force(m, edges);
  EXPECT_TRUE(sets.first == expected.first)
      << what << ": vertex-face " << sets.first.size() << " against " << expected.first.size();
  EXPECT_TRUE(sets.second == expected.second)
      << what << ": edge-edge " << sets.second.size() << " against " << expected.second.size();
  MeshBroadPhase fresh(m.vertex_count(), m.faces, edges);
  const MeshCandidates built = fresh.candidates(m.frames(), largest_of(m), 1);
  EXPECT_TRUE(built.trees_rebuilt) << what;
  EXPECT_TRUE(as_sets(built, what) == sets) << what << ": refitted trees differ from fresh ones";
  for (const unsigned threads : {2u, 3u}) {
    MeshBroadPhase again(m.vertex_count(), m.faces, edges);
    const MeshCandidates c = again.candidates(m.frames(), largest_of(m), threads);
    EXPECT_TRUE(c.vertex_face == built.vertex_face) << what << " threads " << threads;
    EXPECT_TRUE(std::equal(
        c.edge_edge.begin(), c.edge_edge.end(), built.edge_edge.begin(), built.edge_edge.end(),
        [](const EdgeIndexPair& x, const EdgeIndexPair& y) { return x.a == y.a && x.b == y.b; }))
        << what << " threads " << threads;
  }
  return got;
}

TEST(BroadPhase, SheetsMatchBruteForceAcrossSteps) {
  Rng rng = testing::seeded_engine("broad-phase-sheets");
  for (int trial = 0; trial < 4; ++trial) {
    MovingMesh m = moving_sheet(rng, 9);
    const std::vector<Edge> edges = sorted_edges(m.faces);
    MeshBroadPhase kept(m.vertex_count(), m.faces, edges);
    std::size_t candidates = 0;
    for (int step = 0; step < 4; ++step) {
      const std::string what = "sheet " + std::to_string(trial) + " step " + std::to_string(step);
      const MeshCandidates c = expect_step(kept, m, edges, what);
      if (step == 0) {
        EXPECT_TRUE(c.trees_rebuilt) << what;
      }
      candidates += c.vertex_face.size() + c.edge_edge.size();
      // The next step: from where this one ended, by a new motion.
      MovingMesh next = moving_sheet(rng, 9);
      for (std::size_t i = 0; i < m.t0.size(); ++i)
        next.t1[i] = m.t1[i] + (next.t1[i] - next.t0[i]);
      next.t0 = m.t1;
      m = next;
      if (::testing::Test::HasFailure()) return;
    }
    EXPECT_GT(candidates, 100u);
    int rigid_overlaps = 0;
    brute_force(m, edges, &rigid_overlaps);
    EXPECT_GT(rigid_overlaps, 20) << "rigid pairs with overlapping boxes, left out";
  }
}

TEST(BroadPhase, TriangleSoupsMatchBruteForce) {
  Rng rng = testing::seeded_engine("broad-phase-soup");
  for (int trial = 0; trial < 6; ++trial) {
    const MovingMesh m = triangle_soup(rng, 60);
    const std::vector<Edge> edges = sorted_edges(m.faces);
    MeshBroadPhase kept(m.vertex_count(), m.faces, edges);
    expect_step(kept, m, edges, "soup " + std::to_string(trial));
    // The same step again: refitted to the same boxes, nothing rebuilt, nothing changed.
    const MeshCandidates again = kept.candidates(m.frames(), largest_of(m), 2);
    EXPECT_FALSE(again.trees_rebuilt);
    EXPECT_TRUE(as_sets(again, "again") == brute_force(m, edges));
    if (::testing::Test::HasFailure()) return;
  }
}

/// Every vertex moved far from where the trees were built: a refit leaves them loose, so
/// they are rebuilt, and the pairs are still the brute force's.
TEST(BroadPhase, ScrambledMeshesRebuildTheTrees) {
  Rng rng = testing::seeded_engine("broad-phase-scrambled");
  MovingMesh m = moving_sheet(rng, 10);
  const std::vector<Edge> edges = sorted_edges(m.faces);
  MeshBroadPhase kept(m.vertex_count(), m.faces, edges);
  EXPECT_TRUE(kept.candidates(m.frames(), largest_of(m), 1).trees_rebuilt);
  std::vector<std::size_t> order(m.vertex_count());
  for (std::size_t i = 0; i < order.size(); ++i)
    order[i] = i;
  std::shuffle(order.begin(), order.end(), rng);
  MovingMesh scrambled = m;
  for (std::size_t v = 0; v < order.size(); ++v) {
    for (int k = 0; k < 3; ++k) {
      scrambled.t0[3 * v + k] = m.t0[3 * order[v] + k];
      scrambled.t1[3 * v + k] = m.t1[3 * order[v] + k];
    }
  }
  const MeshCandidates c = expect_step(kept, scrambled, edges, "scrambled");
  EXPECT_TRUE(c.trees_rebuilt);
}

/// At 2^+-1000 the boxes are made in the step's scale: the same pairs as at 1.
TEST(BroadPhase, ExtremeMagnitudesMatchBruteForce) {
  Rng rng = testing::seeded_engine("broad-phase-extreme");
  for (const int k : {-1000, 1000}) {
    const MovingMesh m = moving_sheet(rng, 8);
    const std::vector<Edge> edges = sorted_edges(m.faces);
    MeshBroadPhase at_one(m.vertex_count(), m.faces, edges);
    const Pairs one = as_sets(at_one.candidates(m.frames(), largest_of(m), 1), "at 1");
    const MovingMesh far = scaled(m, k);
    MeshBroadPhase kept(far.vertex_count(), far.faces, edges);
    expect_step(kept, far, edges, "2^" + std::to_string(k));
    MeshBroadPhase again(far.vertex_count(), far.faces, edges);
    EXPECT_TRUE(as_sets(again.candidates(far.frames(), largest_of(far), 1), "far") == one)
        << "2^" << k;
  }
}

/// With a separation δ: every non-adjacent, non-rigid pair whose exact swept boxes (min
/// and max of the corners' coordinates) come within δ on every axis is a candidate, and no
/// candidate's boxes are farther apart than δ plus the float boxes' rounding.
TEST(BroadPhase, SeparationKeepsEveryPairWithinDelta) {
  Rng rng = testing::seeded_engine("broad-phase-separation");
  for (int trial = 0; trial < 4; ++trial) {
    const MovingMesh m = triangle_soup(rng, 50);
    const std::vector<Edge> edges = sorted_edges(m.faces);
    const double largest = largest_of(m);
    const double delta = trial == 0 ? 0x1p-20 : 0.125 * trial;
    MeshBroadPhase broad(m.vertex_count(), m.faces, edges);
    const Pairs got = as_sets(broad.candidates(m.frames(), largest, 1, delta), "separation");
    // The exact box of some vertices over the step.
    auto gap = [&](std::initializer_list<VertexIndex> a, std::initializer_list<VertexIndex> b) {
      double worst = 0;
      for (int k = 0; k < 3; ++k) {
        double alo = INFINITY, ahi = -INFINITY, blo = INFINITY, bhi = -INFINITY;
        for (const VertexIndex v : a) {
          for (const double x : {m.t0[3 * v + k], m.t1[3 * v + k]}) {
            alo = std::min(alo, x);
            ahi = std::max(ahi, x);
          }
        }
        for (const VertexIndex v : b) {
          for (const double x : {m.t0[3 * v + k], m.t1[3 * v + k]}) {
            blo = std::min(blo, x);
            bhi = std::max(bhi, x);
          }
        }
        worst = std::max({worst, blo - ahi, alo - bhi});  // exact: grid coordinates
      }
      return worst;
    };
    const double slack = 0x1p-20 * largest;
    int within = 0;
    for (VertexIndex v = 0; v < m.vertex_count(); ++v) {
      for (std::size_t f = 0; f < m.faces.size(); ++f) {
        const Triangle& t = m.faces[f];
        if (v == t[0] || v == t[1] || v == t[2] || rigid(m, {v, t[0], t[1], t[2]})) continue;
        const double g = gap({v}, {t[0], t[1], t[2]});
        const bool candidate = got.first.count({v, static_cast<std::uint32_t>(f)}) > 0;
        if (g <= delta) {
          EXPECT_TRUE(candidate) << "vertex " << v << " face " << f << " gap " << g;
          ++within;
        }
        if (candidate) {
          EXPECT_LE(g, delta + slack) << "vertex " << v << " face " << f;
        }
      }
    }
    for (std::size_t i = 0; i < edges.size(); ++i) {
      for (std::size_t j = i + 1; j < edges.size(); ++j) {
        const Edge &a = edges[i], &b = edges[j];
        if (a[0] == b[0] || a[0] == b[1] || a[1] == b[0] || a[1] == b[1]) continue;
        if (rigid(m, {a[0], a[1], b[0], b[1]})) continue;
        const double g = gap({a[0], a[1]}, {b[0], b[1]});
        const bool candidate =
            got.second.count({static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(j)}) > 0;
        if (g <= delta) {
          EXPECT_TRUE(candidate) << "edges " << i << " " << j << " gap " << g;
        }
        if (candidate) {
          EXPECT_LE(g, delta + slack) << "edges " << i << " " << j;
        }
      }
    }
    EXPECT_GT(within, 50);
    if (::testing::Test::HasFailure()) return;
  }
}

}  // namespace
}  // namespace exactgeo::ccd::internal
