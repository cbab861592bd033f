#pragma once

// Values stored in a binary mesh file's bytes (PLY, STL), in either byte order.

#include <algorithm>
#include <array>
#include <bit>
#include <cstring>

namespace exactgeo::mesh::internal {

/// Whether a file's values must be byte-swapped on this host.
constexpr bool swap_needed(bool file_is_big_endian) noexcept {
  return file_is_big_endian != (std::endian::native == std::endian::big);
}

/// The sizeof(T) bytes at `bytes` as a T, reversed first when `swap`.
template <class T>
T load_value(const char* bytes, bool swap) {
  std::array<unsigned char, sizeof(T)> raw;
  std::memcpy(raw.data(), bytes, sizeof(T));
  if (swap) std::reverse(raw.begin(), raw.end());
  return std::bit_cast<T>(raw);
}

}  // namespace exactgeo::mesh::internal
