// Time of impact on degenerate primitives: zero-length edges, triangles whose corners are
// collinear or coincide, points meeting points; in the plane z = 0, in a tilted plane and
// in space. The exact method must bracket the earliest contact as for any other query
// (a proven bracket, no wider than asked or than one double spacing at the contact),
// and minimum separation must bracket its earliest time within δ alike. The truth is the
// GMP oracle of min_separation_oracle.hpp (δ = 0 for contact).

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <string>

#include "ccd/query_transforms.hpp"
#include "ccd/run_query.hpp"
#include "ccd/separation/min_separation_oracle.hpp"
#include "exactgeo/ccd/ccd.hpp"
#include "support/generators.hpp"
#include "support/seed.hpp"

namespace exactgeo::ccd {
namespace {

using testing::Rng;

/// A moving point and a moving segment (endpoints s0, s1), each at t0 and t1.
struct PointAndSegment {
  Point3 p_t0, p_t1;
  Point3 s0_t0, s1_t0, s0_t1, s1_t1;
};

enum class Layout { plane, tilted_plane, space };

Point3 in_layout(Point3 p, Layout layout) {
  if (layout == Layout::plane) return {p[0], p[1], 0.0};
  if (layout == Layout::tilted_plane) return {p[0], p[1], -p[0] - p[1]};  // x + y + z = 0
  return p;
}

/// Random small integers. In a plane a point and a segment meet at isolated times of a
/// quadratic (often irrational, as in the reported case); in space they generically do
/// not meet at all, so there the point is sent through the segment's midpoint at
/// t* = 1/q (q odd, never a split time), or at 1 - 1/q.
PointAndSegment point_and_segment(Rng& rng, Layout layout) {
  const auto point = [&] { return in_layout(testing::integer_point(rng, 8), layout); };
  PointAndSegment m{point(), point(), point(), point(), point(), point()};
  if (layout != Layout::space) return m;
  const int q = 2 * testing::uniform_int(rng, 1, 5) + 1;
  for (int axis = 0; axis < 3; ++axis) {
    // p(1/q) = s(1/q, 1/2): (q - 1) p0 + p1 = ((q - 1)(s00 + s10) + s01 + s11) / 2.
    double sum = (q - 1) * (m.s0_t0[axis] + m.s1_t0[axis]) + m.s0_t1[axis] + m.s1_t1[axis];
    if (std::fmod(sum, 2.0) != 0.0) {
      m.s1_t1[axis] += 1.0;
      sum += 1.0;
    }
    m.p_t1[axis] = sum / 2 - (q - 1) * m.p_t0[axis];
  }
  if (testing::uniform_int(rng, 0, 1) == 1) {  // the same contact at 1 - 1/q
    std::swap(m.p_t0, m.p_t1);
    std::swap(m.s0_t0, m.s0_t1);
    std::swap(m.s1_t0, m.s1_t1);
  }
  return m;
}

/// Two moving points that meet at t* = 1/q in the layout.
PointAndSegment two_points(Rng& rng, Layout layout) {
  PointAndSegment m = point_and_segment(rng, layout);
  const int q = 2 * testing::uniform_int(rng, 1, 5) + 1;
  m.s1_t0 = m.s0_t0;
  m.s1_t1 = m.s0_t1;
  for (int axis = 0; axis < 3; ++axis)
    m.p_t1[axis] = (q - 1) * m.s0_t0[axis] + m.s0_t1[axis] - (q - 1) * m.p_t0[axis];
  return m;
}

/// The degenerate queries: an edge of length zero against an edge, a point-like edge
/// against a point-like edge, a vertex against a triangle with two coincident corners or
/// with collinear corners (the third corner the segment's midpoint, exact for the even
/// coordinates used), and a vertex against a triangle collapsed to a point.
enum class Kind {
  zero_length_edge,
  two_point_edges,
  coincident_corners,
  collinear_corners,
  point_triangle
};

EdgeEdgeQuery edge_edge(const PointAndSegment& m) {
  return {m.p_t0, m.p_t0, m.s0_t0, m.s1_t0, m.p_t1, m.p_t1, m.s0_t1, m.s1_t1};
}

VertexFaceQuery vertex_face(const PointAndSegment& m, Kind kind) {
  const auto mid = [](const Point3& a, const Point3& b) {
    return Point3{(a[0] + b[0]) / 2, (a[1] + b[1]) / 2, (a[2] + b[2]) / 2};
  };
  if (kind == Kind::coincident_corners) {
    return {m.p_t0, m.s0_t0, m.s0_t0, m.s1_t0, m.p_t1, m.s0_t1, m.s0_t1, m.s1_t1};
  }
  if (kind == Kind::collinear_corners) {
    return {m.p_t0, m.s0_t0, mid(m.s0_t0, m.s1_t0), m.s1_t0,
            m.p_t1, m.s0_t1, mid(m.s0_t1, m.s1_t1), m.s1_t1};
  }
  return {m.p_t0, m.s0_t0, m.s0_t0, m.s0_t0, m.p_t1, m.s0_t1, m.s0_t1, m.s0_t1};
}

/// Even coordinates (so that midpoints stay integers), scaled by 2^k.
PointAndSegment prepared(PointAndSegment m, int k) {
  for (Point3* p : {&m.p_t0, &m.p_t1, &m.s0_t0, &m.s1_t0, &m.s0_t1, &m.s1_t1})
    *p = testing::scaled(*p, k + 1);
  return m;
}

std::string describe(Kind kind, Layout layout, int k, int i) {
  static constexpr const char* kKinds[] = {"zero-length edge", "two point edges",
                                           "coincident corners", "collinear corners",
                                           "point triangle"};
  static constexpr const char* kLayouts[] = {"plane", "tilted plane", "space"};
  return std::string(kKinds[int(kind)]) + " in " + kLayouts[int(layout)] + " at 2^" +
         std::to_string(k) + " #" + std::to_string(i);
}

struct Tally {
  int collisions = 0;
  int misses = 0;
};

/// The exact method's answer against the oracle at every width: the same flag, and for a
/// collision a proven bracket (not the depth limit's) holding the earliest contact, no
/// wider than asked or than one double spacing.
template <class Query>
void expect_bracketed(const Query& q, double delta, const std::string& what, Tally& tally) {
  const testing::MinSeparationAnswer truth = testing::min_separation_oracle(q, delta);
  (truth.within ? tally.collisions : tally.misses) += 1;
  for (const double width : {1e-6, 1e-9, 1e-12, 0x1p-40}) {
    Options o;
    o.min_separation = delta;
    o.time_of_impact_width = width;
    const Result r = run(q, o);
    char numbers[64];
    std::snprintf(numbers, sizeof numbers, ", width %g, delta %a", width, delta);
    const std::string where =
        what + numbers + ", decided by " + std::string(to_string(r.decided_by));
    ASSERT_EQ(r.collision, truth.within) << where;
    if (!r.collision) continue;
    EXPECT_NE(r.decided_by, DecidedBy::depth_limit) << where;
    ASSERT_TRUE(r.time_of_impact.has_value()) << where;
    const TimeInterval t = *r.time_of_impact;
    EXPECT_LE(mpq_class(t.start), truth.earliest_lo) << where << std::hexfloat << ": " << t.start;
    EXPECT_GE(mpq_class(t.end), truth.earliest_hi) << where << std::hexfloat << ": " << t.end;
    // One double spacing at most above the width: a bracket's ends are doubles.
    const double spacing = std::nextafter(t.end, 2.0) - t.end;
    EXPECT_LE(t.end - t.start, std::max(width, 2 * spacing)) << where;
  }
}

class DegenerateTimeOfImpact : public ::testing::TestWithParam<int> {};

TEST_P(DegenerateTimeOfImpact, ContactIsBracketedAsForAnyOtherQuery) {
  const int k = GetParam();
  Rng rng = testing::seeded_engine("ccd.degenerate_toi." + std::to_string(k));
  // Scaled with the effort (tests/support/seed.hpp), at least a contact and a separation.
  const auto per_kind = static_cast<int>(testing::scaled_trials(k == 0 ? 12 : 4, 2));
  Tally tally;
  for (const Layout layout : {Layout::plane, Layout::tilted_plane, Layout::space}) {
    for (const Kind kind : {Kind::zero_length_edge, Kind::two_point_edges, Kind::coincident_corners,
                            Kind::collinear_corners, Kind::point_triangle}) {
      for (int i = 0; i < per_kind; ++i) {
        const bool points = kind == Kind::two_point_edges || kind == Kind::point_triangle;
        const PointAndSegment m =
            prepared(points ? two_points(rng, layout) : point_and_segment(rng, layout), k);
        const std::string what = describe(kind, layout, k, i);
        // Contact, and a separation of a few tenths of the grid (coordinates are even
        // integers times 2^k).
        const double delta = i % 2 == 0 ? 0.0 : std::ldexp(testing::uniform(rng, 0.1, 1.0), k);
        if (kind == Kind::zero_length_edge || kind == Kind::two_point_edges) {
          expect_bracketed(edge_edge(m), delta, what, tally);
        } else {
          expect_bracketed(vertex_face(m, kind), delta, what, tally);
        }
      }
    }
  }
  EXPECT_GT(tally.collisions, per_kind * 5);
  EXPECT_GT(tally.misses, per_kind);
}

INSTANTIATE_TEST_SUITE_P(Scales, DegenerateTimeOfImpact, ::testing::Values(0, 1000, -1000),
                         [](const ::testing::TestParamInfo<int>& param_info) {
                           const int k = param_info.param;
                           return std::string(k < 0 ? "scale_2m" : "scale_2p") +
                                  std::to_string(std::abs(k));
                         });

/// The reported case: a zero-length edge crossing an edge in the plane z = 0 at the root
/// of 554 t^2 - 423 t - 16, t = 0.79965458329901960...
TEST(DegenerateTimeOfImpact, ZeroLengthEdgeInAPlane) {
  const EdgeEdgeQuery q{{0.125, -0.25, 0}, {0.125, -0.25, 0}, {-1.875, -1.875, 0},
                        {-1.875, -2, 0},   {1, -0.375, 0},    {1, -0.375, 0},
                        {-0.25, 1.5, 0},   {1.875, -0.25, 0}};
  Tally tally;
  expect_bracketed(q, 0.0, "reported case", tally);
  EXPECT_EQ(tally.collisions, 1);
}

}  // namespace
}  // namespace exactgeo::ccd
