#include "ply_header.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <optional>
#include <set>

#include "exactgeo/io/input_error.hpp"
#include "exactgeo/io/text_scan.hpp"

namespace exactgeo::mesh::internal {

using io::InputError;
using io::LineCursor;
using io::parse_integer;
using io::quoted;
using io::split_tokens;

namespace {

std::optional<PlyType> type_named(std::string_view name) {
  struct Named {
    std::string_view name;
    PlyType type;
  };
  static constexpr Named kTypes[] = {
      {"char", PlyType::int8},       {"int8", PlyType::int8},       {"uchar", PlyType::uint8},
      {"uint8", PlyType::uint8},     {"short", PlyType::int16},     {"int16", PlyType::int16},
      {"ushort", PlyType::uint16},   {"uint16", PlyType::uint16},   {"int", PlyType::int32},
      {"int32", PlyType::int32},     {"uint", PlyType::uint32},     {"uint32", PlyType::uint32},
      {"float", PlyType::float32},   {"float32", PlyType::float32}, {"double", PlyType::float64},
      {"float64", PlyType::float64},
  };
  for (const Named& t : kTypes) {
    if (t.name == name) return t.type;
  }
  return std::nullopt;
}

bool equal_ignoring_case(std::string_view a, std::string_view b) {
  return std::equal(a.begin(), a.end(), b.begin(), b.end(), [](char x, char y) {
    return std::tolower(static_cast<unsigned char>(x)) ==
           std::tolower(static_cast<unsigned char>(y));
  });
}

/// The fewest typing errors that turn a into b: letters added, dropped or changed, two
/// neighbours swapped, in any order (case ignored). This is the Damerau-Levenshtein
/// distance (Lowrance and Wagner's algorithm), where a swap may be followed by further
/// edits between the swapped letters ("end_ahder" is two from "end_header").
std::size_t typing_distance(std::string_view a, std::string_view b) {
  const auto lower = [](char c) {
    return static_cast<unsigned char>(std::tolower(static_cast<unsigned char>(c)));
  };
  const std::size_t infinity = a.size() + b.size();
  // d[i + 1][j + 1] is the distance of a's first i letters to b's first j.
  std::vector<std::vector<std::size_t>> d(a.size() + 2, std::vector<std::size_t>(b.size() + 2));
  d[0][0] = infinity;
  for (std::size_t i = 0; i <= a.size(); ++i) {
    d[i + 1][0] = infinity;
    d[i + 1][1] = i;
  }
  for (std::size_t j = 0; j <= b.size(); ++j) {
    d[0][j + 1] = infinity;
    d[1][j + 1] = j;
  }
  std::array<std::size_t, 256> last_row{};  // the last row of a holding each letter
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t last_column = 0;  // the last column of b in this row that matched
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t k = last_row[lower(b[j - 1])];
      const std::size_t l = last_column;
      const bool same = lower(a[i - 1]) == lower(b[j - 1]);
      if (same) last_column = j;
      d[i + 1][j + 1] = std::min({d[i][j] + (same ? 0 : 1), d[i + 1][j] + 1, d[i][j + 1] + 1,
                                  d[k][l] + (i - k - 1) + 1 + (j - l - 1)});
    }
    last_row[lower(a[i - 1])] = i;
  }
  return d[a.size() + 1][b.size() + 1];
}

class HeaderParser {
 public:
  HeaderParser(std::string_view data, const std::string& source) : lines_(data), source_(source) {}

