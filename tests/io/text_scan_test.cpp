// Scanning mesh text: integers with at most one sign, UTF-16 text and its cut ends, lines.

#include "exactgeo/io/text_scan.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <limits>
#include <random>
#include <string>
#include <string_view>

#include "exactgeo/io/input_error.hpp"
#include "support/seed.hpp"

namespace exactgeo::io {
namespace {

std::optional<std::int64_t> integer(std::string_view token) {
  std::string error;
  const auto n = parse_integer(token, error);
  if (!n) {
    EXPECT_FALSE(error.empty()) << token;
  }
  return n;
}

TEST(ParseInteger, OneSignAtMost) {
  EXPECT_EQ(integer("12"), 12);
  EXPECT_EQ(integer("+12"), 12);
  EXPECT_EQ(integer("-12"), -12);
  EXPECT_EQ(integer("-0"), 0);
  EXPECT_EQ(integer("007"), 7);
  for (const char* bad : {"+-1", "-+1", "++1", "--1", "+-0", "-", "+", "", " 1", "1 ", "1.0", "1e3",
                          "0x10", "- 1", "+ 1", "1-", "1+", "١"}) {
    EXPECT_FALSE(integer(bad).has_value()) << bad;
  }
}

TEST(ParseInteger, EveryTwoSignPrefixIsRefusedAtEveryMagnitude) {
  std::mt19937_64 rng = testing::seeded_engine("ParseInteger.two_signs");
  std::uniform_int_distribution<std::int64_t> any(std::numeric_limits<std::int64_t>::min(),
                                                  std::numeric_limits<std::int64_t>::max());
  for (int trial = 0; trial < 2000; ++trial) {
    const std::int64_t value =
        trial < 3 ? std::numeric_limits<std::int64_t>::max() - trial : any(rng);
    const std::uint64_t magnitude =
        value < 0 ? 0 - static_cast<std::uint64_t>(value) : static_cast<std::uint64_t>(value);
    const std::string digits = std::to_string(magnitude);
    // One sign, as written, reads back; a sign before another never does.
    EXPECT_EQ(integer(std::to_string(value)), value);
    if (value >= 0) {
      EXPECT_EQ(integer("+" + digits), value);
    }
    for (const char* two : {"+-", "-+", "++", "--"}) {
      EXPECT_FALSE(integer(two + digits).has_value()) << two << digits;
    }
  }
}

TEST(ParseInteger, TheInt64RangeExactly) {
  EXPECT_EQ(integer("9223372036854775807"), std::numeric_limits<std::int64_t>::max());
  EXPECT_EQ(integer("-9223372036854775808"), std::numeric_limits<std::int64_t>::min());
  EXPECT_FALSE(integer("9223372036854775808").has_value());
  EXPECT_FALSE(integer("-9223372036854775809").has_value());
  EXPECT_FALSE(integer("18446744073709551616").has_value());
  std::string error;
  (void)parse_integer("99999999999999999999999", error);
  EXPECT_NE(error.find("too large"), std::string::npos) << error;
}

/// "text" as UTF-16 with a byte order mark, in either byte order.
std::string utf16(std::string_view text, bool big_endian) {
  std::string out = big_endian ? "\xFE\xFF" : "\xFF\xFE";
  for (const char c : text) {
    if (big_endian) out.push_back('\0');
    out.push_back(c);
    if (!big_endian) out.push_back('\0');
  }
  return out;
}

TEST(Utf16, EvenTextIsReadInBothByteOrders) {
  for (const bool big : {false, true}) {
    const auto text = utf16_as_utf8(utf16("v 1 2 3\nf 1 2 3\n", big), "t.obj");
    ASSERT_TRUE(text.has_value());
    EXPECT_EQ(*text, "v 1 2 3\nf 1 2 3\n");
  }
  EXPECT_FALSE(utf16_as_utf8("v 1 2 3\n", "t.obj").has_value());  // not UTF-16
}

TEST(Utf16, AnOddByteCountIsACutFileAtEveryLength) {
  // Every cut of a UTF-16 text inside a character, in both byte orders, is refused naming
  // the file; every cut between characters reads as the characters before it.
  const std::string_view text = "OFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n";
  for (const bool big : {false, true}) {
    const std::string whole = utf16(text, big);
    for (std::size_t size = 3; size <= whole.size(); ++size) {
      const std::string cut = whole.substr(0, size);
      if (size % 2 == 0) {
        const auto read = utf16_as_utf8(cut, "cut.off");
        ASSERT_TRUE(read.has_value());
        EXPECT_EQ(*read, text.substr(0, size / 2 - 1));
        continue;
      }
      try {
        (void)utf16_as_utf8(cut, "cut.off");
        ADD_FAILURE() << "a cut at " << size << " bytes was read";
      } catch (const InputError& e) {
        const std::string message = e.what();
        EXPECT_EQ(message.rfind("cut.off: UTF-16", 0), 0u) << message;
        EXPECT_NE(message.find(std::to_string(size)), std::string::npos) << message;
        EXPECT_NE(message.find(big ? "big-endian" : "little-endian"), std::string::npos);
      }
    }
  }
}

TEST(LineCursor, NumbersLinesAndDropsOneCarriageReturn) {
  LineCursor lines("a\r\nb\n\nc\r\r\n");
  EXPECT_EQ(lines.next(), "a");
  EXPECT_EQ(lines.next(), "b");
  EXPECT_EQ(lines.next(), "");
  EXPECT_EQ(lines.next(), "c\r");
  EXPECT_EQ(lines.line_number(), 4u);
  EXPECT_FALSE(lines.next().has_value());
}

}  // namespace
}  // namespace exactgeo::io
