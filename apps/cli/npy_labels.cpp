#include "cli/npy_labels.hpp"

#include <cstdint>

#include "exactgeo/inside/location.hpp"

namespace exactgeo::cli {

namespace {

/// The format's version 1.0 preamble: the magic string, the version, the header's length
/// (little-endian), then the header, a Python dict literal padded with spaces and ended
/// by a newline so that the data starts at a multiple of 64 bytes.
std::string npy_preamble(std::size_t count) {
  std::string header =
      "{'descr': '|i1', 'fortran_order': False, 'shape': (" + std::to_string(count) + ",), }";
  constexpr std::size_t kFixed = 10;  // magic (6), version (2), header length (2)
  const std::size_t padded = (kFixed + header.size() + 1 + 63) / 64 * 64;
  header.append(padded - kFixed - header.size() - 1, ' ');
  header.push_back('\n');
  std::string out("\x93NUMPY\x01\x00", 8);
  out.push_back(static_cast<char>(header.size() & 0xff));
  out.push_back(static_cast<char>(header.size() >> 8));
  return out + header;
}

}  // namespace

std::string npy_labels(std::span<const inside::Location> labels) {
  std::string out = npy_preamble(labels.size());
  for (const inside::Location l : labels)
    out.push_back(static_cast<char>(static_cast<std::int8_t>(l)));
  return out;
}

}  // namespace exactgeo::cli
