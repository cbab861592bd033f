// The cap of an open surface and its tree (cap_tree.hpp): the cap closes the surface (its
// edges and the surface's balance, multiplicity-2 rims included); the tree's enclosures
// of w_Cap hold the definition summed in 512-bit MPFR (support/solid_angle_oracle.hpp) at
// random points, near the rims, near cap triangles and far away; and end to end, the
// exact signed crossing count S of a ray with the surface and the cap, minus the
// enclosure, brackets the oracle's w of the surface alone, on the side of the levels
// +-1/2 that enclosure_apart promises. Magnitude 2^0 only: the tree, like BoundaryTree,
// is for inputs near magnitude 1 (the classifier's unit frame).

#include "exactgeo/predicates/cap_tree.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <numbers>
#include <optional>
#include <random>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "exactgeo/predicates/ray_directions.hpp"
#include "exactgeo/predicates/ray_triangle.hpp"
#include "support/hexfloat.hpp"
#include "support/seed.hpp"
#include "support/solid_angle_oracle.hpp"

namespace exactgeo::cap_tree_test {
namespace {

using Face = std::array<VertexIndex, 3>;

struct Surface {
  std::string name;
  std::vector<Point3> vertices;
  std::vector<Face> faces;
};

/// A latitude-longitude sphere (rings from polar angle 0.3 to pi - 0.3: two holes at the
/// poles), its vertices jittered (no three boundary vertices on a line), a window of
/// faces cut out and each other face cut with probability 1 / `one_in`.
Surface holed_sphere(std::mt19937_64& rng, std::size_t rings, std::size_t sectors,
                     std::size_t one_in) {
  Surface s{"holed sphere", {}, {}};
  std::uniform_real_distribution<double> jitter(-0.02, 0.02);
  for (std::size_t i = 0; i <= rings; ++i) {
    const double polar =
        0.3 + (std::numbers::pi - 0.6) * static_cast<double>(i) / static_cast<double>(rings);
    for (std::size_t j = 0; j < sectors; ++j) {
      const double around =
          2 * std::numbers::pi * static_cast<double>(j) / static_cast<double>(sectors);
      s.vertices.push_back({std::sin(polar) * std::cos(around) + jitter(rng),
                            std::sin(polar) * std::sin(around) + jitter(rng),
                            std::cos(polar) + jitter(rng)});
    }
  }
  std::uniform_int_distribution<std::size_t> coin(0, one_in - 1);
  const auto at = [&](std::size_t i, std::size_t j) {
    return static_cast<VertexIndex>(i * sectors + j % sectors);
  };
  for (std::size_t i = 0; i < rings; ++i) {
    for (std::size_t j = 0; j < sectors; ++j) {
      if (i >= rings / 3 && i < rings / 3 + 3 && j < 4) continue;  // a window
      if (coin(rng) != 0) s.faces.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      if (coin(rng) != 0) s.faces.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  }
  return s;
}

/// A wavy sheet over [-1, 1]^2 with jittered vertices and faces cut at random.
Surface perforated_sheet(std::mt19937_64& rng, std::size_t n, std::size_t one_in) {
  Surface s{"perforated sheet", {}, {}};
  std::uniform_real_distribution<double> jitter(-0.2, 0.2);
  for (std::size_t j = 0; j <= n; ++j) {
    for (std::size_t i = 0; i <= n; ++i) {
      const double x = -1 + 2 * (static_cast<double>(i) + jitter(rng)) / static_cast<double>(n);
      const double y = -1 + 2 * (static_cast<double>(j) + jitter(rng)) / static_cast<double>(n);
      s.vertices.push_back({x, y, 0.3 * std::sin(3 * x) * std::cos(2 * y) + 0.01 * jitter(rng)});
    }
  }
  const auto at = [&](std::size_t i, std::size_t j) {
    return static_cast<VertexIndex>(j * (n + 1) + i);
  };
  std::uniform_int_distribution<std::size_t> coin(0, one_in - 1);
  for (std::size_t j = 0; j < n; ++j) {
    for (std::size_t i = 0; i < n; ++i) {
      if (coin(rng) != 0) s.faces.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      if (coin(rng) != 0) s.faces.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  }
  return s;
}

/// The surface's faces twice: its rims have multiplicity 2.
Surface twice(Surface s) {
  s.name += ", twice";
  const std::size_t n = s.faces.size();
  for (std::size_t i = 0; i < n; ++i)
    s.faces.push_back(s.faces[i]);
  return s;
}

/// Net uses of each directed edge, keyed by (smaller, larger) vertex: + for smaller to
/// larger.
using EdgeCounts = std::map<std::pair<VertexIndex, VertexIndex>, std::int64_t>;

void count(EdgeCounts& counts, VertexIndex a, VertexIndex b, std::int64_t m) {
  if (a == b) return;
  if (a < b) {
    counts[{a, b}] += m;
  } else {
    counts[{b, a}] -= m;
  }
}

/// The boundary chain, written out here (not the library's): every edge used more often
/// one way than the other, oriented the way more faces run it.
std::vector<BoundaryEdge> chain_of(const Surface& s) {
  EdgeCounts counts;
  for (const Face& f : s.faces) {
    for (int k = 0; k < 3; ++k)
      count(counts, f[k], f[(k + 1) % 3], 1);
  }
  std::vector<BoundaryEdge> chain;
  for (const auto& [e, m] : counts) {
    if (m > 0) chain.push_back({e.first, e.second, static_cast<std::int32_t>(m)});
    if (m < 0) chain.push_back({e.second, e.first, static_cast<std::int32_t>(-m)});
  }
  return chain;
}

/// Triangles with multiplicities as the oracle's list: each |m| times, reversed for m < 0.
std::vector<testing::Triangle> oracle_triangles(const std::vector<Point3>& vertices,
                                                const std::vector<CapTriangle>& cap) {
  std::vector<testing::Triangle> out;
  for (const CapTriangle& t : cap) {
    for (std::int32_t i = 0; i < std::abs(t.multiplicity); ++i) {
      if (t.multiplicity > 0) {
        out.push_back({vertices[t.a], vertices[t.b], vertices[t.c]});
      } else {
        out.push_back({vertices[t.a], vertices[t.c], vertices[t.b]});
      }
    }
  }
  return out;
}

std::vector<testing::Triangle> oracle_triangles(const Surface& s) {
  std::vector<testing::Triangle> out;
  for (const Face& f : s.faces)
    out.push_back({s.vertices[f[0]], s.vertices[f[1]], s.vertices[f[2]]});
  return out;
}

std::vector<Surface> surfaces(std::mt19937_64& rng) {
  std::vector<Surface> out;
  out.push_back(holed_sphere(rng, 8, 12, 6));
  out.push_back(perforated_sheet(rng, 9, 5));
  out.push_back(twice(holed_sphere(rng, 6, 10, 5)));
  return out;
}

TEST(CapTriangles, CloseTheSurface) {
  auto rng = testing::seeded_engine("predicates.cap_tree.closes");
  for (int round = 0; round < 20; ++round) {
    for (const Surface& s : surfaces(rng)) {
      SCOPED_TRACE(s.name);
      const std::vector<BoundaryEdge> chain = chain_of(s);
      ASSERT_FALSE(chain.empty());
      const std::vector<CapTriangle> cap = cap_triangles(s.vertices, chain);
      const CapTree tree(s.vertices, chain);
      // The merged cap and the tree's (each triangle once per loop that made it).
      for (const std::span<const CapTriangle> triangles :
           {std::span<const CapTriangle>(cap), tree.triangles()}) {
        EdgeCounts counts;
        for (const Face& f : s.faces) {
          for (int k = 0; k < 3; ++k)
            count(counts, f[k], f[(k + 1) % 3], 1);
        }
        for (const CapTriangle& t : triangles) {
          ASSERT_NE(t.multiplicity, 0);
          count(counts, t.a, t.b, t.multiplicity);
          count(counts, t.b, t.c, t.multiplicity);
          count(counts, t.c, t.a, t.multiplicity);
        }
        for (const auto& [e, m] : counts)
          ASSERT_EQ(m, 0) << "edge " << e.first << " - " << e.second;
      }
      if (s.name.ends_with("twice")) {
        // Every triangle of a doubled rim's cap counted twice.
        for (const CapTriangle& t : cap)
          EXPECT_EQ(std::abs(t.multiplicity) % 2, 0);
      }
    }
  }
}

TEST(CapTriangles, SmallLoops) {
  // A triangle's loop: one cap triangle, reversed; a loop run there and back: nothing.
  const std::vector<Point3> v{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  const std::vector<BoundaryEdge> loop{{0, 1, 1}, {1, 2, 1}, {2, 0, 1}};
  const std::vector<CapTriangle> cap = cap_triangles(v, loop);
  ASSERT_EQ(cap.size(), 1u);
  EdgeCounts counts;
  for (const BoundaryEdge& e : loop)
    count(counts, e.from, e.to, e.multiplicity);
  count(counts, cap[0].a, cap[0].b, cap[0].multiplicity);
  count(counts, cap[0].b, cap[0].c, cap[0].multiplicity);
  count(counts, cap[0].c, cap[0].a, cap[0].multiplicity);
  for (const auto& [e, m] : counts)
    EXPECT_EQ(m, 0);
  EXPECT_TRUE(cap_triangles(v, std::vector<BoundaryEdge>{{0, 1, 2}, {1, 0, 2}}).empty());
  EXPECT_THROW(cap_triangles(v, std::vector<BoundaryEdge>{{0, 1, 1}}), std::invalid_argument);
}

TEST(CapTree, TrianglesOnALineLeftOut) {
  // The loop 0 -> 1 -> 2 -> 3 -> 4 with 0, 1, 2 on a line: its halving's triangle
  // (v0, v2, v1) has no area and is left out; the other two cover the pentagon.
  const std::vector<Point3> v{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}};
  const std::vector<BoundaryEdge> loop{{0, 1, 1}, {1, 2, 1}, {2, 3, 1}, {3, 4, 1}, {4, 0, 1}};
  const std::vector<CapTriangle> cap = cap_triangles(v, loop);
  EXPECT_EQ(cap.size(), 2u);
  const CapTree tree(v, loop);
  ASSERT_EQ(tree.triangle_count(), 2u);
  const std::vector<CapTriangle> own(tree.triangles().begin(), tree.triangles().end());
  const std::vector<testing::Triangle> triangles = oracle_triangles(v, own);
  CapTree::Refinement r;
  for (const Point3& p : {Point3{1, 0.5, 1}, Point3{1, 0.5, -0x1p-40}, Point3{5, 5, 5}}) {
    const double truth = testing::generalized_winding_oracle(p, triangles);
    const auto e = tree.enclosure(p, 0.0, r);
    ASSERT_TRUE(e.has_value());
    EXPECT_LE(e->lower, truth);
    EXPECT_GE(e->upper, truth);
  }
  // A loop all on a line: no cap at all, and w_Cap = 0.
  const std::vector<BoundaryEdge> flat{{0, 1, 1}, {1, 2, 1}, {2, 0, 1}};
  EXPECT_TRUE(cap_triangles(v, flat).empty());
  const CapTree none(v, flat);
  EXPECT_EQ(none.triangle_count(), 0u);
  const auto e = none.enclosure_apart({1, 1, 1}, r);
  ASSERT_TRUE(e.has_value());
  EXPECT_LE(e->lower, 0.0);
  EXPECT_GE(e->upper, 0.0);
}

/// Points of every kind for a surface and its cap: anywhere in [-1.5, 1.5]^3, far away,
/// near a rim edge's midpoint (moved by 2^-4 to 2^-30) and near a cap triangle's centroid
/// (by 2^-4 to 2^-55).
std::vector<Point3> points_for(std::mt19937_64& rng, const Surface& s,
                               const std::vector<BoundaryEdge>& chain,
                               const std::vector<CapTriangle>& cap, int n) {
  std::uniform_real_distribution<double> anywhere(-1.5, 1.5), unit(-1.0, 1.0);
  std::vector<Point3> out;
  for (int i = 0; i < n; ++i) {
    const double offset = std::ldexp(1.0, -4 - (i % 27));
    switch (i % 4) {
      case 0:
        out.push_back({anywhere(rng), anywhere(rng), anywhere(rng)});
        break;
      case 1: {
        Point3 far{unit(rng), unit(rng), unit(rng)};
        const double scale = (4.0 + 60.0 * (unit(rng) + 1)) /
                             std::sqrt(far[0] * far[0] + far[1] * far[1] + far[2] * far[2]);
        for (double& x : far)
          x *= scale;
        out.push_back(far);
        break;
      }
      case 2: {
        const BoundaryEdge& e = chain[static_cast<std::size_t>(i) % chain.size()];
        Point3 p;
        for (int a = 0; a < 3; ++a)
          p[a] = 0.5 * s.vertices[e.from][a] + 0.5 * s.vertices[e.to][a] + offset * unit(rng);
        out.push_back(p);
        break;
      }
      default: {
        // Down to 2^-55 from the triangle, where the sign of its half angle's numerator
        // is the exact predicate's.
        const CapTriangle& t = cap[static_cast<std::size_t>(i) % cap.size()];
        const double tiny = std::ldexp(1.0, -4 - std::uniform_int_distribution<int>(0, 51)(rng));
        Point3 p;
        for (int a = 0; a < 3; ++a) {
          p[a] =
              (s.vertices[t.a][a] + s.vertices[t.b][a] + s.vertices[t.c][a]) / 3 + tiny * unit(rng);
        }
        out.push_back(p);
      }
    }
  }
  return out;
}

constexpr std::array<double, 4> kWidths{0.5, 0x1p-6, 0x1p-12, 0.0};

TEST(CapTree, EnclosuresHoldTheOracle) {
  auto rng = testing::seeded_engine("predicates.cap_tree.enclosures");
  std::size_t points = 0, enclosed = 0, apart = 0, with_far = 0;
  for (int round = 0; round < 2; ++round) {
    for (const Surface& s : surfaces(rng)) {
      SCOPED_TRACE(s.name);
      const std::vector<BoundaryEdge> chain = chain_of(s);
      const CapTree tree(s.vertices, chain);
      const std::vector<CapTriangle> cap(tree.triangles().begin(), tree.triangles().end());
      const std::vector<testing::Triangle> triangles = oracle_triangles(s.vertices, cap);
      CapTree::Refinement r;
      int i = 0;
      for (const Point3& p : points_for(rng, s, chain, cap, 80)) {
        const double truth = testing::generalized_winding_oracle(p, triangles);
        const double width = kWidths[static_cast<std::size_t>(i++) % kWidths.size()];
        ++points;
        if (const auto e = tree.enclosure(p, width, r)) {
          ++enclosed;
          with_far += r.far_nodes > 0;
          ASSERT_LE(e->lower, truth) << testing::hex(p) << " width " << width;
          ASSERT_GE(e->upper, truth) << testing::hex(p) << " width " << width;
          if (r.far_nodes > 0) {
            EXPECT_LE(e->upper - e->lower, width * (1 + 0x1p-40) + 0x1p-900);
          }
        }
        if (const auto e = tree.enclosure_apart(p, r)) {
          ++apart;
          ASSERT_LE(e->lower, truth) << testing::hex(p);
          ASSERT_GE(e->upper, truth) << testing::hex(p);
          const double k = std::nearbyint(e->lower);
          EXPECT_LT(k - 0.5, e->lower) << testing::hex(p);
          EXPECT_LT(e->upper, k + 0.5) << testing::hex(p);
        }
      }
    }
  }
  std::printf("%zu points: %zu enclosed (%zu with far nodes), %zu apart\n", points, enclosed,
              with_far, apart);
  EXPECT_GT(enclosed, points * 9 / 10);
  EXPECT_GT(apart, points * 9 / 10);
  EXPECT_GT(with_far, points / 3);
}

TEST(CapTree, EnclosuresApartKeepTheirMargin) {
  // enclosure_apart with a margin (a box of space cells asks for its variation): where it
  // answers, the oracle's w_Cap with the margin on either side lies strictly between two
  // consecutive half-integers; where the oracle's value is that far inside with room to
  // spare (2^-8 turns), it answers; and it gives up at once (the enclosure found so far
  // leaves no room) rather than opening every node: fewer angles than the enclosure at
  // width 0 takes.
  auto rng = testing::seeded_engine("predicates.cap_tree.margins");
  constexpr std::array<double, 5> kMargins{0.0, 0x1p-10, 0.1, 0.3, 0.45};
  std::size_t answered = 0, owed = 0, given_up = 0, cheap = 0;
  for (const Surface& s : surfaces(rng)) {
    SCOPED_TRACE(s.name);
    const std::vector<BoundaryEdge> chain = chain_of(s);
    const CapTree tree(s.vertices, chain);
    const std::vector<CapTriangle> cap(tree.triangles().begin(), tree.triangles().end());
    const std::vector<testing::Triangle> triangles = oracle_triangles(s.vertices, cap);
    CapTree::Refinement r, all;
    int i = 0;
    for (const Point3& p : points_for(rng, s, chain, cap, 40)) {
      const double margin = kMargins[static_cast<std::size_t>(i++) % kMargins.size()];
      const double truth = testing::generalized_winding_oracle(p, triangles);
      const double k = std::nearbyint(truth);
      const bool room = k - 0.5 + margin + 0x1p-8 < truth && truth < k + 0.5 - margin - 0x1p-8;
      if (const auto e = tree.enclosure_apart(p, r, margin)) {
        ++answered;
        ASSERT_LE(e->lower, truth) << testing::hex(p);
        ASSERT_GE(e->upper, truth) << testing::hex(p);
        EXPECT_LT(k - 0.5, truth - margin) << testing::hex(p) << " margin " << margin;
        EXPECT_LT(truth + margin, k + 0.5) << testing::hex(p) << " margin " << margin;
        EXPECT_LT(k - 0.5, e->lower - margin) << testing::hex(p) << " margin " << margin;
        EXPECT_LT(e->upper + margin, k + 0.5) << testing::hex(p) << " margin " << margin;
      } else if (room) {
        // Within rounding of a cap triangle only (no enclosure at any width).
        EXPECT_FALSE(tree.enclosure(p, 0.0, all).has_value()) << testing::hex(p);
      } else if (margin > 0.0 && tree.enclosure(p, 0.0, all)) {
        ++given_up;
        cheap += r.triangles < all.triangles;
      }
      owed += room;
    }
  }
  std::printf("%zu answered, %zu with room, %zu given up (%zu before every angle)\n", answered,
              owed, given_up, cheap);
  EXPECT_GE(answered, owed);
  EXPECT_GT(given_up, 0u);
  EXPECT_GT(cheap, given_up / 2);
}

/// The signed crossing count of the ray from p along `ray` with the faces and the cap
/// (each crossing the sign of the triangle's normal along the ray, times its
/// multiplicity), exact; nullopt where the ray meets a triangle other than through its
/// interior (the caller takes another ray).
std::optional<std::int64_t> crossings(const Point3& p, const Vector3& ray, const Surface& s,
                                      const std::vector<CapTriangle>& cap) {
  std::int64_t sum = 0;
  const auto add = [&](const Point3& a, const Point3& b, const Point3& c, std::int64_t m) {
    const RayTriangleHit hit = classify_ray_triangle(p, ray, a, b, c);
    if (hit.kind == RayTriangle::miss) return true;
    if (hit.kind != RayTriangle::interior) return false;
    sum += hit.turn == Sign::positive ? m : -m;
    return true;
  };
  for (const Face& f : s.faces) {
    if (!add(s.vertices[f[0]], s.vertices[f[1]], s.vertices[f[2]], 1)) return std::nullopt;
  }
  for (const CapTriangle& t : cap) {
    if (!add(s.vertices[t.a], s.vertices[t.b], s.vertices[t.c], t.multiplicity)) {
      return std::nullopt;
    }
  }
  return sum;
}

TEST(CapTree, EndToEndWindingNumbers) {
  auto rng = testing::seeded_engine("predicates.cap_tree.end_to_end");
  std::size_t points = 0, decided = 0, near_half = 0;
  for (const Surface& s : surfaces(rng)) {
    SCOPED_TRACE(s.name);
    const std::vector<BoundaryEdge> chain = chain_of(s);
    const CapTree tree(s.vertices, chain);
    const std::vector<CapTriangle> cap(tree.triangles().begin(), tree.triangles().end());
    const std::vector<testing::Triangle> faces = oracle_triangles(s);
    CapTree::Refinement r;
    for (const Point3& p : points_for(rng, s, chain, cap, 60)) {
      std::optional<std::int64_t> count;
      for (std::size_t k = 0; !count && k < 8; ++k)
        count = crossings(p, ray_direction(k), s, cap);
      ASSERT_TRUE(count.has_value()) << testing::hex(p);
      ++points;
      const auto e = tree.enclosure_apart(p, r);
      if (!e) continue;
      ++decided;
      const double w = testing::generalized_winding_oracle(p, faces);
      const auto S = static_cast<double>(*count);
      // w_F = S - w_Cap, and the enclosure lies strictly between k - 1/2 and k + 1/2: w_F
      // is within 1/2 of S - k, on the side of the levels +-1/2 that S - k says.
      ASSERT_LE(S - e->upper, w + 0x1p-40) << testing::hex(p);
      ASSERT_GE(S - e->lower, w - 0x1p-40) << testing::hex(p);
      const double k = std::nearbyint(e->lower);
      EXPECT_LT(std::abs(w - (S - k)), 0.5) << testing::hex(p);
      near_half += std::abs(std::abs(w) - 0.5) < 0.05;
    }
  }
  std::printf("%zu points, %zu decided, %zu of them within 0.05 of a level\n", points, decided,
              near_half);
  EXPECT_GT(decided, points * 9 / 10);
}

}  // namespace
}  // namespace exactgeo::cap_tree_test
