#pragma once

// Scanning mesh text from memory: lines with their numbers, whitespace tokens, integers.
// Shared by the OBJ, OFF and PLY readers; nothing here allocates per line except the
// caller's reused token vector.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace exactgeo::io {

/// Lines of a text, split at '\n' with one trailing '\r' removed (so CRLF files read like LF
/// files), numbered from 1.
class LineCursor {
 public:
  /// Starts at byte `offset` of `text`, whose line number is `first_line`.
  explicit LineCursor(std::string_view text, std::size_t offset = 0, std::size_t first_line = 1)
      : text_(text), pos_(offset < text.size() ? offset : text.size()), next_line_(first_line) {}

  /// The next line, or nullopt at the end of the text.
  std::optional<std::string_view> next();

  /// The number of the line last returned by next() (0 before the first).
  std::size_t line_number() const noexcept { return next_line_ - 1; }
  /// The byte offset just past the line last returned (past its '\n').
  std::size_t offset() const noexcept { return pos_; }
  std::size_t remaining_bytes() const noexcept { return text_.size() - pos_; }

 private:
  std::string_view text_;
  std::size_t pos_;
  std::size_t next_line_;
};

/// The text without a leading UTF-8 byte order mark.
std::string_view skip_utf8_bom(std::string_view text) noexcept;

/// Text that starts with a UTF-16 byte order mark (big or little endian), as UTF-8 (each
/// 16-bit unit encoded alone: the mesh formats' keywords and numbers are ASCII, and what
/// else a line holds is a comment or a name); nullopt for any other text. Some Windows
/// tools save OBJ files so. Throws InputError naming `source` when the text has an odd
/// number of bytes (cut inside its last character).
std::optional<std::string> utf16_as_utf8(std::string_view text, const std::string& source);

/// The line up to its first '#'.
std::string_view strip_comment(std::string_view line) noexcept;

/// Replaces `tokens` by the line's tokens, separated by spaces, tabs, CR, VT and FF.
void split_tokens(std::string_view line, std::vector<std::string_view>& tokens);

/// A decimal integer with at most one sign, in the range of int64, or nullopt with
/// `error` set to a short reason ("'x' is not an integer", "... is too large").
std::optional<std::int64_t> parse_integer(std::string_view token, std::string& error);

/// The text with control and non-ASCII bytes shown as '?', for a message.
std::string printable(std::string_view text);

/// The token in single quotes for a message, cut at 40 characters, control and non-ASCII
/// bytes shown as '?'.
std::string quoted(std::string_view token);

}  // namespace exactgeo::io
