// Crossing parity over a prepared face set (crossing_parity.hpp): the count along one ray
// and the ray loop, against the independent rational oracles for each face, on random,
// flat, exactly degenerate, one-ulp-off and scaled face sets; and the two ways of
// preparing a face (from points, from offsets) against each other.

#include "exactgeo/predicates/crossing_parity.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <cstdio>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "exactgeo/predicates/kernel/signs.hpp"
#include "exactgeo/predicates/ray_directions.hpp"
#include "support/generators.hpp"
#include "support/hexahedron.hpp"
#include "support/rational_oracle.hpp"
#include "support/seed.hpp"

namespace exactgeo {
namespace {

using kernel::Offset;
using testing::Rng;

/// A face set over its own corner list, prepared with exact signs.
struct FaceSet {
  std::vector<Point3> points;
  std::vector<SurfaceFace> faces;
  std::vector<PatchSpan> spans;

  void prepare() {
    spans.clear();
    for (const SurfaceFace& f : faces)
      spans.push_back(span_of(kernel::ExactSigns{}, f, points));
  }
  PreparedFaces prepared() const { return {faces, spans}; }
};

/// The oracle's answer for one face, counted by orientation.
SignedCrossing oracle_crossing(const FaceSet& set, const SurfaceFace& f, const Point3& origin,
                               const Vector3& direction) {
  const auto& p = set.points;
  const auto& c = f.corners;
  if (f.is_triangle()) {
    return crossing_of(testing::ray_triangle_oracle(origin, direction, p[c[0]], p[c[1]], p[c[2]]));
  }
  // Tensor order back to boundary order: p00 = x0, p10 = x1, p11 = x3, p01 = x2.
  return crossing_of(testing::ray_patch_signed_crossings_oracle(
      origin, direction, {p[c[0]], p[c[1]], p[c[3]], p[c[2]]}));
}

/// The oracle's count along one ray, with the predicate's documented stopping rule: the
/// first face that is degenerate or holds the origin decides.
SignedRayCount oracle_count(const FaceSet& set, const Point3& origin, const Vector3& direction) {
  std::int64_t total = 0;
  for (const SurfaceFace& f : set.faces) {
    const SignedCrossing crossing = oracle_crossing(set, f, origin, direction);
    switch (crossing.kind) {
      case Crossing::none:
        break;
      case Crossing::crossed:
        total += to_int(crossing.sign);
        break;
      case Crossing::origin_on:
        return {RayCount::origin_on_face, 0};
      case Crossing::degenerate:
        return {RayCount::degenerate, 0};
    }
  }
  return {total % 2 == 0 ? RayCount::even : RayCount::odd, total};
}

/// The library's signed count along one ray, checked against its parity count.
SignedRayCount library_count(const FaceSet& set, const Point3& origin, const Vector3& direction) {
  const auto corner = [&](VertexIndex i) { return Offset::between(origin, set.points[i]); };
  const kernel::ExactSigns signs;
  const SignedRayCount count =
      count_signed_crossings(signs, set.prepared(), corner, Offset::vector(direction));
  EXPECT_EQ(count_crossings(signs, set.prepared(), corner, Offset::vector(direction)), count.kind);
  return count;
}

void expect_same_count(const SignedRayCount& library, const SignedRayCount& oracle,
                       const std::string& what) {
  ASSERT_EQ(library.kind, oracle.kind) << what;
  ASSERT_EQ(library.total, oracle.total) << what;
}

std::string describe(const FaceSet& set, const Point3& origin) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "origin (%a,%a,%a); corners:", origin[0], origin[1], origin[2]);
  std::string s = buf;
  for (const Point3& p : set.points) {
    std::snprintf(buf, sizeof buf, " (%a,%a,%a)", p[0], p[1], p[2]);
    s += buf;
  }
  return s;
}

