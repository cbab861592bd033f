#include "cli/npy_labels.hpp"

#include <array>
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

std::optional<std::string> npy_labels(std::string_view text) {
  constexpr std::array kLabels{inside::Location::outside, inside::Location::inside,
                               inside::Location::boundary, inside::Location::undecided};
  std::string codes;
  for (std::size_t start = 0; start < text.size();) {
    std::size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    const std::string_view word = text.substr(start, end - start);
    bool known = false;
    for (const inside::Location l : kLabels) {
      if (word == to_string(l)) {
        codes.push_back(static_cast<char>(static_cast<std::int8_t>(l)));
        known = true;
      }
    }
    if (!known) return std::nullopt;
    start = end + 1;
  }
  return npy_preamble(codes.size()) + codes;
}

}  // namespace exactgeo::cli
