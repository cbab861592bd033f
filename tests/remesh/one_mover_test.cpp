// The cheap proof that a pair with one moving corner stays apart (remesh/src/one_mover.hpp,
// internal to the library: reached by path). Random vertex-face and edge-edge pairs on a
// small integer grid (many coplanar points, touches and shared planes), one corner moving,
// at 2^0 and 2^+-1000: whenever the proof says apart, the hull the moving primitive sweeps
// (its standing corners and both ends of the path) and the other primitive do not meet by
// the rational hull oracle (hull_oracle.hpp, no code shared with the library's orient3d),
// and exact CCD finds no contact; whenever the oracle finds them meeting, exact CCD finds
// a contact (the sweep is that hull, so a meeting is a touch at some time of the step).
// Pairs where two corners move, or none, are never declared apart.

#include "../../remesh/src/one_mover.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "exactgeo/ccd/ccd.hpp"
#include "exactgeo/predicates/orient3d.hpp"
#include "remesh/hull_oracle.hpp"
#include "support/scale_names.hpp"
#include "support/seed.hpp"

namespace exactgeo::remesh {
namespace {

using internal::one_mover_apart;

class OneMover : public ::testing::TestWithParam<int> {
 protected:
  /// A point of the grid {0..3}^3, scaled.
  Point3 grid_point(std::mt19937_64& rng) const {
    std::uniform_int_distribution<int> c(0, 3);
    const double s = std::ldexp(1.0, GetParam());
    return {s * c(rng), s * c(rng), s * c(rng)};
  }

  /// The four corners at t0 and t1, corner `mover` moved to a new grid point (the others
  /// standing), or two corners moved when `two` is set.
  void draw(std::mt19937_64& rng, std::array<Point3, 4>& t0, std::array<Point3, 4>& t1,
            std::size_t& mover, bool two) const {
    for (Point3& p : t0)
      p = grid_point(rng);
    t1 = t0;
    mover = std::uniform_int_distribution<std::size_t>(0, 3)(rng);
    while (t1[mover] == t0[mover])
      t1[mover] = grid_point(rng);
    if (two) {
      const std::size_t other = (mover + 1) % 4;
      while (t1[other] == t0[other])
        t1[other] = grid_point(rng);
    }
  }

  /// The moving primitive's swept hull and the other primitive, as point sets
  /// (`first_size` corners belong to the first primitive).
  static void sets(const std::array<Point3, 4>& t0, const std::array<Point3, 4>& t1,
                   std::size_t mover, std::size_t first_size, std::vector<Point3>& swept,
                   std::vector<Point3>& other) {
    swept.clear();
    other.clear();
    for (std::size_t c = 0; c < 4; ++c) {
      if ((c < first_size) == (mover < first_size)) {
        swept.push_back(t0[c]);
        if (c == mover) swept.push_back(t1[c]);
      } else {
        other.push_back(t0[c]);
      }
    }
  }
};

TEST_P(OneMover, ApartOnlyWhenTheSweptHullMeetsNothingAndCcdAgrees) {
  std::mt19937_64 rng = exactgeo::testing::seeded_engine("one_mover");
  ccd::Options exact;
  exact.method = ccd::Method::exact;
  std::size_t apart = 0, meeting = 0, undecided = 0;
  std::vector<Point3> swept, other;
  // 3000 at full effort (tests/support/seed.hpp), at least one of each two kinds; every
  // answer asked of the same share of them.
  const std::size_t trials = exactgeo::testing::scaled_trials(3000, 2);
  for (int trial = 0; trial < static_cast<int>(trials); ++trial) {
    const bool vertex_face = trial % 2 == 0;
    std::array<Point3, 4> t0{}, t1{};
    std::size_t mover = 0;
    draw(rng, t0, t1, mover, false);
    bool says_apart = false, ccd_contact = false;
    if (vertex_face) {
      // A face of zero area is no face a surface has: drawn again.
      if (collinear(t0[1], t0[2], t0[3]) || collinear(t1[1], t1[2], t1[3])) continue;
      const ccd::VertexFaceQuery q{t0[0], t0[1], t0[2], t0[3], t1[0], t1[1], t1[2], t1[3]};
      says_apart = one_mover_apart(q);
      ccd_contact = ccd::vertex_face_ccd(q, exact).collision;
    } else {
      if (t0[0] == t0[1] || t1[0] == t1[1] || t0[2] == t0[3] || t1[2] == t1[3]) continue;
      const ccd::EdgeEdgeQuery q{t0[0], t0[1], t0[2], t0[3], t1[0], t1[1], t1[2], t1[3]};
      says_apart = one_mover_apart(q);
      ccd_contact = ccd::edge_edge_ccd(q, exact).collision;
    }
    sets(t0, t1, mover, vertex_face ? 1 : 2, swept, other);
    const bool meet = exactgeo::testing::hulls_meet(swept, other);
    SCOPED_TRACE("trial " + std::to_string(trial) + (vertex_face ? " vertex-face" : " edge-edge"));
    if (says_apart) {
      EXPECT_FALSE(meet);
      EXPECT_FALSE(ccd_contact);
      ++apart;
    } else if (meet) {
      EXPECT_TRUE(ccd_contact);
      ++meeting;
    } else {
      ++undecided;
    }
  }
  // Each kind is seen often: the grid's touches and shared planes among them.
  EXPECT_GT(apart, 300 * trials / 3000);
  EXPECT_GT(meeting, 300 * trials / 3000);
  EXPECT_GT(undecided, 10 * trials / 3000);
}

TEST_P(OneMover, NeverApartWhenTwoCornersOrNoneMove) {
  std::mt19937_64 rng = exactgeo::testing::seeded_engine("one_mover_two");
  for (int trial = 0; trial < 500; ++trial) {
    std::array<Point3, 4> t0{}, t1{};
    std::size_t mover = 0;
    draw(rng, t0, t1, mover, true);
    EXPECT_FALSE(one_mover_apart(
        ccd::VertexFaceQuery{t0[0], t0[1], t0[2], t0[3], t1[0], t1[1], t1[2], t1[3]}));
    EXPECT_FALSE(one_mover_apart(
        ccd::EdgeEdgeQuery{t0[0], t0[1], t0[2], t0[3], t1[0], t1[1], t1[2], t1[3]}));
    EXPECT_FALSE(one_mover_apart(
        ccd::EdgeEdgeQuery{t0[0], t0[1], t0[2], t0[3], t0[0], t0[1], t0[2], t0[3]}));
  }
}

INSTANTIATE_TEST_SUITE_P(Scales, OneMover, ::testing::Values(0, 1000, -1000),
                         exactgeo::testing::scale_name);

}  // namespace
}  // namespace exactgeo::remesh
