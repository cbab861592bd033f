// The bounded doubles of minimum separation's fourth stage (bounded_double.hpp): the
// invariant |exact - value| <= error after every operation, against GMP; how much of the
// bound the feature polynomials actually use (the largest error seen, as a fraction of the
// bound); and queries at the knife edge, whose distance at the step's end is within an
// ulp or two of δ, where a bound missing one rounding term certifies a wrong side.

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>

#include "ccd/separation/min_separation_oracle.hpp"
#include "exactgeo/ccd/ccd.hpp"
#include "exactgeo/ccd/separation/internal/bounded_double.hpp"
#include "exactgeo/ccd/separation/internal/features.hpp"
#include "support/generators.hpp"
#include "support/seed.hpp"

namespace exactgeo::ccd {
namespace {

using internal::BoundedDouble;
using testing::Rng;

/// A bounded double and the exact value it stands for, computed side by side.
struct Shadowed {
  BoundedDouble bounded;
  mpq_class exact;

  Shadowed() = default;
  Shadowed(double x) : bounded(x), exact(x) {}  // NOLINT: implicit, as BoundedDouble's
  Shadowed(BoundedDouble b, mpq_class e) : bounded(b), exact(std::move(e)) {}

  /// |exact - value| / error (0 when both are 0; infinite when the invariant fails).
  double used() const {
    const mpq_class off = abs(exact - mpq_class(bounded.value));
    if (off == 0) return 0.0;
    if (bounded.error == 0.0) return INFINITY;
    return mpq_class(off / mpq_class(bounded.error)).get_d();
  }
};

Shadowed operator+(const Shadowed& a, const Shadowed& b) {
  return {a.bounded + b.bounded, a.exact + b.exact};
}
Shadowed operator-(const Shadowed& a, const Shadowed& b) {
  return {a.bounded - b.bounded, a.exact - b.exact};
}
Shadowed operator*(const Shadowed& a, const Shadowed& b) {
  return {a.bounded * b.bounded, a.exact * b.exact};
}

/// A double that rounds when combined: a random significand at exponent e, or, one time
/// in four, a subnormal.
double awkward(Rng& rng, int e) {
  if (testing::uniform_int(rng, 0, 3) == 0) return testing::random_magnitude(rng, -1074, -1023);
  return testing::random_magnitude(rng, e - 2, e + 2);
}

TEST(BoundedDouble, EveryOperationKeepsItsInvariant) {
  Rng rng = testing::seeded_engine("ccd.bounded_double.invariant");
  double largest = 0.0;
  // 20000 at full effort (tests/support/seed.hpp), at least one of each three kinds.
  const auto trials = static_cast<int>(testing::scaled_trials(20000, 3));
  for (int trial = 0; trial < trials; ++trial) {
    const int e = testing::uniform_int(rng, -1000, 1000);
    // Exact doubles, then values that already carry errors, through chains of every
    // operation (sums that cancel included: a - b with a close to b).
    Shadowed a = awkward(rng, e), b = awkward(rng, e), c = awkward(rng, e);
    if (trial % 3 == 0) b = Shadowed(std::nextafter(a.bounded.value, INFINITY) * 0.75);
    const std::array<Shadowed, 9> results{a + b,
                                          a - b,
                                          a * b,
                                          (a - b) * c,
                                          (a * b) - (c * c),
                                          (a + b) * (a - b),
                                          (a - b) - (c - b),
                                          (a * c - b * c) * (a - c),
                                          a * a - b * b};
    for (const Shadowed& r : results) {
      if (!r.bounded.usable()) continue;
      const double used = r.used();
      ASSERT_LE(used, 1.0) << std::hexfloat << "a " << a.bounded.value << " b " << b.bounded.value
                           << " c " << c.bounded.value;
      largest = std::max(largest, used);
    }
  }
  std::printf("[ bound    ] largest error / bound of an operation chain: %.3g\n", largest);
  EXPECT_GT(largest, 0.0);
}

/// The minimum-separation features of random pieces of near-degenerate queries, in
/// bounded doubles beside exact rationals: every coefficient keeps the invariant. The
/// largest fraction of the bound seen is printed (docs/predicates.md quotes it).
TEST(BoundedDouble, FeaturePolynomialsKeepTheInvariant) {
  Rng rng = testing::seeded_engine("ccd.bounded_double.features");
  double largest = 0.0;
  int coefficients = 0;
  for (int trial = 0; trial < 300; ++trial) {
    // Corners around a random centre, spread by factors that are not powers of two, so
    // that every difference rounds; every other trial, the worst rounding: corners 0 and
    // 2 hold values of about 1 and corners 1 and 3 values just under half their ulp, so
    // each difference of the two kinds rounds by almost half an ulp, and the same way.
    const Point3 centre = testing::random_point(rng, testing::uniform(rng, 1.0, 100.0));
    const double spread = testing::uniform(rng, 1e-3, 1.0);
    const bool worst = trial % 4 < 2;
    std::array<internal::Moving<Shadowed>, 4> x;
    for (std::size_t k = 0; k < x.size(); ++k) {
      for (int axis = 0; axis < 3; ++axis) {
        double p0 = centre[axis] + testing::uniform(rng, -spread, spread);
        double p1 = centre[axis] + testing::uniform(rng, -spread, spread);
        if (worst) {
          const double big = testing::uniform(rng, 1.0, 2.0);
          p0 = p1 = k % 2 == 0 ? big : -(0.5 - 0x1p-10) * 0x1p-52;
        }
        x[k][axis] = internal::Homogeneous<Shadowed>::linear(p0, p1);
      }
    }
    const Shadowed delta = testing::uniform(rng, 0.1, 1.0) * (worst ? 1.0 : spread);
    const Shadowed delta2 = delta * delta;
    for (std::size_t i = 0; i < internal::kEdgeEdgeFeatures; ++i) {
      const auto f = trial % 2
                         ? internal::edge_edge_feature(i, x, delta2)
                         : internal::vertex_face_feature(std::min<std::size_t>(i, 6), x, delta2);
      const auto note = [&](const internal::Homogeneous<Shadowed>& p) {
        for (int k = 0; k <= p.degree; ++k) {
          const double used = p.c[k].used();
          ASSERT_LE(used, 1.0) << "feature " << i << " coefficient " << k;
          largest = std::max(largest, used);
          ++coefficients;
        }
      };
      note(f.gap);
      note(f.weight);
      for (int k = 0; k < f.in_feature_count; ++k)
        note(f.in_feature[k]);
    }
  }
  std::printf("[ bound    ] largest error / bound over %d feature coefficients: %.3g\n",
              coefficients, largest);
  EXPECT_GT(coefficients, 10000);
}

/// The knife edge where the bound is used most: a vertex ends its step above the inside
/// of a still triangle at a distance within an ulp of δ, and the triangle's corner a is
/// just under half an ulp of the others' coordinates, so that every difference b - a,
/// c - a, v - a rounds by almost half an ulp, the same way, and the normal's components
/// cancel. The face feature's gap (n.(v - a))^2 - δ^2 n.n decides at the step's end only
/// with a bound that counts every rounding; the answer must be the oracle's on both
/// sides of the edge, with and without a time of impact.
TEST(BoundedDouble, KnifeEdgeHeightsAboveAFace) {
  Rng rng = testing::seeded_engine("ccd.bounded_double.knife_edge");
  int within = 0, apart = 0;
  const double tiny = -(0.5 - 0x1p-10) * 0x1p-52;
  // 150 at full effort (tests/support/seed.hpp); both sides asked of the same share.
  const auto trials = static_cast<int>(testing::scaled_trials(150));
  for (int trial = 0; trial < trials; ++trial) {
    const Point3 a{tiny, tiny, tiny};
    const auto corner = [&] {
      return Point3{testing::uniform(rng, 1.0, 2.0), testing::uniform(rng, 1.0, 2.0),
                    testing::uniform(rng, 1.0, 2.0) * (testing::uniform_int(rng, 0, 1) ? 1 : -1)};
    };
    const Point3 b = corner(), c = corner();
    // n = (b - a) x (c - a) and the height of v above the plane, exactly.
    std::array<mpq_class, 3> e1, e2, n;
    for (int i = 0; i < 3; ++i) {
      e1[i] = mpq_class(b[i]) - mpq_class(a[i]);
      e2[i] = mpq_class(c[i]) - mpq_class(a[i]);
    }
    n = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
         e1[0] * e2[1] - e1[1] * e2[0]};
    const mpq_class nn = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
    const double length = std::sqrt(nn.get_d());
    const double lift = testing::uniform(rng, 0.05, 0.5);
    Point3 v1, v0;
    for (int i = 0; i < 3; ++i) {
      const double centroid = (a[i] + b[i] + c[i]) / 3;
      v1[i] = centroid + lift * n[i].get_d() / length;
      v0[i] = centroid + 4 * n[i].get_d() / length;
    }
    mpq_class height = 0;
    for (int i = 0; i < 3; ++i)
      height += n[i] * (mpq_class(v1[i]) - mpq_class(a[i]));
    const mpq_class d2 = height * height / nn;  // the squared distance at the step's end
    const VertexFaceQuery q{v0, a, b, c, v1, a, b, c};
    double delta = std::sqrt(d2.get_d());
    while (mpq_class(delta) * mpq_class(delta) >= d2)
      delta = std::nextafter(delta, 0.0);
    while (mpq_class(std::nextafter(delta, INFINITY)) * mpq_class(std::nextafter(delta, INFINITY)) <
           d2)
      delta = std::nextafter(delta, INFINITY);
    for (const double d : {delta, std::nextafter(delta, INFINITY)}) {
      const bool expected = testing::min_separation_oracle(q, d).within;
      for (const bool toi : {false, true}) {
        Options o;
        o.min_separation = d;
        if (toi) o.time_of_impact_width = 1e-6;
        const Result r = vertex_face_ccd(q, o);
        ASSERT_EQ(r.collision, expected)
            << std::hexfloat << "b " << b[0] << " " << b[1] << " " << b[2] << ", c " << c[0] << " "
            << c[1] << " " << c[2] << ", v1 " << v1[0] << " " << v1[1] << " " << v1[2] << ", delta "
            << d << ", decided by " << to_string(r.decided_by);
      }
      (expected ? within : apart) += 1;
    }
  }
  EXPECT_GT(within, 100 * trials / 150);
  EXPECT_GT(apart, 100 * trials / 150);
}

}  // namespace
}  // namespace exactgeo::ccd
