#include "exactgeo/io/point_reader.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <type_traits>

#include "exactgeo/io/input_error.hpp"
#include "exactgeo/io/npy_header.hpp"

namespace exactgeo::io {

namespace {

constexpr std::size_t kPointBytes = sizeof(PointXyz);
static_assert(kPointBytes == 3 * sizeof(double) && std::is_trivially_copyable_v<PointXyz>,
              "binary points are read straight into the block's storage");

double byte_swapped(double x) {
  auto bits = std::bit_cast<std::uint64_t>(x);
  std::uint64_t swapped = 0;
  for (int i = 0; i < 8; ++i) {
    swapped = (swapped << 8) | (bits & 0xff);
    bits >>= 8;
  }
  return std::bit_cast<double>(swapped);
}

std::string byte_count(std::size_t n) {
  return std::to_string(n) + (n == 1 ? " byte" : " bytes");
}

std::string non_finite_name(double x) {
  if (std::isnan(x)) return "nan";
  return x > 0 ? "inf" : "-inf";
}

}  // namespace

std::string_view to_string(PointFormat format) noexcept {
  switch (format) {
    case PointFormat::text:
      return "text";
    case PointFormat::f64:
      return "f64";
    case PointFormat::npy:
      return "npy";
  }
  return "?";
}

std::optional<PointFormat> parse_point_format(std::string_view name) noexcept {
  for (const PointFormat format : {PointFormat::text, PointFormat::f64, PointFormat::npy}) {
    if (to_string(format) == name) return format;
  }
  return std::nullopt;
}

PointFormat default_point_format(std::string_view path) noexcept {
  constexpr std::string_view kSuffix = ".npy";
  if (path.size() < kSuffix.size()) return PointFormat::text;
  const std::string_view tail = path.substr(path.size() - kSuffix.size());
  const bool npy = std::equal(tail.begin(), tail.end(), kSuffix.begin(), [](char a, char b) {
    return (a >= 'A' && a <= 'Z' ? char(a - 'A' + 'a') : a) == b;
  });
  return npy ? PointFormat::npy : PointFormat::text;
}

PointReader::PointReader(std::istream& in, std::string source, PointFormat format)
    : in_(in), source_(std::move(source)), format_(format), records_(in, source_) {}

std::span<const PointXyz> PointReader::read_block(std::size_t max_points) {
  if (format_ == PointFormat::text) return read_text(max_points);
  if (format_ == PointFormat::npy && !header_read_) read_npy_header();
  return read_binary(max_points);
}

std::span<const PointXyz> PointReader::read_text(std::size_t max_points) {
  storage_.clear();
  while (storage_.size() < max_points) {
    const auto record = records_.next();
    if (!record) break;
    if (record->size() != 3) {
      throw InputError(source_, records_.line_number(),
                       "expected 3 coordinates, found " + std::to_string(record->size()));
    }
    storage_.push_back({(*record)[0], (*record)[1], (*record)[2]});
  }
  return storage_;
}

void PointReader::read_npy_header() {
  header_read_ = true;
  std::string header(kNpyPreambleBytes, '\0');
  in_.read(header.data(), static_cast<std::streamsize>(header.size()));
  header.resize(static_cast<std::size_t>(in_.gcount()));
  // A header shorter than the bytes just read (a dict of at most one byte) cannot be a
  // valid one: parse_npy_header refuses it, so no data byte is lost here.
  const std::size_t size = npy_header_size(header, source_);
  if (size > header.size()) {
    const std::size_t have = header.size();
    header.resize(size);
    in_.read(header.data() + have, static_cast<std::streamsize>(size - have));
    header.resize(have + static_cast<std::size_t>(in_.gcount()));
  }
  if (in_.bad()) throw InputError(source_ + ": read error");
  const NpyPoints npy = parse_npy_header(header, source_);
  points_left_ = npy.points;
  data_offset_ = npy.data_offset;
  big_endian_ = npy.big_endian;
  if (npy.points == 0) require_end_of_data();
}

std::span<const PointXyz> PointReader::read_binary(std::size_t max_points) {
  std::uint64_t wanted = max_points;
  if (points_left_) wanted = std::min(wanted, *points_left_);
  if (wanted == 0) return {};
  PointXyz* const points = binary_destination(static_cast<std::size_t>(wanted));
  in_.read(reinterpret_cast<char*>(points), static_cast<std::streamsize>(wanted * kPointBytes));
  const auto bytes = static_cast<std::size_t>(in_.gcount());
  if (in_.bad()) throw InputError(source_ + ": read error");
  const std::size_t whole = bytes / kPointBytes;
  const std::size_t partial = bytes % kPointBytes;
  if (points_left_ && whole < wanted) {
    fail_at_point(points_read_ + whole,
                  "the data ends " +
                      (partial == 0 ? std::string("before this point")
                                    : byte_count(partial) + " into this point") +
                      "; the header's shape declares " +
                      std::to_string(points_read_ + *points_left_) + " points");
  }
  if (partial != 0) {
    fail_at_point(points_read_ + whole,
                  "the input ends " + byte_count(partial) +
                      " into this point (f64 input is 24 bytes per point: x, y, z)");
  }
  const bool swap = big_endian_ != (std::endian::native == std::endian::big);
  for (std::size_t i = 0; i < whole; ++i) {
    for (std::size_t c = 0; c < 3; ++c) {
      double& x = points[i][c];
      if (swap) x = byte_swapped(x);
      if (!std::isfinite(x)) {
        fail_at_point(points_read_ + i, std::string(1, "xyz"[c]) + " is " + non_finite_name(x) +
                                            "; coordinates must be finite");
      }
    }
  }
  points_read_ += whole;
  if (points_left_) {
    *points_left_ -= whole;
    if (*points_left_ == 0) require_end_of_data();
  }
  return {points, whole};
}

PointXyz* PointReader::binary_destination(std::size_t max_points) {
  // A large read(2) copies from the page cache at the stream position's offset in its page
  // (for a file read from its start). A destination 8 to 24 bytes past that offset modulo
  // 4096, which is where malloc puts a large vector's data when a file is read from offset
  // 0, made the copy several times slower (docs/inside.md, "Point input"), so the block
  // starts at the point of storage_ that lies about half a page away from it.
  constexpr std::size_t kPage = 4096;
  constexpr std::size_t kSlack = kPage / 8;  // 24 k runs through every multiple of 8 mod 4096
  if (storage_.size() < max_points + kSlack) storage_.resize(max_points + kSlack);
  const std::uint64_t position = data_offset_ + points_read_ * kPointBytes;
  const auto address = reinterpret_cast<std::uintptr_t>(storage_.data());
  std::size_t first = 0;
  const auto distance = [&] { return (address + first * kPointBytes - position) % kPage; };
  while (distance() < kPage / 4 || distance() >= 3 * kPage / 4)
    ++first;
  return storage_.data() + first;
}

void PointReader::require_end_of_data() {
  if (in_.peek() != std::istream::traits_type::eof()) {
    throw InputError(source_ + ": byte " +
                     std::to_string(data_offset_ + points_read_ * kPointBytes) +
                     ": data continues after the " + std::to_string(points_read_) +
                     " points the header's shape declares");
  }
  if (in_.bad()) throw InputError(source_ + ": read error");
}

void PointReader::fail_at_point(std::uint64_t point, const std::string& what) const {
  throw InputError(source_ + ": point " + std::to_string(point) + " (byte " +
                   std::to_string(data_offset_ + point * kPointBytes) + "): " + what);
}

}  // namespace exactgeo::io
