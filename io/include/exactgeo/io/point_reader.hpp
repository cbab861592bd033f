#pragma once

// Points from a stream, a block at a time, so that memory stays flat however many there
// are. Three formats:
//   - text: one point per record, three numbers (numbers.hpp: exact, '#' comments);
//   - f64: raw little-endian IEEE float64 triples x, y, z, x, y, z, ...;
//   - npy: a NumPy .npy array of shape (n, 3), float64, either byte order (npy_header.hpp).
// Binary points are counted from 0, like the rows of the array; an error names the point
// and its byte offset ("<source>: point 17 (byte 536): ..."), a text error the line.
// Non-finite coordinates are refused in every format.

#include <array>
#include <cstddef>
#include <cstdint>
#include <istream>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "exactgeo/io/numbers.hpp"

namespace exactgeo::io {

enum class PointFormat : std::uint8_t { text, f64, npy };

/// "text", "f64" or "npy".
std::string_view to_string(PointFormat format) noexcept;
std::optional<PointFormat> parse_point_format(std::string_view name) noexcept;

/// npy for a path ending in ".npy" (in any case), text otherwise.
PointFormat default_point_format(std::string_view path) noexcept;

/// x, y, z (the same type as exactgeo::Point3).
using PointXyz = std::array<double, 3>;

class PointReader {
 public:
  PointReader(std::istream& in, std::string source, PointFormat format);

  /// The next points, at most `max_points` (> 0) of them, in storage the reader owns (valid
  /// until the next call); empty when the input is exhausted. Throws InputError naming the
  /// source and the place.
  std::span<const PointXyz> read_block(std::size_t max_points);

  const std::string& source() const noexcept { return source_; }

 private:
  std::span<const PointXyz> read_text(std::size_t max_points);
  std::span<const PointXyz> read_binary(std::size_t max_points);
  void read_npy_header();
  void require_end_of_data();
  PointXyz* binary_destination(std::size_t max_points);
  [[noreturn]] void fail_at_point(std::uint64_t point, const std::string& what) const;

  std::istream& in_;
  std::string source_;
  PointFormat format_;
  RecordReader records_;                      // text
  std::uint64_t points_read_ = 0;             // binary: points returned so far
  std::optional<std::uint64_t> points_left_;  // npy: rows the header declares, not yet read
  std::uint64_t data_offset_ = 0;             // binary: the byte offset of point 0
  bool big_endian_ = false;                   // binary: the data's byte order
  bool header_read_ = false;                  // npy
  std::vector<PointXyz> storage_;             // the block returned
};

}  // namespace exactgeo::io
