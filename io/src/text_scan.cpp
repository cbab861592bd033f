#include "exactgeo/io/text_scan.hpp"

#include <cctype>
#include <charconv>
#include <limits>
#include <system_error>

#include "exactgeo/io/input_error.hpp"

namespace exactgeo::io {

std::optional<std::string_view> LineCursor::next() {
  if (pos_ >= text_.size()) return std::nullopt;
  const std::size_t newline = text_.find('\n', pos_);
  const std::size_t end = newline == std::string_view::npos ? text_.size() : newline;
  std::string_view line = text_.substr(pos_, end - pos_);
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  pos_ = newline == std::string_view::npos ? text_.size() : newline + 1;
  ++next_line_;
  return line;
}

std::string_view skip_utf8_bom(std::string_view text) noexcept {
  if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
  return text;
}

std::optional<std::string> utf16_as_utf8(std::string_view text, const std::string& source) {
  if (text.size() < 2) return std::nullopt;
  const auto byte = [&](std::size_t i) { return static_cast<unsigned char>(text[i]); };
  const bool big = byte(0) == 0xFE && byte(1) == 0xFF;
  const bool little = byte(0) == 0xFF && byte(1) == 0xFE;
  if (!big && !little) return std::nullopt;
  if (text.size() % 2 != 0) {
    // Every character is two bytes (or four): a file cut between them has lost a part of
    // its last character, and perhaps more than that, which nothing in the text can tell.
    std::string what = source;
    what.append(": UTF-16 text (");
    what.append(big ? "big" : "little");
    what.append("-endian byte order mark) of an odd number of bytes, ");
    what.append(std::to_string(text.size()));
    what.append(": the file is cut inside its last character");
    throw InputError(what);
  }
  std::string utf8;
  utf8.reserve(text.size() / 2);
  for (std::size_t i = 2; i + 1 < text.size(); i += 2) {
    const unsigned unit = big ? (byte(i) << 8) | byte(i + 1) : (byte(i + 1) << 8) | byte(i);
    if (unit < 0x80) {
      utf8.push_back(static_cast<char>(unit));
    } else if (unit < 0x800) {
      utf8.push_back(static_cast<char>(0xC0 | (unit >> 6)));
      utf8.push_back(static_cast<char>(0x80 | (unit & 0x3F)));
    } else {
      utf8.push_back(static_cast<char>(0xE0 | (unit >> 12)));
      utf8.push_back(static_cast<char>(0x80 | ((unit >> 6) & 0x3F)));
      utf8.push_back(static_cast<char>(0x80 | (unit & 0x3F)));
    }
  }
  return utf8;
}

std::string_view strip_comment(std::string_view line) noexcept {
  const std::size_t hash = line.find('#');
  return hash == std::string_view::npos ? line : line.substr(0, hash);
}

void split_tokens(std::string_view line, std::vector<std::string_view>& tokens) {
  tokens.clear();
  auto is_space = [](char c) {
    return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
  };
  std::size_t i = 0;
  while (i < line.size()) {
    if (is_space(line[i])) {
      ++i;
      continue;
    }
    std::size_t j = i;
    while (j < line.size() && !is_space(line[j]))
      ++j;
    tokens.push_back(line.substr(i, j - i));
    i = j;
  }
}

std::optional<std::int64_t> parse_integer(std::string_view token, std::string& error) {
  // One optional sign, then decimal digits only: from_chars would take a '-' of its own
  // after a '+' ("+-1").
  std::string_view digits = token;
  const bool negative = !digits.empty() && digits[0] == '-';
  if (!digits.empty() && (digits[0] == '+' || digits[0] == '-')) digits.remove_prefix(1);
  if (digits.empty() || !std::isdigit(static_cast<unsigned char>(digits[0]))) {
    error = quoted(token) + " is not an integer";
    return std::nullopt;
  }
  std::uint64_t magnitude = 0;
  const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), magnitude);
  if (ec != std::errc() && ec != std::errc::result_out_of_range) {
    error = quoted(token) + " is not an integer";
    return std::nullopt;
  }
  if (end != digits.data() + digits.size()) {
    error = quoted(token) + " is not an integer";
    return std::nullopt;
  }
  constexpr std::uint64_t kMaxPositive = std::numeric_limits<std::int64_t>::max();
  if (ec == std::errc::result_out_of_range || magnitude > kMaxPositive + (negative ? 1 : 0)) {
    error = quoted(token) + " is too large";
    return std::nullopt;
  }
  // -2^63 is representable; its magnitude is not, as an int64: negate in unsigned.
  return negative ? static_cast<std::int64_t>(0 - magnitude) : static_cast<std::int64_t>(magnitude);
}

std::string printable(std::string_view text) {
  std::string shown;
  shown.reserve(text.size());
  for (const char c : text) {
    const auto u = static_cast<unsigned char>(c);
    shown.push_back(u < 0x20 || u >= 0x7f ? '?' : c);
  }
  return shown;
}

std::string quoted(std::string_view token) {
  constexpr std::size_t kMaxShown = 40;
  std::string shown = "'";
  shown.append(printable(token.substr(0, kMaxShown)));
  shown.append(token.size() > kMaxShown ? "...'" : "'");
  return shown;
}

}  // namespace exactgeo::io
