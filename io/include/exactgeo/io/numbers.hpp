#pragma once

// Reading numbers from text exactly. A number is a decimal or hexadecimal floating-point
// literal ("-1.5e-3", "0x1.8p+3", "+2"), converted with correct rounding (std::from_chars:
// the double nearest to the decimal value, hexfloats exactly). Refused: anything that is
// not entirely one literal, "inf"/"nan", and values outside the double range (overflow,
// or a nonzero value that rounds to zero).
//
// A record is one line of numbers separated by whitespace and/or commas; blank lines and
// everything after '#' are skipped.

#include <cstddef>
#include <istream>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace exactgeo::io {

/// The number, or nullopt with `error` set to a short reason.
std::optional<double> parse_number(std::string_view token, std::string& error);

/// The token is one number literal as parse_number reads them, whatever its value: also
/// a literal beyond the double range (which parse_number refuses), for a field whose value
/// is not used but whose form is checked.
bool is_number_literal(std::string_view token);

/// The same literal rounded once, straight to the nearest float (a value a file declares
/// 32-bit, as a binary copy of it holds), returned exactly as a double. Refused beyond the
/// float range, as parse_number refuses beyond the double range.
std::optional<double> parse_float32(std::string_view token, std::string& error);

/// Splits a line into fields (whitespace and/or commas; '#' starts a comment). An empty
/// field between two commas is returned as an empty string_view so it can be reported.
std::vector<std::string_view> split_fields(std::string_view line);

/// One line's numbers, or throws InputError naming source, line and field.
std::vector<double> parse_numbers(std::string_view line, const std::string& source,
                                  std::size_t line_number);

/// Reads records (non-blank, non-comment lines) one at a time, counting lines.
class RecordReader {
 public:
  RecordReader(std::istream& in, std::string source) : in_(in), source_(std::move(source)) {}

  /// The next record's numbers, or nullopt at end of input. Throws InputError.
  std::optional<std::vector<double>> next();

  const std::string& source() const noexcept { return source_; }
  std::size_t line_number() const noexcept { return line_number_; }

 private:
  std::istream& in_;
  std::string source_;
  std::string line_;
  std::size_t line_number_ = 0;
};

}  // namespace exactgeo::io
