// Overlapping point groups found by box trees (boxes/point_groups.hpp): every pair whose
// exact boxes meet is reported, once, against brute force over all pairs, for random
// groups of random sizes at 2^0 and 2^+-1000, groups that only touch included; the scan of
// many groups against a few finds the same pairs.

#include "exactgeo/boxes/point_groups.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>
#include <set>
#include <utility>
#include <vector>

#include "exactgeo/boxes/exact_box.hpp"
#include "support/seed.hpp"

namespace exactgeo::boxes {
namespace {

template <std::size_t N>
ExactBox box_of(std::span<const Point3> points, const std::array<VertexIndex, N>& g) {
  ExactBox b = ExactBox::of(points[g[0]]);
  for (const VertexIndex v : g)
    b.add(points[v]);
  return b;
}

TEST(PointGroups, EveryPairWhoseExactBoxesMeetIsFoundOnce) {
  std::mt19937_64 rng = testing::seeded_engine("PointGroups.brute_force");
  for (const int e : {0, 1000, -1000}) {
    const double s = std::ldexp(1.0, e);
    // A grid of 2^-3 steps, so that many boxes touch exactly.
    std::uniform_int_distribution<int> grid(0, 64);
    std::vector<Point3> points(300);
    for (Point3& p : points) {
      for (double& x : p)
        x = s * grid(rng) / 8.0;
    }
    std::uniform_int_distribution<VertexIndex> any(0, static_cast<VertexIndex>(points.size() - 1));
    std::vector<std::array<VertexIndex, 4>> a(80);
    std::vector<std::array<VertexIndex, 3>> b(120);
    for (auto& g : a) {
      g[0] = any(rng);
      for (std::size_t k = 1; k < 4; ++k)  // near the first point
        g[k] = static_cast<VertexIndex>((g[0] + k * (1 + rng() % 5)) % points.size());
    }
    for (auto& g : b) {
      for (VertexIndex& v : g)
        v = any(rng);
    }
    std::set<std::pair<std::size_t, std::size_t>> expected;
    for (std::size_t i = 0; i < a.size(); ++i) {
      for (std::size_t j = 0; j < b.size(); ++j) {
        if (box_of<4>(points, a[i]).meets(box_of<3>(points, b[j]))) expected.insert({i, j});
      }
    }
    std::multiset<std::pair<std::size_t, std::size_t>> found;
    overlapping_groups<4, 3>(points, a, b, [&](std::size_t i, std::size_t j) {
      found.insert({i, j});
    });
    for (const auto& pair : expected) {
      EXPECT_EQ(found.count(pair), 1u) << "2^" << e << ": " << pair.first << ", " << pair.second;
    }
    EXPECT_GT(expected.size(), 100u);
    // A few groups against many, by a scan of the many: the same pairs, each once.
    std::multiset<std::pair<std::size_t, std::size_t>> scanned;
    overlapping_groups_by_scan<4, 3>(points, a, b, [&](std::size_t i, std::size_t j) {
      scanned.insert({i, j});
    });
    EXPECT_EQ(scanned, found) << "2^" << e;
    for (const auto& pair : expected)
      EXPECT_EQ(scanned.count(pair), 1u) << "2^" << e << ": " << pair.first << ", " << pair.second;
    std::multiset<std::pair<std::size_t, std::size_t>> few;  // fewer than a leaf holds
    overlapping_groups_by_scan<4, 3>(points, std::span(a).first(5), b,
                                     [&](std::size_t i, std::size_t j) {
                                       few.insert({i, j});
                                     });
    std::multiset<std::pair<std::size_t, std::size_t>> few_expected;
    for (const auto& pair : found)
      if (pair.first < 5) few_expected.insert(pair);
    EXPECT_EQ(few, few_expected) << "2^" << e;
    for (const auto& pair : expected) {  // against brute force too, not only the trees
      if (pair.first < 5) {
        EXPECT_EQ(few.count(pair), 1u) << "2^" << e << ": " << pair.first << ", " << pair.second;
      }
    }
    EXPECT_FALSE(few.empty());
    // Within one set: i < j, each once.
    std::set<std::pair<std::size_t, std::size_t>> within;
    for (std::size_t i = 0; i < b.size(); ++i) {
      for (std::size_t j = i + 1; j < b.size(); ++j) {
        if (box_of<3>(points, b[i]).meets(box_of<3>(points, b[j]))) within.insert({i, j});
      }
    }
    std::multiset<std::pair<std::size_t, std::size_t>> found_within;
    overlapping_groups<3>(points, b, [&](std::size_t i, std::size_t j) {
      EXPECT_LT(i, j);
      found_within.insert({i, j});
    });
    for (const auto& pair : within)
      EXPECT_EQ(found_within.count(pair), 1u) << pair.first;
  }
}

}  // namespace
}  // namespace exactgeo::boxes
