// libFuzzer target for the binary points behind `exactgeo inside --points-format npy|f64`:
// the .npy header parser and PointReader, from memory. Invariants on every input:
//   - no crash, no sanitizer report, no huge allocation from a declared shape or length;
//   - npy_header_size and parse_npy_header agree: the parsed header's data offset is the
//     size, and an input the size check refuses is refused by the parser too;
//   - read as npy: either an InputError naming "<fuzz>", or the header's n points, all
//     finite, and then the input is exactly the header and 24 n bytes;
//   - read as f64: either an InputError naming "<fuzz>", or size / 24 finite points with
//     the input's bits (size a multiple of 24).
// Blocks are small (1 to 4 points) so that reads cross block boundaries.
//
// Build with clang (EXACTGEO_BUILD_FUZZERS) and run e.g.
//   build-fuzz/bin/npy_points_fuzz -max_total_time=300 <copy of tests/fuzz/corpus/npy>

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "exactgeo/io/input_error.hpp"
#include "exactgeo/io/npy_header.hpp"
#include "exactgeo/io/point_reader.hpp"

namespace {

using exactgeo::io::InputError;
using exactgeo::io::PointFormat;
using exactgeo::io::PointXyz;

const std::string kSource = "<fuzz>";

void check(bool condition) {
  if (!condition) std::abort();
}

void check_message(const InputError& e) {
  check(std::string_view(e.what()).find(kSource) != std::string_view::npos);
}

/// Every point of `bytes`, or nullopt after an InputError.
std::optional<std::vector<PointXyz>> read_all(std::string_view bytes, PointFormat format,
                                              std::size_t block_points) {
  std::istringstream in{std::string(bytes)};
  exactgeo::io::PointReader reader(in, kSource, format);
  std::vector<PointXyz> all;
  try {
    for (auto block = reader.read_block(block_points); !block.empty();
         block = reader.read_block(block_points)) {
      check(block.size() <= block_points);
      all.insert(all.end(), block.begin(), block.end());
    }
  } catch (const InputError& e) {
    check_message(e);
    return std::nullopt;
  }
  for (const PointXyz& p : all) {
    for (const double x : p)
      check(std::isfinite(x));
  }
  return all;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  const std::size_t block_points = 1 + size % 4;

  std::optional<exactgeo::io::NpyPoints> header;
  try {
    header = exactgeo::io::parse_npy_header(bytes, kSource);
    check(header->data_offset == exactgeo::io::npy_header_size(bytes, kSource));
    check(header->data_offset <= size);
  } catch (const InputError& e) {
    check_message(e);
  }
  const auto npy = read_all(bytes, PointFormat::npy, block_points);
  check(!npy || header);  // the reader accepts no header the parser refuses
  if (npy) {
    check(npy->size() == header->points);
    check(size == header->data_offset + 24 * npy->size());
  }

  const auto f64 = read_all(bytes, PointFormat::f64, block_points);
  if (f64) {
    check(size % 24 == 0 && f64->size() == size / 24);
    check(f64->empty() || std::memcmp(f64->data(), data, size) == 0 ||
          std::endian::native == std::endian::big);
  }
  return 0;
}
