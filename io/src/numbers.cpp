#include "exactgeo/io/numbers.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <system_error>

#include "exactgeo/io/input_error.hpp"
#include "exactgeo/io/text_scan.hpp"

namespace exactgeo::io {

namespace {

bool starts_with_hex_prefix(std::string_view s) {
  return s.size() >= 2 && s[0] == '0' && (s[1] == 'x' || s[1] == 'X');
}

/// The body of a literal after its sign and hex prefix is digits with at most one point
/// (at least one digit), then optionally the exponent marker, at most one sign and
/// decimal digits. Checked here because libstdc++ 12's from_chars reads the hexadecimal
/// "1p+-3" as 2^-3.
bool well_formed(std::string_view body, bool hex) {
  const auto is_digit = [&](char c) {
    const auto u = static_cast<unsigned char>(c);
    return hex ? std::isxdigit(u) != 0 : std::isdigit(u) != 0;
  };
  std::size_t i = 0;
  std::size_t digits = 0;
  bool point = false;
  for (; i < body.size(); ++i) {
    if (is_digit(body[i])) {
      ++digits;
    } else if (body[i] == '.' && !point) {
      point = true;
    } else {
      break;
    }
  }
  if (digits == 0) return false;
  if (i == body.size()) return true;
  const char marker = static_cast<char>(std::tolower(static_cast<unsigned char>(body[i])));
  if (marker != (hex ? 'p' : 'e')) return false;
  ++i;
  if (i < body.size() && (body[i] == '+' || body[i] == '-')) ++i;
  if (i == body.size()) return false;
  for (; i < body.size(); ++i) {
    if (!std::isdigit(static_cast<unsigned char>(body[i]))) return false;
  }
  return true;
}

/// The literal as the nearest T (double or float: rounded once, straight to T's
/// precision), or nullopt with the reason.
template <class T>
std::optional<T> parse_literal(std::string_view token, std::string& error, const char* range) {
  std::string_view body = token;
  bool negative = false;
  if (!body.empty() && (body[0] == '+' || body[0] == '-')) {
    negative = body[0] == '-';
    body.remove_prefix(1);
  }
  std::chars_format format = std::chars_format::general;
  if (starts_with_hex_prefix(body)) {
    format = std::chars_format::hex;
    body.remove_prefix(2);
  }
  // from_chars would accept a second sign, "inf" and "nan": the grammar is checked first.
  // A hexfloat's first digit may be a letter ("0xAp-3", as C's %a can write it).
  if (!well_formed(body, format == std::chars_format::hex)) {
    error = quoted(token) + " is not a number";
    return std::nullopt;
  }
  T value = 0;
  const auto [end, ec] = std::from_chars(body.data(), body.data() + body.size(), value, format);
  if (ec == std::errc::result_out_of_range) {
    error = quoted(token) + " is outside the range of " + range;
    return std::nullopt;
  }
  if (ec != std::errc() || end != body.data() + body.size()) {
    error = quoted(token) + " is not a number";
    return std::nullopt;
  }
  if (!std::isfinite(value)) {
    error = quoted(token) + " is not finite";
    return std::nullopt;
  }
  return negative ? -value : value;
}

}  // namespace

std::optional<double> parse_number(std::string_view token, std::string& error) {
  return parse_literal<double>(token, error, "double");
}

bool is_number_literal(std::string_view token) {
  std::string_view body = token;
  if (!body.empty() && (body[0] == '+' || body[0] == '-')) body.remove_prefix(1);
  const bool hex = starts_with_hex_prefix(body);
  if (hex) body.remove_prefix(2);
  return well_formed(body, hex);
}

std::optional<double> parse_float32(std::string_view token, std::string& error) {
  const auto x = parse_literal<float>(token, error, "float");
  if (!x) return std::nullopt;
  return *x;  // widening is exact
}

std::vector<std::string_view> split_fields(std::string_view line) {
  if (const auto hash = line.find('#'); hash != std::string_view::npos) line = line.substr(0, hash);
  auto is_space = [](char c) {
    return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
  };
  std::vector<std::string_view> fields;
  std::size_t i = 0;
  bool after_comma = false;  // a comma was seen since the last field
  while (i < line.size()) {
    if (is_space(line[i])) {
      ++i;
    } else if (line[i] == ',') {
      if (after_comma || fields.empty()) fields.emplace_back();  // ",," or a leading comma
      after_comma = true;
      ++i;
    } else {
      std::size_t j = i;
      while (j < line.size() && !is_space(line[j]) && line[j] != ',')
        ++j;
      fields.push_back(line.substr(i, j - i));
      after_comma = false;
      i = j;
    }
  }
  if (after_comma) fields.emplace_back();  // a trailing comma
  return fields;
}

std::vector<double> parse_numbers(std::string_view line, const std::string& source,
                                  std::size_t line_number) {
  const std::vector<std::string_view> fields = split_fields(line);
  std::vector<double> numbers;
  numbers.reserve(fields.size());
  for (std::size_t i = 0; i < fields.size(); ++i) {
    if (fields[i].empty()) {
      throw InputError(source, line_number, "field " + std::to_string(i + 1) + " is empty");
    }
    std::string error;
    const std::optional<double> x = parse_number(fields[i], error);
    if (!x) throw InputError(source, line_number, "field " + std::to_string(i + 1) + ": " + error);
    numbers.push_back(*x);
  }
  return numbers;
}

std::optional<std::vector<double>> RecordReader::next() {
  while (std::getline(in_, line_)) {
    ++line_number_;
    if (line_.find('\0') != std::string::npos) {
      throw InputError(source_, line_number_, "contains a NUL byte (binary input?)");
    }
    std::vector<double> numbers = parse_numbers(line_, source_, line_number_);
    if (!numbers.empty()) return numbers;
  }
  if (in_.bad()) throw InputError(source_ + ": read error");
  return std::nullopt;
}

}  // namespace exactgeo::io
