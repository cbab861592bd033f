// Exact, correctly rounded number parsing and the record format.

#include "exactgeo/io/numbers.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cerrno>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <string_view>

#include "exactgeo/io/input_error.hpp"
#include "support/generators.hpp"
#include "support/seed.hpp"

namespace exactgeo::io {
namespace {

double parsed(std::string_view token) {
  std::string error;
  const auto x = parse_number(token, error);
  EXPECT_TRUE(x.has_value()) << token << ": " << error;
  return x.value_or(NAN);
}

bool rejected(std::string_view token) {
  std::string error;
  const bool no = !parse_number(token, error).has_value();
  if (no) {
    EXPECT_FALSE(error.empty());
  }
  return no;
}

TEST(ParseNumber, DecimalIsCorrectlyRounded) {
  EXPECT_EQ(parsed("0.1"), 0x1.999999999999ap-4);
  EXPECT_EQ(parsed("-2.5e-3"), -2.5e-3);
  EXPECT_EQ(parsed("+7"), 7.0);
  EXPECT_EQ(parsed(".5"), 0.5);
  EXPECT_EQ(parsed("5."), 5.0);
  // Halfway between 1 and the next double: ties to even (down).
  EXPECT_EQ(parsed("1.00000000000000011102230246251565404236316680908203125"), 1.0);
  // Just above halfway: up.
  EXPECT_EQ(parsed("1.00000000000000011102230246251565404236316680908203126"),
            std::nextafter(1.0, 2.0));
  EXPECT_EQ(parsed("1.7976931348623157e308"), DBL_MAX);
}

TEST(ParseNumber, SubnormalsAndSignedZero) {
  EXPECT_EQ(parsed("4.9406564584124654e-324"), std::nextafter(0.0, 1.0));
  EXPECT_EQ(parsed("2.2250738585072009e-308"), std::nextafter(DBL_MIN, 0.0));
  EXPECT_EQ(parsed("0"), 0.0);
  EXPECT_TRUE(std::signbit(parsed("-0")));
  EXPECT_EQ(parsed("-0x0p+0"), 0.0);
}

TEST(ParseNumber, HexfloatIsExact) {
  EXPECT_EQ(parsed("0x1.8p3"), 12.0);
  EXPECT_EQ(parsed("-0X1.fffffffffffffp+1023"), -DBL_MAX);
  EXPECT_EQ(parsed("0x1p-1074"), std::nextafter(0.0, 1.0));
  EXPECT_EQ(parsed("0x.8p1"), 1.0);
  // A first digit that is a letter, as C's %a may write it.
  EXPECT_EQ(parsed("0xAp-3"), 1.25);
  EXPECT_EQ(parsed("0xcp-3"), 1.5);
  EXPECT_EQ(parsed("0xFFp0"), 255.0);
  EXPECT_EQ(parsed("-0xa.8P0"), -10.5);
  EXPECT_EQ(parsed("0xAbCdEf"), 11259375.0);
  EXPECT_EQ(parsed("0xf.ffffffffffff8p+1020"), DBL_MAX);
}

/// Random tokens of the whole grammar (sign, decimal or hexadecimal digits of either case,
/// with or without a point, an exponent of either case and sign), against glibc's strtod,
/// which rounds correctly: the same double wherever the value is in the double range.
TEST(ParseNumber, GrammarAgreesWithACorrectlyRoundedReference) {
  testing::Rng rng = testing::seeded_engine("parse-grammar");
  const auto pick = [&](std::string_view from) {
    return from[static_cast<std::size_t>(testing::uniform_int(rng, 0, int(from.size()) - 1))];
  };
  int compared = 0;
  for (int i = 0; i < 40000; ++i) {
    const bool hex = i % 2 == 1;
    std::string token;
    if (testing::uniform_int(rng, 0, 2) == 0) token += pick("+-");
    if (hex) token += testing::uniform_int(rng, 0, 1) ? "0x" : "0X";
    const std::string_view digits = hex ? "0123456789abcdefABCDEF" : "0123456789";
    const int before = testing::uniform_int(rng, 0, 25), after = testing::uniform_int(rng, 0, 25);
    for (int k = 0; k < before; ++k)
      token += pick(digits);
    if (after > 0 || testing::uniform_int(rng, 0, 3) == 0) token += '.';
    for (int k = 0; k < after; ++k)
      token += pick(digits);
    if (before + after == 0) token += pick(digits);
    if (hex || testing::uniform_int(rng, 0, 1)) {
      token += hex ? pick("pP") : pick("eE");
      if (testing::uniform_int(rng, 0, 1)) token += pick("+-");
      token += std::to_string(testing::uniform_int(rng, 0, hex ? 1000 : 300));
    }
    errno = 0;
    char* end = nullptr;
    const double reference = std::strtod(token.c_str(), &end);
    ASSERT_EQ(end, token.c_str() + token.size()) << token;  // the grammar is strtod's
    std::string error;
    const auto x = parse_number(token, error);
    if (errno == ERANGE && (std::isinf(reference) || reference == 0.0)) {
      EXPECT_FALSE(x) << token << " is beyond the double range";
      continue;
    }
    ASSERT_TRUE(x) << token << ": " << error;
    EXPECT_EQ(std::bit_cast<std::uint64_t>(*x), std::bit_cast<std::uint64_t>(reference))
        << token << std::hexfloat << ": " << *x << " against " << reference;
    ++compared;
  }
  EXPECT_GT(compared, 30000);
}

TEST(ParseNumber, RoundTripsEveryPrintedDouble) {
  testing::Rng rng = testing::seeded_engine("parse-round-trip");
  for (int i = 0; i < 20000; ++i) {
    const double x = testing::random_magnitude(rng, -1074, 1023);
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.17g", x);
    ASSERT_EQ(parsed(buf), x) << buf;
    std::snprintf(buf, sizeof buf, "%a", x);
    ASSERT_EQ(parsed(buf), x) << buf;
  }
}

TEST(ParseNumber, RejectsWhatIsNotOneFiniteDouble) {
  for (const char* bad :
       {"",      "+",      "-",      "abc",       "1e",   "1e+", "1.2.3", "--1",      "+-1",
        "0x",    "0xg",    "1x",     "inf",       "-inf", "nan", "NaN",   "infinity", "0x1p",
        "1e400", "-1e400", "1e-400", "0x1p-1080", "1 2",  "1,",  "١"}) {
    EXPECT_TRUE(rejected(bad)) << bad;
  }
}

TEST(ParseNumber, OneSignAtMostInEveryPart) {
  // A sign before another is refused in the significand and in the exponent, for decimal
  // and hexadecimal literals: from_chars must never see a second one.
  for (const char* body : {"5", "1.5e3", "0x1.8p3", ".5", "7e-2"}) {
    EXPECT_EQ(parsed(std::string("+") + body), parsed(body)) << body;
    EXPECT_EQ(parsed(std::string("-") + body), -parsed(body)) << body;
    for (const char* two : {"+-", "-+", "++", "--"}) {
      EXPECT_TRUE(rejected(std::string(two) + body)) << two << body;
    }
  }
  for (const char* bad :
       {"1e+-5", "1e-+5", "1e--5", "1e++5", "0x1p+-3", "0x-1p3", "-0x-1", "0x+1", "+0x-1p3"}) {
    EXPECT_TRUE(rejected(bad)) << bad;
  }
}

TEST(IsNumberLiteral, TheFormWhateverTheRange) {
  for (const char* literal :
       {"1", "-1.5e-3", "0x1.8p3", "1e400", "-1e400", "1e-400", "0x1p-1080", "+.5", "5."}) {
    EXPECT_TRUE(is_number_literal(literal)) << literal;
  }
  for (const char* bad :
       {"", "+", "-", "+-1", "--1e400", "nan", "inf", "1e", "0x", "1,5", "1 2", "a"}) {
    EXPECT_FALSE(is_number_literal(bad)) << bad;
  }
}

TEST(SplitFields, SpacesCommasAndComments) {
  using V = std::vector<std::string_view>;
  EXPECT_EQ(split_fields("1 2\t3"), (V{"1", "2", "3"}));
  EXPECT_EQ(split_fields("1,2 , 3,  4"), (V{"1", "2", "3", "4"}));
  EXPECT_EQ(split_fields("  # only a comment"), V{});
  EXPECT_EQ(split_fields("1 2 # and a comment, with 3 4"), (V{"1", "2"}));
  EXPECT_EQ(split_fields("1,,2"), (V{"1", "", "2"}));
  EXPECT_EQ(split_fields(",1"), (V{"", "1"}));
  EXPECT_EQ(split_fields("1,"), (V{"1", ""}));
  EXPECT_EQ(split_fields("1 2\r"), (V{"1", "2"}));
}

TEST(RecordReader, SkipsBlankAndCommentLinesAndCountsLines) {
  std::istringstream in("# header\n\n1 2 3\n   \n4,5,6 # tail\n");
  RecordReader reader(in, "points.txt");
  auto r = reader.next();
  ASSERT_TRUE(r);
  EXPECT_EQ(*r, (std::vector<double>{1, 2, 3}));
  EXPECT_EQ(reader.line_number(), 3u);
  r = reader.next();
  ASSERT_TRUE(r);
  EXPECT_EQ(*r, (std::vector<double>{4, 5, 6}));
  EXPECT_EQ(reader.line_number(), 5u);
  EXPECT_FALSE(reader.next());
}

TEST(RecordReader, ErrorsNameSourceLineAndField) {
  std::istringstream in("1 2 3\n4 five 6\n");
  RecordReader reader(in, "points.txt");
  ASSERT_TRUE(reader.next());
  try {
    reader.next();
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "points.txt:2: field 2: 'five' is not a number");
  }
  std::istringstream with_nul(std::string("1 2\0 3\n", 7));
  RecordReader binary(with_nul, "b");
  EXPECT_THROW(binary.next(), InputError);
}

}  // namespace
}  // namespace exactgeo::io
