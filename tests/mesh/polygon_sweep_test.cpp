// The plane sweep that finds whether a polygon's walk bounds a region in one projection
// and how it turns (polygon_sweep.hpp, internal): walks whose edges touch or overlap
// (bridges across a hole, a spike's foot inside an edge, edges on one line that overlap,
// bridges that cross) are refused, a keyhole and a spike walked there and back are taken;
// and its exact test of two segments against an oracle in rationals, on every pair of
// segments of a small integer grid's points, whatever the order given.

#include "../../mesh/src/polygon_sweep.hpp"

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <array>
#include <optional>
#include <random>
#include <vector>

#include "../../mesh/src/polygon_walk.hpp"
#include "support/seed.hpp"

namespace exactgeo::mesh::internal {
namespace {

using Point2 = std::array<double, 2>;

/// Points of the (x, y) plane at z = 0, seen along z (axis 2).
std::vector<Point3> in_plane(const std::vector<std::array<double, 2>>& points) {
  std::vector<Point3> vertices;
  for (const auto& [x, y] : points)
    vertices.push_back({x, y, 0.0});
  return vertices;
}

/// region_turn for these corners along z.
std::optional<Sign> turn_of(const std::vector<VertexIndex>& corners,
                            const std::vector<Point3>& vertices) {
  const PolygonWalk walk = walk_of(corners);
  const Projection plane(2);
  return region_turn(walk, sweep_order(walk, vertices, plane), vertices, plane);
}

TEST(PolygonSweep, EdgesThatTouchOrOverlapAreRefused) {
  const std::vector<Point3> v = in_plane(
      {{0, 0}, {8, 0}, {8, 8}, {0, 8}, {3, 3}, {3, 5}, {5, 5}, {5, 3}, {4, 0}, {4, 4}, {8, 0}});
  // A keyhole, and the same with its bridge across the hole (through its corner (3, 3)).
  EXPECT_EQ(turn_of({0, 1, 2, 3, 0, 4, 5, 6, 7, 4}, v), Sign::positive);
  EXPECT_EQ(turn_of({0, 1, 2, 3, 0, 6, 7, 4, 5, 6}, v), std::nullopt);
  // A spike from the bottom edge's middle up to (4, 4), where the bottom edge is not
  // split: the spike's foot lies inside the edge (0, 1).
  EXPECT_EQ(turn_of({0, 1, 2, 3, 8, 9}, v), std::nullopt);
  // The same with the edge split at the foot: a spike walked there and back bounds
  // nothing, and touches the rest only at its foot.
  EXPECT_EQ(turn_of({0, 8, 9, 8, 1, 2, 3}, v), Sign::positive);
  // Two edges on one line that overlap: (0, 1) and (8, 10), 10 a copy of corner 1.
  EXPECT_EQ(turn_of({0, 1, 2, 10, 8, 3}, v), std::nullopt);
  // A keyhole whose bridge crosses an edge of the hole inside it, at (3, 3): every winding
  // number is still 0 or 1 (the bridge bounds nothing), only the crossing is wrong.
  const std::vector<Point3> w =
      in_plane({{0, 0}, {8, 0}, {8, 8}, {0, 8}, {3, 2}, {3, 5}, {5, 5}, {5, 2}});
  EXPECT_EQ(turn_of({0, 1, 2, 3, 0, 4, 5, 6, 7, 4}, w), Sign::positive);
  EXPECT_EQ(turn_of({0, 1, 2, 3, 0, 6, 7, 4, 5, 6}, w), std::nullopt);
  // Two holes whose bridges cross each other at (4, 4): on both sides of each bridge the
  // winding number is the same, so only the test of the two edges finds it.
  const std::vector<Point3> x = in_plane({{0, 0},
                                          {8, 0},
                                          {8, 8},
                                          {0, 8},  // outside
                                          {5, 5},
                                          {5, 6},
                                          {6, 6},
                                          {6, 5},  // hole A
                                          {3, 5},
                                          {2, 5},
                                          {2, 6},
                                          {3, 6}});  // hole B
  EXPECT_EQ(turn_of({0, 1, 8, 9, 10, 11, 8, 1, 2, 3, 0, 4, 5, 6, 7, 4}, x), std::nullopt);
  EXPECT_EQ(turn_of({0, 1, 2, 3, 10, 11, 8, 9, 10, 3, 0, 4, 5, 6, 7, 4}, x), Sign::positive);
}

/// Whether the closed segments [a0, a1] and [b0, b1] of the plane (neither of zero length)
/// share a point other than an endpoint of both, in rationals: their lines' meeting point
/// by Cramer's rule, or, on one line, the overlap of their parameter intervals.
bool meet_improperly_oracle(const Point2& a0, const Point2& a1, const Point2& b0,
                            const Point2& b1) {
  const auto q = [](double x) { return mpq_class(x); };
  const mpq_class dax = q(a1[0]) - q(a0[0]), day = q(a1[1]) - q(a0[1]);
  const mpq_class dbx = q(b1[0]) - q(b0[0]), dby = q(b1[1]) - q(b0[1]);
  const mpq_class ex = q(b0[0]) - q(a0[0]), ey = q(b0[1]) - q(a0[1]);
  const mpq_class det = dax * dby - day * dbx;
  if (det != 0) {
    // a0 + s da = b0 + t db.
    const mpq_class s = (ex * dby - ey * dbx) / det, t = (ex * day - ey * dax) / det;
    if (s < 0 || s > 1 || t < 0 || t > 1) return false;
    const bool end_of_a = s == 0 || s == 1, end_of_b = t == 0 || t == 1;
    return !(end_of_a && end_of_b);
  }
  if (ex * day - ey * dax != 0) return false;  // parallel, on two lines
  // One line: b's ends at parameters of a's, a = [0, 1]; the overlap is a point or more.
  const mpq_class len = dax * dax + day * day;
  const mpq_class t0 = (ex * dax + ey * day) / len;
  const mpq_class t1 = t0 + (dbx * dax + dby * day) / len;
  const mpq_class lo = t0 < t1 ? t0 : t1, hi = t0 < t1 ? t1 : t0;
  const mpq_class from = lo > 0 ? lo : mpq_class(0), to = hi < 1 ? hi : mpq_class(1);
  if (from > to) return false;
  return from < to;  // more than one point; a single common point is an end of both
}

TEST(PolygonSweep, SegmentsMeetImproperlyAsTheOracleSays) {
  // Segments between the points of a 4 x 4 grid: crossings, ends inside other segments,
  // overlaps and touching ends in every arrangement.
  auto rng = testing::seeded_engine("mesh.polygon_sweep.segments");
  std::uniform_int_distribution<int> coordinate(0, 3);
  const Projection plane(2);
  int improper = 0, proper = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    std::array<Point2, 4> p;
    for (Point2& q : p)
      q = {double(coordinate(rng)), double(coordinate(rng))};
    if (p[0] == p[1] || p[2] == p[3]) continue;
    const bool want = meet_improperly_oracle(p[0], p[1], p[2], p[3]);
    // Each segment from its earlier end in sweep order to its later one.
    std::array<Point3, 4> v;
    for (std::size_t k = 0; k < 4; ++k)
      v[k] = {p[k][0], p[k][1], 0.0};
    if (plane.before(v[1], v[0])) std::swap(v[0], v[1]);
    if (plane.before(v[3], v[2])) std::swap(v[2], v[3]);
    ASSERT_EQ(segments_meet_improperly(v[0], v[1], v[2], v[3], plane), want)
        << "(" << p[0][0] << ", " << p[0][1] << ")-(" << p[1][0] << ", " << p[1][1] << ") and ("
        << p[2][0] << ", " << p[2][1] << ")-(" << p[3][0] << ", " << p[3][1] << ")";
    ASSERT_EQ(segments_meet_improperly(v[2], v[3], v[0], v[1], plane), want);
    (want ? improper : proper) += 1;
  }
  EXPECT_GT(improper, 1000);
  EXPECT_GT(proper, 1000);
}

}  // namespace
}  // namespace exactgeo::mesh::internal
