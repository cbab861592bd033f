// The box tree's walk (boxes/box_tree.hpp, boxes/tree_pairs.hpp) against brute force: every
// pair of primitives whose boxes overlap is reported exactly once, within one tree and
// between two, with adjacent pairs kept or skipped as the walk's rule says; a refitted
// tree reports what a fresh one does; split walks report the same pairs as one walk.

#include "exactgeo/boxes/box_tree.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <set>
#include <utility>
#include <vector>

#include "exactgeo/boxes/tree_pairs.hpp"
#include "support/generators.hpp"
#include "support/seed.hpp"

namespace exactgeo::boxes {
namespace {

using Pairs = std::set<std::pair<std::uint32_t, std::uint32_t>>;

/// Random points in a cube, their boxes at rest.
VertexBoxes random_vertices(testing::Rng& rng, std::size_t n, double spread) {
  const Scale scale(spread);
  std::vector<FloatBox> boxes(n);
  for (FloatBox& b : boxes)
    b = point_box(testing::random_point(rng, spread), scale);
  return VertexBoxes::at_rest(std::move(boxes));
}

/// Primitives of N corners on random vertices, some sharing corners.
template <std::size_t N>
std::vector<std::array<VertexIndex, N>> random_primitives(testing::Rng& rng, std::size_t count,
                                                          std::size_t vertices) {
  std::vector<std::array<VertexIndex, N>> p(count);
  for (auto& corners : p) {
    const auto first = static_cast<VertexIndex>(testing::uniform_int(rng, 0, int(vertices) - 1));
    for (std::size_t k = 0; k < N; ++k) {  // near each other, so boxes stay small
      const int step = testing::uniform_int(rng, 0, 6);
      corners[k] = static_cast<VertexIndex>((first + step) % vertices);
    }
  }
  return p;
}

template <std::size_t N>
FloatBox box_of(const std::array<VertexIndex, N>& corners, const VertexBoxes& v) {
  FloatBox b = v.box[corners[0]];
  for (std::size_t k = 1; k < N; ++k)
    b = united(b, v.box[corners[k]]);
  return b;
}

template <std::size_t NA, std::size_t NB>
bool share_corner(const std::array<VertexIndex, NA>& a, const std::array<VertexIndex, NB>& b) {
  for (const VertexIndex x : a)
    if (std::find(b.begin(), b.end(), x) != b.end()) return true;
  return false;
}

/// Every pair the walk reports, each asserted to be new (reported once).
template <std::size_t NA, std::size_t NB>
Pairs walked(const Walk<NA, NB>& walk, std::size_t splits) {
  Pairs found;
  std::vector<NodePair> stack;
  for (const NodePair start : split_pairs(walk, splits)) {
    overlapping_pairs(walk, start, stack,
                      [&](const Packet<NA>& a, std::size_t i, const Packet<NB>& b, std::size_t j) {
                        auto pair = std::pair{a.id[i], b.id[j]};
                        if (walk.within({0, 0}) && pair.first > pair.second) {
                          std::swap(pair.first, pair.second);
                        }
                        EXPECT_TRUE(found.insert(pair).second) << "reported twice";
                      });
  }
  return found;
}

TEST(BoxTree, OneTreeReportsEveryOverlappingPairOnce) {
  auto rng = testing::seeded_engine("boxes.box_tree.self");
  // 6 rounds at full effort (tests/support/seed.hpp), at least one at each magnitude.
  const auto rounds = static_cast<int>(testing::scaled_trials(6, 2));
  for (int round = 0; round < rounds; ++round) {
    const std::size_t vertices = 400;
    const VertexBoxes v = random_vertices(rng, vertices, round % 2 ? 1e-300 : 1.0);
    const auto faces = random_primitives<4>(rng, 600, vertices);
    const BoxTree<4> tree(faces, v);
    for (const SharedCorners rule : {SharedCorners::keep, SharedCorners::skip}) {
      Pairs expected;
      for (std::uint32_t i = 0; i < faces.size(); ++i) {
        for (std::uint32_t j = i + 1; j < faces.size(); ++j) {
          if (!overlap(box_of(faces[i], v), box_of(faces[j], v))) continue;
          if (rule == SharedCorners::skip && share_corner(faces[i], faces[j])) continue;
          expected.insert({i, j});
        }
      }
      const Walk<4, 4> walk{tree, tree, v, rule};
      EXPECT_EQ(walked(walk, 1), expected) << "round " << round;
      EXPECT_EQ(walked(walk, 64), expected) << "round " << round << ", split walk";
      EXPECT_GT(expected.size(), 100u);
    }
  }
}

TEST(BoxTree, TwoTreesAndARefitReportWhatBruteForceDoes) {
  auto rng = testing::seeded_engine("boxes.box_tree.two");
  const std::size_t vertices = 300;
  VertexBoxes v = random_vertices(rng, vertices, 1.0);
  std::vector<std::array<VertexIndex, 1>> points(vertices);
  for (VertexIndex i = 0; i < vertices; ++i)
    points[i] = {i};
  const auto triangles = random_primitives<3>(rng, 500, vertices);
  BoxTree<1> point_tree(points, v);
  BoxTree<3> triangle_tree(triangles, v);
  for (int round = 0; round < 3; ++round) {
    if (round > 0) {  // the vertices move: refit, and compare with fresh trees
      v = random_vertices(rng, vertices, 1.0);
      point_tree.refit(v);
      triangle_tree.refit(v);
    }
    Pairs expected;
    for (std::uint32_t i = 0; i < vertices; ++i) {
      for (std::uint32_t j = 0; j < triangles.size(); ++j) {
        if (overlap(v.box[i], box_of(triangles[j], v)) && !share_corner(points[i], triangles[j])) {
          expected.insert({i, j});
        }
      }
    }
    const Walk<1, 3> refitted{point_tree, triangle_tree, v, SharedCorners::skip};
    EXPECT_EQ(walked(refitted, 16), expected) << "round " << round;
    const BoxTree<1> fresh_points(points, v);
    const BoxTree<3> fresh_triangles(triangles, v);
    const Walk<1, 3> fresh{fresh_points, fresh_triangles, v, SharedCorners::skip};
    EXPECT_EQ(walked(fresh, 16), expected) << "round " << round;
    EXPECT_GT(expected.size(), 50u);
  }
}

/// The build sorts along a Morton curve of the box centres on a grid over their bounds
/// (box_tree.hpp); whatever that grid makes of the centres, the tree must hold every pair.
TEST(BoxTree, CentresTheGridCannotTellApartStillGiveEveryPair) {
  auto rng = testing::seeded_engine("boxes.box_tree.grid");
  constexpr float kInf = std::numeric_limits<float>::infinity();
  for (int layout = 0; layout < 3; ++layout) {
    const std::size_t vertices = 500;
    VertexBoxes v = random_vertices(rng, vertices, 1.0);
    if (layout == 0) {  // half the vertices on one point: one grid cell for their primitives
      for (std::size_t i = 0; i < vertices / 2; ++i)
        v.box[i] = v.box[0];
    } else if (layout == 1) {  // one far vertex: the others share a few cells on every axis
      v.box[7] = point_box({1e30, -1e30, 1e30}, Scale(1e30));
    } else {  // boxes reaching infinity: centres that are not finite, spreads that are not
      v.box[3].hi = {kInf, kInf, kInf};
      v.box[5].lo = {-kInf, -kInf, -kInf};
      v.box[5].hi = {kInf, 0.0f, kInf};
    }
    const auto triangles = random_primitives<3>(rng, 700, vertices);
    const BoxTree<3> tree(triangles, v);
    Pairs expected;
    for (std::uint32_t i = 0; i < triangles.size(); ++i) {
      for (std::uint32_t j = i + 1; j < triangles.size(); ++j) {
        if (overlap(box_of(triangles[i], v), box_of(triangles[j], v))) expected.insert({i, j});
      }
    }
    const Walk<3, 3> walk{tree, tree, v, SharedCorners::keep};
    EXPECT_EQ(walked(walk, 1), expected) << "layout " << layout;
    EXPECT_EQ(walked(walk, 64), expected) << "layout " << layout << ", split walk";
    EXPECT_GT(expected.size(), 100u) << "layout " << layout;
  }
}

/// The measure the mesh broad phase rebuilds its trees on (box_tree.hpp): blind to how
/// large the boxes are and to motions that move everything alike, grown when the
/// primitives a tree groups move apart.
TEST(BoxTree, CentreSpreadSeesPrimitivesMoveApartNotTheirBoxesGrow) {
  auto rng = testing::seeded_engine("boxes.box_tree.spread");
  const std::size_t vertices = 600;
  const VertexBoxes v = random_vertices(rng, vertices, 1.0);
  const auto triangles = random_primitives<3>(rng, 800, vertices);
  BoxTree<3> tree(triangles, v);
  const double built = tree.centre_spread();
  ASSERT_EQ(built, tree.built_centre_spread());
  ASSERT_GT(built, 1.0);
  const auto refit_to = [&](const auto& change) {
    VertexBoxes moved = v;
    for (FloatBox& b : moved.box)
      change(b);
    tree.refit(moved);
    return tree.centre_spread();
  };
  const double loose = tree.looseness();
  // Every box grown by the same amount on every side: the same centres (up to the float
  // rounding of the grown bounds), where the looseness, which weighs the boxes' sizes,
  // moves by a tenth or more.
  const double grown = refit_to([](FloatBox& b) {
    for (int k = 0; k < 3; ++k) {
      b.lo[k] -= 0.25f;
      b.hi[k] += 0.25f;
    }
  });
  EXPECT_NEAR(grown, built, 1e-4 * built);
  EXPECT_GT(std::abs(tree.looseness() - loose), 0.1 * loose);
  // Everything scaled by 2 (exact in float and in the sums): the same spread.
  const double doubled = refit_to([](FloatBox& b) {
    for (int k = 0; k < 3; ++k) {
      b.lo[k] *= 2;
      b.hi[k] *= 2;
    }
  });
  EXPECT_EQ(doubled, built);
  // The vertices' places shuffled: what the tree groups is scattered.
  std::vector<std::size_t> order(vertices);
  for (std::size_t i = 0; i < vertices; ++i)
    order[i] = i;
  std::shuffle(order.begin(), order.end(), rng);
  VertexBoxes shuffled = v;
  for (std::size_t i = 0; i < vertices; ++i)
    shuffled.box[i] = v.box[order[i]];
  tree.refit(shuffled);
  EXPECT_GT(tree.centre_spread(), 1.5 * built);
  EXPECT_LT(BoxTree<3>(triangles, shuffled).centre_spread(), 1.5 * built)
      << "a fresh tree on the shuffled boxes is about as tight as the first";
}

}  // namespace
}  // namespace exactgeo::boxes
