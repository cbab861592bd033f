// Ray vs bilinear patch parity and signed crossings, the patch's implicit function and its
// shape: hand cases for every flat shape, then the independent rational oracle (which
// counts preimages directly, by exact algebra in Q(sqrt D), each with the sign of the
// patch's normal there) on generic, dense dyadic, flat, near-flat, collapsed, scaled and
// extreme-magnitude inputs.

#include "exactgeo/predicates/bilinear_patch.hpp"

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <cstdio>
#include <map>
#include <string>

#include "exactgeo/predicates/internal/patch_span.hpp"
#include "exactgeo/predicates/ray_triangle.hpp"
#include "support/generators.hpp"
#include "support/rational_oracle.hpp"
#include "support/seed.hpp"

namespace exactgeo {
namespace {

using testing::Rng;

const BilinearPatch kSaddle{{0, 0, 0}, {1, 0, 0}, {1, 1, 1}, {0, 1, 0}};  // (u, v, uv)
const BilinearPatch kDart{{0, 0, 0}, {2, 0, 0}, {0.5, 0.5, 0}, {0, 2, 0}};
// The hourglass (the original 2012 code mishandles it): in the plane x + y = 1, edges p00p10
// and p11p01 cross.
const BilinearPatch kHourglass{{1, 0, 1}, {0, 1, 1}, {1, 0, 0}, {0, 1, 0}};
const BilinearPatch kSquare{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};

std::string describe(const Point3& o, const Vector3& d, const BilinearPatch& p) {
  char buf[640];
  std::snprintf(buf, sizeof buf,
                "origin (%a,%a,%a) direction (%a,%a,%a) p00 (%a,%a,%a) p10 (%a,%a,%a) "
                "p11 (%a,%a,%a) p01 (%a,%a,%a)",
                o[0], o[1], o[2], d[0], d[1], d[2], p.p00[0], p.p00[1], p.p00[2], p.p10[0],
                p.p10[1], p.p10[2], p.p11[0], p.p11[1], p.p11[2], p.p01[0], p.p01[1], p.p01[2]);
  return buf;
}

TEST(PatchShape, EveryShapeByHand) {
  EXPECT_EQ(classify_patch(kSaddle), PatchShape::skew);
  EXPECT_EQ(classify_patch(kSquare), PatchShape::convex);
  EXPECT_EQ(classify_patch(kDart), PatchShape::concave);
  EXPECT_EQ(classify_patch(kHourglass), PatchShape::butterfly);
  EXPECT_EQ(classify_patch({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 1, 0}}),
            PatchShape::degenerate_planar);  // a triangle
  EXPECT_EQ(classify_patch({{0, 0, 0}, {1, 1, 1}, {3, 3, 3}, {-1, -1, -1}}), PatchShape::segment);
  EXPECT_EQ(classify_patch({{1, 2, 3}, {1, 2, 3}, {1, 2, 3}, {1, 2, 3}}), PatchShape::point);
}

TEST(RayPatch, SkewPatchByHand) {
  EXPECT_EQ(ray_patch_parity({0.3, 0.3, 5}, {0, 0, -1}, kSaddle), RayPatch::odd);
  EXPECT_EQ(ray_patch_parity({0.3, 0.3, -5}, {0, 0, 1}, kSaddle), RayPatch::odd);
  EXPECT_EQ(ray_patch_parity({3, 3, 5}, {0, 0, -1}, kSaddle), RayPatch::even);
  EXPECT_EQ(ray_patch_parity({0.5, 0.5, 0.25}, {0, 0, 1}, kSaddle), RayPatch::origin_on_patch);
  EXPECT_EQ(ray_patch_parity({0.5, 0, 5}, {0, 0, -1}, kSaddle), RayPatch::degenerate);
  EXPECT_EQ(ray_patch_parity({1, 1, 5}, {0, 0, -1}, kSaddle), RayPatch::degenerate);
  // Inside the corners' tetrahedron, on either side of the saddle (it passes z = 0.25).
  EXPECT_EQ(ray_patch_parity({0.5, 0.5, 0.2}, {0, 0, 1}, kSaddle), RayPatch::odd);
  EXPECT_EQ(ray_patch_parity({0.5, 0.5, 0.2}, {0, 0, -1}, kSaddle), RayPatch::even);
  EXPECT_EQ(ray_patch_parity({0.5, 0.5, 0.3}, {0, 0, 1}, kSaddle), RayPatch::even);
  EXPECT_EQ(ray_patch_parity({0.5, 0.5, 0.3}, {0, 0, -1}, kSaddle), RayPatch::odd);
  // The line z = t - 3/16 over (t, t) meets the saddle z = uv twice, at t = 1/4 and 3/4:
  // from before both crossings the count is even, from between them odd.
  EXPECT_EQ(ray_patch_parity({0, 0, -0.1875}, {1, 1, 1}, kSaddle), RayPatch::even);
  EXPECT_EQ(ray_patch_parity({0.5, 0.5, 0.3125}, {1, 1, 1}, kSaddle), RayPatch::odd);
}

TEST(RayPatch, FlatShapesByHand) {
  // Convex: crossing, missing, on, edge.
  EXPECT_EQ(ray_patch_parity({0.5, 0.5, 1}, {0, 0, -1}, kSquare), RayPatch::odd);
  EXPECT_EQ(ray_patch_parity({0.5, 0.5, 0}, {1, 2, 3}, kSquare), RayPatch::origin_on_patch);
  EXPECT_EQ(ray_patch_parity({1, 0.5, 1}, {0, 0, -1}, kSquare), RayPatch::degenerate);
  EXPECT_EQ(ray_patch_parity({0.5, 0.5, 1}, {1, 1, 0}, kSquare), RayPatch::even);
  // Through the square's diagonal p10 p01 (x + y = 1): one crossing, not two or zero.
  EXPECT_EQ(ray_patch_parity({0.25, 0.75, 1}, {0, 0, -1}, kSquare), RayPatch::odd);
  // Ray in the plane: degenerate when it meets the patch, even when it does not.
  EXPECT_EQ(ray_patch_parity({-1, 0.5, 0}, {1, 0, 0}, kSquare), RayPatch::degenerate);
  EXPECT_EQ(ray_patch_parity({-1, 0.5, 0}, {-1, 0, 0}, kSquare), RayPatch::even);
  // Concave dart: its centre p(1/2, 1/2) = (0.625, 0.625, 0) is outside the quadrilateral
  // but on the patch (two preimages), so a ray through it crosses twice.
  EXPECT_EQ(ray_patch_parity({0.625, 0.625, 0}, {0, 0, 1}, kDart), RayPatch::origin_on_patch);
  EXPECT_EQ(ray_patch_parity({0.625, 0.625, 1}, {0, 0, -1}, kDart), RayPatch::even);
  EXPECT_EQ(ray_patch_parity({0.2, 0.2, 1}, {0, 0, -1}, kDart), RayPatch::odd);
  // In the corners' hull but not on the patch (the fold does not reach it).
  EXPECT_EQ(ray_patch_parity({0.9, 0.9, 0}, {0, 0, 1}, kDart), RayPatch::even);
  // Hourglass: each lobe is covered once, the crossing point p(1/2, 1/2) = (1/2, 1/2, 1/2)
  // is on it.
  EXPECT_EQ(ray_patch_parity({0, 0, 0.75}, {1, 1, 0}, kHourglass), RayPatch::odd);
  EXPECT_EQ(ray_patch_parity({0, 0, 0.25}, {1, 1, 0}, kHourglass), RayPatch::odd);
  EXPECT_EQ(ray_patch_parity({0.5, 0.5, 0.5}, {1, 0, 0}, kHourglass), RayPatch::origin_on_patch);
  EXPECT_EQ(ray_patch_parity({0, 0, 0.5}, {1, 1, 0}, kHourglass), RayPatch::degenerate);
  EXPECT_EQ(ray_patch_parity({0.5, 0.5, 0.2}, {1, 0, 0}, kHourglass), RayPatch::origin_on_patch);
  // Between the lobes, in the plane (exactly: 0.75 + 0.25 = 1): off the patch. A ray
  // leaving the plane crosses nothing; a ray in the plane meeting the corners' hull is
  // reported degenerate. (From (0.9, 0.1, 0.5) the same ray would cross nothing: 0.9 + 0.1
  // is not 1 in binary, so that origin is off the plane and the ray parallel to it.)
  EXPECT_EQ(ray_patch_parity({0.75, 0.25, 0.5}, {1, 0, 0}, kHourglass), RayPatch::even);
  EXPECT_EQ(ray_patch_parity({0.75, 0.25, 0.5}, {0, 0, 1}, kHourglass), RayPatch::degenerate);
  EXPECT_EQ(ray_patch_parity({0.9, 0.1, 0.5}, {0, 0, 1}, kHourglass), RayPatch::even);
}

TEST(RayPatch, CollapsedPatchesByHand) {
  const BilinearPatch segment{{0, 0, 0}, {2, 0, 0}, {1, 0, 0}, {1, 0, 0}};
  EXPECT_EQ(ray_patch_parity({1.5, 0, 0}, {0, 1, 0}, segment), RayPatch::origin_on_patch);
  EXPECT_EQ(ray_patch_parity({1, -1, 0}, {0, 1, 0}, segment), RayPatch::degenerate);
  EXPECT_EQ(ray_patch_parity({1, -1, 0}, {0, 1, 1}, segment), RayPatch::even);
  EXPECT_EQ(ray_patch_parity({3, 0, 0}, {-1, 0, 0}, segment), RayPatch::degenerate);
  EXPECT_EQ(ray_patch_parity({3, 0, 0}, {1, 0, 0}, segment), RayPatch::even);
  const BilinearPatch point{{1, 1, 1}, {1, 1, 1}, {1, 1, 1}, {1, 1, 1}};
  EXPECT_EQ(ray_patch_parity({1, 1, 1}, {0, 1, 0}, point), RayPatch::origin_on_patch);
  EXPECT_EQ(ray_patch_parity({0, 0, 0}, {2, 2, 2}, point), RayPatch::degenerate);
  EXPECT_EQ(ray_patch_parity({0, 0, 0}, {-2, -2, -2}, point), RayPatch::even);
  EXPECT_EQ(ray_patch_parity({0, 0, 0}, {2, 2, 2.5}, point), RayPatch::even);
}

TEST(PatchSide, ZeroOnThePatchAndSidesInsideTheTetrahedron) {
  // p(u, v) with dyadic (u, v) is exact for small integer corners: phi vanishes there.
  for (int i = 0; i <= 8; ++i) {
    for (int j = 0; j <= 8; ++j) {
      const double u = i / 8.0, v = j / 8.0;
      const Point3 p{u, v, u * v};
      EXPECT_EQ(patch_side(kSaddle, p), Sign::zero) << u << " " << v;
    }
  }
  // Inside the tetrahedron: below the saddle is the side of triangles (p00, p10, p01) and
  // (p10, p11, p01), which phi calls negative.
  EXPECT_EQ(patch_side(kSaddle, {0.5, 0.5, 0.2}), Sign::negative);
  EXPECT_EQ(patch_side(kSaddle, {0.5, 0.5, 0.3}), Sign::positive);
}

/// Parity and signed count, in every arithmetic that claims exactness, are the oracle's.
void expect_matches_oracle(const Point3& o, const Vector3& d, const BilinearPatch& p) {
  const RayPatchCrossings expected = testing::ray_patch_signed_crossings_oracle(o, d, p);
  for (const Arithmetic arithmetic : {Arithmetic::exact, Arithmetic::rational}) {
    const RayPatchCrossings r = ray_patch_crossings(o, d, p, arithmetic);
    ASSERT_EQ(r.parity, expected.parity) << describe(o, d, p);
    ASSERT_EQ(r.signed_count, expected.signed_count) << describe(o, d, p);
    ASSERT_EQ(ray_patch_parity(o, d, p, arithmetic), expected.parity) << describe(o, d, p);
  }
}

BilinearPatch integer_patch(Rng& rng, int range) {
  return {testing::integer_point(rng, range), testing::integer_point(rng, range),
          testing::integer_point(rng, range), testing::integer_point(rng, range)};
}

TEST(RayPatch, GenericInputsAgreeWithOracle) {
  Rng rng = testing::seeded_engine("ray-patch-generic");
  const auto trials = static_cast<int>(testing::scaled_trials(3000));  // tests/support/seed.hpp
  for (int i = 0; i < trials; ++i) {
    const BilinearPatch p{testing::random_point(rng), testing::random_point(rng),
                          testing::random_point(rng), testing::random_point(rng)};
    // Origins near the patch so that many fall inside the corners' tetrahedron.
    const Point3 o = testing::rounded_affine(p.p00, p.p10, p.p01, testing::uniform(rng, 0, 1),
                                             testing::uniform(rng, 0, 1));
    const Point3 jitter = testing::random_point(rng, 0.2);
    expect_matches_oracle({o[0] + jitter[0], o[1] + jitter[1], o[2] + jitter[2]},
                          testing::random_point(rng), p);
  }
}

/// Small integer and half-integer coordinates: rays through corners and edges, along
/// rulings, origins on the patch, flat and collapsed patches all occur often.
TEST(RayPatch, DenseDyadicInputsAgreeWithOracle) {
  Rng rng = testing::seeded_engine("ray-patch-dyadic");
  std::map<RayPatch, int> outcomes;
  std::map<PatchShape, int> shapes;
  for (int i = 0; i < 20000; ++i) {
    const BilinearPatch p = integer_patch(rng, 2);
    const Point3 o = testing::scaled(testing::integer_point(rng, 4), -1);
    const Vector3 d = testing::nonzero_integer_direction(rng, 2);
    expect_matches_oracle(o, d, p);
    ++outcomes[ray_patch_parity(o, d, p)];
    ++shapes[classify_patch(p)];
  }
  for (const RayPatch r :
       {RayPatch::even, RayPatch::odd, RayPatch::origin_on_patch, RayPatch::degenerate}) {
    EXPECT_GT(outcomes[r], 200) << to_string(r);
  }
  EXPECT_GT(shapes[PatchShape::skew], 1000);
}

/// Flat patches of every shape, with origins in and off their plane.
TEST(RayPatch, FlatPatchesAgreeWithOracle) {
  Rng rng = testing::seeded_engine("ray-patch-flat");
  std::map<PatchShape, int> shapes;
  for (int i = 0; i < 30000; ++i) {
    BilinearPatch p = integer_patch(rng, 3);
    p.p00[2] = p.p10[2] = p.p11[2] = p.p01[2] = 0;  // flat in z = 0
    Point3 o = testing::scaled(testing::integer_point(rng, 6), -1);
    if (i % 2 == 0) o[2] = 0;  // origin in the plane half of the time
    const Vector3 d = testing::nonzero_integer_direction(rng, 2);
    expect_matches_oracle(o, d, p);
    ++shapes[classify_patch(p)];
  }
  for (const PatchShape s : {PatchShape::convex, PatchShape::concave, PatchShape::butterfly,
                             PatchShape::degenerate_planar, PatchShape::segment}) {
    EXPECT_GT(shapes[s], 100) << to_string(s);
  }
}

/// A flat patch in a tilted plane: corners a + s e1 + t e2 with small integers a, e1, e2,
/// s, t, so coplanar exactly (often concave or butterfly; collinear when e1, e2 are).
BilinearPatch tilted_flat_patch(Rng& rng) {
  const Point3 a = testing::integer_point(rng, 2), e1 = testing::integer_point(rng, 2),
               e2 = testing::integer_point(rng, 2);
  auto corner = [&] {
    return testing::rounded_affine(
        a, {a[0] + e1[0], a[1] + e1[1], a[2] + e1[2]}, {a[0] + e2[0], a[1] + e2[1], a[2] + e2[2]},
        testing::uniform_int(rng, -3, 3), testing::uniform_int(rng, -3, 3));
  };
  return {corner(), corner(), corner(), corner()};  // a braced list: drawn in this order
}

/// Tilted flat patches (the plane is not a coordinate plane) and origins in the fold
/// region of concave and butterfly patches: p(u, v) at dyadic parameters is on the patch.
TEST(RayPatch, FoldRegionsOfTiltedFlatPatchesAgreeWithOracle) {
  Rng rng = testing::seeded_engine("ray-patch-fold");
  int folded_on = 0;
  for (int i = 0; i < 5000; ++i) {
    const BilinearPatch p = tilted_flat_patch(rng);
    const double u = testing::uniform_int(rng, 0, 4) / 4.0,
                 v = testing::uniform_int(rng, 0, 4) / 4.0;
    Point3 o;
    for (int k = 0; k < 3; ++k) {
      o[k] = (1 - u) * (1 - v) * p.p00[k] + u * (1 - v) * p.p10[k] + u * v * p.p11[k] +
             (1 - u) * v * p.p01[k];  // exact: few bits
    }
    const Vector3 d = testing::nonzero_integer_direction(rng, 2);
    expect_matches_oracle(o, d, p);
    ASSERT_EQ(ray_patch_parity(o, d, p), RayPatch::origin_on_patch) << describe(o, d, p);
    const PatchShape shape = classify_patch(p);
    folded_on += shape == PatchShape::concave || shape == PatchShape::butterfly;
    // Off the point along the plane normal-ish direction: a generic nearby origin.
    expect_matches_oracle({o[0] + 0.125, o[1] - 0.375, o[2] + 0.25}, d, p);
  }
  EXPECT_GT(folded_on, 200);
}

/// Flat patches of every shape, tilted, and one corner one ulp off their plane (a skew
/// patch thinner than any filter can see), rays through them off the plane: the signed
/// count (and the parity) is the oracle's, so the count through the fold of a concave or
/// butterfly patch, where the two sheets face opposite ways, is 0.
TEST(RayPatch, NearFlatPatchesOneUlpOffAgreeWithOracle) {
  Rng rng = testing::seeded_engine("ray-patch-near-flat");
  std::map<PatchShape, int> shapes;
  std::map<Sign, int> counts;
  // 6000 at full effort (tests/support/seed.hpp); every shape and sign asked of the same
  // share of them.
  const auto trials = static_cast<int>(testing::scaled_trials(6000, 2));
  for (int i = 0; i < trials; ++i) {
    BilinearPatch p = tilted_flat_patch(rng);
    if (i % 2 == 1) {
      p.p11 = testing::ulp_step(p.p11, testing::uniform_int(rng, 0, 2),
                                testing::uniform_int(rng, 0, 1) * 2 - 1);
    }
    const Point3 o = testing::random_point(rng, 2.0);
    const Point3 target = testing::rounded_affine(p.p00, p.p10, p.p01, testing::uniform(rng, 0, 1),
                                                  testing::uniform(rng, 0, 1));
    const Vector3 d{target[0] - o[0], target[1] - o[1], target[2] - o[2]};
    if (d == Vector3{0, 0, 0}) continue;
    expect_matches_oracle(o, d, p);
    ++shapes[classify_patch(p)];
    ++counts[ray_patch_crossings(o, d, p).signed_count];
  }
  for (const PatchShape s :
       {PatchShape::skew, PatchShape::convex, PatchShape::concave, PatchShape::butterfly}) {
    EXPECT_GT(shapes[s], 100 * trials / 6000) << to_string(s);
  }
  for (const Sign s : {Sign::negative, Sign::zero, Sign::positive}) {
    EXPECT_GT(counts[s], 500 * trials / 6000) << to_int(s);
  }
}

/// The same kinds of inputs as the dense dyadic test, scaled by 2^k for k up to +-1000 and
/// compared with the oracle there (not only with the unscaled answer): the filters fail
/// at these magnitudes and the exact stages answer.
TEST(RayPatch, ExtremeMagnitudesAgreeWithOracle) {
  Rng rng = testing::seeded_engine("ray-patch-extreme");
  for (int i = 0; i < 1500; ++i) {
    const BilinearPatch p = integer_patch(rng, 2);
    const Point3 o = testing::scaled(testing::integer_point(rng, 4), -1);
    const int k = testing::uniform_int(rng, 0, 1) == 0 ? testing::uniform_int(rng, -1000, -900)
                                                       : testing::uniform_int(rng, 900, 1000);
    const BilinearPatch ps{testing::scaled(p.p00, k), testing::scaled(p.p10, k),
                           testing::scaled(p.p11, k), testing::scaled(p.p01, k)};
    const Vector3 d = testing::scaled(testing::nonzero_integer_direction(rng, 2),
                                      testing::uniform_int(rng, -1000, 1000));
    expect_matches_oracle(testing::scaled(o, k), d, ps);
  }
}

TEST(RayPatch, ScalingByPowersOfTwoChangesNothing) {
  Rng rng = testing::seeded_engine("ray-patch-scaled");
  for (int i = 0; i < 2000; ++i) {
    const BilinearPatch p = integer_patch(rng, 3);
    const Point3 o = testing::scaled(testing::integer_point(rng, 6), -1);
    const Vector3 d = testing::nonzero_integer_direction(rng, 2);
    const RayPatchCrossings reference = ray_patch_crossings(o, d, p);
    const int k = testing::uniform_int(rng, -1070, 1015);
    const BilinearPatch ps{testing::scaled(p.p00, k), testing::scaled(p.p10, k),
                           testing::scaled(p.p11, k), testing::scaled(p.p01, k)};
    const Vector3 ds = testing::scaled(d, testing::uniform_int(rng, -1070, 1015));
    const RayPatchCrossings r = ray_patch_crossings(testing::scaled(o, k), ds, ps);
    ASSERT_EQ(r.parity, reference.parity) << "k=" << k << " " << describe(o, d, p);
    ASSERT_EQ(r.signed_count, reference.signed_count) << "k=" << k << " " << describe(o, d, p);
  }
}

TEST(RayPatch, ReparametrizingThePatchChangesNothing) {
  // The same surface with (u, v) swapped or reversed has the same crossings.
  Rng rng = testing::seeded_engine("ray-patch-reparametrize");
  for (int i = 0; i < 5000; ++i) {
    const BilinearPatch p = integer_patch(rng, 2);
    const Point3 o = testing::scaled(testing::integer_point(rng, 4), -1);
    const Vector3 d = testing::nonzero_integer_direction(rng, 2);
    const RayPatchCrossings r = ray_patch_crossings(o, d, p);
    // Swapping u and v, or reversing one of them, reverses the orientation; both reversed
    // keep it.
    const RayPatchCrossings swapped = ray_patch_crossings(o, d, {p.p00, p.p01, p.p11, p.p10});
    const RayPatchCrossings mirrored = ray_patch_crossings(o, d, {p.p10, p.p00, p.p01, p.p11});
    const RayPatchCrossings turned = ray_patch_crossings(o, d, {p.p11, p.p01, p.p00, p.p10});
    for (const RayPatchCrossings& other : {swapped, mirrored, turned})
      EXPECT_EQ(other.parity, r.parity);
    EXPECT_EQ(swapped.signed_count, -r.signed_count);
    EXPECT_EQ(mirrored.signed_count, -r.signed_count);
    EXPECT_EQ(turned.signed_count, r.signed_count);
  }
}

TEST(RayPatch, TriangleAsDegeneratePatchMatchesRayTriangle) {
  Rng rng = testing::seeded_engine("ray-patch-triangle");
  for (int i = 0; i < 10000; ++i) {
    const Point3 a = testing::integer_point(rng, 2), b = testing::integer_point(rng, 2),
                 c = testing::integer_point(rng, 2);
    const Point3 o = testing::integer_point(rng, 2);
    const Vector3 d = testing::nonzero_integer_direction(rng, 2);
    const RayTriangleHit t = classify_ray_triangle(o, d, a, b, c);
    const RayPatchCrossings crossings = ray_patch_crossings(o, d, {a, b, c, c});
    const RayPatch r = crossings.parity;
    EXPECT_EQ(crossings.signed_count, t.kind == RayTriangle::interior ? t.turn : Sign::zero);
    switch (t.kind) {
      case RayTriangle::miss:
        EXPECT_EQ(r, RayPatch::even);
        break;
      case RayTriangle::interior:
        EXPECT_EQ(r, RayPatch::odd);
        break;
      case RayTriangle::origin_on:
        EXPECT_EQ(r, RayPatch::origin_on_patch);
        break;
      case RayTriangle::edge:
      case RayTriangle::vertex:
      case RayTriangle::coplanar:
        EXPECT_EQ(r, RayPatch::degenerate);
        break;
    }
  }
}

TEST(PatchShape, AgreesWithOracle) {
  Rng rng = testing::seeded_engine("patch-shape");
  for (int i = 0; i < 20000; ++i) {
    BilinearPatch p = integer_patch(rng, 2);
    if (i % 2 == 0) p.p00[1] = p.p10[1] = p.p11[1] = p.p01[1] = 1;  // flat half of the time
    ASSERT_EQ(classify_patch(p), testing::patch_shape_oracle(p))
        << describe({0, 0, 0}, {0, 0, 0}, p);
  }
}

/// The span of a patch known only through offsets from an origin (as in CCD) is the span
/// of the patch itself, wherever the origin is.
TEST(PatchSpan, FromOffsetsMatchesFromCorners) {
  Rng rng = testing::seeded_engine("patch-frame-offsets");
  for (int i = 0; i < 20000; ++i) {
    BilinearPatch p = i % 3 == 0
                          ? integer_patch(rng, 2)
                          : BilinearPatch{testing::random_point(rng), testing::random_point(rng),
                                          testing::random_point(rng), testing::random_point(rng)};
    if (i % 3 == 1) p.p11 = testing::rounded_affine(p.p00, p.p10, p.p01, 1, 1);  // nearly flat
    const auto x = internal::tensor_corners(p);
    const Point3 origin = i % 2 ? testing::random_point(rng, 4) : testing::integer_point(rng, 3);
    const kernel::ExactSigns signs;
    const PatchSpan expected = internal::patch_span(signs, x);
    const PatchSpan got =
        internal::patch_span_from_offsets(signs, internal::offsets_from(origin, x));
    ASSERT_EQ(got.kind, expected.kind) << describe(origin, {0, 0, 0}, p);
    ASSERT_EQ(got.volume, expected.volume);
    if (got.kind == PatchSpan::Kind::planar) {
      // Any non-collinear triple will do; it must really be one.
      ASSERT_NE(testing::patch_shape_oracle(p), PatchShape::skew);
    }
  }
}

/// CCD side patches: corners v(t) - f(t) sharing points, with static points making
/// parallelograms and repeated corners (the span's shortcuts). Checked exactly in mpq.
TEST(PatchSpan, FromOffsetsIsExactOnCcdStyleCorners) {
  Rng rng = testing::seeded_engine("patch-frame-ccd");
  using Q = std::array<mpq_class, 3>;
  auto exact = [](const kernel::Offset& o) {
    return Q{mpq_class(o.head(0)) - o.tail(0), mpq_class(o.head(1)) - o.tail(1),
             mpq_class(o.head(2)) - o.tail(2)};
  };
  auto sub = [](const Q& a, const Q& b) { return Q{a[0] - b[0], a[1] - b[1], a[2] - b[2]}; };
  auto cross = [](const Q& a, const Q& b) {
    return Q{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
  };
  auto is_zero = [](const Q& a) { return a[0] == 0 && a[1] == 0 && a[2] == 0; };
  int kinds[3] = {};
  for (int i = 0; i < 20000; ++i) {
    auto point = [&] {
      return i % 2 ? testing::integer_point(rng, 2) : testing::random_point(rng);
    };
    const Point3 v0 = point(), f0 = point(), g0 = point();
    const Point3 v1 = i % 3 == 0 ? v0 : point();  // static vertex a third of the time
    const Point3 f1 = i % 4 < 2 ? f0 : point();   // static edge half of the time
    const Point3 g1 = i % 4 < 2 ? g0 : (i % 5 == 0 ? f1 : point());
    // Side patch over the edge (f, g): p00 = v0 - f0, p10 = v1 - f1, p11 = v1 - g1, p01 = v0 - g0.
    const kernel::Offsets<4> a{kernel::Offset::between(f0, v0), kernel::Offset::between(f1, v1),
                               kernel::Offset::between(g0, v0), kernel::Offset::between(g1, v1)};
    const PatchSpan span = internal::patch_span_from_offsets(kernel::ExactSigns{}, a);
    ++kinds[static_cast<int>(span.kind)];
    std::array<Q, 4> c{exact(a[0]), exact(a[1]), exact(a[2]), exact(a[3])};
    const Q n012 = cross(sub(c[1], c[0]), sub(c[2], c[0]));
    const mpq_class volume = n012[0] * (c[3][0] - c[0][0]) + n012[1] * (c[3][1] - c[0][1]) +
                             n012[2] * (c[3][2] - c[0][2]);
    ASSERT_EQ(span.volume, sign_of(sgn(volume)));
    bool all_collinear = true;
    for (const auto& t : internal::kFaceTriples) {
      all_collinear &= is_zero(cross(sub(c[t[1]], c[t[0]]), sub(c[t[2]], c[t[0]])));
    }
    switch (span.kind) {
      case PatchSpan::Kind::skew:
        ASSERT_NE(volume, 0);
        break;
      case PatchSpan::Kind::planar: {
        ASSERT_EQ(volume, 0);
        const auto& t = span.plane_triple;
        ASSERT_FALSE(is_zero(cross(sub(c[t[1]], c[t[0]]), sub(c[t[2]], c[t[0]]))));
        break;
      }
      case PatchSpan::Kind::collinear:
        ASSERT_TRUE(all_collinear);
        break;
    }
  }
  for (const int k : kinds)
    EXPECT_GT(k, 500);
}

TEST(PatchSide, AgreesWithOracleOnSkewPatches) {
  // (For a flat patch phi is identically zero on its plane and its sign elsewhere depends
  // on the choice of equation; only skew patches have a canonical side.)
  Rng rng = testing::seeded_engine("patch-side");
  for (int i = 0; i < 10000; ++i) {
    const BilinearPatch p =
        i % 2 ? integer_patch(rng, 2)
              : BilinearPatch{testing::random_point(rng), testing::random_point(rng),
                              testing::random_point(rng), testing::random_point(rng)};
    if (classify_patch(p) != PatchShape::skew) continue;
    const Point3 x =
        i % 2 ? testing::scaled(testing::integer_point(rng, 4), -1) : testing::random_point(rng);
    ASSERT_EQ(patch_side(p, x), testing::patch_side_oracle(p, x));
  }
}

}  // namespace
}  // namespace exactgeo
