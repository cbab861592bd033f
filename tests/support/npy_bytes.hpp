#pragma once

// Binary point files written byte by byte, so the tests need no numpy: raw float64 in
// either byte order, and .npy files with the header np.save writes (or any other dict, to
// test what the reader refuses).

#include <array>
#include <bit>
#include <cstdint>
#include <string>
#include <vector>

namespace exactgeo::testing {

/// Each coordinate's 8 bytes, little-endian unless `big_endian`.
inline std::string float64_bytes(const std::vector<std::array<double, 3>>& points,
                                 bool big_endian = false) {
  std::string bytes;
  bytes.reserve(points.size() * 24);
  for (const auto& p : points) {
    for (const double x : p) {
      const auto bits = std::bit_cast<std::uint64_t>(x);
      for (int i = 0; i < 8; ++i) {
        const int shift = 8 * (big_endian ? 7 - i : i);
        bytes.push_back(static_cast<char>((bits >> shift) & 0xff));
      }
    }
  }
  return bytes;
}

/// The magic string, format version `major`.0, the length and `dict`, padded with spaces
/// to a multiple of 64 bytes and ended by '\n', as np.save writes it.
inline std::string npy_header(const std::string& dict, int major = 1) {
  const std::size_t preamble = major == 1 ? 10 : 12;
  std::string text = dict;
  text.append((64 - (preamble + text.size() + 1) % 64) % 64, ' ');
  text.push_back('\n');
  std::string bytes = "\x93NUMPY";
  bytes.push_back(static_cast<char>(major));
  bytes.push_back('\0');
  for (std::size_t i = 8; i < preamble; ++i) {
    bytes.push_back(static_cast<char>((text.size() >> (8 * (i - 8))) & 0xff));
  }
  return bytes + text;
}

/// The dict np.save writes for a float64 (n, 3) array.
inline std::string npy_points_dict(std::size_t n, bool big_endian = false) {
  return std::string("{'descr': '") + (big_endian ? ">f8" : "<f8") +
         "', 'fortran_order': False, 'shape': (" + std::to_string(n) + ", 3), }";
}

/// A whole .npy file of `points`.
inline std::string npy_file(const std::vector<std::array<double, 3>>& points, int major = 1,
                            bool big_endian = false) {
  return npy_header(npy_points_dict(points.size(), big_endian), major) +
         float64_bytes(points, big_endian);
}

}  // namespace exactgeo::testing
