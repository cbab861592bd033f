// Exact-vector inputs (exact_vector.hpp): the rounded value honours the filter's input
// model, and every predicate answers on them exactly as on the same vectors given as
// differences of doubles, checked against the independent rational oracle.

#include "exactgeo/predicates/kernel/exact_vector.hpp"

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <cmath>

#include "exactgeo/predicates/internal/patch_span.hpp"
#include "exactgeo/predicates/internal/ray_patch_core.hpp"
#include "exactgeo/predicates/kernel/exact_stages.hpp"
#include "exactgeo/predicates/kernel/signs.hpp"
#include "support/generators.hpp"
#include "support/rational_oracle.hpp"
#include "support/seed.hpp"

namespace exactgeo {
namespace {

using kernel::ExactVector;
using kernel::Offset;
using testing::random_magnitude;
using testing::Rng;

mpq_class exact_value(const ExactVector::Coordinate& e) {
  mpq_class sum = 0;
  for (int i = 0; i < e.size(); ++i)
    sum += e.data()[i];
  return sum;
}

/// The exact difference head - tail as an exact vector (two components per coordinate).
ExactVector exact_difference(const Point3& head, const Point3& tail) {
  std::array<ExactVector::Coordinate, 3> c;
  for (int axis = 0; axis < 3; ++axis)
    c[axis] = kernel::Expansion<2>::difference(head[axis], tail[axis]);
  return kernel::make_exact_vector(c);
}

TEST(ExactVector, RoundedValueIsWithinTheFilterInputModel) {
  Rng rng = testing::seeded_engine("exact-vector-rounding");
  int multi_component = 0;
  for (int i = 0; i < 20000; ++i) {
    // Sums of up to four doubles whose exponents are spread over a random range: many
    // exact values are not doubles, some cancel exactly, some are near binade edges.
    ExactVector::Coordinate x;
    const int terms = testing::uniform_int(rng, 1, 4);
    const int spread = testing::uniform_int(rng, 0, 200);
    for (int t = 0; t < terms; ++t) {
      const double term = random_magnitude(rng, -spread, 0);
      x = *(x + ExactVector::Coordinate(term)).compress().narrow<ExactVector::kCapacity>();
    }
    if (i % 7 == 0) x = *(x - ExactVector::Coordinate(x.head())).compress().narrow<8>();
    const ExactVector v = kernel::make_exact_vector({x, x, x});
    const mpq_class exact = exact_value(x);
    ASSERT_TRUE(v.filterable);
    ASSERT_EQ(sgn(mpq_class(v.rounded[0])), sgn(exact));
    // |rounded - exact| <= 2^-53 |rounded|
    const mpq_class error = abs(mpq_class(v.rounded[0]) - exact);
    ASSERT_LE(error, abs(mpq_class(std::ldexp(v.rounded[0], -53))))
        << std::hexfloat << v.rounded[0];
    multi_component += x.size() > 1;
  }
  EXPECT_GT(multi_component, 5000);
}

/// Near ties: h + (a half ulp of h) + t with t tiny. The exact value is just above or just
/// below the midpoint between two doubles, and a plain sum from the smallest component up
/// rounds the midpoint to even, off by a little more than half an ulp whenever t points the
/// other way. The rounded value must still be the nearest double: within half an ulp.
TEST(ExactVector, RoundedValueIsNearestAtTies) {
  Rng rng = testing::seeded_engine("exact-vector-ties");
  int corrected = 0;
  for (int i = 0; i < 20000; ++i) {
    const double h = random_magnitude(rng, -300, 300);
    const double half =
        std::ldexp(1.0, std::ilogb(h) - 53) * (testing::uniform_int(rng, 0, 1) ? 1 : -1);
    const double tiny = random_magnitude(rng, std::ilogb(h) - 200, std::ilogb(h) - 60);
    ExactVector::Coordinate x = ExactVector::Coordinate(h);
    for (const double term : {half, tiny})
      x = *(x + ExactVector::Coordinate(term)).compress().narrow<ExactVector::kCapacity>();
    const ExactVector v = kernel::make_exact_vector({x, x, x});
    ASSERT_TRUE(v.filterable);
    const double r = v.rounded[0];
    const mpq_class error = abs(mpq_class(r) - exact_value(x));
    const mpq_class half_ulp = mpq_class(std::ldexp(1.0, std::ilogb(r) - 53));
    ASSERT_LE(error, half_ulp) << std::hexfloat << "h " << h << " half " << half << " tiny " << tiny
                               << ": rounded " << r;
    double plain = 0;  // the plain sum, smallest component first
    for (int k = 0; k < x.size(); ++k)
      plain += x.data()[k];
    corrected += plain != r;
  }
  EXPECT_GT(corrected, 1000);  // the plain sum is off often: the cases reach the edge
}

TEST(ExactVector, ExtremeValues) {
  // Below 2^-1021 every sum of doubles is itself a double (all are multiples of 2^-1074):
  // it compresses to one exact component.
  const ExactVector::Coordinate tiny =
      *(kernel::Expansion<1>(0x1p-1074) + kernel::Expansion<1>(-0x1p-1030)).narrow<8>();
  // Near the top of the range: a quarter ulp below the largest double.
  const ExactVector::Coordinate huge =
      *(kernel::Expansion<1>(0x1.fffffffffffffp1023) + kernel::Expansion<1>(-0x1p969)).narrow<8>();
  const ExactVector v = kernel::make_exact_vector({tiny, huge, {}});
  EXPECT_EQ(v.exact[0].size(), 1);
  EXPECT_EQ(v.rounded[0], -0x1p-1030 + 0x1p-1074);
  EXPECT_EQ(v.exact[1].size(), 2);
  EXPECT_TRUE(v.filterable);
  EXPECT_EQ(v.rounded[1], 0x1.fffffffffffffp1023);
  EXPECT_EQ(v.rounded[2], 0.0);
}

/// Ray vs patch with corners given relative to the ray origin as exact vectors (not
/// rounded differences): the oracle on the original points decides.
void expect_exact_vector_corners_match_oracle(const Point3& o, const Vector3& d,
                                              const BilinearPatch& p) {
  const auto x = internal::tensor_corners(p);
  const std::array<ExactVector, 4> e{exact_difference(x[0], o), exact_difference(x[1], o),
                                     exact_difference(x[2], o), exact_difference(x[3], o)};
  const kernel::Offsets<4> a{Offset::exact(e[0]), Offset::exact(e[1]), Offset::exact(e[2]),
                             Offset::exact(e[3])};
  const Offset direction = Offset::vector(d);
  const RayPatch expected = testing::ray_patch_oracle(o, d, p);
  auto answer = [&](const auto& signs) {
    return internal::ray_patch_parity_offsets(signs, internal::patch_span_from_offsets(signs, a), a,
                                              direction);
  };
  ASSERT_EQ(answer(kernel::ExactSigns{}), expected);
  ASSERT_EQ(answer(kernel::RationalSigns{}), expected);
}

TEST(ExactVector, RayPatchOnExactVectorCornersAgreesWithOracle) {
  Rng rng = testing::seeded_engine("exact-vector-ray-patch");
  for (int i = 0; i < 6000; ++i) {
    BilinearPatch p;
    Point3 o;
    Vector3 d;
    if (i % 3 == 0) {  // generic, origins near the patch, differences not doubles
      p = {testing::random_point(rng), testing::random_point(rng), testing::random_point(rng),
           testing::random_point(rng)};
      o = testing::random_point(rng, 1e-3);
      d = testing::random_point(rng);
    } else {  // dense dyadic: flat, collapsed, rays through edges and corners
      p = {testing::integer_point(rng, 2), testing::integer_point(rng, 2),
           testing::integer_point(rng, 2), testing::integer_point(rng, 2)};
      if (i % 3 == 2) p.p00[2] = p.p10[2] = p.p11[2] = p.p01[2] = 0;
      o = testing::scaled(testing::integer_point(rng, 4), -1);
      d = testing::nonzero_integer_direction(rng, 2);
    }
    if (d == Vector3{0, 0, 0}) continue;
    expect_exact_vector_corners_match_oracle(o, d, p);
  }
}

/// Exact vectors whose coordinates have at most two components are decided by the
/// expansion stage, as differences of two doubles are, with the rational stage's sign;
/// longer ones go to the rational stage. (The ray-patch test above checks signs on exact
/// vectors against the independent oracle.)
TEST(ExactVector, ExpansionStageDecidesShortExactVectors) {
  Rng rng = testing::seeded_engine("exact-vector-expansion-stage");
  int decided = 0;
  for (int i = 0; i < 3000; ++i) {
    // Nearly coplanar: c = a + b up to the last bits, so that the filter would defer.
    const Point3 a = testing::random_point(rng), b = testing::random_point(rng);
    const Point3 shift = testing::random_point(rng, 1e-3);
    const ExactVector va = exact_difference(a, shift), vb = exact_difference(b, shift);
    Point3 sum{};
    for (int k = 0; k < 3; ++k)
      sum[k] = a[k] + b[k];
    const ExactVector vc = exact_difference(sum, shift);
    const kernel::Offsets<3> in{Offset::exact(va), Offset::exact(vb), Offset::exact(vc)};
    const auto by_expansions = kernel::expansion_sign<kernel::Det3Formula>(in, 0);
    ASSERT_TRUE(by_expansions.has_value()) << i;
    EXPECT_EQ(*by_expansions, kernel::rational_sign<kernel::Det3Formula>(in, 0)) << i;
    ++decided;
  }
  EXPECT_EQ(decided, 3000);

  // Three components in a coordinate: decided by four-component expansions (for the
  // tetrahedron volume after narrowing its differences); five components are deferred;
  // the rational stage decides all of them.
  std::array<ExactVector::Coordinate, 3> long_coordinates;
  long_coordinates[0] =
      *(kernel::Expansion<2>::difference(1.0, 0x1p-60) + kernel::Expansion<1>(0x1p-130))
           .template narrow<ExactVector::kCapacity>();
  long_coordinates[1] = kernel::Expansion<2>::difference(2.0, 0.0);
  long_coordinates[2] = kernel::Expansion<2>::difference(3.0, 0.0);
  ASSERT_EQ(long_coordinates[0].size(), 3);
  const ExactVector long_vector = kernel::make_exact_vector(long_coordinates);
  const ExactVector unit_y = exact_difference({0, 1, 0}, {0, 0, 0});
  const ExactVector unit_z = exact_difference({0, 0, 1}, {0, 0, 0});
  const kernel::Offsets<3> in{Offset::exact(long_vector), Offset::exact(unit_y),
                              Offset::exact(unit_z)};
  EXPECT_EQ(kernel::expansion_sign<kernel::Det3Formula>(in, 0), Sign::positive);
  EXPECT_EQ(kernel::rational_sign<kernel::Det3Formula>(in, 0), Sign::positive);
  const ExactVector origin = exact_difference({0, 0, 0}, {0, 0, 0});
  const kernel::Offsets<4> tetrahedron{Offset::exact(origin), Offset::exact(long_vector),
                                       Offset::exact(unit_y), Offset::exact(unit_z)};
  EXPECT_EQ(kernel::expansion_sign<kernel::TetrahedronVolumeFormula>(tetrahedron, 0),
            Sign::positive);
  EXPECT_EQ(kernel::rational_sign<kernel::TetrahedronVolumeFormula>(tetrahedron, 0),
            Sign::positive);

  long_coordinates[0] =
      *(long_coordinates[0] + kernel::Expansion<1>(0x1p-200) + kernel::Expansion<1>(0x1p-270))
           .template narrow<ExactVector::kCapacity>();
  ASSERT_EQ(long_coordinates[0].size(), 5);
  const ExactVector longer_vector = kernel::make_exact_vector(long_coordinates);
  const kernel::Offsets<3> longer{Offset::exact(longer_vector), Offset::exact(unit_y),
                                  Offset::exact(unit_z)};
  EXPECT_FALSE(kernel::expansion_sign<kernel::Det3Formula>(longer, 0).has_value());
  EXPECT_EQ(kernel::rational_sign<kernel::Det3Formula>(longer, 0), Sign::positive);
}

/// An exact vector whose coordinates are sums of `components` doubles spread over
/// `spread` binades around x (nonoverlapping by construction: each next component is
/// below half an ulp of the previous one).
ExactVector long_exact_vector(Rng& rng, const Point3& x, int components) {
  std::array<ExactVector::Coordinate, 3> c;
  for (int k = 0; k < 3; ++k) {
    kernel::Expansion<ExactVector::kCapacity> sum;
    double part = x[k];
    for (int i = 0; i < components && part != 0.0; ++i) {
      sum = *(sum + kernel::Expansion<1>(part)).template narrow<ExactVector::kCapacity>();
      part = std::ldexp(testing::uniform(rng, -1, 1),
                        std::ilogb(part) - 54 - testing::uniform_int(rng, 0, 20));
    }
    c[k] = sum;
  }
  return kernel::make_exact_vector(c);
}

TEST(ExactVector, LongExactVectorsAgreeWithRationals) {
  // det3, cross2, dot3, the triangle normal and the tetrahedron volume of three- and
  // four-component coordinates, nearly degenerate (the third vector is the sum of the
  // first two up to the last components): the expansion stage answers and agrees with
  // the rational stage.
  Rng rng = testing::seeded_engine("exact-vector-long");
  int decided = 0, volumes = 0;
  for (int i = 0; i < 2000; ++i) {
    const int components = testing::uniform_int(rng, 3, 4);
    const Point3 a = testing::random_point(rng), b = testing::random_point(rng);
    Point3 sum{};
    for (int k = 0; k < 3; ++k)
      sum[k] = a[k] + b[k];
    const ExactVector va = long_exact_vector(rng, a, components);
    const ExactVector vb = long_exact_vector(rng, b, components);
    const ExactVector vc = long_exact_vector(rng, sum, components);
    const kernel::Offsets<3> in{Offset::exact(va), Offset::exact(vb), Offset::exact(vc)};
    const auto det = kernel::expansion_sign<kernel::Det3Formula>(in, 0);
    ASSERT_TRUE(det.has_value()) << i;
    EXPECT_EQ(*det, kernel::rational_sign<kernel::Det3Formula>(in, 0)) << i;
    const kernel::Offsets<2> pair{Offset::exact(va), Offset::exact(vc)};
    for (int axis = 0; axis < 3; ++axis) {
      const auto cross = kernel::expansion_sign<kernel::Cross2Formula>(pair, axis);
      ASSERT_TRUE(cross.has_value()) << i;
      EXPECT_EQ(*cross, kernel::rational_sign<kernel::Cross2Formula>(pair, axis)) << i;
    }
    const auto dot = kernel::expansion_sign<kernel::Dot3Formula>(pair, 0);
    ASSERT_TRUE(dot.has_value()) << i;
    EXPECT_EQ(*dot, kernel::rational_sign<kernel::Dot3Formula>(pair, 0)) << i;
    // Four points, the fourth nearly in the plane of the others (vd = va + vb - vc is
    // coplanar with them up to the last components).
    Point3 fourth{};
    for (int k = 0; k < 3; ++k)
      fourth[k] = a[k] + b[k] - 0.5 * sum[k];
    const ExactVector vd = long_exact_vector(rng, fourth, components);
    const kernel::Offsets<4> four{Offset::exact(va), Offset::exact(vb), Offset::exact(vc),
                                  Offset::exact(vd)};
    const auto volume = kernel::expansion_sign<kernel::TetrahedronVolumeFormula>(four, 0);
    if (volume) {  // deferred only when a difference does not narrow to four components
      EXPECT_EQ(*volume, kernel::rational_sign<kernel::TetrahedronVolumeFormula>(four, 0)) << i;
      ++volumes;
    }
    const kernel::Offsets<3> triangle{Offset::exact(va), Offset::exact(vb), Offset::exact(vd)};
    for (int axis = 0; axis < 3; ++axis) {
      const auto normal = kernel::expansion_sign<kernel::TriangleNormalFormula>(triangle, axis);
      ASSERT_TRUE(normal.has_value()) << i;
      EXPECT_EQ(*normal, kernel::rational_sign<kernel::TriangleNormalFormula>(triangle, axis)) << i;
    }
    ++decided;
  }
  EXPECT_EQ(decided, 2000);
  EXPECT_GT(volumes, 1000);  // most differences of nearby long coordinates are short
}

TEST(ExactVector, ExactEqualityAndParallelograms) {
  const ExactVector a = exact_difference({1, 2, 3}, {0.1, 0.2, 0.3});
  const ExactVector b = exact_difference({1, 2, 3}, {0.1, 0.2, 0.3});
  const ExactVector c = exact_difference({1, 2, 3}, {0.1, 0.2, 0x1.3333333333334p-2});
  EXPECT_TRUE(Offset::exact(a).same_points_as(Offset::exact(b)));
  EXPECT_FALSE(Offset::exact(a).same_points_as(Offset::exact(c)));
  // x1 - x0 == x3 - x2 with x_i exact differences that are not doubles.
  const ExactVector x0 = exact_difference({1, 0, 0}, {0.1, 0, 0});
  const ExactVector x1 = exact_difference({1, 1, 0}, {0.1, 0, 0});
  const ExactVector x2 = exact_difference({1, 0, 1}, {0.1, 0, 0});
  const ExactVector x3 = exact_difference({1, 1, 1}, {0.1, 0, 0});
  const kernel::Offsets<4> square{Offset::exact(x0), Offset::exact(x1), Offset::exact(x2),
                                  Offset::exact(x3)};
  EXPECT_TRUE(internal::certainly_parallelogram(square));
  const kernel::Offsets<4> skewed{Offset::exact(x0), Offset::exact(x1), Offset::exact(x2),
                                  Offset::exact(c)};
  EXPECT_FALSE(internal::certainly_parallelogram(skewed));
}

}  // namespace
}  // namespace exactgeo
