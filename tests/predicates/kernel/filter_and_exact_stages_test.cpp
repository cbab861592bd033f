// Soundness of each stage on its own: whenever the filter or the expansion stage answers,
// it agrees with the independent oracle, and each answers where it should.

#include "exactgeo/predicates/kernel/exact_stages.hpp"
#include "exactgeo/predicates/kernel/filter.hpp"

#include <gtest/gtest.h>

#include <cfloat>

#include "support/generators.hpp"
#include "support/rational_oracle.hpp"
#include "support/seed.hpp"

namespace exactgeo::kernel {
namespace {

using testing::Rng;

/// An orient3d case that owns its points (Offsets are views).
struct OrientCase {
  Point3 a, b, c, d;
  Offsets<3> offsets() const {
    return {Offset::between(a, b), Offset::between(a, c), Offset::between(a, d)};
  }
};

struct StageAnswers {
  int filter = 0;
  int expansion = 0;
  int cases = 0;
};

/// Runs both stages on one orient3d case, checks any answer, counts answers.
void check_stages(const Point3& a, const Point3& b, const Point3& c, const Point3& d,
                  StageAnswers& answers) {
  const Sign expected = testing::orient3d_oracle(a, b, c, d);
  const Offsets<3> in{Offset::between(a, b), Offset::between(a, c), Offset::between(a, d)};
  ++answers.cases;
  if (const auto s = filtered_sign<Det3Formula, Grouping::by_axis>(in, 0)) {
    ASSERT_EQ(*s, expected) << "filter";
    ++answers.filter;
  }
  if (const auto s = expansion_sign<Det3Formula>(in, 0)) {
    ASSERT_EQ(*s, expected) << "expansion";
    ++answers.expansion;
  }
  ASSERT_EQ(rational_sign<Det3Formula>(in, 0), expected) << "rational";
}

TEST(SignStages, FilterDecidesNearlyAllRandomInputs) {
  Rng rng = testing::seeded_engine("stages-random");
  StageAnswers answers;
  for (int i = 0; i < 20000; ++i) {
    check_stages(testing::random_point(rng), testing::random_point(rng), testing::random_point(rng),
                 testing::random_point(rng), answers);
  }
  EXPECT_GE(answers.filter, answers.cases * 999 / 1000);
  EXPECT_EQ(answers.expansion, answers.cases);
}

TEST(SignStages, FilterIsSoundOnNearDegenerateInputsAndDefers) {
  Rng rng = testing::seeded_engine("stages-near-degenerate");
  StageAnswers answers;
  for (int i = 0; i < 20000; ++i) {
    const double scale = std::ldexp(1.0, testing::uniform_int(rng, -200, 200));
    const auto [a, b, c, d] = testing::near_coplanar_points(rng, scale, 2);
    check_stages(a, b, c, d, answers);
  }
  // Most near-coplanar cases are beyond the filter: it must leave them undecided, and the
  // expansion stage (inputs well inside the exponent range) must decide every one.
  EXPECT_LT(answers.filter, answers.cases / 2);
  EXPECT_EQ(answers.expansion, answers.cases);
}

TEST(SignStages, FilterCertifiesExactZeroWhenAnAxisVanishes) {
  // All four points in the plane z = 0.3: every z difference is exactly zero.
  const OrientCase flat{{0.1, 0.2, 0.3}, {1.7, -2, 0.3}, {5, 1e-3, 0.3}, {-9, 4, 0.3}};
  EXPECT_EQ((filtered_sign<Det3Formula, Grouping::by_axis>(flat.offsets(), 0)), Sign::zero);
}

TEST(SignStages, FilterDefersOutsideItsGuard) {
  const double big = 0x1p300, tiny = 0x1p-300;
  const OrientCase huge{{0, 0, 0}, {big, 0, 0}, {0, big, 0}, {0, 0, big}};
  EXPECT_FALSE((filtered_sign<Det3Formula, Grouping::by_axis>(huge.offsets(), 0)).has_value());
  const OrientCase small{{0, 0, 0}, {tiny, 0, 0}, {0, tiny, 0}, {0, 0, tiny}};
  EXPECT_FALSE((filtered_sign<Det3Formula, Grouping::by_axis>(small.offsets(), 0)).has_value());
}

TEST(SignStages, ExpansionStageRescalesExtremeInputsExactly) {
  Rng rng = testing::seeded_engine("stages-extreme");
  StageAnswers answers;
  for (int i = 0; i < 5000; ++i) {
    // One binade range per case, anywhere from subnormal to near overflow: always
    // rescalable, so the expansion stage must answer.
    const int lo = testing::uniform_int(rng, -1074, 1000);
    auto p = [&] { return testing::random_magnitude_point(rng, lo, std::min(lo + 20, 1022)); };
    const Point3 a = p(), b = p(), c = p();
    check_stages(a, b, c, testing::rounded_affine(a, b, c, 0.5, 0.25), answers);
  }
  EXPECT_EQ(answers.expansion, answers.cases);
}

TEST(SignStages, ExpansionStageDefersWhenNoScalingIsSafe) {
  // Coordinates spanning 2^-1074 .. 2^1000: no single power of two makes degree-3
  // expansion arithmetic safe. The rational stage decides.
  const double t = 4.9406564584124654e-324;
  const OrientCase wide{{0, 0, 0}, {0x1p1000, t, 0}, {t, 0x1p1000, 0}, {3 * t, t, t}};
  EXPECT_FALSE(expansion_sign<Det3Formula>(wide.offsets(), 0).has_value());
  EXPECT_EQ(rational_sign<Det3Formula>(wide.offsets(), 0), Sign::positive);
}

TEST(ExponentRange, NoScalingForOrdinaryInputs) {
  ExponentRange r;
  for (const double x : {1.0, -3.5, 1e-10, 7e12})
    r.include(x);
  EXPECT_EQ(r.exact_scaling(3), 0);
  EXPECT_EQ(r.exact_scaling(6), 0);
  EXPECT_EQ(ExponentRange{}.exact_scaling(3), 0);  // all zero
}

TEST(ExponentRange, ScalesUpSubnormalsAndDownHugeValues) {
  ExponentRange tiny;
  tiny.include(4.9406564584124654e-324);
  tiny.include(DBL_MIN);
  const auto up = tiny.exact_scaling(3);
  ASSERT_TRUE(up.has_value());
  EXPECT_GT(*up, 0);
  EXPECT_GE(3 * (-1074 + *up), -969);  // the grain condition now holds
  ExponentRange huge;
  huge.include(DBL_MAX);
  const auto down = huge.exact_scaling(3);
  ASSERT_TRUE(down.has_value());
  EXPECT_LT(*down, 0);
  EXPECT_LE(3 * (1024 + 1 + *down) + ExponentRange::kHeadroomBits, 995);
}

}  // namespace
}  // namespace exactgeo::kernel
