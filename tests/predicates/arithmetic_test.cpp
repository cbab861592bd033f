// The names of the arithmetics: every enumerator has one, parsing gives it back, and any
// other string is refused rather than read as the nearest name.

#include "exactgeo/predicates/arithmetic.hpp"

#include <gtest/gtest.h>

#include <string_view>

namespace exactgeo {
namespace {

constexpr Arithmetic kEvery[] = {Arithmetic::exact, Arithmetic::plain_double, Arithmetic::rational};

TEST(Arithmetic, EveryEnumeratorHasItsCommandLineName) {
  EXPECT_EQ(to_string(Arithmetic::exact), "exact");
  EXPECT_EQ(to_string(Arithmetic::plain_double), "double");
  EXPECT_EQ(to_string(Arithmetic::rational), "rational");
}

TEST(Arithmetic, ParseGivesEveryNameBack) {
  for (const Arithmetic a : kEvery)
    EXPECT_EQ(parse_arithmetic(to_string(a)), a);
}

TEST(Arithmetic, ParseRefusesEveryOtherString) {
  for (const std::string_view name :
       {"", "?", "Exact", "EXACT", "exact ", " double", "plain_double", "float", "rationals"}) {
    EXPECT_FALSE(parse_arithmetic(name)) << "'" << name << "'";
  }
}

TEST(Arithmetic, AValueThatIsNoEnumeratorHasNoName) {
  EXPECT_EQ(to_string(static_cast<Arithmetic>(3)), "?");
}

}  // namespace
}  // namespace exactgeo
