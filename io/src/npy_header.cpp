#include "exactgeo/io/npy_header.hpp"

#include <limits>
#include <optional>
#include <vector>

#include "exactgeo/io/input_error.hpp"
#include "exactgeo/io/text_scan.hpp"

namespace exactgeo::io {

namespace {

constexpr std::string_view kMagic = "\x93NUMPY";
constexpr std::size_t kPointBytes = 3 * sizeof(double);

[[noreturn]] void fail(const std::string& source, const std::string& what) {
  throw InputError(source + ": header: " + what);
}

/// The unsigned little-endian integer in `bytes` (2 or 4 of them).
std::uint32_t little_endian(std::string_view bytes) {
  std::uint32_t value = 0;
  for (std::size_t i = bytes.size(); i-- > 0;) {
    value = (value << 8) | static_cast<unsigned char>(bytes[i]);
  }
  return value;
}

/// The preamble's size: 10 bytes for version 1 (uint16 length), 12 for 2 and 3 (uint32).
std::size_t preamble_size(std::string_view bytes, const std::string& source) {
  if (bytes.empty()) fail(source, "the input is empty, not an .npy file");
  if (bytes.substr(0, kMagic.size()) != kMagic.substr(0, bytes.size())) {
    fail(source, "not an .npy file (it does not start with \"\\x93NUMPY\")");
  }
  if (bytes.size() < kMagic.size() + 2) {
    fail(source, "the file ends within the magic string and version (" +
                     std::to_string(bytes.size()) + " bytes)");
  }
  const auto major = static_cast<unsigned char>(bytes[6]);
  const auto minor = static_cast<unsigned char>(bytes[7]);
  if (major < 1 || major > 3 || minor != 0) {
    fail(source, "format version " + std::to_string(major) + "." + std::to_string(minor) +
                     "; accepted: 1.0, 2.0, 3.0");
  }
  const std::size_t size = major == 1 ? 10 : 12;
  if (bytes.size() < size) {
    fail(source,
         "the file ends within the header length (" + std::to_string(bytes.size()) + " bytes)");
  }
  return size;
}

/// Python's repr of a shape tuple: (), (7,), (7, 3).
std::string shape_text(const std::vector<std::uint64_t>& shape) {
  std::string text = "(";
  for (std::size_t i = 0; i < shape.size(); ++i) {
    if (i > 0) text += ", ";
    text += std::to_string(shape[i]);
  }
  return text + (shape.size() == 1 ? ",)" : ")");
}

struct Dict {
  std::optional<std::string> descr;
  std::optional<bool> fortran_order;
  std::optional<std::vector<std::uint64_t>> shape;
};

/// The header dict as the small subset of Python literals numpy writes (ast.literal_eval
/// reads more; nothing else is needed for a float64 array).
class DictParser {
 public:
  DictParser(std::string_view text, std::size_t offset, const std::string& source)
      : text_(text), offset_(offset), source_(source) {}

  Dict parse() {
    skip_space();
    expect('{', "the header is not a dict");
    skip_space();
    while (!at('}')) {
      read_entry();
      skip_space();
      if (at(',')) {
        ++pos_;
        skip_space();
      } else if (!at('}')) {
        fail_here("expected ',' or '}' after a value");
      }
    }
    ++pos_;
    skip_space();
    if (pos_ != text_.size()) fail_here("unexpected text after the dict");
    for (const auto& [key, present] :
         {std::pair{"'descr'", dict_.descr.has_value()},
          std::pair{"'fortran_order'", dict_.fortran_order.has_value()},
          std::pair{"'shape'", dict_.shape.has_value()}}) {
      if (!present) {
        fail_at(offset_, std::string("the dict lacks ") + key +
                             " (it needs 'descr', 'fortran_order' and 'shape')");
      }
    }
    return std::move(dict_);
  }

 private:
  [[noreturn]] void fail_at(std::size_t byte, const std::string& what) const {
    fail(source_, what + " (at byte " + std::to_string(byte) + ")");
  }
  [[noreturn]] void fail_here(const std::string& what) const { fail_at(offset_ + pos_, what); }

  bool at(char c) const { return pos_ < text_.size() && text_[pos_] == c; }

  void skip_space() {
    while (pos_ < text_.size() && (text_[pos_] == ' ' || text_[pos_] == '\t' ||
                                   text_[pos_] == '\n' || text_[pos_] == '\r')) {
      ++pos_;
    }
  }

  void expect(char c, const char* what) {
    if (!at(c)) fail_here(what);
    ++pos_;
  }

  void read_entry() {
    const std::size_t key_at = offset_ + pos_;
    const std::string key = string_literal("a key");
    skip_space();
    expect(':', "expected ':' after a key");
    skip_space();
    if (key == "descr") {
      if (dict_.descr) fail_at(key_at, "'descr' appears twice");
      if (at('[')) {
        fail_here("descr is a list of fields (a structured array); accepted: '<f8' or '>f8'");
      }
      dict_.descr = string_literal("descr");
    } else if (key == "fortran_order") {
      if (dict_.fortran_order) fail_at(key_at, "'fortran_order' appears twice");
      dict_.fortran_order = boolean();
    } else if (key == "shape") {
      if (dict_.shape) fail_at(key_at, "'shape' appears twice");
      dict_.shape = tuple();
    } else {
      fail_at(key_at, "unexpected key " + quoted(key) +
                          " (an .npy header has 'descr', 'fortran_order' and 'shape')");
    }
  }