/// Random faces over a few shared corners, some of them flat or exactly degenerate: the
/// corners are small integers (so rays from integer origins along the sequence's
/// directions often meet edges and corners exactly), or random reals.
FaceSet random_face_set(Rng& rng, bool integer_corners) {
  FaceSet set;
  const int n = testing::uniform_int(rng, 4, 7);
  for (int i = 0; i < n; ++i) {
    set.points.push_back(integer_corners ? testing::integer_point(rng, 2)
                                         : testing::random_point(rng, 1.0));
  }
  auto index = [&] { return static_cast<VertexIndex>(testing::uniform_int(rng, 0, n - 1)); };
  const int faces = testing::uniform_int(rng, 1, 4);
  for (int f = 0; f < faces; ++f) {
    if (testing::uniform_int(rng, 0, 2) == 0) {
      set.faces.push_back(SurfaceFace::triangle(index(), index(), index()));
    } else {
      set.faces.push_back(SurfaceFace::patch(index(), index(), index(), index()));
    }
  }
  set.prepare();
  return set;
}

TEST(CrossingParity, OneRayMatchesTheOracleFaceByFace) {
  Rng rng = testing::seeded_engine("CrossingParity.OneRay");
  std::array<int, 4> seen{};
  for (int trial = 0; trial < 3000; ++trial) {
    const bool integer = trial % 2 == 0;
    const FaceSet set = random_face_set(rng, integer);
    const Vector3 direction = ray_direction(static_cast<std::size_t>(trial % 5));
    Point3 origin = integer ? testing::integer_point(rng, 2) : testing::random_point(rng, 1.0);
    if (integer && trial % 4 == 0) {
      // Aimed at a corner or an edge midpoint: origin = target - s direction, exactly
      // (dyadic coordinates), so the ray meets a face's boundary.
      const auto& c = set.faces[0].corners;
      const Point3& a = set.points[c[0]];
      const Point3& b = set.points[c[testing::uniform_int(rng, 0, 1)]];
      const double s = 0.25 * testing::uniform_int(rng, 1, 4);
      for (int i = 0; i < 3; ++i)
        origin[i] = 0.5 * (a[i] + b[i]) - s * direction[i];
    }
    const SignedRayCount expected = oracle_count(set, origin, direction);
    expect_same_count(library_count(set, origin, direction), expected,
                      "trial " + std::to_string(trial) + ": " + describe(set, origin));
    ++seen[static_cast<int>(expected.kind)];
  }
  // The inputs reach every answer, so each path was compared.
  for (int kind = 0; kind < 4; ++kind)
    EXPECT_GT(seen[kind], 20) << "RayCount " << kind;
}

TEST(CrossingParity, ScaledCopiesCountAlike) {
  // Scaling corners and origin by 2^k changes no sign; at extreme k the filters' guards
  // fail and the exact stages (rescaled expansions, rationals) must answer instead.
  Rng rng = testing::seeded_engine("CrossingParity.Scaled");
  for (int trial = 0; trial < 300; ++trial) {
    FaceSet set = random_face_set(rng, false);
    const Point3 origin = testing::random_point(rng, 1.0);
    const Vector3 direction = ray_direction(static_cast<std::size_t>(trial % 3));
    const SignedRayCount expected = oracle_count(set, origin, direction);
    for (const int k : {-900, -500, 300, 900}) {
      FaceSet scaled = set;
      for (Point3& p : scaled.points)
        p = testing::scaled(p, k);
      scaled.prepare();
      expect_same_count(library_count(scaled, testing::scaled(origin, k), direction), expected,
                        "trial " + std::to_string(trial) + ", scale 2^" + std::to_string(k) + ": " +
                            describe(set, origin));
    }
  }
}

TEST(CrossingParity, CandidatesRestrictTheCount) {
  // Two parallel squares z = 0 and z = 1 (as patches); a ray up from below crosses both.
  FaceSet set;
  set.points = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  set.faces = {SurfaceFace::patch(0, 1, 2, 3), SurfaceFace::patch(4, 5, 6, 7)};
  set.prepare();
  const Point3 origin{0.25, 0.375, -1};
  const Vector3 up{0.0625, 0.03125, 1};
  const auto corner = [&](VertexIndex i) { return Offset::between(origin, set.points[i]); };
  const kernel::ExactSigns signs;
  const std::vector<std::size_t> first{0}, both{0, 1}, none{};
  EXPECT_EQ(count_crossings(signs, set.prepared(), first, corner, Offset::vector(up)),
            RayCount::odd);
  EXPECT_EQ(count_crossings(signs, set.prepared(), both, corner, Offset::vector(up)),
            RayCount::even);
  EXPECT_EQ(count_crossings(signs, set.prepared(), none, corner, Offset::vector(up)),
            RayCount::even);
  EXPECT_EQ(count_crossings(signs, set.prepared(), corner, Offset::vector(up)), RayCount::even);
}

