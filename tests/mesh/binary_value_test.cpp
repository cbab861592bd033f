// Values in a binary file's bytes (binary_value.hpp, internal): the bytes of a float,
// a double and integers written out by hand in both byte orders (as PLY and STL files hold
// them) read back as those values on this host, and a swap is needed exactly when the
// file's byte order is not the host's.

#include "../../mesh/src/binary_value.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <string>

namespace exactgeo::mesh::internal {
namespace {

TEST(BinaryValue, SwapOnlyWhenTheByteOrdersDiffer) {
  const bool host_big = std::endian::native == std::endian::big;
  EXPECT_EQ(swap_needed(true), !host_big);
  EXPECT_EQ(swap_needed(false), host_big);
}

TEST(BinaryValue, LiteralBytesInEitherOrderReadAsTheirValues) {
  struct Case {
    std::string little, big;
  };
  // 1.0f = 0x3f800000; 0.1 = 0x3fb999999999999a; -2 as int16 = 0xfffe; 258 as uint32.
  const Case one_f{std::string("\x00\x00\x80\x3f", 4), std::string("\x3f\x80\x00\x00", 4)};
  const Case tenth{std::string("\x9a\x99\x99\x99\x99\x99\xb9\x3f", 8),
                   std::string("\x3f\xb9\x99\x99\x99\x99\x99\x9a", 8)};
  const Case minus_two{std::string("\xfe\xff", 2), std::string("\xff\xfe", 2)};
  const Case n258{std::string("\x02\x01\x00\x00", 4), std::string("\x00\x00\x01\x02", 4)};
  for (const bool big : {false, true}) {
    const auto bytes = [big](const Case& c) { return (big ? c.big : c.little).data(); };
    const bool swap = swap_needed(big);
    EXPECT_EQ(load_value<float>(bytes(one_f), swap), 1.0f);
    EXPECT_EQ(load_value<double>(bytes(tenth), swap), 0.1);
    EXPECT_EQ(load_value<std::int16_t>(bytes(minus_two), swap), -2);
    EXPECT_EQ(load_value<std::uint16_t>(bytes(minus_two), swap), 0xfffe);
    EXPECT_EQ(load_value<std::uint32_t>(bytes(n258), swap), 258u);
  }
}

}  // namespace
}  // namespace exactgeo::mesh::internal
