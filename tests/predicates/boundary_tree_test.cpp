// The boundary tree's term (boundary_tree.hpp) against the decomposition written out
// independently in 512-bit MPFR over every edge (support/solid_angle_oracle.hpp): wherever
// the tree encloses the term, at any width asked for, the enclosure holds the oracle's
// value, and wherever its refinement settles levels, it settles them as the oracle's
// value does. Chains of 10 to 10,000 edges: loops of every size (one big, many small),
// multiplicity 3, points anywhere, near the edges and far away, at 2^0 and 2^+-1000;
// levels a few 2^-k turns from the term, which the refinement must open the tree to
// settle. Then far nodes whose fan the zero-order bound nearly fills (a thin rectangle)
// or whose second-order expansion carries the fan (a flat arc seen from far away, on
// its axis and off it), and rays aimed through far nodes, where the fan's identity
// needs its 4 pi.

#include "exactgeo/predicates/boundary_tree.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "exactgeo/predicates/ray_directions.hpp"
#include "support/hexfloat.hpp"
#include "support/scale_names.hpp"
#include "support/seed.hpp"
#include "support/solid_angle_oracle.hpp"

namespace exactgeo::boundary_tree_test {
namespace {

struct Chain {
  std::vector<Point3> vertices;
  std::vector<BoundaryEdge> edges;
};

/// A loop of n edges around a jittered circle of radius `radius` about `centre`, in a
/// random plane, multiplicity m.
void add_loop(Chain& chain, std::mt19937_64& rng, std::size_t n, const Point3& centre,
              double radius, std::int32_t m) {
  std::normal_distribution<double> normal;
  std::uniform_real_distribution<double> jitter(0.9, 1.1);
  Vector3 u{normal(rng), normal(rng), normal(rng)}, v{normal(rng), normal(rng), normal(rng)};
  const auto normalize = [](Vector3& x) {
    const double l = std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
    for (double& c : x)
      c /= l;
  };
  normalize(u);
  const double uv = u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
  for (int i = 0; i < 3; ++i)
    v[i] -= uv * u[i];
  normalize(v);
  const auto first = static_cast<VertexIndex>(chain.vertices.size());
  for (std::size_t i = 0; i < n; ++i) {
    const double angle = 2 * std::numbers::pi * static_cast<double>(i) / static_cast<double>(n);
    const double r = radius * jitter(rng);
    Point3 p;
    for (int k = 0; k < 3; ++k)
      p[k] = centre[k] + r * (std::cos(angle) * u[k] + std::sin(angle) * v[k]);
    chain.vertices.push_back(p);
  }
  for (std::size_t i = 0; i < n; ++i) {
    chain.edges.push_back(
        {first + static_cast<VertexIndex>(i), first + static_cast<VertexIndex>((i + 1) % n), m});
  }
}

Chain scaled(Chain chain, int k) {
  for (Point3& p : chain.vertices) {
    for (double& x : p)
      x = std::ldexp(x, k);
  }
  return chain;
}

/// The oracle's term (1/4 pi) sum m Omega(p; a, b, p - r), in turns.
double oracle_term(const Point3& p, const Vector3& ray, const Chain& chain) {
  std::vector<testing::Segment> segments;
  for (const BoundaryEdge& e : chain.edges) {
    for (std::int32_t i = 0; i < e.multiplicity; ++i)
      segments.push_back({chain.vertices[e.from], chain.vertices[e.to]});
  }
  return testing::decomposed_winding_oracle(p, ray, 0, segments);
}

struct Tally {
  std::size_t points = 0;
  std::size_t enclosed = 0;
  std::size_t with_far_nodes = 0;  ///< enclosed with a far node's bound in it
};

/// The widths asked for in turns, in turn: coarse (far nodes stay), fine, and 0 (every
/// node opened).
constexpr std::array<double, 4> kWidths{0.5, 0x1p-6, 0x1p-12, 0.0};

/// The tree's enclosure at `width` turns (by default, each of kWidths in turn) holds the
/// oracle's term.
void expect_held(const BoundaryTree& tree, const Chain& chain, const Point3& p, const Vector3& ray,
                 Tally& tally, std::optional<double> asked = std::nullopt) {
  BoundaryTree::Refinement refinement;
  const double width = asked.value_or(kWidths[tally.points % kWidths.size()]);
  const std::optional<Enclosure> e = tree.enclosure(p, ray, width, refinement);
  ++tally.points;
  if (!e) return;
  ++tally.enclosed;
  tally.with_far_nodes += refinement.far_nodes > 0;
  const double truth = oracle_term(p, ray, chain);
  ASSERT_LE(e->lower, truth) << "point " << testing::hex(p) << ", slack " << refinement.slack;
  ASSERT_GE(e->upper, truth) << "point " << testing::hex(p) << ", slack " << refinement.slack;
  if (width > 0.0 && refinement.far_nodes > 0) {
    // Refined no further than asked: with far nodes left, it is narrow enough.
    EXPECT_LE(e->upper - e->lower, width * (1 + 0x1p-40) + 0x1p-900) << testing::hex(p);
  }
}

struct Case {
  const char* name;
  std::size_t loops;
  std::size_t edges_per_loop;
  std::int32_t multiplicity;
};

class BoundaryTreeChains : public ::testing::TestWithParam<int> {};

TEST_P(BoundaryTreeChains, EnclosuresHoldTheOraclesTerm) {
  const int k = GetParam();
  auto rng = testing::seeded_engine("predicates.boundary_tree.chains." + std::to_string(k));
  std::uniform_real_distribution<double> anywhere(-1.5, 1.5), unit(-1.0, 1.0);
  const std::array<Case, 6> cases{{{"one loop of 10", 1, 10, 1},
                                   {"one loop of 1000", 1, 1000, 1},
                                   {"one loop of 10000", 1, 10000, 1},
                                   {"250 loops of 4", 250, 4, 1},
                                   {"30 loops of 3 to 90", 30, 0, 1},
                                   {"a loop of 600 three times", 1, 600, 3}}};
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    Chain chain;
    for (std::size_t l = 0; l < c.loops; ++l) {
      const std::size_t n = c.edges_per_loop ? c.edges_per_loop : 3 * (l + 1);
      const double radius = c.loops == 1 ? 1.0 : 0.05 + 0.1 * (unit(rng) + 1);
      add_loop(chain, rng, n, {anywhere(rng) * (c.loops > 1), anywhere(rng) * (c.loops > 1), 0.0},
               radius, c.multiplicity);
    }
    const Chain unscaled = chain;
    chain = scaled(chain, k);
    const BoundaryTree tree(chain.vertices, chain.edges);
    ASSERT_EQ(tree.edge_count(), chain.edges.size());
    Tally tally;
    // The oracle takes about 35 us an edge: fewer points on the long chains and far from
    // magnitude 1 (where every node is near, see below). Scaled with the effort
    // (tests/support/seed.hpp), at least one point for each of the three rays.
    const std::size_t n = chain.edges.size();
    const std::size_t full = k != 0 ? 4 : n > 2000 ? 4 : n > 500 ? 12 : 30;
    const auto points = static_cast<int>(testing::scaled_trials(full, 3));
    for (int i = 0; i < points; ++i) {
      const Vector3 ray = ray_direction(static_cast<std::size_t>(i % 3));
      // Anywhere, far away, and near an edge (its midpoint moved by 2^-4 to 2^-30).
      const Point3 any{anywhere(rng), anywhere(rng), anywhere(rng)};
      const double far_scale = 4.0 + 60.0 * (unit(rng) + 1);
      Point3 far{unit(rng), unit(rng), unit(rng)};
      const double length = std::sqrt(far[0] * far[0] + far[1] * far[1] + far[2] * far[2]);
      for (double& x : far)
        x *= far_scale / length;
      const BoundaryEdge& e = unscaled.edges[static_cast<std::size_t>(i) % unscaled.edges.size()];
      Point3 near;
      const double offset = std::ldexp(1.0, -4 - (i % 27));
      for (int a = 0; a < 3; ++a) {
        near[a] = 0.5 * unscaled.vertices[e.from][a] + 0.5 * unscaled.vertices[e.to][a] +
                  offset * unit(rng);
      }
      for (const Point3& p : {any, far, near}) {
        const Point3 q{std::ldexp(p[0], k), std::ldexp(p[1], k), std::ldexp(p[2], k)};
        expect_held(tree, chain, q, ray, tally);
        ASSERT_FALSE(HasFatalFailure());
      }
    }
    std::printf("%s, 2^%d: %zu of %zu points enclosed, %zu with far nodes\n", c.name, k,
                tally.enclosed, tally.points, tally.with_far_nodes);
    // At 2^0 the filter and the far nodes settle nearly every point; far from magnitude 1
    // the areas leave the doubles' range and every node is near (the classifier maps
    // such meshes to magnitude 1 first).
    EXPECT_GT(tally.enclosed, tally.points * 9 / 10);
    if (k == 0 && c.edges_per_loop != 10) {
      EXPECT_GT(tally.with_far_nodes, tally.points / 3);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Scales, BoundaryTreeChains, ::testing::Values(0, 1000, -1000),
                         exactgeo::testing::scale_name);

/// An arc of n edges of the unit circle in the plane z = 0, from angle 0 to 3 pi / 2,
/// counter-clockwise: its box is [-1, 1]^2 x {0}, whose centre (the origin) is the
/// circle's, so the fan is the three-quarter disc.
Chain flat_arc(std::size_t n) {
  Chain chain;
  for (std::size_t i = 0; i <= n; ++i) {
    const double angle = 1.5 * std::numbers::pi * static_cast<double>(i) / static_cast<double>(n);
    chain.vertices.push_back({std::cos(angle), std::sin(angle), 0.0});
  }
  // Angles pi / 2, pi and 3 pi / 2 exactly on the axes: the box is [-1, 1]^2 x {0}.
  chain.vertices[n / 3] = {0.0, 1.0, 0.0};
  chain.vertices[2 * n / 3] = {-1.0, 0.0, 0.0};
  chain.vertices[n] = {0.0, -1.0, 0.0};
  for (std::size_t i = 0; i < n; ++i)
    chain.edges.push_back({static_cast<VertexIndex>(i), static_cast<VertexIndex>(i + 1), 1});
  return chain;
}

TEST(BoundaryTree, AFarFanCarriedByItsExpansionIsHeld) {
  // The arc closed by its chord (1, 0) -> (0, -1) bounds the three-quarter disc and the
  // triangle (0, 0), (0, -1), (1, 0): area A = 3 pi / 4 + 1/2, first moments
  // -1/3 + 1/6 along x and 1/3 - 1/6 along y. Seen from (0, 0, h) its solid angle is
  // A / h^2 - O(1 / h^4); its zero-order bound F / h^2 with F the same area (the fan
  // about the centre is the region itself; the box is flat, so the distance is h). The
  // box reaches rho = sqrt(2) from its centre, so from h = 2 rho on the second-order
  // bound 3 rho^2 F / h^4 (in solid angle) is the one taken, and the node gives its
  // chord's angle and its expansion: on the axis the dipole part, -A / (2 h^2) in half
  // angles (the quadrupole part is 0 there: Q's symmetric part is xz = -1/12,
  // yz = 1/12), within 1/8 of its bound of what remains; off the axis the quadrupole
  // part, -(3/2) v^T Q v / h^5 in half angles (0.12 / h^3 from direction (0.6, 0, 0.8)),
  // exceeds the bound 8.6 / h^4 from h = 72 on. A term left out, or a bound without its
  // reach, misses the term.
  const Chain chain = flat_arc(96);
  const BoundaryTree tree(chain.vertices, chain.edges);
  for (const double h : {8.0, 16.0, 40.0, 100.0, 400.0}) {
    for (const Vector3& direction : {Vector3{0.0, 0.0, 1.0}, Vector3{0.6, 0.0, 0.8},
                                     Vector3{-0.48, 0.36, 0.8}, Vector3{0.0, -0.6, 0.8}}) {
      for (std::size_t k = 0; k < 3; ++k) {
        const Point3 p{h * direction[0], h * direction[1], h * direction[2]};
        // Up and away from the arc.
        const Vector3 up = ray_direction(k);
        const Vector3 ray{up[2], up[1], up[0]};
        BoundaryTree::Refinement refinement;
        const std::optional<Enclosure> e = tree.enclosure(p, ray, 0.5, refinement);
        ASSERT_TRUE(e.has_value());
        // The root stood in for the arc, by its chord and its expansion.
        EXPECT_EQ(refinement.far_nodes, 1u) << h;
        EXPECT_EQ(refinement.expansions, 1u) << h;
        EXPECT_EQ(refinement.angles, 1u) << h;
        const double truth = oracle_term(p, ray, chain);
        EXPECT_LE(e->lower, truth) << h << " " << testing::hex(p);
        EXPECT_GE(e->upper, truth) << h << " " << testing::hex(p);
      }
    }
  }
}

/// The rectangle [-1, 1] x [-0.025, 0.025] in the plane z = 0, n edges along each long
/// side, one across each end; without its side x = -1 when not `closed` (an open trail
/// from (-1, -0.025) to (-1, 0.025)).
Chain rectangle(int n, bool closed) {
  Chain chain;
  for (int i = 0; i <= n; ++i)
    chain.vertices.push_back({-1.0 + 2.0 * i / n, -0.025, 0.0});
  for (int i = 0; i <= n; ++i)
    chain.vertices.push_back({1.0 - 2.0 * i / n, 0.025, 0.0});
  const auto size = static_cast<VertexIndex>(chain.vertices.size());
  for (VertexIndex i = 0; i + 1 < size; ++i)
    chain.edges.push_back({i, i + 1, 1});
  if (closed) chain.edges.push_back({size - 1, 0, 1});
  return chain;
}

TEST(BoundaryTree, AFarLoopWhoseFanFillsMostOfItsBoundIsHeld) {
  // A closed rectangle 2 x 0.05 in the plane z = 0 (one leaf, no ends, its fan about the
  // centre the rectangle itself, F = 0.1), seen from (0, 0, 1.5): the box reaches
  // rho = sqrt(1 + 0.025^2) from its centre, more than d / 2, so F / (2 d^2) = 0.022 is
  // the bound taken (no expansion). The rectangle's solid angle is
  // 0.05 x 2 / (1.5 sqrt(3.25)) = 0.037, 0.83 of F / d^2: a bound halved, or a distance
  // 22% long, misses it, and nothing but the bound accounts for it (no ends, no dipole).
  // With n edges along each long side (a node of children whose ends' fans the nested
  // bound must count) as well as one.
  for (const int n : {1, 5, 7}) {
    const Chain chain = rectangle(n, true);
    const BoundaryTree tree(chain.vertices, chain.edges);
    for (std::size_t k = 0; k < 3; ++k) {
      for (const double h : {1.5, -1.5}) {
        const Point3 p{0.0, 0.0, h};
        Vector3 ray = ray_direction(k);
        if (h < 0) ray = {-ray[0], -ray[1], -ray[2]};  // away from the rectangle
        BoundaryTree::Refinement refinement;
        const std::optional<Enclosure> e = tree.enclosure(p, ray, 0.5, refinement);
        ASSERT_TRUE(e.has_value());
        // The root alone, its bound and nothing else: no angle, no expansion.
        EXPECT_EQ(refinement.far_nodes, 1u);
        EXPECT_EQ(refinement.angles, 0u);
        EXPECT_EQ(refinement.expansions, 0u);
        const double truth = oracle_term(p, ray, chain);
        EXPECT_GT(std::abs(truth), 0.8 * refinement.slack / (2 * std::numbers::pi));
        EXPECT_LE(e->lower, truth) << h << ", " << n;
        EXPECT_GE(e->upper, truth) << h << ", " << n;
      }
    }
  }
}

TEST(BoundaryTree, AFarOpenTrailClosedByItsChordIsHeld) {
  // The same rectangle without its side x = -1: an open trail from (-1, -0.025) to
  // (-1, 0.025), which the root stands in for by its chord (the missing side) and the
  // bound of the rectangle its chord closes, F = 0.1 again, of which the chord's triangle
  // about the centre is a quarter: a nested bound without the node's own chords (its
  // children's fans and chords alone) falls below the rectangle's solid angle.
  for (const int n : {5, 7, 11}) {
    const Chain chain = rectangle(n, false);
    const BoundaryTree tree(chain.vertices, chain.edges);
    for (std::size_t k = 0; k < 3; ++k) {
      for (const double h : {1.5, -1.5}) {
        const Point3 p{0.0, 0.0, h};
        Vector3 ray = ray_direction(k);
        if (h < 0) ray = {-ray[0], -ray[1], -ray[2]};  // away from the rectangle
        BoundaryTree::Refinement refinement;
        const std::optional<Enclosure> e = tree.enclosure(p, ray, 0.5, refinement);
        ASSERT_TRUE(e.has_value());
        // The root alone: its chord's angle and its bound.
        EXPECT_EQ(refinement.far_nodes, 1u);
        EXPECT_EQ(refinement.angles, 1u);
        const double truth = oracle_term(p, ray, chain);
        EXPECT_LE(e->lower, truth) << h << ", " << n;
        EXPECT_GE(e->upper, truth) << h << ", " << n;
      }
    }
  }
}

class BoundaryTreeLevels : public ::testing::TestWithParam<int> {};

TEST_P(BoundaryTreeLevels, SettledLevelsAreOnTheOraclesSide) {
  // A sheet with many holes: 200 small loops of 4 to 12 edges over [-1, 1]^2 (near the
  // plane z = 0), and points in it and near it, most within a few loops' widths of many
  // rims, where far bounds add up. Each point's levels are set 2^-2 to 2^-20 turns from
  // the oracle's term, below and above it (as the classifier's are, 1/2 - S and -1/2 - S
  // against the term): the refinement must open the tree until the enclosure passes
  // between them, and what it settles must be the oracle's side.
  const int k = GetParam();
  auto rng = testing::seeded_engine("predicates.boundary_tree.levels." + std::to_string(k));
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  Chain chain;
  for (int l = 0; l < 200; ++l) {
    const auto n = static_cast<std::size_t>(4 + l % 9);
    add_loop(chain, rng, n, {unit(rng), unit(rng), 0.05 * unit(rng)}, 0.02 + 0.03 * (unit(rng) + 1),
             1 + (l % 7 == 0));
  }
  chain = scaled(chain, k);
  const BoundaryTree tree(chain.vertices, chain.edges);
  std::size_t settled = 0, points = 0, angles = 0;
  // Scaled with the effort (tests/support/seed.hpp), at least one point for each of the
  // five rays.
  const auto trials = static_cast<int>(testing::scaled_trials(k == 0 ? 40 : 8, 5));
  for (int i = 0; i < trials; ++i) {
    const Point3 p{std::ldexp(1.2 * unit(rng), k), std::ldexp(1.2 * unit(rng), k),
                   std::ldexp(0.3 * unit(rng), k)};
    const Vector3 ray = ray_direction(static_cast<std::size_t>(i % 5));
    const double truth = oracle_term(p, ray, chain);
    const double gap = std::ldexp(1.0, -2 - (i % 19));
    for (const double sign : {1.0, -1.0}) {
      // One level on each side of the term, one of them 2^-k away, the other a turn.
      const std::array<double, 2> levels =
          sign > 0 ? std::array{truth - 1.0, truth + gap} : std::array{truth - gap, truth + 1.0};
      BoundaryTree::Refinement refinement;
      const std::optional<BoundaryTerm> term = tree.term(p, ray, levels, refinement);
      ++points;
      if (!term) continue;
      ++settled;
      angles += refinement.angles;
      ASSERT_EQ(term->kind, BoundaryTermKind::enclosed);
      EXPECT_EQ(term->versus[0], Versus::above) << testing::hex(p) << " gap " << gap;
      EXPECT_EQ(term->versus[1], Versus::below) << testing::hex(p) << " gap " << gap;
      EXPECT_LE(term->turns.lower, truth) << testing::hex(p);
      EXPECT_GE(term->turns.upper, truth) << testing::hex(p);
    }
  }
  std::printf("2^%d: %zu of %zu settled by the tree, %zu angles each on average (of %zu edges)\n",
              k, settled, points, settled ? angles / settled : 0, tree.edge_count());
  if (k == 0) {
    // Near the magnitude 1 the tree settles most (the rest, whose levels lie within its
    // filter's errors or cost every edge, go to the term over every edge), with fewer
    // angles than edges.
    EXPECT_GT(settled, points / 2);
    EXPECT_LT(angles, settled * tree.edge_count());
  }
}

INSTANTIATE_TEST_SUITE_P(Scales, BoundaryTreeLevels, ::testing::Values(0, 1000, -1000),
                         exactgeo::testing::scale_name);

TEST(BoundaryTree, RaysThroughFarNodesAreSummedEdgeByEdge) {
  // A point far from a small loop, its ray aimed through the loop's disc: the ray meets
  // the fan triangles, the identity gains 4 pi, and the node must be opened. Points
  // moved back from the loop's edges and its centre along the ray.
  auto rng = testing::seeded_engine("predicates.boundary_tree.aimed");
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  Chain chain;
  add_loop(chain, rng, 64, {0.0, 0.0, 0.0}, 0.05, 1);
  add_loop(chain, rng, 64, {2.0, 0.5, -0.3}, 0.05, 1);
  const BoundaryTree tree(chain.vertices, chain.edges);
  Tally tally;
  for (int i = 0; i < 60; ++i) {
    const Vector3 ray = ray_direction(static_cast<std::size_t>(i % 4));
    // A point of the first loop's disc: a convex combination of its centre and an edge.
    const BoundaryEdge& e = chain.edges[static_cast<std::size_t>(i)];
    const double s = unit(rng) * 0.9, t = unit(rng);
    Point3 target;
    for (int a = 0; a < 3; ++a) {
      const double on_edge = (1 - t) * chain.vertices[e.from][a] + t * chain.vertices[e.to][a];
      target[a] = s * on_edge;
    }
    const double back = 5.0 + 50.0 * unit(rng);
    const Point3 p{target[0] - back * ray[0], target[1] - back * ray[1], target[2] - back * ray[2]};
    expect_held(tree, chain, p, ray, tally, 0.5);
    ASSERT_FALSE(HasFatalFailure());
  }
  EXPECT_GT(tally.enclosed, 50u);
  EXPECT_GT(tally.with_far_nodes, 50u);  // the other loop stood in for its edges
}

}  // namespace
}  // namespace exactgeo::boundary_tree_test