  /// A Python string in single or double quotes, without escapes.
  std::string string_literal(const char* what) {
    if (!at('\'') && !at('"')) fail_here(std::string(what) + " is not a string");
    const char quote = text_[pos_];
    const std::size_t end = text_.find(quote, pos_ + 1);
    if (end == std::string_view::npos) fail_here("a string is not closed");
    const std::string_view body = text_.substr(pos_ + 1, end - pos_ - 1);
    if (body.find_first_of("\\\n") != std::string_view::npos) {
      fail_here("a string holds a backslash or a line break");
    }
    pos_ = end + 1;
    return std::string(body);
  }

  bool boolean() {
    for (const auto& [word, value] :
         {std::pair{std::string_view("True"), true}, std::pair{std::string_view("False"), false}}) {
      if (text_.substr(pos_, word.size()) == word) {
        pos_ += word.size();
        return value;
      }
    }
    fail_here("fortran_order is not True or False");
  }

  /// A tuple of non-negative integers: (), (7,), (7, 3), (7, 3,).
  std::vector<std::uint64_t> tuple() {
    expect('(', "shape is not a tuple");
    std::vector<std::uint64_t> values;
    bool trailing_comma = false;
    skip_space();
    while (!at(')')) {
      values.push_back(integer());
      skip_space();
      trailing_comma = at(',');
      if (trailing_comma) {
        ++pos_;
        skip_space();
      } else if (!at(')')) {
        fail_here("expected ',' or ')' in shape");
      }
    }
    ++pos_;
    // "(7)" is the integer 7 in Python, not a tuple.
    if (values.size() == 1 && !trailing_comma) fail_here("shape is not a tuple");
    return values;
  }

  std::uint64_t integer() {
    const std::size_t start = pos_;
    std::uint64_t value = 0;
    constexpr std::uint64_t kMax = std::numeric_limits<std::uint64_t>::max();
    while (pos_ < text_.size() && text_[pos_] >= '0' && text_[pos_] <= '9') {
      const auto digit = static_cast<std::uint64_t>(text_[pos_] - '0');
      if (value > (kMax - digit) / 10) fail_at(offset_ + start, "a shape entry is too large");
      value = value * 10 + digit;
      ++pos_;
    }
    if (pos_ == start) fail_here("a shape entry is not a non-negative integer");
    if (at('L')) ++pos_;  // Python 2's long suffix, in files written by old numpy
    return value;
  }

  std::string_view text_;
  std::size_t offset_;  // of text_[0] in the file
  const std::string& source_;
  std::size_t pos_ = 0;
  Dict dict_;
};

}  // namespace

std::size_t npy_header_size(std::string_view first_bytes, const std::string& source) {
  const std::size_t preamble = preamble_size(first_bytes, source);
  const std::size_t length = little_endian(first_bytes.substr(8, preamble - 8));
  if (length > kNpyMaxHeaderBytes) {
    fail(source, "the header length " + std::to_string(length) + " is larger than " +
                     std::to_string(kNpyMaxHeaderBytes) + " bytes");
  }
  return preamble + length;
}

NpyPoints parse_npy_header(std::string_view bytes, const std::string& source) {
  const std::size_t preamble = preamble_size(bytes, source);
  const std::size_t size = npy_header_size(bytes, source);
  if (bytes.size() < size) {
    fail(source, "the header is " + std::to_string(size) +
                     " bytes long but the file ends at byte " + std::to_string(bytes.size()));
  }
  const Dict dict = DictParser(bytes.substr(preamble, size - preamble), preamble, source).parse();

  NpyPoints points;
  if (*dict.descr != "<f8" && *dict.descr != ">f8") {
    fail(source, "descr is " + quoted(*dict.descr) +
                     "; accepted: '<f8' or '>f8' (float64: convert with "
                     "points.astype(np.float64))");
  }
  points.big_endian = *dict.descr == ">f8";
  if (*dict.fortran_order) {
    fail(source,
         "fortran_order is True (the array is stored column by column); save a C-ordered "
         "copy: np.save(path, np.ascontiguousarray(points))");
  }
  const std::vector<std::uint64_t>& shape = *dict.shape;
  if (shape.size() != 2 || shape[1] != 3) {
    fail(source, "shape is " + shape_text(shape) + "; accepted: (n, 3), one row per point");
  }
  // The data's size must be representable, so that every later offset is.
  constexpr std::uint64_t kMax = std::numeric_limits<std::uint64_t>::max();
  if (shape[0] > (kMax - size) / kPointBytes) {
    fail(source, "shape is " + shape_text(shape) + ": too many points");
  }
  points.points = shape[0];
  points.data_offset = size;
  return points;
}

}  // namespace exactgeo::io