/// The unit cube as six quads (tensor order through SurfaceFace::patch).
FaceSet unit_cube() {
  FaceSet cube;
  const auto corners = testing::unit_cube_corners();
  cube.points.assign(corners.begin(), corners.end());
  for (const auto& q : testing::kHexahedronFaces)
    cube.faces.push_back(SurfaceFace::patch(q[0], q[1], q[2], q[3]));
  cube.prepare();
  return cube;
}

std::optional<CrossingParityResult> parity_of(const FaceSet& set, const Point3& origin) {
  const auto corner = [&](VertexIndex i) { return Offset::between(origin, set.points[i]); };
  return crossing_parity(64, [&](std::size_t k) {
    const Vector3 d = ray_direction(k);
    return count_crossings(kernel::ExactSigns{}, set.prepared(), corner, Offset::vector(d));
  });
}

TEST(CrossingParity, RayLoopRecastsUntilAClean) {
  const FaceSet cube = unit_cube();
  const auto centre = parity_of(cube, {0.5, 0.5, 0.5});
  ASSERT_TRUE(centre.has_value());
  EXPECT_EQ(centre->parity, CrossingParity::odd);
  EXPECT_EQ(centre->rays, 1u);

  const auto outside = parity_of(cube, {-1, 0.5, 0.5});
  ASSERT_TRUE(outside.has_value());
  EXPECT_EQ(outside->parity, CrossingParity::even);

  const auto on_face = parity_of(cube, {1, 0.25, 0.75});
  ASSERT_TRUE(on_face.has_value());
  EXPECT_EQ(on_face->parity, CrossingParity::on_surface);

  // Ray 0 from this origin passes exactly through the cube's corner (1, 1, 1), a vertex of
  // three faces: degenerate. Ray 1 is clean; the origin is inside.
  const Vector3 d0 = ray_direction(0);
  const double s = 0.25;  // (1, 1, 1) - s d0, exact: d0 is dyadic
  const Point3 origin{1 - s * d0[0], 1 - s * d0[1], 1 - s * d0[2]};
  ASSERT_EQ(library_count(cube, origin, d0).kind, RayCount::degenerate);
  const auto recast = parity_of(cube, origin);
  ASSERT_TRUE(recast.has_value());
  EXPECT_EQ(recast->parity, CrossingParity::odd);
  EXPECT_EQ(recast->rays, 2u);
}

/// Hexahedra (six quads over eight corners, kHexahedronFaces) put together in one face
/// set; `reversed` ones have their faces' corner order reversed (normals inward).
struct Hexahedra {
  FaceSet set;
  void add(const std::array<Point3, 8>& corners, bool reversed) {
    const auto base = static_cast<VertexIndex>(set.points.size());
    set.points.insert(set.points.end(), corners.begin(), corners.end());
    for (const auto& q : testing::kHexahedronFaces) {
      set.faces.push_back(
          reversed ? SurfaceFace::patch(base + q[0], base + q[3], base + q[2], base + q[1])
                   : SurfaceFace::patch(base + q[0], base + q[1], base + q[2], base + q[3]));
    }
  }
};

/// The winding number of `origin`, casting the sequence's rays from index `first` on.
std::optional<WindingNumberResult> winding_of(const FaceSet& set, const Point3& origin,
                                              std::size_t first) {
  const auto corner = [&](VertexIndex i) { return Offset::between(origin, set.points[i]); };
  return winding_number(64, [&](std::size_t k) {
    const Vector3 d = ray_direction(first + k);
    return count_signed_crossings(kernel::ExactSigns{}, set.prepared(), corner, Offset::vector(d));
  });
}