  PlyHeader parse() {
    const auto magic = lines_.next();
    if (magic) split_tokens(*magic, tokens_);
    if (!magic || tokens_.size() != 1 || tokens_[0] != "ply") {
      fail("not a PLY file: the first line must be 'ply'");
    }
    bool have_format = false;
    while (const auto line = lines_.next()) {
      split_tokens(*line, tokens_);
      if (tokens_.empty()) continue;
      const std::string_view keyword = tokens_[0];
      if (keyword == "comment" || keyword == "obj_info") continue;
      if (keyword == "end_header") {
        if (tokens_.size() != 1) fail("unexpected text after end_header");
        if (!have_format) fail("the header has no format line");
        header_.data_offset = lines_.offset();
        header_.data_line = lines_.line_number() + 1;
        return std::move(header_);
      }
      if (keyword == "format") {
        if (have_format) fail("a second format line");
        read_format();
        have_format = true;
      } else if (keyword == "element") {
        read_element();
      } else if (keyword == "property") {
        read_property();
      } else {
        skip_unknown(*line);
      }
    }
    fail("the header has no end_header line");
  }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    throw InputError(source_, lines_.line_number(), what);
  }

  void read_format() {
    if (tokens_.size() != 3)
      fail("expected 'format <ascii|binary_little_endian|binary_big_endian> 1.0'");
    if (tokens_[1] == "ascii") {
      header_.format = PlyFormat::ascii;
    } else if (tokens_[1] == "binary_little_endian") {
      header_.format = PlyFormat::binary_little_endian;
    } else if (tokens_[1] == "binary_big_endian") {
      header_.format = PlyFormat::binary_big_endian;
    } else {
      std::string what = "unknown PLY format ";
      what.append(quoted(tokens_[1]));
      fail(what);
    }
    if (tokens_[2] != "1.0" && tokens_[2] != "1") {
      std::string what = "unsupported PLY version ";
      what.append(quoted(tokens_[2]));
      what.append(" (only 1.0)");
      fail(what);
    }
  }

  /// A line whose first word is no PLY keyword: exporters write "Created by ..." lines,
  /// which the data's layout (the format, element and property lines) does not depend on.
  /// It is skipped, and said, only when it cannot be a layout line written wrong: its first
  /// word is no layout keyword in another case or one or two typing errors away from one, it does
  /// not have a property line's shape inside an element (it could be one of its
  /// properties), and no property line follows it before the next element line (they
  /// could be its own). Else it is refused, with the line.
  void skip_unknown(std::string_view line) {
    const std::string_view word = tokens_[0];
    if (const std::optional<std::string_view> meant = keyword_meant(word)) {
      std::string what = quoted(word);
      what.append(" is not a PLY keyword (meant ");
      what.append(quoted(*meant));
      what.append("? keywords are lower case): a layout line written wrong would change how ");
      what.append("the data is read; correct it, or make it a comment");
      fail(what);
    }
    if (!header_.elements.empty() && has_property_shape()) {
      std::string what = quoted(line);
      what.append(" is not a PLY keyword line but has the shape of a property of element ");
      what.append(quoted(header_.elements.back().name));
      what.append(", which it may have been meant to be: correct it, or make it a comment");
      fail(what);
    }
    UnknownLine unknown{lines_.line_number(), std::string(line)};
    std::string note = source_;
    note.append(":").append(std::to_string(unknown.line));
    note.append(": skipped header line ").append(quoted(line));
    note.append(": not a PLY keyword, and nothing the data's layout depends on");
    header_.skipped.push_back(std::move(note));
    unknown_in_element_ = std::move(unknown);
  }

  /// The layout keyword `word` was meant to be, when it is one in another case or at most
  /// two typing errors (a letter added, dropped or changed, two swapped) from one. (A
  /// comment keyword written wrong is a skipped line like any other.)
  static std::optional<std::string_view> keyword_meant(std::string_view word) {
    static constexpr std::string_view kLayout[] = {"format", "element", "property", "end_header"};
    for (const std::string_view k : kLayout) {
      if (typing_distance(word, k) <= 2) return k;
    }
    return std::nullopt;
  }

  /// "<word> <type> <name>" or "<word> list <type> <type> <name>", types in any case.
  bool has_property_shape() const {
    const auto is_type = [](std::string_view t) {
      std::string lower(t);
      for (char& c : lower)
        c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
      return type_named(lower).has_value();
    };
    if (tokens_.size() == 3) return is_type(tokens_[1]);
    return tokens_.size() == 5 && equal_ignoring_case(tokens_[1], "list") && is_type(tokens_[2]) &&
           is_type(tokens_[3]);
  }

  void read_element() {
    if (tokens_.size() != 3) fail("expected 'element <name> <count>'");
    if (!element_names_.emplace(tokens_[1]).second) {
      std::string what = "a second element named ";
      what.append(quoted(tokens_[1]));
      fail(what);
    }
    property_names_.clear();
    unknown_in_element_.reset();
    std::string error;
    const std::optional<std::int64_t> count = parse_integer(tokens_[2], error);
    if (!count) fail("element count: " + error);
    if (*count < 0) fail("element count is negative");
    PlyElement element;
    element.name = std::string(tokens_[1]);
    element.count = static_cast<std::uint64_t>(*count);
    element.line = lines_.line_number();
    header_.elements.push_back(std::move(element));
  }

  PlyType type(std::string_view name) const {
    const std::optional<PlyType> t = type_named(name);
    if (!t) {
      std::string what = "unknown property type ";
      what.append(quoted(name));
      fail(what);
    }
    return *t;
  }

  void read_property() {
    if (header_.elements.empty()) fail("a property before any element");
    if (unknown_in_element_) {
      std::string what = "this property follows header line ";
      what.append(std::to_string(unknown_in_element_->line));
      what.append(", ");
      what.append(quoted(unknown_in_element_->text));
      what.append(", which is not a PLY keyword line: if it was meant to declare an element, ");
      what.append("the properties after it are that element's, not ");
      what.append(quoted(header_.elements.back().name));
      what.append("'s; correct it, or make it a comment");
      fail(what);
    }
    PlyProperty property;
    property.line = lines_.line_number();
    if (tokens_.size() >= 2 && tokens_[1] == "list") {
      if (tokens_.size() != 5) fail("expected 'property list <count type> <item type> <name>'");
      property.is_list = true;
      property.count_type = type(tokens_[2]);
      property.type = type(tokens_[3]);
      if (!ply_type_is_integer(property.count_type)) {
        fail("a list's count type must be an integer type");
      }
      property.name = std::string(tokens_[4]);
    } else {
      if (tokens_.size() != 3) fail("expected 'property <type> <name>'");
      property.type = type(tokens_[1]);
      property.name = std::string(tokens_[2]);
    }
    if (!property_names_.insert(property.name).second) {
      std::string what = "a second property named ";
      what.append(quoted(property.name));
      fail(what);
    }
    header_.elements.back().properties.push_back(std::move(property));
  }

  struct UnknownLine {
    std::size_t line;
    std::string text;
  };

  LineCursor lines_;
  const std::string& source_;
  PlyHeader header_;
  std::optional<UnknownLine> unknown_in_element_;  // skipped since the last element line
  std::vector<std::string_view> tokens_;
  std::set<std::string, std::less<>> element_names_;   // to refuse duplicates
  std::set<std::string, std::less<>> property_names_;  // of the current element
};

}  // namespace

