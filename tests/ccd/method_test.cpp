// The names of the CCD methods: every enumerator has one, parsing gives it back, any other
// string is refused, and the names shared with Arithmetic are Arithmetic's.

#include "exactgeo/ccd/ccd.hpp"

#include <gtest/gtest.h>

#include <string_view>

#include "exactgeo/predicates/arithmetic.hpp"

namespace exactgeo::ccd {
namespace {

constexpr Method kEvery[] = {Method::exact, Method::parity, Method::plain_double, Method::rational,
                             Method::cubic};

TEST(Method, EveryEnumeratorHasItsCommandLineName) {
  EXPECT_EQ(to_string(Method::exact), "exact");
  EXPECT_EQ(to_string(Method::parity), "parity");
  EXPECT_EQ(to_string(Method::plain_double), "double");
  EXPECT_EQ(to_string(Method::rational), "rational");
  EXPECT_EQ(to_string(Method::cubic), "cubic");
}

TEST(Method, ParseGivesEveryNameBack) {
  for (const Method m : kEvery)
    EXPECT_EQ(parse_method(to_string(m)), m);
}

TEST(Method, ParseRefusesEveryOtherString) {
  for (const std::string_view name :
       {"", "?", "Exact", "PARITY", "exact ", " cubic", "plain_double", "float", "rationals"}) {
    EXPECT_FALSE(parse_method(name)) << "'" << name << "'";
  }
}

TEST(Method, AValueThatIsNoEnumeratorHasNoName) {
  EXPECT_EQ(to_string(static_cast<Method>(5)), "?");
}

TEST(Method, SharesArithmeticsNames) {
  EXPECT_EQ(to_string(Method::exact), to_string(Arithmetic::exact));
  EXPECT_EQ(to_string(Method::plain_double), to_string(Arithmetic::plain_double));
  EXPECT_EQ(to_string(Method::rational), to_string(Arithmetic::rational));
}

}  // namespace
}  // namespace exactgeo::ccd
