// The culling's exact dot product (expansion_dot) and the sign it gives (dot_sign) against
// GMP: either undecided or exact, at every magnitude from subnormal to near DBL_MAX,
// including the factors whose Dekker split would overflow.

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <optional>

#include "exactgeo/ccd/internal/culling.hpp"
#include "support/generators.hpp"
#include "support/seed.hpp"

namespace exactgeo::ccd {
namespace {

/// n . (to - from), exactly.
mpq_class exact_dot(const Point3& from, const Point3& to, const Vector3& n) {
  mpq_class sum = 0;
  for (int i = 0; i < 3; ++i)
    sum += mpq_class(n[i]) * (mpq_class(to[i]) - mpq_class(from[i]));
  return sum;
}

Sign sign_of(const mpq_class& x) {
  return x > 0 ? Sign::positive : x < 0 ? Sign::negative : Sign::zero;
}

/// Asserts that expansion_dot is undecided or exact, and dot_sign undecided or right.
/// Returns whether expansion_dot decided.
bool expect_exact_or_undecided(const Point3& from, const Point3& to, const Vector3& n) {
  const kernel::Offset p = kernel::Offset::between(from, to);
  const mpq_class exact = exact_dot(from, to, n);
  char where[256];
  std::snprintf(where, sizeof where, "from (%a, %a, %a) to (%a, %a, %a), n (%a, %a, %a)", from[0],
                from[1], from[2], to[0], to[1], to[2], n[0], n[1], n[2]);
  if (const auto s = internal::dot_sign(p, n)) {
    EXPECT_EQ(*s, sign_of(exact)) << where;
  }
  const auto value = internal::expansion_dot(p, n);
  if (!value) return false;
  mpq_class sum = 0;
  for (int i = 0; i < value->size(); ++i) {
    const double c = value->data()[i];
    EXPECT_TRUE(std::isfinite(c)) << where;
    if (!std::isfinite(c)) return true;
    sum += mpq_class(c);
  }
  EXPECT_EQ(sum, exact) << where;
  return true;
}

TEST(Culling, ExpansionDotIsExactOrUndecidedAtEveryMagnitude) {
  auto rng = testing::seeded_engine("ccd.culling.expansion_dot");
  int decided = 0, undecided = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    // Both factors anywhere in the double range, or near magnitude 1 (mostly decided).
    const int spread = trial % 3 == 0 ? 4 : 1023;
    Point3 from = testing::random_magnitude_point(rng, -spread - (spread > 4 ? 51 : 0), spread);
    Point3 to = testing::random_magnitude_point(rng, -spread - (spread > 4 ? 51 : 0), spread);
    Vector3 n = testing::random_magnitude_point(rng, -spread - (spread > 4 ? 51 : 0), spread);
    if (trial % 5 == 1) from = {0, 0, 0};                  // a plain vector
    if (trial % 7 == 2) n[trial % 3] = 0.0;                // a zero component
    if (trial % 11 == 3) to[trial % 3] = from[trial % 3];  // a zero difference
    (expect_exact_or_undecided(from, to, n) ? decided : undecided) += 1;
  }
  EXPECT_GT(decided, 5000);
  EXPECT_GT(undecided, 1000);
}

TEST(Culling, ExpansionDotRefusesFactorsWhoseSplitOverflows) {
  // 2^1000 times 2^-100 is a fine product, but Dekker's split of 2^1000 overflows: the
  // dot product must be undecided, not a sum of NaNs.
  const Point3 origin{0, 0, 0}, huge_x{0x1.8p1000, 1, 1}, small_y{1, 0x1p-100, 1};
  EXPECT_FALSE(
      internal::expansion_dot(kernel::Offset::between(origin, huge_x), Vector3{0x1.8p-100, 1, 1}));
  EXPECT_FALSE(
      internal::expansion_dot(kernel::Offset::between(origin, small_y), Vector3{1, 0x1.8p999, 1}));
  // Just inside the ranges: exact.
  EXPECT_TRUE(
      expect_exact_or_undecided({0, 0, 0}, {0x1.fffffffffffffp995, 1, 1}, {0x1p-100, 1, 1}));
}

}  // namespace
}  // namespace exactgeo::ccd