std::string_view ply_type_name(PlyType type) noexcept {
  switch (type) {
    case PlyType::int8:
      return "char";
    case PlyType::uint8:
      return "uchar";
    case PlyType::int16:
      return "short";
    case PlyType::uint16:
      return "ushort";
    case PlyType::int32:
      return "int";
    case PlyType::uint32:
      return "uint";
    case PlyType::float32:
      return "float";
    case PlyType::float64:
      return "double";
  }
  return "?";
}

std::size_t ply_type_size(PlyType type) noexcept {
  switch (type) {
    case PlyType::int8:
    case PlyType::uint8:
      return 1;
    case PlyType::int16:
    case PlyType::uint16:
      return 2;
    case PlyType::int32:
    case PlyType::uint32:
    case PlyType::float32:
      return 4;
    case PlyType::float64:
      return 8;
  }
  return 8;
}

bool ply_type_is_integer(PlyType type) noexcept {
  return type != PlyType::float32 && type != PlyType::float64;
}

PlyHeader parse_ply_header(std::string_view data, const std::string& source) {
  return HeaderParser(data, source).parse();
}

std::string ply_format_name(PlyFormat format) {
  switch (format) {
    case PlyFormat::ascii:
      return "ply ascii";
    case PlyFormat::binary_little_endian:
      return "ply binary little endian";
    case PlyFormat::binary_big_endian:
      return "ply binary big endian";
  }
  return "ply";
}

}  // namespace exactgeo::mesh::internal
