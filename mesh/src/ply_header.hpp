#pragma once

// The header of a PLY 1.0 file: format, elements and their properties.

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace exactgeo::mesh::internal {

enum class PlyFormat { ascii, binary_little_endian, binary_big_endian };

/// The scalar types of PLY, under either of their names (char/int8, uchar/uint8,
/// short/int16, ushort/uint16, int/int32, uint/uint32, float/float32, double/float64).
enum class PlyType { int8, uint8, int16, uint16, int32, uint32, float32, float64 };

std::size_t ply_type_size(PlyType type) noexcept;
/// "char", "uchar", ..., "double": the type's name in PLY 1.0's first spelling.
std::string_view ply_type_name(PlyType type) noexcept;
bool ply_type_is_integer(PlyType type) noexcept;

struct PlyProperty {
  std::string name;
  bool is_list = false;
  PlyType count_type = PlyType::uint8;  ///< lists only; always an integer type
  PlyType type = PlyType::float32;      ///< the value type, or the list's item type
  std::size_t line = 0;                 ///< the header line that declares it
};

struct PlyElement {
  std::string name;
  std::uint64_t count = 0;
  std::vector<PlyProperty> properties;
  std::size_t line = 0;  ///< the header line that declares it
};

struct PlyHeader {
  PlyFormat format = PlyFormat::ascii;
  std::vector<PlyElement> elements;
  std::size_t data_offset = 0;  ///< the first byte after "end_header" and its line end
  std::size_t data_line = 0;    ///< the line number of the first data line (ASCII)
  /// Header lines that were skipped, as messages naming the source and line.
  std::vector<std::string> skipped;
};

/// Parses the header at the start of `data`. A line whose first word is no PLY keyword
/// (exporters write "Created by ..." lines) is skipped and listed, when it cannot be a
/// layout line written wrong (the data's layout comes from the format, element and
/// property lines only): else it is refused, as is a keyword in another case or misspelt
/// by one or two letters. Throws
/// InputError("<source>:<line>: ...") for a missing "ply" magic line, an unknown format or version,
/// a malformed element or property line, a list whose count type is not an integer type, duplicate
/// names, or a missing end_header.
PlyHeader parse_ply_header(std::string_view data, const std::string& source);

/// "ply ascii", "ply binary little endian" or "ply binary big endian".
std::string ply_format_name(PlyFormat format);

}  // namespace exactgeo::mesh::internal
