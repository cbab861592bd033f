// Which operations of a pass go ahead together (remesh/src/pass_schedule.hpp, internal to
// the library: reached by path, as tests/mesh/ reaches mesh/src/). Hand cases, at 2^0 and
// 2^+-1000: an operation sharing a vertex with an earlier one that goes ahead waits, one
// sharing a vertex only with one that waits goes ahead; regions touching at a point wait,
// one ulp apart they go ahead; regions whose boxes overlap but which are apart go ahead,
// unless a footprint asks for boxes; a split's new point counts as a corner. Then seeded
// passes of random footprints against the rule as the header states it, decided by the
// rational hull oracle (hull_oracle.hpp) instead of regions_meet.

#include "../../remesh/src/pass_schedule.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "remesh/hull_oracle.hpp"
#include "support/scale_names.hpp"
#include "support/seed.hpp"
#include "support/segment_triangle_oracle.hpp"

namespace exactgeo::remesh {
namespace {

using internal::BoxSchedule;
using internal::Footprint;
using internal::go_ahead;
using Region = std::array<RegionCorner, 4>;

class PassSchedule : public ::testing::TestWithParam<int> {
 protected:
  double scale() const { return std::ldexp(1.0, GetParam()); }
  Point3 at(double x, double y, double z) const {
    const double s = scale();
    return {s * x, s * y, s * z};
  }
  /// The region of vertices first .. first + 3 of `points`.
  static Region region_of(const std::vector<Point3>& points, VertexIndex first) {
    Region r{};
    for (VertexIndex i = 0; i < 4; ++i)
      r[i] = {first + i, points[first + i]};
    return r;
  }
  /// A corner tetrahedron x, y, z >= 0, x + y + z <= 4, moved by (dx, 0, 0) (scaled).
  std::array<Point3, 4> tetrahedron(double dx) const {
    const double s = scale();
    return {Point3{dx, 0, 0}, Point3{dx + 4 * s, 0, 0}, Point3{dx, 4 * s, 0}, Point3{dx, 0, 4 * s}};
  }
};

TEST_P(PassSchedule, ASharedVertexDefersTheLaterOperation) {
  std::vector<Point3> points;
  for (int i = 0; i < 8; ++i)
    points.push_back(at(i, 0, 0));
  // No regions: only the vertices decide. Operation 2 shares vertex 2 with operation 1
  // only, which waits (it shares 1 with operation 0): 2 goes ahead.
  const std::vector<Footprint> pass{
      {{0, 1}, {}}, {{1, 2}, {}}, {{2, 3}, {}}, {{4, 5}, {}}, {{5, 0}, {}}, {{}, {}},
  };
  EXPECT_EQ(go_ahead(pass, points), (std::vector<bool>{true, false, true, true, false, true}));
  // The order decides: the same operations the other way round.
  const std::vector<Footprint> reversed(pass.rbegin(), pass.rend());
  EXPECT_EQ(go_ahead(reversed, points), (std::vector<bool>{true, true, false, true, false, false}));
}

TEST_P(PassSchedule, RegionsTouchingAtAPointWaitAndOneUlpApartGoAhead) {
  const double four = 4 * scale();
  for (const auto& [dx, both] : {std::pair{5 * scale(), true}, std::pair{four, false},
                                 std::pair{std::nextafter(four, HUGE_VAL), true}}) {
    std::vector<Point3> points;
    for (const auto& corners : {tetrahedron(0.0), tetrahedron(dx)}) {
      for (const Point3& p : corners)
        points.push_back(p);
    }
    const std::vector<Footprint> pass{{{0, 1, 2, 3}, {region_of(points, 0)}},
                                      {{4, 5, 6, 7}, {region_of(points, 4)}}};
    EXPECT_EQ(go_ahead(pass, points), (std::vector<bool>{true, both})) << "moved by " << dx;
  }
}

TEST_P(PassSchedule, OverlappingBoxesWaitOnlyInABoxSchedule) {
  // The corner tetrahedron (x + y + z <= 4) and one with x + y + z >= 10 in the same box:
  // apart as hulls (go_ahead lets both go ahead), not as boxes (a BoxSchedule defers the
  // second).
  std::vector<Point3> points;
  for (const Point3& p : tetrahedron(0.0))
    points.push_back(p);
  for (const Point3& p : {at(4, 4, 4), at(2, 4, 4), at(4, 2, 4), at(4, 4, 2)})
    points.push_back(p);
  const auto both_ways = [&](const std::vector<bool>& as_boxes) {
    const std::vector<Footprint> pass{{{0, 1, 2, 3}, {region_of(points, 0)}},
                                      {{4, 5, 6, 7}, {region_of(points, 4)}}};
    EXPECT_EQ(go_ahead(pass, points), (std::vector<bool>{true, true}));
    BoxSchedule schedule(points.size());
    EXPECT_EQ(schedule.take(pass[0]), as_boxes[0]);
    EXPECT_EQ(schedule.take(pass[1]), as_boxes[1]);
  };
  both_ways({true, false});
  // Boxes far apart: both go ahead either way.
  for (std::size_t i = 4; i < points.size(); ++i)
    points[i][0] += 10 * scale();
  both_ways({true, true});
}

TEST_P(PassSchedule, OnlyOperationsThatGoAheadHoldOthersBack) {
  // Three tetrahedra in a row, each touching the next at a point: the second waits for the
  // first, and the third, touching only the second, goes ahead.
  std::vector<Point3> points;
  for (const double dx : {0.0, 4 * scale(), 8 * scale()}) {
    for (const Point3& p : tetrahedron(dx))
      points.push_back(p);
  }
  std::vector<Footprint> pass;
  for (VertexIndex first : {0u, 4u, 8u})
    pass.push_back({{first, first + 1, first + 2, first + 3}, {region_of(points, first)}});
  EXPECT_EQ(go_ahead(pass, points), (std::vector<bool>{true, false, true}));
}

TEST_P(PassSchedule, ASplitsNewPointIsACornerOfItsRegion) {
  // A split's region: three vertices and a new point below them, (1, 1, -2). Another
  // operation's region has a vertex at that point (touching: it waits), or one step
  // lower (apart: it goes ahead).
  const double s = scale();
  for (const auto& [z, both] :
       {std::pair{-2 * s, false}, std::pair{std::nextafter(-2 * s, -HUGE_VAL), true}}) {
    std::vector<Point3> points{at(0, 0, 0),   at(4, 0, 0),  at(0, 4, 0),  Point3{s, s, z},
                               at(1, -3, -6), at(5, 1, -6), at(-3, 1, -6)};
    const Region split{RegionCorner{0, points[0]}, RegionCorner{1, points[1]},
                       RegionCorner{2, points[2]}, RegionCorner{kNoVertex, at(1, 1, -2)}};
    const std::vector<Footprint> pass{{{0, 1, 2}, {split}}, {{3, 4, 5, 6}, {region_of(points, 3)}}};
    EXPECT_EQ(go_ahead(pass, points), (std::vector<bool>{true, both})) << "z = " << z;
  }
}

TEST_P(PassSchedule, RandomPassesFollowTheRule) {
  auto rng = testing::seeded_engine("remesh.pass_schedule.random");
  std::uniform_int_distribution<int> coordinate(-6, 6);
  std::uniform_int_distribution<int> small(0, 3);
  const auto grid_point = [&] { return at(coordinate(rng), coordinate(rng), coordinate(rng)); };
  int ahead = 0, waiting_for_a_vertex = 0, waiting_for_a_region = 0;
  // 60 passes at full effort (tests/support/seed.hpp); every answer asked of the same
  // share of them.
  const auto trials = static_cast<int>(testing::scaled_trials(60));
  for (int trial = 0; trial < trials; ++trial) {
    std::vector<Point3> points;
    for (int i = 0; i < 40; ++i)
      points.push_back(grid_point());
    std::uniform_int_distribution<VertexIndex> vertex(0, 39);
    std::vector<Footprint> pass(12);
    for (Footprint& f : pass) {
      for (int k = small(rng); k >= 0; --k)
        f.vertices.push_back(vertex(rng));
      for (int r = small(rng) % 3; r > 0; --r) {  // up to two regions, corners of the pool
        Region region{};                          // or new points
        for (RegionCorner& c : region) {
          if (small(rng) == 0) {
            c = {kNoVertex, grid_point()};
          } else {
            const VertexIndex v = vertex(rng);
            c = {v, points[v]};
          }
        }
        bool well_formed = true;
        for (int skip = 0; skip < 4; ++skip) {
          std::vector<Point3> three;
          for (int i = 0; i < 4; ++i) {
            if (i != skip) three.push_back(region[i].point);
          }
          well_formed = well_formed && !testing::collinear_oracle(three[0], three[1], three[2]);
        }
        if (well_formed) f.regions.push_back(region);
      }
    }
    // The rule, in order: an operation goes ahead unless it shares a vertex with an
    // earlier one that goes ahead, or one of its regions meets one of that one's.
    std::vector<bool> expected;
    for (std::size_t i = 0; i < pass.size(); ++i) {
      bool go = true, by_vertex = false;
      for (std::size_t j = 0; j < i && go; ++j) {
        if (!expected[j]) continue;
        for (const VertexIndex v : pass[i].vertices) {
          if (std::count(pass[j].vertices.begin(), pass[j].vertices.end(), v) > 0) {
            go = false;
            by_vertex = true;
          }
        }
        for (const Region& x : pass[i].regions) {
          for (const Region& y : pass[j].regions) {
            const std::array<Point3, 4> px{x[0].point, x[1].point, x[2].point, x[3].point};
            const std::array<Point3, 4> py{y[0].point, y[1].point, y[2].point, y[3].point};
            if (go && testing::hulls_meet(px, py)) go = false;
          }
        }
      }
      expected.push_back(go);
      ahead += go ? 1 : 0;
      waiting_for_a_vertex += by_vertex ? 1 : 0;
      waiting_for_a_region += !go && !by_vertex ? 1 : 0;
    }
    EXPECT_EQ(go_ahead(pass, points), expected) << "trial " << trial;
  }
  EXPECT_GT(ahead, 100 * trials / 60);
  EXPECT_GT(waiting_for_a_vertex, 50 * trials / 60);
  EXPECT_GT(waiting_for_a_region, 50 * trials / 60);
}

TEST_P(PassSchedule, ABoxScheduleWaitsForOverlappingBoxes) {
  // A pass of collapses: BoxSchedule takes each footprint's regions as boxes and checks
  // each operation against those going ahead. Grid points at every scale (a power of two),
  // so that boxes touch: the rule as the header states it, with the regions' exact boxes,
  // touching counting; a pass of forty operations over a pool of sixty vertices, so that
  // both reasons to wait occur.
  auto rng = testing::seeded_engine("remesh.pass_schedule.boxes");
  std::uniform_int_distribution<int> coordinate(-8, 8);
  std::uniform_int_distribution<int> reach(0, 4);
  std::uniform_int_distribution<VertexIndex> vertex(0, 59);
  std::uniform_int_distribution<int> count(1, 3);
  int ahead = 0, waiting_for_a_vertex = 0, waiting_for_a_box = 0;
  for (int trial = 0; trial < 40; ++trial) {
    std::vector<Point3> points;
    for (int i = 0; i < 60; ++i)
      points.push_back(at(coordinate(rng), coordinate(rng), coordinate(rng)));
    std::vector<Footprint> pass(40);
    for (Footprint& f : pass) {
      for (int k = count(rng); k > 0; --k)
        f.vertices.push_back(vertex(rng));
      const Point3& centre = points[f.vertices[0]];
      for (int r = count(rng) - 1; r > 0; --r) {  // up to two regions, near the first vertex
        Region region{};
        for (RegionCorner& c : region) {
          Point3 q = centre;
          for (double& x : q)
            x += reach(rng) * scale();
          c = {kNoVertex, q};
        }
        f.regions.push_back(region);
      }
    }
    const auto boxes_overlap = [](const Region& x, const Region& y) {
      for (int k = 0; k < 3; ++k) {
        double x_lo = x[0].point[k], x_hi = x_lo, y_lo = y[0].point[k], y_hi = y_lo;
        for (const RegionCorner& c : x) {
          x_lo = std::min(x_lo, c.point[k]);
          x_hi = std::max(x_hi, c.point[k]);
        }
        for (const RegionCorner& c : y) {
          y_lo = std::min(y_lo, c.point[k]);
          y_hi = std::max(y_hi, c.point[k]);
        }
        if (x_hi < y_lo || y_hi < x_lo) return false;
      }
      return true;
    };
    std::vector<bool> expected;
    for (std::size_t i = 0; i < pass.size(); ++i) {
      bool by_vertex = false, by_box = false;
      for (std::size_t j = 0; j < i; ++j) {
        if (!expected[j]) continue;
        for (const VertexIndex v : pass[i].vertices)
          by_vertex =
              by_vertex || std::count(pass[j].vertices.begin(), pass[j].vertices.end(), v) > 0;
        for (const Region& x : pass[i].regions) {
          for (const Region& y : pass[j].regions)
            by_box = by_box || boxes_overlap(x, y);
        }
      }
      expected.push_back(!by_vertex && !by_box);
      ahead += expected.back() ? 1 : 0;
      waiting_for_a_vertex += by_vertex ? 1 : 0;
      waiting_for_a_box += by_box && !by_vertex ? 1 : 0;
    }
    BoxSchedule schedule(points.size());
    for (std::size_t i = 0; i < pass.size(); ++i)
      EXPECT_EQ(schedule.take(pass[i]), expected[i]) << "trial " << trial << ", operation " << i;
  }
  EXPECT_GT(ahead, 200);
  EXPECT_GT(waiting_for_a_vertex, 100);
  EXPECT_GT(waiting_for_a_box, 50);
}

TEST(PassScheduleVertices, ShareNoVertexIsGoAheadWithoutRegions) {
  // Random operations of two to four vertices among 40 (kNoVertex for the missing ones),
  // in passes of 30: share_no_vertex (the flip and split passes' first test) must answer
  // as go_ahead does for the same vertices and no regions, which an operation that took a
  // missing corner for a vertex, or ignored a later one's, would break.
  std::mt19937_64 rng = exactgeo::testing::seeded_engine("share_no_vertex");
  std::uniform_int_distribution<VertexIndex> vertex(0, 39);
  std::uniform_int_distribution<int> count(2, 4);
  const std::vector<Point3> points(40, Point3{0, 0, 0});
  std::size_t ahead = 0, waiting = 0;
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<std::array<VertexIndex, 4>> operations(30);
    std::vector<Footprint> footprints(30);
    for (std::size_t i = 0; i < operations.size(); ++i) {
      operations[i].fill(kNoVertex);
      const int n = count(rng);
      for (int k = 0; k < n; ++k) {
        operations[i][static_cast<std::size_t>(k)] = vertex(rng);
        footprints[i].vertices.push_back(operations[i][static_cast<std::size_t>(k)]);
      }
      if (n < 4) std::swap(operations[i][0], operations[i][3]);  // a gap first
    }
    const std::vector<bool> expected = go_ahead(footprints, points);
    EXPECT_EQ(internal::share_no_vertex(operations, points.size()), expected) << trial;
    ahead += static_cast<std::size_t>(std::count(expected.begin(), expected.end(), true));
    waiting += static_cast<std::size_t>(std::count(expected.begin(), expected.end(), false));
  }
  EXPECT_GT(ahead, 500u);
  EXPECT_GT(waiting, 500u);
}

INSTANTIATE_TEST_SUITE_P(Scales, PassSchedule, ::testing::Values(0, 1000, -1000),
                         exactgeo::testing::scale_name);

}  // namespace
}  // namespace exactgeo::remesh
