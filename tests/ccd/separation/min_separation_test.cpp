// Minimum-separation CCD (Options::min_separation > 0) against the exact oracle of
// min_separation_oracle.hpp: random, near-tangent, exactly degenerate and extreme-magnitude
// queries; the exact symmetries; monotonicity in δ; δ = 0 as the contact question; the
// mesh broad phase against every pair.

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <limits>
#include <span>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "ccd/query_transforms.hpp"
#include "ccd/run_query.hpp"
#include "ccd/separation/min_separation_oracle.hpp"
#include "ccd/separation/sampled_distance.hpp"
#include "exactgeo/ccd/ccd.hpp"
#include "exactgeo/ccd/files/query_files.hpp"
#include "exactgeo/ccd/mesh/mesh_ccd.hpp"
#include "exactgeo/ccd/separation/internal/min_separation.hpp"
#include "support/generators.hpp"
#include "support/seed.hpp"

namespace exactgeo::ccd {
namespace {

using testing::Rng;

template <class Query>
void expect_as_oracle(const Query& q, double delta, const std::string& what, int& within,
                      int& apart) {
  const bool expected = testing::min_separation_oracle(q, delta).within;
  const Result r = separated(q, delta);
  EXPECT_EQ(r.collision, expected)
      << what << " delta " << delta << " decided by " << to_string(r.decided_by);
  (expected ? within : apart) += 1;
}

template <class Query>
void random_queries_agree(const char* stream, int count) {
  Rng rng = testing::seeded_engine(stream);
  int within = 0, apart = 0;
  for (int i = 0; i < count; ++i) {
    Query q = i % 2 ? random_dyadic_query<Query>(rng) : varied_query<Query>(rng, i / 2);
    if (i % 7 == 3) {  // general position at magnitude 1
      q = mapped(q, [&](const Point3&) { return testing::random_point(rng, 1.0); });
    }
    for (const double delta : deltas_for(q, rng))
      expect_as_oracle(q, delta, std::string(stream) + " #" + std::to_string(i), within, apart);
  }
  // Both answers must be common, or the comparison says little.
  EXPECT_GT(within, count / 4);
  EXPECT_GT(apart, count / 4);
}

TEST(MinSeparation, RandomVertexFaceQueriesAgreeWithTheOracle) {
  random_queries_agree<VertexFaceQuery>("min-separation-vf", 120);
}

TEST(MinSeparation, RandomEdgeEdgeQueriesAgreeWithTheOracle) {
  random_queries_agree<EdgeEdgeQuery>("min-separation-ee", 120);
}

/// Distance exactly δ at one time (a tangent contact of the δ-sphere), and one ulp more
/// or less: a vertex passing over a face, an edge, a corner; edges crossing at a height;
/// parallel edges sliding past each other.
TEST(MinSeparation, TangentCasesAndOneUlpEitherSide) {
  Rng rng = testing::seeded_engine("min-separation-tangent");
  int within = 0, apart = 0;
  for (int i = 0; i < 200; ++i) {
    const double h = testing::uniform(rng, 0.01, 1.0);
    const double y = testing::uniform(rng, 0.05, 0.4);
    const std::array<double, 3> deltas{std::nextafter(h, 0.0), h, std::nextafter(h, 1.0)};
    // Over the inside of the face z = 0 at height h.
    const VertexFaceQuery face{{-1, y, h}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0},
                               {1, y, h},  {0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    // Beside the edge along x (y = 0), at distance h: passes at (x, -h, 0).
    const VertexFaceQuery edge{{-1, -h, 0}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0},
                               {2, -h, 0},  {0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    // Skew edges crossing at height h (closest pair interior to both).
    const EdgeEdgeQuery skew{{-1, y, 0}, {1, y, 0}, {y, -1, h}, {y, 1, h},
                             {-1, y, 0}, {1, y, 0}, {y, -1, h}, {y, 1, h}};
    // Parallel edges at distance h, sliding past each other.
    const EdgeEdgeQuery parallel{{-3, 0, 0}, {-2, 0, 0}, {0, 0, h}, {1, 0, h},
                                 {2, 0, 0},  {3, 0, 0},  {0, 0, h}, {1, 0, h}};
    for (const double d : deltas) {
      expect_as_oracle(face, d, "face", within, apart);
      expect_as_oracle(edge, d, "edge", within, apart);
      expect_as_oracle(skew, d, "skew", within, apart);
      expect_as_oracle(parallel, d, "parallel", within, apart);
      // Exactly at δ = h the distance is attained: within; one ulp less: apart (the
      // heights are exact doubles, so these are the exact answers).
      if (d == h) {
        EXPECT_TRUE(separated(face, d).collision);
      }
      if (d < h) {
        EXPECT_FALSE(separated(skew, d).collision);
      }
    }
  }
  EXPECT_GT(within, 100);
  EXPECT_GT(apart, 100);
}

/// Degenerate primitives and motions: zero-area triangles (collinear, one point), zero-
/// length edges, parallel and collinear edges, identical motion (everything translates
/// together: the answer is the distance at t = 0), and points that stay put.
TEST(MinSeparation, DegenerateConfigurationsAgreeWithTheOracle) {
  Rng rng = testing::seeded_engine("min-separation-degenerate");
  int within = 0, apart = 0;
  for (int i = 0; i < 100; ++i) {
    VertexFaceQuery vf = random_dyadic_query<VertexFaceQuery>(rng);
    EdgeEdgeQuery ee = random_dyadic_query<EdgeEdgeQuery>(rng);
    switch (i % 5) {
      case 0:  // collinear triangle and parallel edges, at both times
        for (const bool end : {false, true}) {
          Point3& a = end ? vf.f0_t1 : vf.f0_t0;
          Point3& b = end ? vf.f1_t1 : vf.f1_t0;
          Point3& c = end ? vf.f2_t1 : vf.f2_t0;
          c = {2 * b[0] - a[0], 2 * b[1] - a[1], 2 * b[2] - a[2]};
        }
        ee.eb1_t0 = {ee.eb0_t0[0] + ee.ea1_t0[0] - ee.ea0_t0[0],
                     ee.eb0_t0[1] + ee.ea1_t0[1] - ee.ea0_t0[1],
                     ee.eb0_t0[2] + ee.ea1_t0[2] - ee.ea0_t0[2]};
        ee.eb1_t1 = {ee.eb0_t1[0] + ee.ea1_t1[0] - ee.ea0_t1[0],
                     ee.eb0_t1[1] + ee.ea1_t1[1] - ee.ea0_t1[1],
                     ee.eb0_t1[2] + ee.ea1_t1[2] - ee.ea0_t1[2]};
        break;
      case 1:  // a triangle collapsed to a point, an edge of length zero
        vf.f1_t0 = vf.f2_t0 = vf.f0_t0;
        vf.f1_t1 = vf.f2_t1 = vf.f0_t1;
        ee.ea1_t0 = ee.ea0_t0;
        ee.ea1_t1 = ee.ea0_t1;
        break;
      case 2: {  // identical motion
        const Point3 d = testing::integer_point(rng, 2);
        auto move = [&](Point3& to, const Point3& from) {
          to = {from[0] + d[0], from[1] + d[1], from[2] + d[2]};
        };
        move(vf.v_t1, vf.v_t0), move(vf.f0_t1, vf.f0_t0), move(vf.f1_t1, vf.f1_t0),
            move(vf.f2_t1, vf.f2_t0);
        move(ee.ea0_t1, ee.ea0_t0), move(ee.ea1_t1, ee.ea1_t0), move(ee.eb0_t1, ee.eb0_t0),
            move(ee.eb1_t1, ee.eb1_t0);
        break;
      }
      case 3:  // collinear edges (on one line at both times)
        ee.eb0_t0 = {3 * ee.ea0_t0[0] - 2 * ee.ea1_t0[0], 3 * ee.ea0_t0[1] - 2 * ee.ea1_t0[1],
                     3 * ee.ea0_t0[2] - 2 * ee.ea1_t0[2]};
        ee.eb1_t0 = {2 * ee.ea1_t0[0] - ee.ea0_t0[0], 2 * ee.ea1_t0[1] - ee.ea0_t0[1],
                     2 * ee.ea1_t0[2] - ee.ea0_t0[2]};
        break;
      default:  // nothing moves
        vf.v_t1 = vf.v_t0, vf.f0_t1 = vf.f0_t0, vf.f1_t1 = vf.f1_t0, vf.f2_t1 = vf.f2_t0;
        ee.ea0_t1 = ee.ea0_t0, ee.ea1_t1 = ee.ea1_t0, ee.eb0_t1 = ee.eb0_t0, ee.eb1_t1 = ee.eb1_t0;
        break;
    }
    const std::string what = "degenerate kind " + std::to_string(i % 5) + " #" + std::to_string(i);
    for (const double delta : deltas_for(vf, rng))
      expect_as_oracle(vf, delta, what + " vf", within, apart);
    for (const double delta : deltas_for(ee, rng))
      expect_as_oracle(ee, delta, what + " ee", within, apart);
  }
  EXPECT_GT(within, 60);
  EXPECT_GT(apart, 60);
}

/// Scaling the coordinates and δ by the same power of two changes no answer, toward
/// both ends of the double range (where the filters' products would overflow or
/// underflow without the library's own rescaling).
TEST(MinSeparation, ExtremeMagnitudesScaleWithDelta) {
  Rng rng = testing::seeded_engine("min-separation-magnitudes");
  int checked = 0;
  for (int i = 0; i < 300; ++i) {
    const auto vf = random_dyadic_query<VertexFaceQuery>(rng);
    const auto ee = random_dyadic_query<EdgeEdgeQuery>(rng);
    const int k = (i % 2 ? 1 : -1) * testing::uniform_int(rng, 900, 1000);
    for (const double delta : {0.25, 0.5, 0.75, 1.0, 1.5}) {
      const double scaled_delta = std::ldexp(delta, k);
      auto scale = [k](const Point3& x) { return testing::scaled(x, k); };
      EXPECT_EQ(separated(mapped(vf, scale), scaled_delta).collision,
                separated(vf, delta).collision)
          << "vf #" << i << " 2^" << k << " delta " << delta;
      EXPECT_EQ(separated(mapped(ee, scale), scaled_delta).collision,
                separated(ee, delta).collision)
          << "ee #" << i << " 2^" << k << " delta " << delta;
      ++checked;
    }
    if (i % 10 == 0) {  // and against the oracle itself, at the extreme magnitude
      int within = 0, apart = 0;
      auto scale = [k](const Point3& x) { return testing::scaled(x, k); };
      expect_as_oracle(mapped(vf, scale), std::ldexp(0.5, k), "scaled vf", within, apart);
      expect_as_oracle(mapped(ee, scale), std::ldexp(0.5, k), "scaled ee", within, apart);
    }
  }
  EXPECT_EQ(checked, 1500);
}

/// The reported case: a vertex falls from 2^10 to 2^-542 above a face of size 2^-560 that
/// stands still, with δ = 2^-540. δ^2 underflows to zero while the plane test's normal,
/// taken from the start, has length 2^10: the loss of δ^2 is absolute and was magnified
/// by n.n beyond the bound's 2^-1070, so the plane "proved" a separation that the end of
/// the step contradicts. The same with an edge falling onto a standing edge.
TEST(MinSeparation, UnderflowingDeltaSquaredIsNotAProof) {
  const double a = 0x1p-560;
  const VertexFaceQuery vf{{0, 0, 0x1p+10},  {-a, -a, 0}, {a, -a, 0}, {0, a, 0},
                           {0, 0, 0x1p-542}, {-a, -a, 0}, {a, -a, 0}, {0, a, 0}};
  const double delta = 0x1p-540;
  ASSERT_TRUE(testing::min_separation_oracle(vf, delta).within);
  EXPECT_FALSE(internal::separation_apart(vf, delta));
  const Result r = separated(vf, delta);
  EXPECT_TRUE(r.collision) << "decided by " << to_string(r.decided_by);

  const EdgeEdgeQuery ee{{-a, 0, 0x1p+10},  {a, 0, 0x1p+10},  {0, -a, 0}, {0, a, 0},
                         {-a, 0, 0x1p-542}, {a, 0, 0x1p-542}, {0, -a, 0}, {0, a, 0}};
  ASSERT_TRUE(testing::min_separation_oracle(ee, delta).within);
  EXPECT_FALSE(internal::separation_apart(ee, delta));
  EXPECT_TRUE(separated(ee, delta).collision);
}

/// One primitive of size about 2^k (k from -1070 to -500) stands still; the other comes
/// from a distance of 2^0 to 2^10 and ends about 2^k away on the side it came from (so the
/// plane facing where it came from has every end corner on its far side, as in the case
/// above); δ is 2^k times 1/4 to 4. So δ^2 and many products underflow while the step's
/// start is at magnitude 1. Every answer is the oracle's, and a separation the cheap
/// tests prove (separation_apart) is one. (The oracle is slow at these magnitudes, the
/// library is not: few queries.)
template <class Query>
void tiny_separations_agree(const char* stream, int count) {
  Rng rng = testing::seeded_engine(stream);
  int within = 0, apart = 0;
  for (int i = 0; i < count; ++i) {
    // Every other query where the old bound failed: δ^2 just below the smallest double
    // and a long normal (n.n about 2^20 magnified its lost 2^-1075).
    const bool window = i % 2 == 0;
    const int k =
        window ? testing::uniform_int(rng, -548, -530) : testing::uniform_int(rng, -1070, -500);
    Query q = random_dyadic_query<Query>(rng);  // corners on a grid of [-2, 2]^3
    const std::array<Point3*, 8> p = points(q);
    const Point3 from = testing::random_magnitude_point(rng, window ? 9 : 0, 10);
    const double length = std::sqrt(from[0] * from[0] + from[1] * from[1] + from[2] * from[2]);
    const double gap = std::ldexp(testing::uniform(rng, 0.5, 3.0), k) / length;
    const Vector3 offset{from[0] * gap, from[1] * gap, from[2] * gap};
    constexpr int kMoving = std::is_same_v<Query, VertexFaceQuery> ? 1 : 2;
    for (int c = 0; c < 4; ++c) {
      const Point3 shape = testing::scaled(*p[c], k - 3);  // within 2^(k-2) of 0
      if (c < kMoving) {                                   // from magnitude 2^0..2^10 to the offset
        *p[c + 4] = {offset[0] + shape[0], offset[1] + shape[1], offset[2] + shape[2]};
        *p[c] = {from[0] + shape[0], from[1] + shape[1], from[2] + shape[2]};
      } else {  // standing still at 0
        *p[c] = shape;
        *p[c + 4] = shape;
      }
    }
    const double delta = std::ldexp(testing::uniform(rng, 0.25, 4.0), k);
    const bool expected = testing::min_separation_oracle(q, delta).within;
    const std::string what =
        std::string(stream) + " #" + std::to_string(i) + " 2^" + std::to_string(k);
    if (internal::separation_apart(q, delta)) {
      EXPECT_FALSE(expected) << what << ": a separation proof for a pair within δ";
    }
    const Result r = separated(q, delta);
    EXPECT_EQ(r.collision, expected) << what << " decided by " << to_string(r.decided_by);
    (expected ? within : apart) += 1;
  }
  EXPECT_GT(within, count / 5);
  EXPECT_GT(apart, count / 5);
}

/// The reported case as a mesh step: a triangle of size 2^-560 stands still, a copy of it
/// falls from 2^10 to 2^-542 above it, δ = 2^-540. The broad phase keeps the pairs, and
/// the narrow phase reports every pair the oracle finds within δ, and no other.
TEST(MinSeparation, MeshStepWithAnUnderflowingDeltaSquared) {
  const double a = 0x1p-560, delta = 0x1p-540;
  const std::array<Point3, 3> shape{Point3{-a, -a, 0}, Point3{a, -a, 0}, Point3{0, a, 0}};
  std::vector<double> t0, t1;
  for (const double height0 : {0.0, 0x1p+10}) {
    const double height1 = height0 == 0.0 ? 0.0 : 0x1p-542;
    for (const Point3& c : shape) {
      t0.insert(t0.end(), {c[0], c[1], height0});
      t1.insert(t1.end(), {c[0], c[1], height1});
    }
  }
  const std::vector<Triangle> faces{{0, 1, 2}, {3, 4, 5}};
  MeshCcd mesh(6, faces);
  MeshCcdOptions options;
  options.min_separation = delta;
  const MeshCcdResult r = mesh.step({t0, t1}, options);
  auto at = [](const std::vector<double>& x, VertexIndex v) {
    return Point3{x[3 * v], x[3 * v + 1], x[3 * v + 2]};
  };
  std::vector<VertexFacePair> expected;
  for (VertexIndex v = 0; v < 6; ++v) {
    const FaceIndex f = v < 3 ? 1 : 0;
    const Triangle& t = faces[f];
    const VertexFaceQuery q{at(t0, v), at(t0, t[0]), at(t0, t[1]), at(t0, t[2]),
                            at(t1, v), at(t1, t[0]), at(t1, t[1]), at(t1, t[2])};
    if (testing::min_separation_oracle(q, delta).within) expected.push_back({v, f});
  }
  EXPECT_EQ(expected.size(), 6u);  // every corner ends 2^-542 from the other face
  EXPECT_EQ(r.vertex_face, expected);
}

TEST(MinSeparation, TinyVertexFaceSeparationsAgreeWithTheOracle) {
  tiny_separations_agree<VertexFaceQuery>("min-separation-tiny-vf", 40);
}

TEST(MinSeparation, TinyEdgeEdgeSeparationsAgreeWithTheOracle) {
  tiny_separations_agree<EdgeEdgeQuery>("min-separation-tiny-ee", 40);
}

/// Axis permutation, mirroring, time reversal and the order of the vertices change no
/// distance, so no answer; and a larger δ never loses a pair.
TEST(MinSeparation, SymmetriesAndMonotonicity) {
  Rng rng = testing::seeded_engine("min-separation-symmetries");
  int monotone_checks = 0;
  for (int i = 0; i < 300; ++i) {
    const auto vf = varied_query<VertexFaceQuery>(rng, i);
    const auto ee = varied_query<EdgeEdgeQuery>(rng, i);
    const double delta = sampled_distance(vf, 16) * testing::uniform(rng, 0.9, 1.1);
    const double delta_ee = sampled_distance(ee, 16) * testing::uniform(rng, 0.9, 1.1);
    if (!(delta > 0.0) || !(delta_ee > 0.0) || !std::isfinite(delta) || !std::isfinite(delta_ee))
      continue;
    const bool a = separated(vf, delta).collision;
    const bool b = separated(ee, delta_ee).collision;
    auto permute = [](const Point3& p) { return Point3{p[2], p[0], p[1]}; };
    auto mirror = [](const Point3& p) { return Point3{-p[0], p[1], p[2]}; };
    EXPECT_EQ(separated(mapped(vf, permute), delta).collision, a) << "vf permuted #" << i;
    EXPECT_EQ(separated(mapped(vf, mirror), delta).collision, a) << "vf mirrored #" << i;
    EXPECT_EQ(separated(time_reversed(vf), delta).collision, a) << "vf reversed #" << i;
    VertexFaceQuery rotated = vf;  // f0 f1 f2 -> f1 f2 f0
    rotated.f0_t0 = vf.f1_t0, rotated.f1_t0 = vf.f2_t0, rotated.f2_t0 = vf.f0_t0;
    rotated.f0_t1 = vf.f1_t1, rotated.f1_t1 = vf.f2_t1, rotated.f2_t1 = vf.f0_t1;
    EXPECT_EQ(separated(rotated, delta).collision, a) << "vf rotated #" << i;
    EXPECT_EQ(separated(mapped(ee, permute), delta_ee).collision, b) << "ee permuted #" << i;
    EXPECT_EQ(separated(mapped(ee, mirror), delta_ee).collision, b) << "ee mirrored #" << i;
    EXPECT_EQ(separated(time_reversed(ee), delta_ee).collision, b) << "ee reversed #" << i;
    EdgeEdgeQuery swapped = ee;  // b first, and a's ends in the other order
    swapped.ea0_t0 = ee.eb0_t0, swapped.ea1_t0 = ee.eb1_t0, swapped.eb0_t0 = ee.ea1_t0,
    swapped.eb1_t0 = ee.ea0_t0;
    swapped.ea0_t1 = ee.eb0_t1, swapped.ea1_t1 = ee.eb1_t1, swapped.eb0_t1 = ee.ea1_t1,
    swapped.eb1_t1 = ee.ea0_t1;
    EXPECT_EQ(separated(swapped, delta_ee).collision, b) << "ee swapped #" << i;
    // Monotone: within at δ implies within at every larger δ; apart at δ implies apart
    // at every smaller one (the contact answer included).
    for (const double factor : {0.5, 0.999, 1.001, 2.0}) {
      const bool at_vf = separated(vf, delta * factor).collision;
      const bool at_ee = separated(ee, delta_ee * factor).collision;
      if (factor > 1.0) {
        EXPECT_TRUE(!a || at_vf) << "vf #" << i;
        EXPECT_TRUE(!b || at_ee) << "ee #" << i;
      } else {
        EXPECT_TRUE(a || !at_vf) << "vf #" << i;
        EXPECT_TRUE(b || !at_ee) << "ee #" << i;
      }
      ++monotone_checks;
    }
    const Result contact = vertex_face_ccd(vf);
    EXPECT_TRUE(!contact.collision || a) << "vf #" << i << ": a contact is within every δ";
  }
  EXPECT_GT(monotone_checks, 600);
}

/// With a width, the earliest time within δ is bracketed: the oracle's exact earliest
/// time lies in the bracket, and the bracket is no wider than asked (or than one double
/// spacing next to it).
template <class Query>
void brackets_hold_the_earliest_time(const char* stream) {
  Rng rng = testing::seeded_engine(stream);
  int bracketed = 0;
  for (int i = 0; i < 40; ++i) {
    const Query q = i % 2 ? random_dyadic_query<Query>(rng) : varied_query<Query>(rng, i / 2);
    for (const double delta : deltas_for(q, rng)) {
      const testing::MinSeparationAnswer truth = testing::min_separation_oracle(q, delta);
      for (const double width : {0.25, 1e-3, 1e-9}) {
        Options o;
        o.min_separation = delta;
        o.time_of_impact_width = width;
        const Result r = run(q, o);
        ASSERT_EQ(r.collision, truth.within) << stream << " #" << i << " delta " << delta;
        if (!r.collision) continue;
        ASSERT_TRUE(r.time_of_impact.has_value()) << stream << " #" << i;
        const TimeInterval t = *r.time_of_impact;
        EXPECT_LE(mpq_class(t.start), truth.earliest_hi)
            << stream << " #" << i << " delta " << delta;
        EXPECT_GE(mpq_class(t.end), truth.earliest_lo) << stream << " #" << i << " delta " << delta;
        const double spacing = std::nextafter(t.end, 2.0) - t.end;
        EXPECT_LE(t.end - t.start, std::max(width, 2 * spacing)) << stream << " #" << i;
        ++bracketed;
      }
    }
  }
  EXPECT_GT(bracketed, 40);
}

TEST(MinSeparation, VertexFaceTimeOfImpactBracketsTheEarliestTime) {
  brackets_hold_the_earliest_time<VertexFaceQuery>("min-separation-toi-vf");
}

TEST(MinSeparation, EdgeEdgeTimeOfImpactBracketsTheEarliestTime) {
  brackets_hold_the_earliest_time<EdgeEdgeQuery>("min-separation-toi-ee");
}

/// On every bundled benchmark query: δ = 0 answers as the contact question, with its
/// stage; the smallest positive δ finds every contact, and the truth's collisions.
TEST(MinSeparation, BundledQueriesAtZeroAndAtTheSmallestDelta) {
  int contacts = 0;
  for (const QueryFile& file :
       read_query_files({(std::filesystem::path(EXACTGEO_TEST_DATA_DIR) / "ccd").string()})) {
    for (const QueryRecord& record : file.records) {
      auto check = [&](const auto& q) {
        Options zero;
        zero.min_separation = 0.0;
        const Result contact = run(q, Options{});
        const Result at_zero = run(q, zero);
        EXPECT_EQ(at_zero.collision, contact.collision) << file.path;
        EXPECT_EQ(at_zero.decided_by, contact.decided_by) << file.path;
        const Result tiny = separated(q, std::numeric_limits<double>::denorm_min());
        EXPECT_TRUE(!contact.collision || tiny.collision) << file.path;
        if (record.truth) {
          EXPECT_TRUE(!*record.truth || tiny.collision) << file.path;
        }
        contacts += contact.collision;
      };
      if (file.type == QueryType::edge_edge) {
        check(edge_edge_query(record));
      } else {
        check(vertex_face_query(record));
      }
    }
  }
  EXPECT_GT(contacts, 10);
}

TEST(MinSeparation, ZeroIsTheContactQuestionAndTheValidityCheck) {
  Rng rng = testing::seeded_engine("min-separation-zero");
  for (int i = 0; i < 500; ++i) {
    const auto q = varied_query<EdgeEdgeQuery>(rng, i);
    Options zero;
    zero.min_separation = 0.0;
    const Result a = edge_edge_ccd(q);
    const Result b = edge_edge_ccd(q, zero);
    EXPECT_EQ(a.collision, b.collision);
    EXPECT_EQ(a.decided_by, b.decided_by);
  }
  EXPECT_TRUE(is_valid_min_separation(0.0));
  EXPECT_TRUE(is_valid_min_separation(std::numeric_limits<double>::denorm_min()));
  EXPECT_TRUE(is_valid_min_separation(std::numeric_limits<double>::max()));
  EXPECT_FALSE(is_valid_min_separation(-0.5));
  EXPECT_FALSE(is_valid_min_separation(std::nan("")));
  EXPECT_FALSE(is_valid_min_separation(INFINITY));
}

/// The mesh broad phase grows its boxes by δ and drops no pair: a random soup of small
/// triangles under random motion, against every non-adjacent pair decided one by one.
TEST(MinSeparation, MeshStepFindsEveryPairWithinDelta) {
  Rng rng = testing::seeded_engine("min-separation-mesh");
  for (int round = 0; round < 4; ++round) {
    const int triangles = 40;
    std::vector<Triangle> faces;
    std::vector<double> t0, t1;
    for (int f = 0; f < triangles; ++f) {
      const Point3 c = testing::random_point(rng, 1.0);
      const Point3 m = testing::random_point(rng, 0.3);
      for (int k = 0; k < 3; ++k) {
        const Point3 p = testing::random_point(rng, 0.15);
        for (int axis = 0; axis < 3; ++axis) {
          t0.push_back(c[axis] + p[axis]);
          t1.push_back(c[axis] + p[axis] + m[axis]);
        }
      }
      const auto v = static_cast<VertexIndex>(3 * f);
      faces.push_back({v, v + 1, v + 2});
    }
    const int k = round % 2 ? 0 : (round == 0 ? 1000 : -1000);  // and at 2^±1000
    for (double& x : t0)
      x = std::ldexp(x, k);
    for (double& x : t1)
      x = std::ldexp(x, k);
    const double delta = std::ldexp(0.05 * (round + 1), k);
    MeshCcd mesh(t0.size() / 3, faces);
    MeshCcdOptions options;
    options.min_separation = delta;
    const MeshCcdResult r = mesh.step({t0, t1}, options);
    // Every pair, one by one.
    std::vector<VertexFacePair> vf;
    for (VertexIndex v = 0; v < t0.size() / 3; ++v) {
      for (FaceIndex f = 0; f < faces.size(); ++f) {
        const Triangle& t = faces[f];
        if (v == t[0] || v == t[1] || v == t[2]) continue;
        auto at = [&](const std::vector<double>& x, VertexIndex i) {
          return Point3{x[3 * i], x[3 * i + 1], x[3 * i + 2]};
        };
        const VertexFaceQuery q{at(t0, v), at(t0, t[0]), at(t0, t[1]), at(t0, t[2]),
                                at(t1, v), at(t1, t[0]), at(t1, t[1]), at(t1, t[2])};
        if (separated(q, delta).collision) vf.push_back({v, f});
      }
    }
    std::vector<EdgeEdgePair> ee;
    const std::span<const Edge> edges = mesh.edges();
    for (std::size_t i = 0; i < edges.size(); ++i) {
      for (std::size_t j = i + 1; j < edges.size(); ++j) {
        const Edge& a = edges[i];
        const Edge& b = edges[j];
        if (a[0] == b[0] || a[0] == b[1] || a[1] == b[0] || a[1] == b[1]) continue;
        auto at = [&](const std::vector<double>& x, VertexIndex v) {
          return Point3{x[3 * v], x[3 * v + 1], x[3 * v + 2]};
        };
        const EdgeEdgeQuery q{at(t0, a[0]), at(t0, a[1]), at(t0, b[0]), at(t0, b[1]),
                              at(t1, a[0]), at(t1, a[1]), at(t1, b[0]), at(t1, b[1])};
        if (separated(q, delta).collision) ee.push_back({a, b});
      }
    }
    std::sort(ee.begin(), ee.end());
    EXPECT_EQ(r.vertex_face, vf) << "round " << round;
    EXPECT_EQ(r.edge_edge, ee) << "round " << round;
    // The mesh's earliest time within δ is the earliest of its pairs'.
    MeshCcd fresh(t0.size() / 3, faces);
    options.time_of_impact_width = 1e-6;
    const MeshCcdResult timed = fresh.step({t0, t1}, options);
    ASSERT_TRUE(timed.time_of_impact.has_value()) << "round " << round;
    double earliest_end = 1.0, earliest_start = 1.0;
    auto note = [&](const Result& pair) {
      ASSERT_TRUE(pair.time_of_impact.has_value());
      earliest_end = std::min(earliest_end, pair.time_of_impact->end);
      earliest_start = std::min(earliest_start, pair.time_of_impact->start);
    };
    Options pair_options;
    pair_options.min_separation = delta;
    pair_options.time_of_impact_width = 1e-6;
    auto point = [&](const std::vector<double>& x, VertexIndex i) {
      return Point3{x[3 * i], x[3 * i + 1], x[3 * i + 2]};
    };
    for (const VertexFacePair& p : vf) {
      const Triangle& t = faces[p.face];
      note(vertex_face_ccd({point(t0, p.vertex), point(t0, t[0]), point(t0, t[1]), point(t0, t[2]),
                            point(t1, p.vertex), point(t1, t[0]), point(t1, t[1]), point(t1, t[2])},
                           pair_options));
    }
    for (const EdgeEdgePair& p : ee) {
      note(edge_edge_ccd(
          {point(t0, p.a[0]), point(t0, p.a[1]), point(t0, p.b[0]), point(t0, p.b[1]),
           point(t1, p.a[0]), point(t1, p.a[1]), point(t1, p.b[0]), point(t1, p.b[1])},
          pair_options));
    }
    EXPECT_LE(timed.time_of_impact->start, earliest_end) << "round " << round;
    EXPECT_GE(timed.time_of_impact->end, earliest_start) << "round " << round;
    EXPECT_LE(timed.time_of_impact->end - timed.time_of_impact->start, 1e-6) << "round " << round;
    EXPECT_GT(vf.size(), 0u) << "round " << round << ": a test that finds nothing says little";
  }
  MeshCcd mesh(3, std::vector<Triangle>{{0, 1, 2}});
  const std::vector<double> x{0, 0, 0, 1, 0, 0, 0, 1, 0};
  MeshCcdOptions bad;
  bad.min_separation = -1.0;
  EXPECT_THROW(mesh.step({x, x}, bad), std::invalid_argument);
  bad.min_separation = std::nan("");
  EXPECT_THROW(mesh.step({x, x}, bad), std::invalid_argument);
}

}  // namespace
}  // namespace exactgeo::ccd
