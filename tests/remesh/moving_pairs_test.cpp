// The collapse pass's broad phase (remesh/src/moving_pairs.hpp, internal to the library:
// reached by path) against the rule it stands for, by brute force over every vertex-face
// and edge-edge pair of the mesh: the pairs with a moving corner, sharing no vertex, not
// moving rigidly (four corners by one vector), whose swept boxes meet (closed: touching
// counts). Random meshes on a fine grid and on a coarse one (coincident points, touching
// boxes, coplanar triangles, vertices moved onto others, several moved by one vector), and
// flat ones (every point in one plane), at 2^0 and 2^+-1000; each star's near triangles
// given as the fewest the header asks for, and as every triangle, twice.

#include "../../remesh/src/moving_pairs.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "support/scale_names.hpp"
#include "support/seed.hpp"

namespace exactgeo::remesh {
namespace {

using internal::moving_pairs;
using internal::MovingStar;

enum class Layout : std::uint8_t {
  fine,    ///< coordinates on a grid of 2^20 steps a side: boxes mostly cross, rarely touch
  coarse,  ///< on {0..3}^3: coincident points, touching boxes, shared planes
  flat,    ///< on {0..5}^2 x {0}: every triangle in one plane
};

struct Step {
  std::vector<Triangle> triangles;
  std::vector<Point3> start, end;
};

struct Box {
  Point3 lo, hi;
};

Box box_of(const Step& s, std::initializer_list<VertexIndex> corners) {
  Box b{s.start[*corners.begin()], s.start[*corners.begin()]};
  for (const VertexIndex v : corners) {
    for (const Point3* p : {&s.start[v], &s.end[v]}) {
      for (std::size_t k = 0; k < 3; ++k) {
        b.lo[k] = std::min(b.lo[k], (*p)[k]);
        b.hi[k] = std::max(b.hi[k], (*p)[k]);
      }
    }
  }
  return b;
}

bool meet(const Box& a, const Box& b) {
  for (std::size_t k = 0; k < 3; ++k) {
    if (a.hi[k] < b.lo[k] || b.hi[k] < a.lo[k]) return false;
  }
  return true;
}

bool moves(const Step& s, VertexIndex v) {
  return s.start[v] != s.end[v];
}

/// Every coordinate is an integer of at most 2^21 times one power of two, so each
/// difference is exact in doubles: rigid when all four corners move by equal differences.
bool rigid(const Step& s, std::array<VertexIndex, 4> c) {
  for (const VertexIndex v : c) {
    if (!moves(s, v)) return false;
    for (std::size_t k = 0; k < 3; ++k) {
      if (s.end[v][k] - s.start[v][k] != s.end[c[0]][k] - s.start[c[0]][k]) return false;
    }
  }
  return true;
}

bool counted(const Step& s, std::array<VertexIndex, 4> c) {
  return std::any_of(c.begin(), c.end(), [&](VertexIndex v) { return moves(s, v); }) &&
         !rigid(s, c);
}

/// The rule, pair by pair over the whole mesh.
ccd::MeshCcdCandidates brute_force(const Step& s) {
  ccd::MeshCcdCandidates out;
  for (VertexIndex v = 0; v < s.start.size(); ++v) {
    for (std::size_t f = 0; f < s.triangles.size(); ++f) {
      const Triangle& t = s.triangles[f];
      if (std::find(t.begin(), t.end(), v) != t.end()) continue;
      if (!counted(s, {v, t[0], t[1], t[2]})) continue;
      if (meet(box_of(s, {v}), box_of(s, {t[0], t[1], t[2]})))
        out.vertex_face.push_back({v, static_cast<FaceIndex>(f)});
    }
  }
  const std::vector<Edge> edges = edges_of(s.triangles, s.start.size());
  for (std::size_t i = 0; i < edges.size(); ++i) {
    for (std::size_t j = i + 1; j < edges.size(); ++j) {
      const Edge &a = edges[i], &b = edges[j];
      if (a[0] == b[0] || a[0] == b[1] || a[1] == b[0] || a[1] == b[1]) continue;
      if (!counted(s, {a[0], a[1], b[0], b[1]})) continue;
      if (meet(box_of(s, {a[0], a[1]}), box_of(s, {b[0], b[1]}))) out.edge_edge.push_back({a, b});
    }
  }
  return out;  // in the order of operator<=>: vertices, faces and edges all ascending
}

/// One star per moving vertex: the triangles around it, and near them either the fewest
/// the header asks for (those whose swept box meets one around it) or every triangle twice.
std::vector<MovingStar> stars_of(const Step& s, bool fewest) {
  std::vector<MovingStar> stars;
  for (VertexIndex v = 0; v < s.start.size(); ++v) {
    if (!moves(s, v)) continue;
    MovingStar star{v, {}, {}};
    for (std::uint32_t f = 0; f < s.triangles.size(); ++f) {
      const Triangle& t = s.triangles[f];
      if (std::find(t.begin(), t.end(), v) != t.end()) star.around.push_back(f);
    }
    for (int copy = 0; copy < (fewest ? 1 : 2); ++copy) {
      for (std::uint32_t f = 0; f < s.triangles.size(); ++f) {
        const Triangle& t = s.triangles[f];
        const Box b = box_of(s, {t[0], t[1], t[2]});
        const bool near = std::any_of(star.around.begin(), star.around.end(), [&](auto g) {
          const Triangle& u = s.triangles[g];
          return meet(b, box_of(s, {u[0], u[1], u[2]}));
        });
        if (near || !fewest) star.near.push_back(f);
      }
    }
    stars.push_back(std::move(star));
  }
  return stars;
}

class MovingPairs : public ::testing::TestWithParam<int> {
 protected:
  /// A random mesh of `layout`, every vertex a corner; a few vertices moved, some of them
  /// by one shared vector, some onto another vertex's place.
  Step draw(std::mt19937_64& rng, Layout layout) const {
    const int steps = layout == Layout::fine ? 1 << 20 : layout == Layout::coarse ? 3 : 5;
    const double unit = std::ldexp(1.0, GetParam() - (layout == Layout::fine ? 20 : 0));
    std::uniform_int_distribution<int> coordinate(0, steps);
    const auto point = [&] {
      return Point3{unit * coordinate(rng), unit * coordinate(rng),
                    layout == Layout::flat ? 0.0 : unit * coordinate(rng)};
    };
    const VertexIndex n = 30;
    Step s;
    for (std::size_t i = 0; i < n; ++i)
      s.start.push_back(point());
    std::uniform_int_distribution<VertexIndex> vertex(0, n - 1);
    for (VertexIndex i = 0; i < 45; ++i) {
      Triangle t{i % n, vertex(rng), vertex(rng)};
      while (t[1] == t[0])
        t[1] = vertex(rng);
      while (t[2] == t[0] || t[2] == t[1])
        t[2] = vertex(rng);
      s.triangles.push_back(t);
    }
    s.end = s.start;
    const Point3 shared = point();
    std::uniform_int_distribution<int> how(0, 3);
    for (VertexIndex v = 0; v < n; v += 2 + static_cast<VertexIndex>(how(rng))) {
      switch (how(rng)) {
        case 0:
        case 3:  // by the shared vector (from the origin of the grid)
          for (std::size_t k = 0; k < 3; ++k)
            s.end[v][k] = s.start[v][k] + shared[k];
          break;
        case 1:  // onto another vertex's place
          s.end[v] = s.start[vertex(rng)];
          break;
        default:  // anywhere
          s.end[v] = point();
      }
    }
    return s;
  }
};

TEST_P(MovingPairs, FindsExactlyThePairsOfTheRule) {
  std::mt19937_64 rng = testing::seeded_engine("MovingPairs.rule." + std::to_string(GetParam()));
  std::size_t found = 0, rigid_seen = 0;
  // 150 steps a layout at full effort (tests/support/seed.hpp); the pairs asked of the
  // same share of them.
  const std::size_t trials = testing::scaled_trials(150);
  for (const Layout layout : {Layout::fine, Layout::coarse, Layout::flat}) {
    for (int trial = 0; trial < static_cast<int>(trials); ++trial) {
      const Step s = draw(rng, layout);
      const ccd::MeshCcdCandidates expected = brute_force(s);
      for (const bool fewest : {true, false}) {
        const ccd::MeshCcdCandidates got =
            moving_pairs(s.triangles, s.start, s.end, stars_of(s, fewest));
        ASSERT_EQ(got.vertex_face, expected.vertex_face)
            << "layout " << static_cast<int>(layout) << ", trial " << trial << ", fewest "
            << fewest;
        ASSERT_EQ(got.edge_edge, expected.edge_edge)
            << "layout " << static_cast<int>(layout) << ", trial " << trial << ", fewest "
            << fewest;
      }
      found += expected.vertex_face.size() + expected.edge_edge.size();
      for (const Edge& a : edges_of(s.triangles, s.start.size())) {
        for (const Edge& b : edges_of(s.triangles, s.start.size())) {
          if (a < b && a[0] != b[0] && a[0] != b[1] && a[1] != b[0] && a[1] != b[1] &&
              rigid(s, {a[0], a[1], b[0], b[1]}) &&
              meet(box_of(s, {a[0], a[1]}), box_of(s, {b[0], b[1]})))
            ++rigid_seen;
        }
      }
    }
  }
  // The draws exercise the rule: pairs found, and rigid pairs (whose boxes meet) left out.
  EXPECT_GT(found, 10000 * trials / 150);
  EXPECT_GT(rigid_seen, 10 * trials / 150);
}

INSTANTIATE_TEST_SUITE_P(Scales, MovingPairs, ::testing::Values(0, 1000, -1000),
                         exactgeo::testing::scale_name);

}  // namespace
}  // namespace exactgeo::remesh