/// Axis-aligned boxes with small integer bounds that overlap, nest and touch, each
/// outward (+1 inside) or reversed (-1 inside): the winding number of a point is the sum
/// of the signs of the boxes holding it in their interior, the same from every first ray
/// direction; a point on a face has none. Points on a grid of halves (many lie on faces),
/// a quarter of them placed so that ray 0 passes through a box corner (cast again).
TEST(WindingNumber, OverlappingNestedAndReversedBoxes) {
  Rng rng = testing::seeded_engine("WindingNumber.Boxes");
  std::map<std::int64_t, int> seen;
  int recast = 0;
  for (int trial = 0; trial < 300; ++trial) {
    Hexahedra boxes;
    std::vector<std::pair<std::array<Point3, 2>, int>> truth;  // bounds, sign
    const int count = testing::uniform_int(rng, 1, 4);
    for (int b = 0; b < count; ++b) {
      Point3 lo, hi;
      for (int i = 0; i < 3; ++i) {
        lo[i] = testing::uniform_int(rng, -3, 0);
        hi[i] = testing::uniform_int(rng, static_cast<int>(lo[i]) + 2, 3);
      }
      std::array<Point3, 8> corners;
      for (int c = 0; c < 8; ++c) {
        for (int i = 0; i < 3; ++i)
          corners[static_cast<std::size_t>(c)][i] = (c >> i) & 1 ? hi[i] : lo[i];
      }
      const bool reversed = testing::uniform_int(rng, 0, 3) == 0;
      boxes.add(corners, reversed);
      truth.push_back({{lo, hi}, reversed ? -1 : 1});
    }
    boxes.set.prepare();
    for (int q = 0; q < 20; ++q) {
      Point3 origin = testing::scaled(testing::integer_point(rng, 7), -1);
      if (q % 4 == 0) {
        // Ray 0 through a box corner: c - d0 / 2, exact (d0 is dyadic).
        const Vector3 d0 = ray_direction(0);
        const Point3& c = boxes.set.points[static_cast<std::size_t>(
            testing::uniform_int(rng, 0, static_cast<int>(boxes.set.points.size()) - 1))];
        for (int i = 0; i < 3; ++i)
          origin[i] = c[i] - d0[i] / 2;
      }
      bool on_face = false;
      std::int64_t expected = 0;
      for (const auto& [bounds, sign] : truth) {
        bool closed = true, open = true;
        for (int i = 0; i < 3; ++i) {
          closed &= bounds[0][i] <= origin[i] && origin[i] <= bounds[1][i];
          open &= bounds[0][i] < origin[i] && origin[i] < bounds[1][i];
        }
        on_face |= closed && !open;
        expected += open ? sign : 0;
      }
      for (const std::size_t first : {0u, 5u, 11u}) {
        const auto w = winding_of(boxes.set, origin, first);
        ASSERT_TRUE(w.has_value());
        const std::string what = "trial " + std::to_string(trial) + " first ray " +
                                 std::to_string(first) + ": " + describe(boxes.set, origin);
        if (on_face) {
          ASSERT_FALSE(w->winding.has_value()) << what;
        } else {
          ASSERT_EQ(w->winding, expected) << what;
          ++seen[expected];
        }
        recast += w->rays > 1;
      }
    }
  }
  for (const std::int64_t w : {-1, 0, 1, 2})
    EXPECT_GT(seen[w], 50) << "winding " << w;
  EXPECT_GT(recast, 300);  // first rays through corners were cast again
}

/// Twisted hexahedra (every corner moved at random, so that the faces are skew, and the
/// solids fold through themselves and each other) are closed oriented surfaces still:
/// every first ray direction gives the same winding number, which is the oracle's signed
/// count along the ray that decided it, at magnitudes from 2^-1000 to 2^1000.
TEST(WindingNumber, TwistedHexahedraAgreeAcrossRaysAndWithTheOracle) {
  Rng rng = testing::seeded_engine("WindingNumber.Twisted");
  std::map<std::int64_t, int> seen;
  for (int trial = 0; trial < 80; ++trial) {
    Hexahedra solids;
    const int count = testing::uniform_int(rng, 1, 3);
    const int k = trial % 3 == 0 ? 0 : testing::uniform_int(rng, -1000, 1000);
    for (int h = 0; h < count; ++h) {
      std::array<Point3, 8> corners = testing::unit_cube_corners();
      const Point3 shift = testing::random_point(rng, 0.5);
      for (Point3& c : corners) {
        const Point3 jitter = testing::random_point(rng, 0.4);
        for (int i = 0; i < 3; ++i)
          c[i] = 2 * c[i] - 1 + jitter[i] + shift[i];
        c = testing::scaled(c, k);
      }
      solids.add(corners, testing::uniform_int(rng, 0, 3) == 0);
    }
    solids.set.prepare();
    for (int q = 0; q < 6; ++q) {
      const Point3 origin = testing::scaled(testing::random_point(rng, 1.5), k);
      const auto reference = winding_of(solids.set, origin, 0);
      ASSERT_TRUE(reference.has_value() && reference->winding.has_value());
      const SignedRayCount oracle =
          oracle_count(solids.set, origin, ray_direction(reference->rays - 1));
      const std::string what =
          "trial " + std::to_string(trial) + ": " + describe(solids.set, origin);
      ASSERT_EQ(oracle.total, *reference->winding) << what;
      for (const std::size_t first : {3u, 8u}) {
        const auto w = winding_of(solids.set, origin, first);
        ASSERT_TRUE(w.has_value());
        ASSERT_EQ(w->winding, reference->winding) << what << " first ray " << first;
      }
      ++seen[*reference->winding];
    }
  }
  EXPECT_GT(seen[0], 30);
  EXPECT_GT(seen[1] + seen[-1], 30);
  EXPECT_GT(seen[2] + seen[-2] + seen[3] + seen[-3], 5);  // overlaps of like solids
}

