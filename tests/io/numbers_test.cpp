// Exact, correctly rounded number parsing and the record format.

#include "exactgeo/io/numbers.hpp"

#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <cstdio>
#include <sstream>

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
