// The ray-independent patch facts for corners given as differences of points (CCD's side
// patches): the parallelogram shortcut may only claim what is exactly true, it must see
// rigid translations (the common case it exists for), and the span must equal the one
// an independent rational volume gives.

#include "exactgeo/predicates/internal/patch_span.hpp"

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>

#include "exactgeo/predicates/kernel/signs.hpp"
#include "support/generators.hpp"
#include "support/seed.hpp"

namespace exactgeo {
namespace {

using kernel::Offset;
using kernel::Offsets;
using testing::Rng;

using ExactPoint = std::array<mpq_class, 3>;

ExactPoint exact_difference(const Offset& o) {
  return {mpq_class(o.head(0)) - o.tail(0), mpq_class(o.head(1)) - o.tail(1),
          mpq_class(o.head(2)) - o.tail(2)};
}

bool oracle_parallelogram(const Offsets<4>& a) {
  const ExactPoint x0 = exact_difference(a[0]), x1 = exact_difference(a[1]),
                   x2 = exact_difference(a[2]), x3 = exact_difference(a[3]);
  for (int k = 0; k < 3; ++k) {
    if (x1[k] - x0[k] != x3[k] - x2[k]) return false;
  }
  return true;
}

int oracle_volume_sign(const Offsets<4>& a) {
  const ExactPoint x0 = exact_difference(a[0]);
  std::array<ExactPoint, 3> e;
  for (int i = 0; i < 3; ++i) {
    const ExactPoint xi = exact_difference(a[i + 1]);
    for (int k = 0; k < 3; ++k)
      e[i][k] = xi[k] - x0[k];
  }
  const mpq_class det = e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) -
                        e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) +
                        e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0]);
  return sgn(det);
}

/// A vertex-face side patch: corners v(t) - f_i(t) for t = 0, 1 and the face's edge f0 f1.
struct SidePatch {
  Point3 v_t0, v_t1, f0_t0, f0_t1, f1_t0, f1_t1;

  Offsets<4> corners() const {  // p00, p10, p01, p11 with u along t
    return {Offset::between(f0_t0, v_t0), Offset::between(f0_t1, v_t1),
            Offset::between(f1_t0, v_t0), Offset::between(f1_t1, v_t1)};
  }
};

/// Coordinates on the grid 2^(k - 20) Z with |x| < 2^(k + 10): sums stay exact, while the
/// differences with a vertex at another magnitude are not doubles.
Point3 grid_point(Rng& rng, int k) {
  return testing::scaled(testing::integer_point(rng, 1 << 30), k - 20);
}

Point3 plus(const Point3& p, const Point3& d) {
  return {p[0] + d[0], p[1] + d[1], p[2] + d[2]};
}

/// The face edge translates by one exact vector, the vertex moves freely at another scale.
SidePatch translating_edge(Rng& rng) {
  const int k = testing::uniform_int(rng, -60, 60);
  const Point3 d = grid_point(rng, k);
  SidePatch p;
  p.v_t0 = testing::random_magnitude_point(rng, k - 40, k + 40);
  p.v_t1 = testing::random_magnitude_point(rng, k - 40, k + 40);
  p.f0_t0 = grid_point(rng, k);
  p.f1_t0 = grid_point(rng, k);
  p.f0_t1 = plus(p.f0_t0, d);
  p.f1_t1 = plus(p.f1_t0, d);
  return p;
}

TEST(PatchSpan, RigidTranslationIsACertainParallelogram) {
  Rng rng = testing::seeded_engine("PatchSpan.RigidTranslation");
  for (int i = 0; i < 2000; ++i) {
    const SidePatch p = translating_edge(rng);
    ASSERT_TRUE(oracle_parallelogram(p.corners()));  // the construction is exact
    EXPECT_TRUE(internal::certainly_parallelogram(p.corners())) << "case " << i;
    const PatchSpan span = internal::patch_span_from_offsets(kernel::ExactSigns{}, p.corners());
    EXPECT_EQ(span.volume, Sign::zero);
    EXPECT_NE(span.kind, PatchSpan::Kind::skew);
  }
}

TEST(PatchSpan, OneUlpFromATranslationIsNotClaimed) {
  Rng rng = testing::seeded_engine("PatchSpan.OneUlp");
  int skew = 0;
  for (int i = 0; i < 2000; ++i) {
    SidePatch p = translating_edge(rng);
    const int axis = testing::uniform_int(rng, 0, 2);
    p.f1_t1 = testing::ulp_step(p.f1_t1, axis, testing::uniform_int(rng, 0, 1) * 2 - 1);
    const Offsets<4> a = p.corners();
    const bool parallelogram = oracle_parallelogram(a);
    if (internal::certainly_parallelogram(a)) {
      EXPECT_TRUE(parallelogram) << "case " << i;
    }
    const PatchSpan span = internal::patch_span_from_offsets(kernel::ExactSigns{}, a);
    const int volume = oracle_volume_sign(a);
    EXPECT_EQ(static_cast<int>(span.volume), volume) << "case " << i;
    EXPECT_EQ(span.kind == PatchSpan::Kind::skew, volume != 0) << "case " << i;
    skew += volume != 0;
  }
  EXPECT_GT(skew, 1000);  // the perturbation does make most patches skew
}

TEST(PatchSpan, OverflowingDisplacements) {
  constexpr double big = std::numeric_limits<double>::max();
  const Point3 v{1.0, 2.0, 3.0};
  const Point3 left{-big, 0.0, 0.0}, right{big, 0.0, 0.0}, up{0.0, 1.0, 0.0};
  // Both edge ends move by 2 big in x, beyond the double range: a parallelogram whose
  // displacements overflow. Claiming it is optional; the span must be exact either way.
  const SidePatch same{v, v, left, right, plus(left, up), plus(right, up)};
  // One end's displacement one ulp shorter: still infinite when rounded, and not a
  // parallelogram, which must never be claimed.
  const Point3 short_of_right{std::nextafter(big, 0.0), 0.0, 0.0};
  const SidePatch shorter{v, v, left, short_of_right, plus(left, up), plus(right, up)};
  EXPECT_TRUE(oracle_parallelogram(same.corners()));
  EXPECT_FALSE(oracle_parallelogram(shorter.corners()));
  EXPECT_FALSE(internal::certainly_parallelogram(shorter.corners()));
  for (const SidePatch& p : {same, shorter}) {
    const PatchSpan span = internal::patch_span_from_offsets(kernel::ExactSigns{}, p.corners());
    EXPECT_EQ(static_cast<int>(span.volume), oracle_volume_sign(p.corners()));
  }
}

}  // namespace
}  // namespace exactgeo