TEST(WindingNumber, GivesUpOnlyAfterMaxRays) {
  const auto none = winding_number(3, [](std::size_t) {
    return SignedRayCount{RayCount::degenerate, 0};
  });
  EXPECT_FALSE(none.has_value());
}

TEST(CrossingParity, GivesUpOnlyAfterMaxRays) {
  int cast = 0;
  const auto none = crossing_parity(5, [&](std::size_t) {
    ++cast;
    return RayCount::degenerate;
  });
  EXPECT_FALSE(none.has_value());
  EXPECT_EQ(cast, 5);
}

TEST(CrossingParity, SpansFromPointsAndFromOffsetsAgree) {
  // CCD prepares faces from offsets (corner images, origin 0), meshes from points. On the
  // same corners both must give the same span, for exactly flat, near-flat and skew
  // patches at any magnitude.
  Rng rng = testing::seeded_engine("CrossingParity.Frames");
  const kernel::ExactSigns signs;
  const SurfaceFace face = SurfaceFace::patch(0, 1, 2, 3);
  int flat = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    std::array<Point3, 4> x;
    switch (trial % 4) {
      case 0:  // random: skew
        for (Point3& p : x)
          p = testing::random_point(rng, 1.0);
        break;
      case 1: {  // coplanar up to rounding
        const auto q = testing::near_coplanar_points(rng, 1.0, 2.0);
        x = {q[0], q[1], q[3], q[2]};
        break;
      }
      case 2:  // small integers: exactly flat or collinear shapes are frequent
        for (Point3& p : x)
          p = testing::integer_point(rng, 1);
        break;
      default:  // one ulp off a parallelogram
        x[0] = testing::random_point(rng, 1.0);
        x[1] = testing::random_point(rng, 1.0);
        x[3] = testing::random_point(rng, 1.0);
        for (int i = 0; i < 3; ++i)
          x[2][i] = x[1][i] + (x[3][i] - x[0][i]);
        x[2] = testing::ulp_step(x[2], testing::uniform_int(rng, 0, 2),
                                 testing::uniform_int(rng, -1, 1));
    }
    const int k = testing::uniform_int(rng, -900, 900);
    for (Point3& p : x)
      p = testing::scaled(p, k);
    const PatchSpan from_points = span_of(signs, face, x);
    const auto corner = [&](VertexIndex i) { return Offset::vector(x[i]); };
    const PatchSpan from_offsets = span_of_offsets(signs, face, corner);
    ASSERT_EQ(from_points.kind, from_offsets.kind) << "trial " << trial;
    ASSERT_EQ(from_points.volume, from_offsets.volume) << "trial " << trial;
    // Both spans are the oracle's shape class.
    const PatchShape shape = testing::patch_shape_oracle({x[0], x[1], x[2], x[3]});
    const PatchSpan::Kind expected = shape == PatchShape::skew ? PatchSpan::Kind::skew
                                     : shape == PatchShape::segment || shape == PatchShape::point
                                         ? PatchSpan::Kind::collinear
                                         : PatchSpan::Kind::planar;
    ASSERT_EQ(from_points.kind, expected) << "trial " << trial;
    flat += expected != PatchSpan::Kind::skew;
  }
  EXPECT_GT(flat, 500);
}

}  // namespace
}  // namespace exactgeo
